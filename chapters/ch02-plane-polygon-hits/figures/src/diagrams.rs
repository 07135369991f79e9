//! The chapter's lecture figures, drawn from the reference code.
//!
//! Every number and verdict shown (t, the case of a ray, each f, inside or
//! outside, who owns a shared edge, which polygon a pixel sees) comes from
//! [`ray_plane`], [`edge_function`], [`inside_convex`], [`inside_crossing`]
//! and [`hit_map`].
use raystep_figure::numbers::{fixed, signed};
use raystep_figure::{
    Anchor, Color, DVec2, DVec3, Figure, Page, Stroke, palette,
};

use ch01::rotate90;
use ch02::{
    Interval, Plane, Ray, RayPlane, demo_camera, demo_scene, edge_function,
    hit_map, inside_convex, inside_crossing, ray_plane,
};

/// Every figure of this chapter, in the order the lecture shows them.
pub fn all() -> Vec<Figure> {
    vec![
        ray_plane_figure(),
        parallel_and_behind(),
        inside_test(),
        concave(),
        tie_rule(),
        hit_map_figure(),
    ]
}

/// Colours of the chapter's figures (N and D as in every chapter: `palette::role`).
const INSIDE_COLOR: Color = palette::GREEN;
const OUTSIDE_COLOR: Color = palette::VERMILION;
/// One colour per polygon: A, B, C, D of the demo scene and the fan.
const POLYGON_COLORS: [Color; 4] = [
    palette::SKY_BLUE,
    palette::ORANGE,
    palette::GREEN,
    palette::PURPLE,
];

/// A 3D point of the side view: z = 0.
fn v3(p: DVec2) -> DVec3 {
    p.extend(0.0)
}

/// The plane through the 2D points `a` and `b` of the side view, standing
/// straight up out of the page (it contains the z axis direction), with its
/// normal on the left of `a → b`.
fn side_plane(a: DVec2, b: DVec2) -> Plane {
    Plane::through(v3(a), v3(a) + DVec3::Z, v3(b))
        .expect("two distinct points and z fix a plane")
}

/// The plane's normal in the side view.
fn side_normal(plane: &Plane) -> DVec2 {
    plane.normal.truncate()
}

/// A ray from P₀ along D meets a tilted plane at the t that `ray_plane` computes.
fn ray_plane_figure() -> Figure {
    let (a, b) = (DVec2::new(5.0, -0.9), DVec2::new(6.2, 4.4));
    let plane = side_plane(a, b);
    let n = side_normal(&plane);
    let p0 = DVec2::new(0.6, 1.3);
    let d = DVec2::new(1.0, 0.3).normalize();
    let ray = Ray::new(v3(p0), v3(d));
    let RayPlane::Hit(t) = ray_plane(&plane, &ray, Interval::FORWARD) else {
        panic!("the example ray hits the plane");
    };
    let hit = ray.at(t).truncate();
    let distance = plane.eval(ray.origin);
    let approach = plane.normal.dot(ray.direction);

    let mut page = Page::new(640.0, 420.0)
        .view(DVec2::new(-0.4, -1.0), DVec2::new(7.4, 4.6));
    // the plane, seen edge-on
    page.segment(a, b, &Stroke::ink().width(2.0));
    page.label(b, "N·P + d = 0", Anchor::W);
    // N·P₀ + d: the distance of P₀ from the plane, measured along N
    let foot = p0 - distance * n;
    page.segment(p0, foot, &Stroke::new(palette::GREY).width(1.5).dashed());
    page.right_angle(foot, (b - a).normalize(), n, 0.18);
    page.label(
        p0 + 0.62 * (foot - p0),
        &format!("N·P_0 + d = {}", fixed(distance, 2)),
        Anchor::SW,
    );
    page.arrow(foot, foot + n, &Stroke::vector(palette::role::NORMAL));
    page.label(foot + 0.6 * n, "N", Anchor::S);
    // the ray up to the hit, and beyond it (dashed)
    page.segment(p0, hit, &Stroke::new(palette::role::RAY).width(1.5));
    page.segment(
        hit,
        hit + 0.8 * d,
        &Stroke::new(palette::role::RAY).width(1.5).dashed(),
    );
    page.arrow(p0, p0 + d, &Stroke::vector(palette::role::RAY));
    page.label(p0 + d, "D", Anchor::N);
    page.point(p0, palette::BLACK);
    page.label(p0, "P_0", Anchor::W);
    page.point(hit, palette::BLACK);
    page.label(hit, "P(t)", Anchor::NW);
    // the formula, with the numbers of this ray
    for (k, line) in [
        "P(t) = P_0 + t·D".to_string(),
        "t = −(N·P_0 + d) / (N·D)".to_string(),
        format!(
            "= −{} / ({}) = {}",
            fixed(distance, 2),
            fixed(approach, 2),
            fixed(t, 2)
        ),
    ]
    .iter()
    .enumerate()
    {
        // the last line starts under the first "=" (about 12 px in)
        let indent = if k == 2 { 12.0 / page.scale() } else { 0.0 };
        page.label(
            DVec2::new(-0.2 + indent, 4.2 - 0.55 * k as f64),
            line,
            Anchor::E,
        );
    }
    Figure::new(
        "ray-plane",
        "The ray P(t) = P₀ + t·D meets the plane N·P + d = 0 at t = −(N·P₀ + d)/(N·D): the distance of P₀ over the rate at which the ray approaches.",
        page,
    )
}

