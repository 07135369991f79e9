//! The idea of an instance, in the plane: one mesh in its own frame, two
//! placements of it in the world, and a world ray taken into the mesh's
//! frame by the inverse placement, where it hits at the same t. The
//! steps are [`MeshInstance`](ch08::MeshInstance)'s, in two dimensions:
//! the figure computes what it draws.
use raystep_core::glam::{DAffine2, DMat2};
use raystep_figure::palette;
use raystep_figure::{Anchor, DVec2, Figure, Page, Stroke};

/// The mesh, a house with a chimney (in its own frame; counter-clockwise,
/// so an edge's outward normal is its direction turned clockwise).
const MESH: [(f64, f64); 9] = [
    (-1.0, -0.8),
    (1.0, -0.8),
    (1.0, 0.3),
    (0.0, 1.1),
    (-0.4, 0.78),
    (-0.4, 1.05),
    (-0.7, 1.05),
    (-0.7, 0.54),
    (-1.0, 0.3),
];

/// The placement T · R · S of a translation, an angle in degrees and a
/// scale along the mesh's x and y.
fn placement(translate: DVec2, degrees: f64, scale: DVec2) -> DAffine2 {
    DAffine2::from_mat2_translation(
        DMat2::from_angle(degrees.to_radians()) * DMat2::from_diagonal(scale),
        translate,
    )
}

/// The closest hit of the ray `origin + t·direction` (t > 0) on the
/// polygon's edges: its t and the edge's index.
fn closest_hit(
    polygon: &[DVec2], origin: DVec2, direction: DVec2,
) -> Option<(f64, usize)> {
    let mut best: Option<(f64, usize)> = None;
    for k in 0..polygon.len() {
        let (a, b) = (polygon[k], polygon[(k + 1) % polygon.len()]);
        let edge = b - a;
        let det = direction.perp_dot(edge);
        if det.abs() < 1e-12 {
            continue;
        }
        let t = (a - origin).perp_dot(edge) / det;
        let s = (a - origin).perp_dot(direction) / det;
        if t > 0.0 && (0.0..=1.0).contains(&s) && best.is_none_or(|b| t < b.0) {
            best = Some((t, k));
        }
    }
    best
}

/// The box's four corners, counter-clockwise.
fn corners(min: DVec2, max: DVec2) -> [DVec2; 4] {
    [min, DVec2::new(max.x, min.y), max, DVec2::new(min.x, max.y)]
}

/// The box around `points`.
fn around(points: &[DVec2]) -> (DVec2, DVec2) {
    points.iter().fold(
        (DVec2::splat(f64::INFINITY), DVec2::splat(f64::NEG_INFINITY)),
        |(lo, hi), &p| (lo.min(p), hi.max(p)),
    )
}

/// Tick marks across a ray at t = 0.5, 1, 1.5, … up to `end`.
fn ticks(
    page: &mut Page, origin: DVec2, direction: DVec2, end: f64, colour: Stroke,
) {
    let across = direction.perp().normalize() * 0.08;
    let mut t = 0.5;
    while t < end {
        let p = origin + t * direction;
        page.segment(p - across, p + across, &colour);
        t += 0.5;
    }
}

