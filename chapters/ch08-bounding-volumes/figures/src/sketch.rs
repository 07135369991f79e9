//! The lecture's sketch of bounding volumes, in the plane z = 0: a few
//! flat shapes and the circles and boxes around them, computed by the
//! chapter's code that bounds 3D objects.
use std::f64::consts::{PI, TAU};

use raystep_core::{Aabb, DVec3};

use ch08::{BoundingSphere, sphere_of_points};

/// The shapes of the sketch, each as points on its outline in the plane
/// z = 0, centred on the origin: a circle, a square, a thin rotated
/// rectangle and a long capsule. A figure places them side by side.
pub fn sketch_shapes() -> Vec<(&'static str, Vec<DVec3>)> {
    let arc = |center: DVec3, radius: f64, from: f64, count: usize| {
        (0..=count).map(move |k| {
            let angle = from + PI * k as f64 / count as f64;
            center + radius * DVec3::new(angle.cos(), angle.sin(), 0.0)
        })
    };
    let circle = (0..64)
        .map(|k| {
            let angle = TAU * f64::from(k) / 64.0;
            DVec3::new(angle.cos(), angle.sin(), 0.0)
        })
        .collect();
    let square = corners(1.6, 1.6, 0.0);
    let rectangle = corners(2.4, 0.3, 30f64.to_radians());
    let capsule = arc(DVec3::new(1.5, 0.0, 0.0), 0.35, -PI / 2.0, 16)
        .chain(arc(DVec3::new(-1.5, 0.0, 0.0), 0.35, PI / 2.0, 16))
        .collect();
    vec![
        ("circle", circle),
        ("square", square),
        ("thin rectangle", rectangle),
        ("capsule", capsule),
    ]
}

/// The corners of a `width × height` rectangle centred on the origin,
/// turned by `angle` (radians) in the plane z = 0.
fn corners(width: f64, height: f64, angle: f64) -> Vec<DVec3> {
    let (sin, cos) = angle.sin_cos();
    [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)]
        .iter()
        .map(|&(x, y)| {
            let (x, y) = (0.5 * width * x, 0.5 * height * y);
            DVec3::new(cos * x - sin * y, sin * x + cos * y, 0.0)
        })
        .collect()
}

/// The bounds of one shape of the sketch: its box (a rectangle, flat in
/// z), its tight bounding circle ([`sphere_of_points`]) and the circle
/// through its box's corners.
pub fn sketch_bounds(
    points: &[DVec3],
) -> (Aabb, BoundingSphere, BoundingSphere) {
    (
        Aabb::around(points.iter().copied()),
        sphere_of_points(points),
        BoundingSphere::around_points_by_box(points),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The sketch, in the plane z = 0: each shape inside its box (flat: z
    /// from 0 to 0) and its two circles, the tight one within 15 % of the
    /// smallest (known for these shapes) and centred in the plane, the
    /// box's circle through the box's corners.
    #[test]
    fn the_lecture_sketch() {
        let smallest = [
            ("circle", 1.0),
            ("square", 0.8 * 2f64.sqrt()),
            (
                "thin rectangle",
                0.5 * (2.4f64.powi(2) + 0.3f64.powi(2)).sqrt(),
            ),
            ("capsule", 1.5 + 0.35),
        ];
        let shapes = sketch_shapes();
        assert_eq!(shapes.len(), smallest.len());
        for ((name, points), (expected_name, r_min)) in
            shapes.iter().zip(smallest)
        {
            assert_eq!(*name, expected_name);
            let (b, tight, by_box) = sketch_bounds(points);
            assert!(
                points.iter().all(|&p| p.z == 0.0 && b.contains(p)),
                "{name}"
            );
            assert_eq!((b.min.z, b.max.z), (0.0, 0.0), "{name}");
            assert_eq!(by_box, BoundingSphere::around_box(&b), "{name}");
            for sphere in [tight, by_box] {
                let outside = |p: &DVec3| {
                    p.distance(sphere.center) > sphere.radius * (1.0 + 1e-12)
                };
                assert!(!points.iter().any(outside), "{name}: {sphere:?}");
            }
            assert!(tight.center.z.abs() < 1e-12, "{name}: {tight:?}");
            assert!(
                (r_min * (1.0 - 1e-9)..=1.15 * r_min).contains(&tight.radius),
                "{name}: expected a radius within 1.15 × the smallest \
                 sphere's {r_min}, got {tight:?}"
            );
        }
    }
}