/// Left: a ray parallel to the plane; right: a ray pointing away from it, hit behind its origin.
fn parallel_and_behind() -> Figure {
    let mut page = Page::new(900.0, 420.0)
        .view(DVec2::new(0.0, 0.0), DVec2::new(16.0, 7.0));
    page.segment(
        DVec2::new(8.0, 0.2),
        DVec2::new(8.0, 6.8),
        &Stroke::new(palette::LIGHT_GREY).width(1.5),
    );
    let title = |page: &mut Page, x: f64, text: &str| {
        page.label(DVec2::new(x, 6.3), text, Anchor::Center);
    };

    // Left panel: D along the plane.
    let (a, b) = (DVec2::new(0.6, 1.6), DVec2::new(7.4, 1.6));
    let plane = side_plane(a, b);
    let n = side_normal(&plane);
    let p0 = DVec2::new(1.4, 3.8);
    let d = DVec2::new(1.0, 0.0);
    let ray = Ray::new(v3(p0), v3(d));
    let case = ray_plane(&plane, &ray, Interval::FORWARD);
    assert_eq!(case, RayPlane::Parallel, "the left ray runs parallel");
    title(&mut page, 4.0, "parallel: N·D = 0");
    page.segment(a, b, &Stroke::ink().width(2.0));
    let foot = DVec2::new(6.4, 1.6);
    page.arrow(foot, foot + n, &Stroke::vector(palette::role::NORMAL));
    page.label(foot + n, "N", Anchor::E);
    page.segment(
        p0,
        DVec2::new(7.2, p0.y),
        &Stroke::new(palette::role::RAY).width(1.5),
    );
    page.arrow(p0, p0 + d, &Stroke::vector(palette::role::RAY));
    page.label(p0 + d, "D", Anchor::N);
    page.point(p0, palette::BLACK);
    page.label(p0, "P_0", Anchor::W);
    // N·P₀ + d ≠ 0: off the plane (= 0 would put the whole ray in it)
    let distance = plane.eval(ray.origin);
    let foot = p0 - distance * n;
    page.segment(p0, foot, &Stroke::new(palette::GREY).width(1.5).dashed());
    page.label(
        (p0 + foot) / 2.0,
        &format!("N·P_0 + d = {} ≠ 0", fixed(distance, 2)),
        Anchor::E,
    );
    page.label(DVec2::new(7.2, p0.y), "never meets it", Anchor::SW);
    page.label(
        DVec2::new(4.0, 1.6),
        &format!("ray\\_plane → {case:?}"),
        Anchor::S,
    );

    // Right panel: D pointing away from the plane.
    let (a, b) = (DVec2::new(8.6, 1.6), DVec2::new(15.4, 1.6));
    let plane = side_plane(a, b);
    let n = side_normal(&plane);
    let p0 = DVec2::new(12.2, 3.4);
    let d = DVec2::new(0.55, 0.8).normalize();
    let ray = Ray::new(v3(p0), v3(d));
    let case = ray_plane(&plane, &ray, Interval::FORWARD);
    let RayPlane::Outside(t) = case else {
        panic!("the right ray meets the plane behind its origin");
    };
    let behind = ray.at(t).truncate();
    title(&mut page, 12.0, "pointing away: N·D > 0, t < 0");
    page.segment(a, b, &Stroke::ink().width(2.0));
    let foot = DVec2::new(14.4, 1.6);
    page.arrow(foot, foot + n, &Stroke::vector(palette::role::NORMAL));
    page.label(foot + n, "N", Anchor::E);
    page.segment(
        p0,
        behind,
        &Stroke::new(palette::role::RAY).width(1.5).dashed(),
    );
    page.segment(
        p0,
        p0 + 2.0 * d,
        &Stroke::new(palette::role::RAY).width(1.5),
    );
    page.arrow(p0, p0 + d, &Stroke::vector(palette::role::RAY));
    page.label(p0 + d, "D", Anchor::E);
    page.point(p0, palette::BLACK);
    page.label(p0, "P_0", Anchor::E);
    page.hollow_point(behind, palette::BLACK);
    page.label(
        behind,
        &format!("behind the origin: t = {}", fixed(t, 2)),
        Anchor::S,
    );
    page.label(
        behind + DVec2::new(0.0, -0.55),
        &format!("ray\\_plane → Outside({})", fixed(t, 2)),
        Anchor::S,
    );

    Figure::new(
        "parallel-and-behind",
        "No hit: a ray with N·D = 0 never meets the plane, and a ray pointing away meets it only behind its origin, at t < 0.",
        page,
    )
}

