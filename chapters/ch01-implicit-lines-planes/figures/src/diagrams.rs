//! The chapter's lecture figures, drawn from the reference code.
//!
//! Every vector and number shown (V, N, f(Q), E₁, E₂, the error texts)
//! comes from [`Line2::through`], [`rotate90`] and [`Plane::through`].
use raystep_figure::{
    Anchor, DVec2, DVec3, Figure, Page, Projection, Stroke, palette,
};

use ch01::{Line2, Plane, rotate90};

/// Every figure of this chapter, in the order the lecture shows them.
pub fn all() -> Vec<Figure> {
    vec![line_sign(), rotation(), plane(), collinear()]
}

/// The two points of the lecture's example line: P₁ − P₀ = (2, 1.5), so
/// V = (0.8, 0.6) and N = (−0.6, 0.8).
const LINE_P0: DVec2 = DVec2::new(1.0, 1.0);
const LINE_P1: DVec2 = DVec2::new(3.0, 2.5);

/// Colours shared by every figure of the chapter.
const V_COLOR: raystep_figure::Color = palette::GREEN;
const E1_COLOR: raystep_figure::Color = palette::BLUE;
const E2_COLOR: raystep_figure::Color = palette::GREEN;

/// The line through P₀ and P₁ with V, N and the sign of f shaded on both sides.
fn line_sign() -> Figure {
    let line = Line2::through(LINE_P0, LINE_P1).expect("P₀ ≠ P₁ gives a line");
    let (v, n) = (line.direction, line.normal);
    // 100 px per unit: the grid cells are big enough to hold every label.
    let mut page = Page::new(640.0, 420.0)
        .view(DVec2::new(-0.46, -0.36), DVec2::new(5.46, 3.36));

    // f / 4 splits the bands at |f| = 1, 2 and 4: every band edge is a line
    // parallel to f = 0 at that distance, and N's tip lies on the first.
    page.scalar_field(|p| line.eval(p), 4.0, 1.0);
    page.grid(1.0, palette::LIGHT_GREY);
    page.axes(palette::GREY);

    page.line(LINE_P0, v, &Stroke::ink().width(2.0));
    page.right_angle(LINE_P0, v, n, 0.2);
    page.arrow(LINE_P0, LINE_P0 + v, &Stroke::vector(V_COLOR));
    page.arrow(LINE_P0, LINE_P0 + n, &Stroke::vector(palette::role::NORMAL));
    page.label(LINE_P0 + v, "V", Anchor::SE);
    page.label(LINE_P0 + n, "N", Anchor::W);

    // A probe point and the foot of its perpendicular on the line.
    let q = DVec2::new(1.6, 3.2);
    let fq = line.eval(q);
    let foot = q - fq * n;
    page.segment(q, foot, &Stroke::new(palette::BLACK).thin().dashed());
    page.right_angle(foot, -v, n, 0.15);
    page.point(q, palette::BLACK);
    page.label(q, "Q", Anchor::NW);
    // centred in the grid cell left of the perpendicular's middle
    let mid = (q + foot) / 2.0;
    page.label(
        DVec2::new(mid.x.floor() - 0.5, mid.y - 0.1),
        &format!("f(Q) = {fq:.2}"),
        Anchor::Center,
    );

    for (p, name) in [(LINE_P0, "P_0"), (LINE_P1, "P_1")] {
        page.point(p, palette::BLACK);
        page.label(p, name, Anchor::SE);
    }
    page.label(LINE_P0 - 0.6 * v / v.x, "f = 0", Anchor::SE);
    page.label(DVec2::new(0.5, 2.5), "f > 0", Anchor::Center);
    page.label(DVec2::new(4.5, 0.5), "f < 0", Anchor::Center);
    Figure::new(
        "line-sign",
        "The line through P₀ and P₁: N = R·V points to the side where f > 0, and |f| is the distance to the line.",
        page,
    )
}

/// R turns V a quarter turn counter-clockwise: N = R·V = (−v_y, v_x).
fn rotation() -> Figure {
    let v = Line2::through(LINE_P0, LINE_P1)
        .expect("P₀ ≠ P₁ gives a line")
        .direction;
    let n = rotate90(v);
    let mut page = Page::new(640.0, 420.0)
        .view(DVec2::new(-0.9, -0.12), DVec2::new(1.0, 0.9));

    let o = DVec2::ZERO;
    let legs = Stroke::new(palette::BLACK).thin().dashed();
    let mark = 0.04;
    // V's legs: v_x along x, then v_y up.
    let vx = DVec2::new(v.x, 0.0);
    page.segment(o, vx, &legs);
    page.segment(vx, v, &legs);
    page.right_angle(vx, -DVec2::X, DVec2::Y, mark);
    page.label(vx / 2.0, "v_x", Anchor::S);
    page.label((vx + v) / 2.0, "v_y", Anchor::E);
    // N's legs: n_x = −v_y along x, then n_y = v_x up.
    let nx = DVec2::new(n.x, 0.0);
    page.segment(o, nx, &legs);
    page.segment(nx, n, &legs);
    page.right_angle(nx, DVec2::X, DVec2::Y, mark);
    page.label(nx / 2.0, "−v_y", Anchor::S);
    page.label((nx + n) / 2.0, "v_x", Anchor::W);

    page.angle_arc(o, v, n, 40.0, &Stroke::ink().thin(), Some("90°"));
    page.arrow(o, v, &Stroke::vector(V_COLOR));
    page.arrow(o, n, &Stroke::vector(palette::role::NORMAL));
    page.point(o, palette::BLACK);
    page.label(v, "V = (v_x, v_y)", Anchor::N);
    page.label(n, "N = R·V = (−v_y, v_x)", Anchor::N);
    axes_2d(&mut page, DVec2::new(0.82, -0.22), 0.12);
    Figure::new(
        "rotation",
        "R turns V a quarter turn counter-clockwise: the legs swap and v_y changes sign, so N = (−v_y, v_x).",
        page,
    )
}