/// The figure: the mesh in its frame (left), the world (right).
pub fn instance_idea() -> Figure {
    let mesh: Vec<DVec2> =
        MESH.iter().map(|&(x, y)| DVec2::new(x, y)).collect();
    let (box_min, box_max) = around(&mesh);
    // Two placements: A turned and shrunk, B turned and stretched.
    let a = placement(DVec2::new(-2.1, 0.45), 28.0, DVec2::splat(0.75));
    let b = placement(DVec2::new(1.5, -0.15), -12.0, DVec2::new(1.3, 0.7));
    // The world ray (a unit direction: t is a distance there), and the
    // same ray in B's mesh frame: origin and direction by the inverse
    // placement, the direction not normalised.
    let aim = b.transform_point2(DVec2::new(0.5, 0.7));
    let towards = DVec2::from_angle(290f64.to_radians());
    let (origin, direction) = (aim - 1.5 * towards, towards);
    let to_mesh = b.inverse();
    let (local_origin, local_direction) = (
        to_mesh.transform_point2(origin),
        to_mesh.transform_vector2(direction),
    );
    let (t, edge) = closest_hit(&mesh, local_origin, local_direction)
        .expect("the ray hits instance B");
    // The edge's normal in the mesh frame, and in the world: by the
    // inverse transpose (right) and, wrongly, by the matrix itself.
    let along = mesh[(edge + 1) % mesh.len()] - mesh[edge];
    let normal = DVec2::new(along.y, -along.x).normalize();
    let world_normal = (to_mesh.matrix2.transpose() * normal).normalize();
    let wrong_normal = (b.matrix2 * normal).normalize();

    // Where each frame is drawn on the page: the mesh's origin at `left`,
    // the world's at `right`.
    let (left, right) = (DVec2::new(-5.0, 0.3), DVec2::new(2.2, 0.0));
    let mut page = Page::new(900.0, 380.0)
        .view(DVec2::new(-7.0, -1.3), DVec2::new(5.6, 3.3));
    let ink = Stroke::ink();
    let fill = palette::ORANGE.with_alpha(0.45);
    let box_stroke = Stroke::new(palette::BLUE).width(2.0);
    let moved_stroke = Stroke::new(palette::GREY).width(1.5).dashed();
    let ray = Stroke::new(palette::BLUE).width(2.0);
    let tick = Stroke::new(palette::BLUE).width(1.5);

    // Left: the mesh in its frame, its box, and the ray taken in.
    let at_left = |p: DVec2| left + p;
    let frame = Stroke::new(palette::GREY).width(1.0);
    page.arrow(
        at_left(DVec2::new(-1.5, 0.0)),
        at_left(DVec2::X * 1.6),
        &frame,
    );
    page.arrow(
        at_left(DVec2::new(0.0, -1.2)),
        at_left(DVec2::Y * 1.6),
        &frame,
    );
    let outline: Vec<DVec2> = mesh.iter().map(|&p| at_left(p)).collect();
    page.polygon_alpha(&outline, Some(fill), Some(&ink));
    let square = corners(box_min, box_max).map(at_left);
    page.polygon(&square, None, Some(&box_stroke));
    let hit_local = local_origin + t * local_direction;
    page.arrow(at_left(local_origin), at_left(hit_local), &ray);
    ticks(&mut page, at_left(local_origin), local_direction, t, tick);
    page.point(at_left(hit_local), palette::BLACK);
    page.label_sized(
        at_left(local_origin),
        "M^{−1}O",
        Anchor::W,
        16.0,
        palette::BLUE,
    );
    page.label_sized(
        at_left(hit_local),
        &format!("t = {t:.2}"),
        Anchor::SW,
        16.0,
        palette::BLACK,
    );
    page.arrow(
        at_left(hit_local),
        at_left(hit_local + 0.75 * normal),
        &Stroke::new(palette::VERMILION).width(2.0),
    );
    page.label_sized(
        at_left(hit_local + 0.75 * normal),
        "N",
        Anchor::pointing(normal),
        16.0,
        palette::VERMILION,
    );

    // Right: the two instances, the boxes of their moved corners, and
    // the world ray.
    let at_right = |p: DVec2| right + p;
    for (placed, name) in [(a, "A"), (b, "B")] {
        let outline: Vec<DVec2> = mesh
            .iter()
            .map(|&p| at_right(placed.transform_point2(p)))
            .collect();
        page.polygon_alpha(&outline, Some(fill), Some(&ink));
        let moved = corners(box_min, box_max)
            .map(|c| at_right(placed.transform_point2(c)));
        page.polygon(&moved, None, Some(&moved_stroke));
        let (lo, hi) = around(&moved);
        page.polygon(&corners(lo, hi), None, Some(&box_stroke));
        page.label_sized(
            DVec2::new(lo.x, hi.y),
            name,
            Anchor::NE,
            16.0,
            palette::BLACK,
        );
    }
    let hit = origin + t * direction;
    page.arrow(at_right(origin), at_right(hit), &ray);
    ticks(&mut page, at_right(origin), direction, t, tick);
    page.point(at_right(hit), palette::BLACK);
    page.label_sized(at_right(origin), "O", Anchor::W, 16.0, palette::BLUE);
    page.label_sized(
        at_right(hit),
        &format!("t = {t:.2}"),
        Anchor::SW,
        16.0,
        palette::BLACK,
    );
    page.arrow(
        at_right(hit),
        at_right(hit + 0.75 * world_normal),
        &Stroke::new(palette::VERMILION).width(2.0),
    );
    page.label_sized(
        at_right(hit + 0.75 * world_normal),
        "(M^{−1})^{T}N",
        Anchor::pointing(world_normal),
        16.0,
        palette::VERMILION,
    );
    page.arrow(
        at_right(hit),
        at_right(hit + 0.75 * wrong_normal),
        &Stroke::new(palette::PURPLE).width(2.0).dashed(),
    );
    page.label_sized(
        at_right(hit + 0.75 * wrong_normal),
        "MN",
        Anchor::pointing(wrong_normal),
        16.0,
        palette::PURPLE,
    );

    // Titles.
    for (x, text) in [
        (left.x, "the mesh, in its own frame"),
        (right.x, "the world: the mesh placed twice"),
    ] {
        page.label_sized(
            DVec2::new(x, 3.05),
            text,
            Anchor::Center,
            16.0,
            palette::BLACK,
        );
    }
    Figure::new(
        "instance-idea",
        &format!(
            "Instances, in the plane. Left: one mesh in its own frame, with its box (blue), built once with its own hierarchy. Right: the mesh placed twice, A turned and shrunk, B turned and stretched by M = T·R·S (scale 1.3 × 0.7); each instance's box is the box around its mesh box's corners moved (dashed), what the top hierarchy is built over. The world ray from O (a unit direction; ticks every 0.5 of t) is taken into B's frame by M⁻¹: its origin and its direction, not normalised, so its ticks are spaced differently there but it reaches the mesh at the same t = {t:.2}. The normal goes back by the inverse transpose (vermilion), which keeps it across the surface; moved by M itself (purple, dashed) it leans off it."
        ),
        page,
    )
}