/// The lecture's convex house: counter-clockwise, small integers.
const HOUSE: [DVec2; 5] = [
    DVec2::new(0.0, 0.0),
    DVec2::new(4.0, 0.0),
    DVec2::new(4.0, 3.0),
    DVec2::new(2.0, 5.0),
    DVec2::new(0.0, 3.0),
];

/// Edge `i` of a closed vertex list.
fn edge(vertices: &[DVec2], i: usize) -> (DVec2, DVec2) {
    (vertices[i], vertices[(i + 1) % vertices.len()])
}

/// The edge test on a convex polygon: inward normals, every f(Q) ≥ 0, one f(R) < 0.
fn inside_test() -> Figure {
    let q = DVec2::new(2.0, 2.0);
    let r = DVec2::new(5.5, 1.0); // off every edge line, so only f₂ is negative
    let (q_in, r_in) = (inside_convex(&HOUSE, q), inside_convex(&HOUSE, r));
    assert!(q_in && !r_in, "Q is inside the house, R outside");
    let verdict = |inside: bool| if inside { "inside" } else { "outside" };
    let mut page = Page::new(640.0, 420.0)
        .view(DVec2::new(-1.6, -0.7), DVec2::new(8.0, 5.4));
    page.polygon_alpha(
        &HOUSE,
        Some(INSIDE_COLOR.with_alpha(0.12)),
        Some(&Stroke::ink()),
    );
    let mut failing = Vec::new();
    for i in 0..HOUSE.len() {
        let (a, b) = edge(&HOUSE, i);
        let (fq, fr) = (edge_function(a, b, q), edge_function(a, b, r));
        let inward = rotate90(b - a).normalize();
        let mid = (a + b) / 2.0;
        if fr < 0.0 {
            // the edge R fails: its whole implicit line, f = 0, dashed
            failing.push((i, fr));
            page.segment(
                a - 0.25 * (b - a),
                b + 0.25 * (b - a),
                &Stroke::new(OUTSIDE_COLOR).width(1.5).dashed(),
            );
            page.segment(a, b, &Stroke::new(OUTSIDE_COLOR).width(4.0));
        }
        page.arrow(
            mid,
            mid + 0.6 * inward,
            &Stroke::new(palette::BLACK).width(2.0),
        );
        // f(Q) outside the edge; beside R's edge, high up so R's label has room
        let along = if fr < 0.0 { 0.85 } else { 0.5 };
        page.label_sized(
            a + along * (b - a) - 0.08 * inward,
            &format!("f_{}(Q) = {}", i + 1, signed(fq, 5)),
            Anchor::pointing(-inward),
            16.0,
            INSIDE_COLOR,
        );
    }
    page.point(q, palette::BLACK);
    page.label(q, "Q", Anchor::E);
    page.point(r, palette::BLACK);
    page.label(r, "R", Anchor::N);
    let mut lines =
        vec![(format!("Q: every f ≥ 0, {}", verdict(q_in)), INSIDE_COLOR)];
    for (i, fr) in failing {
        page.label_sized(
            r,
            &format!("f_{}(R) = {}", i + 1, signed(fr, 5)),
            Anchor::SE,
            16.0,
            OUTSIDE_COLOR,
        );
        lines.push((
            format!("R: f_{} < 0, {}", i + 1, verdict(r_in)),
            OUTSIDE_COLOR,
        ));
    }
    for (k, (text, color)) in lines.iter().enumerate() {
        page.label_sized(
            DVec2::new(4.9, 4.9 - 0.5 * k as f64),
            text,
            Anchor::E,
            16.0,
            *color,
        );
    }
    lines.push(("arrows: inward normals".to_string(), palette::BLACK));
    Figure::new(
        "inside-test",
        "The edge test: Q is inside because f ≥ 0 on the inner side of every edge, where the inward normals point; R is outside because one f is negative.",
        page,
    )
}