/// Small x and y axes at `at`, each `len` world units long.
fn axes_2d(page: &mut Page, at: DVec2, len: f64) {
    let stroke = Stroke::new(palette::GREY).width(1.5);
    for (axis, name, anchor) in
        [(DVec2::X, "x", Anchor::E), (DVec2::Y, "y", Anchor::N)]
    {
        page.arrow(at, at + len * axis, &stroke);
        page.label_sized(at + len * axis, name, anchor, 16.0, palette::GREY);
    }
}

/// The three points of the lecture's example plane: P₀ front left, P₁ front
/// right, P₂ at the back, so they run counter-clockwise seen from above.
const PLANE_P: [DVec3; 3] = [
    DVec3::new(0.0, 0.0, 1.2),
    DVec3::new(2.6, 0.3, 1.4),
    DVec3::new(1.0, 0.5, -1.2),
];

/// The oblique view of the 3D figures: x right, y up, z towards the viewer.
fn oblique() -> Projection {
    Projection::oblique(225.0, 0.5)
}

/// Small x, y, z axes at `at` (world units of the page), each `len` long.
fn axes_3d(page: &mut Page, proj: &Projection, at: DVec2, len: f64) {
    let stroke = Stroke::new(palette::GREY).width(1.5);
    for (axis, name, anchor) in [
        (DVec3::X, "x", Anchor::E),
        (DVec3::Y, "y", Anchor::N),
        (DVec3::Z, "z", Anchor::SW),
    ] {
        let tip = at + len * proj.project(axis);
        page.arrow(at, tip, &stroke);
        page.label_sized(tip, name, anchor, 16.0, palette::GREY);
    }
}

/// The plane through P₀, P₁, P₂ with E₁, E₂ and N = E₁×E₂/|E₁×E₂|.
fn plane() -> Figure {
    let [p0, p1, p2] = PLANE_P;
    let plane =
        Plane::through(p0, p1, p2).expect("three points in general position");
    let n = plane.normal;
    let (e1, e2) = (p1 - p0, p2 - p0);
    let proj = oblique();
    let pr = |p: DVec3| proj.project(p);
    let mut page = Page::new(640.0, 420.0)
        .view(DVec2::new(-1.3, -1.27), DVec2::new(3.75, 1.28));

    // A patch of the plane: a rectangle in the plane around the triangle,
    // its sides along u (x made to lie in the plane) and w = N×u.
    let u = (DVec3::X - DVec3::X.dot(n) * n).normalize();
    let w = n.cross(u);
    let centre = (p0 + p1 + p2) / 3.0;
    let (mut lo, mut hi) =
        (DVec2::splat(f64::INFINITY), DVec2::splat(f64::NEG_INFINITY));
    for p in PLANE_P {
        let local = DVec2::new((p - centre).dot(u), (p - centre).dot(w));
        (lo, hi) = (lo.min(local), hi.max(local));
    }
    let (lo, hi) = (lo - 0.45, hi + 0.45);
    let patch: Vec<DVec2> =
        [(lo.x, lo.y), (hi.x, lo.y), (hi.x, hi.y), (lo.x, hi.y)]
            .iter()
            .map(|&(a, b)| pr(centre + a * u + b * w))
            .collect();
    page.polygon_alpha(
        &patch,
        Some(palette::SKY_BLUE.with_alpha(0.22)),
        Some(&Stroke::new(palette::SKY_BLUE).width(1.0)),
    );
    page.polygon_alpha(
        &[pr(p0), pr(p1), pr(p2)],
        Some(palette::SKY_BLUE.with_alpha(0.35)),
        Some(&Stroke::ink()),
    );

    // N is at right angles to the plane: a right-angle mark between N and
    // −E₁, on the side away from the triangle.
    let (s, back) = (0.2, -e1.normalize());
    page.polyline(
        &[pr(p0 + s * back), pr(p0 + s * (back + n)), pr(p0 + s * n)],
        &Stroke::new(palette::BLACK).thin(),
    );
    page.arrow(pr(p0), pr(p1), &Stroke::vector(E1_COLOR));
    page.arrow(pr(p0), pr(p2), &Stroke::vector(E2_COLOR));
    let n_tip = pr(p0 + 1.6 * n);
    page.arrow(pr(p0), n_tip, &Stroke::vector(palette::role::NORMAL));
    page.label(n_tip, "N = E_1×E_2/|E_1×E_2|", Anchor::N);
    page.label(pr(p0 + 0.55 * e1), "E_1", Anchor::S);
    page.label(pr(p0 + 0.5 * e2), "E_2", Anchor::NW);
    for (p, name, anchor) in [
        (p0, "P_0", Anchor::S),
        (p1, "P_1", Anchor::E),
        (p2, "P_2", Anchor::NE),
    ] {
        page.point(pr(p), palette::BLACK);
        page.label(pr(p), name, anchor);
    }
    axes_3d(&mut page, &proj, DVec2::new(3.1, -0.95), 0.35);
    Figure::new(
        "plane",
        "The plane through P₀, P₁, P₂: the edges E₁ and E₂ span it, and their cross product, made unit, is the normal N.",
        page,
    )
}