/// The part of the convex polygon `poly` where `edge_function(a, b, ·) ≥ 0`: one step of
/// the edge test, as a region (Sutherland–Hodgman clipping).
fn clip_to_inner_side(poly: &[DVec2], a: DVec2, b: DVec2) -> Vec<DVec2> {
    let mut out = Vec::new();
    for i in 0..poly.len() {
        let (p, q) = edge(poly, i);
        let (fp, fq) = (edge_function(a, b, p), edge_function(a, b, q));
        if fp >= 0.0 {
            out.push(p);
        }
        if (fp >= 0.0) != (fq >= 0.0) {
            out.push(p + fp / (fp - fq) * (q - p));
        }
    }
    out
}

/// A concave dart: where the edge test and the crossing test disagree.
fn concave() -> Figure {
    let dart = [
        DVec2::new(0.0, 2.4),
        DVec2::new(-1.8, -1.4),
        DVec2::new(0.0, -0.2),
        DVec2::new(1.8, -1.4),
    ];
    let p = DVec2::new(-1.05, -0.55);
    let (crossing_says, edge_says) =
        (inside_crossing(&dart, p), inside_convex(&dart, p));
    assert!(crossing_says && !edge_says, "the tests disagree at P");
    let verdict = |inside: bool| if inside { "inside" } else { "outside" };
    let mut page = Page::new(640.0, 420.0)
        .view(DVec2::new(-2.0, -1.6), DVec2::new(5.0, 2.6));

    // What the edge test accepts: the points on the inner side of every edge.
    let mut accepted = vec![
        DVec2::new(-9.0, -9.0),
        DVec2::new(9.0, -9.0),
        DVec2::new(9.0, 9.0),
        DVec2::new(-9.0, 9.0),
    ];
    for i in 0..dart.len() {
        let (a, b) = edge(&dart, i);
        accepted = clip_to_inner_side(&accepted, a, b);
    }
    let centre =
        accepted.iter().copied().sum::<DVec2>() / accepted.len() as f64;
    assert!(
        inside_convex(&dart, centre),
        "the clipped region is what the edge test accepts"
    );
    let real = palette::WHITE.mix(palette::SKY_BLUE, 0.4);
    let both = palette::WHITE.mix(palette::BLUE, 0.5);
    page.polygon(&dart, Some(real), None);
    page.polygon(&accepted, Some(both), None);
    page.polygon(&dart, None, Some(&Stroke::ink()));

    // The crossing test's ray, with the crossings found the way inside_crossing finds them.
    let far = DVec2::new(2.2, p.y);
    page.arrow(p, far, &Stroke::new(palette::BLACK).width(1.5));
    let mut crossings = 0;
    for i in 0..dart.len() {
        let (a, b) = edge(&dart, i);
        if (a.y > p.y) != (b.y > p.y) {
            let (lo, hi) = if a.y < b.y { (a, b) } else { (b, a) };
            if edge_function(lo, hi, p) > 0.0 {
                crossings += 1;
                let c = DVec2::new(
                    lo.x + (p.y - lo.y) / (hi.y - lo.y) * (hi.x - lo.x),
                    p.y,
                );
                page.point(c, OUTSIDE_COLOR);
                // the number on the side the edge leaves free
                let anchor = if hi.x > lo.x { Anchor::NW } else { Anchor::NE };
                page.label_sized(
                    c,
                    &crossings.to_string(),
                    anchor,
                    16.0,
                    OUTSIDE_COLOR,
                );
            }
        }
    }
    assert_eq!(crossings % 2 == 1, crossing_says, "odd means inside");
    page.point(p, palette::BLACK);
    page.label(p, "P", Anchor::W);

    // legend and verdicts
    let x = 2.4;
    let swatch = |page: &mut Page, y: f64, color: Color| {
        let (lo, hi) =
            (DVec2::new(x, y - 0.14), DVec2::new(x + 0.28, y + 0.14));
        page.polygon(
            &[lo, DVec2::new(hi.x, lo.y), hi, DVec2::new(lo.x, hi.y)],
            Some(color),
            Some(&Stroke::new(palette::BLACK).thin()),
        );
    };
    swatch(&mut page, 2.2, both);
    page.label(DVec2::new(x + 0.28, 2.2), "edge test: inside", Anchor::E);
    swatch(&mut page, 1.7, real);
    page.label(
        DVec2::new(x + 0.28, 1.7),
        "missed by the edge test",
        Anchor::E,
    );
    page.label(DVec2::new(x, 0.95), "crossing test at P:", Anchor::E);
    page.label(
        DVec2::new(x, 0.5),
        &format!("{crossings} crossings: {}", verdict(crossing_says)),
        Anchor::E,
    );
    page.label_sized(
        DVec2::new(x, -0.1),
        &format!("edge test at P: {}", verdict(edge_says)),
        Anchor::E,
        16.0,
        OUTSIDE_COLOR,
    );
    Figure::new(
        "concave",
        "On a concave polygon the edge test accepts only the dark part, while the crossing test counts the edges a ray from P crosses: odd means inside.",
        page,
    )
}

/// A fan of polygons around a shared vertex: every point on a shared edge, and the shared
/// vertex itself, is owned by exactly one of them.
fn tie_rule() -> Figure {
    let v = DVec2::ZERO;
    let rim = [
        DVec2::new(4.0, 0.0),
        DVec2::new(2.0, 4.0),
        DVec2::new(-2.0, 4.0),
        DVec2::new(-4.0, 0.0),
        DVec2::new(0.0, -4.0),
    ];
    let fan: [Vec<DVec2>; 4] = [
        vec![v, rim[0], rim[1]],
        vec![v, rim[1], rim[2], rim[3]],
        vec![v, rim[3], rim[4]],
        vec![v, rim[4], rim[0]],
    ];
    let names = ["A", "B", "C", "D"];
    let mut page = Page::new(640.0, 420.0)
        .view(DVec2::new(-4.4, -4.4), DVec2::new(11.0, 4.4));
    for (k, poly) in fan.iter().enumerate() {
        page.polygon_alpha(
            poly,
            Some(POLYGON_COLORS[k].with_alpha(0.3)),
            Some(&Stroke::new(palette::BLACK).width(1.0)),
        );
        let centre = poly.iter().copied().sum::<DVec2>() / poly.len() as f64;
        page.label(centre, names[k], Anchor::Center);
    }
    // points on the shared edges (the spokes) and the shared vertex
    let mut probes = vec![v];
    for &r in &[rim[0], rim[1], rim[3], rim[4]] {
        for k in 1..4 {
            probes.push(v + (r - v) * (f64::from(k) / 4.0));
        }
    }
    let owner = |p: DVec2| {
        let owners: Vec<usize> = (0..fan.len())
            .filter(|&k| inside_convex(&fan[k], p))
            .collect();
        assert_eq!(owners.len(), 1, "{p} has exactly one owner");
        owners[0]
    };
    for p in probes {
        page.circle(
            p,
            6.0 / page.scale(),
            Some(POLYGON_COLORS[owner(p)]),
            Some(&Stroke::new(palette::BLACK).width(1.5)),
        );
    }
    page.label(v, "V", Anchor::NW);
    let x = 4.7;
    let v_owner = names[owner(v)];
    for (k, line) in [
        "tie rule: a shared edge".to_string(),
        "belongs to the polygon on".to_string(),
        "its right (+x side), or to".to_string(),
        "the one above it if the".to_string(),
        "edge is horizontal".to_string(),
        String::new(),
        format!("V belongs to {v_owner}: moved"),
        format!("by (δ, δ²) it lands in {v_owner}"),
    ]
    .iter()
    .enumerate()
    {
        page.label(DVec2::new(x, 3.7 - 0.62 * k as f64), line, Anchor::E);
    }
    Figure::new(
        "tie-rule",
        "The tie rule: each point on a shared edge or at the shared vertex is drawn in the colour of the one polygon that owns it.",
        page,
    )
}