/// No plane through collinear points, no line through one point twice.
fn collinear() -> Figure {
    // World units are page px (y up): the plane case left, the line case right.
    let (width, split) = (680.0, 400.0);
    let mut page = Page::new(width, 420.0);
    let divider = Stroke::new(palette::LIGHT_GREY).width(1.0);
    page.segment(DVec2::new(split, 20.0), DVec2::new(split, 400.0), &divider);
    let text_rows = [128.0, 98.0, 68.0];

    // Left: three collinear points, P₂ − P₀ = −1.5·(P₁ − P₀): E₁ and E₂
    // point opposite ways along one line.
    let proj = oblique();
    let p0 = DVec3::ZERO;
    let step = DVec3::new(1.0, 0.5, -0.4);
    let (p1, p2) = (p0 + step, p0 - 1.5 * step);
    let plane_error =
        Plane::through(p0, p1, p2).expect_err("collinear points give no plane");
    let at = |p: DVec3| DVec2::new(225.0, 265.0) + 85.0 * proj.project(p);
    let dir = step.normalize();
    let (ends0, ends1) = (at(p2 - 0.5 * dir), at(p1 + 0.6 * dir));
    page.segment(ends0, ends1, &Stroke::new(palette::GREY).thin().dashed());
    page.arrow(at(p0), at(p1), &Stroke::vector(E1_COLOR));
    page.arrow(at(p0), at(p2), &Stroke::vector(E2_COLOR));
    page.label((at(p0) + at(p1)) / 2.0, "E_1", Anchor::NW);
    page.label((at(p0) + at(p2)) / 2.0, "E_2", Anchor::NW);
    for (p, name, anchor) in [
        (p0, "P_0", Anchor::SE),
        (p1, "P_1", Anchor::SE),
        (p2, "P_2", Anchor::SE),
    ] {
        page.point(at(p), palette::BLACK);
        page.label(at(p), name, anchor);
    }
    let left = split / 2.0;
    page.label(
        DVec2::new(left, text_rows[0]),
        "E_1×E_2 = 0 → no plane",
        Anchor::Center,
    );
    page.label(
        DVec2::new(left, text_rows[1]),
        "Plane::through returns",
        Anchor::Center,
    );
    page.label_sized(
        DVec2::new(left, text_rows[2]),
        &format!("Err: {plane_error}"),
        Anchor::Center,
        16.0,
        palette::VERMILION,
    );

    // Right: P₀ = P₁, and every line through the point would do.
    let right = (split + width) / 2.0;
    let p = DVec2::new(right, 265.0);
    let line_error = Line2::through(p, p).expect_err("one point gives no line");
    let fan = Stroke::new(palette::GREY).thin().dashed();
    for k in 0..6 {
        let d = DVec2::from_angle(f64::from(k) * std::f64::consts::PI / 6.0);
        page.segment(p - 70.0 * d, p + 70.0 * d, &fan);
    }
    page.point(p, palette::BLACK);
    page.label(p + DVec2::new(0.0, 78.0), "P_0 = P_1", Anchor::N);
    page.label(
        DVec2::new(right, text_rows[0]),
        "P_1 − P_0 = 0 → no direction V",
        Anchor::Center,
    );
    page.label(
        DVec2::new(right, text_rows[1]),
        "Line2::through returns",
        Anchor::Center,
    );
    page.label_sized(
        DVec2::new(right, text_rows[2]),
        &format!("Err: {line_error}"),
        Anchor::Center,
        16.0,
        palette::VERMILION,
    );
    Figure::new(
        "collinear",
        "Degenerate input: collinear points lie in many planes and one point lies on many lines, so both constructors return an error instead of a normal.",
        page,
    )
}