/// The demo scene as the camera sees it: one colour per polygon, the closest hit winning.
fn hit_map_figure() -> Figure {
    let (w, h) = (96, 48);
    let map = hit_map(&demo_scene(), &demo_camera(), w, h);
    let mut page = Page::new(640.0, 420.0)
        .view(DVec2::new(0.0, -9.0), DVec2::new(96.0, 48.0));
    page.raster(DVec2::ZERO, DVec2::new(96.0, 48.0), w, h, |x, y| match map
        .get(x, y)
    {
        Some(i) => POLYGON_COLORS[i % POLYGON_COLORS.len()],
        None => palette::LIGHT_GREY,
    });
    page.polygon(
        &[
            DVec2::ZERO,
            DVec2::new(96.0, 0.0),
            DVec2::new(96.0, 48.0),
            DVec2::new(0.0, 48.0),
        ],
        None,
        Some(&Stroke::new(palette::GREY).thin()),
    );
    let names = ["A triangle", "B square", "C L-shape", "D tilted quad"];
    for (k, name) in names.iter().enumerate() {
        let x = 1.0 + 24.0 * k as f64;
        let y = -5.0;
        page.polygon(
            &[
                DVec2::new(x, y - 1.2),
                DVec2::new(x + 2.4, y - 1.2),
                DVec2::new(x + 2.4, y + 1.2),
                DVec2::new(x, y + 1.2),
            ],
            Some(POLYGON_COLORS[k]),
            Some(&Stroke::new(palette::BLACK).thin()),
        );
        page.label(DVec2::new(x + 2.4, y), name, Anchor::E);
    }
    Figure::new(
        "hit-map",
        "The demo scene ray-cast at 96 × 48 pixels: each pixel shows the polygon its ray hits first, grey where it hits none.",
        page,
    )
}
