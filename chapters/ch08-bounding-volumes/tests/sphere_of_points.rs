//! Exercise 4: a tight bounding sphere of a point set, against the box's
//! circumsphere and against the smallest sphere where it is known.
mod common;

use ch08::{BoundingSphere, DVec3, sphere_of_points};
use common::{Rng, bunny, half_diameter};
use proptest::prelude::*;
use raystep_check::{Table, num_places, seeded};
use raystep_core::glam::DQuat;

/// How much larger than the smallest sphere a tight sphere may be.
/// Ritter's algorithm stays within 5 to 20 % in general; on the sets below
/// it is within 12 %, and an exact algorithm (Welzl's) is at 1.
const FACTOR: f64 = 1.15;

/// How far outside the sphere a point may be: rounding, relative to the
/// sizes involved (the radius and the coordinates of the centre).
fn slack(s: &BoundingSphere) -> f64 {
    1e-12 * (s.radius + s.center.abs().max_element())
}

/// Every point inside `s` (up to [`slack`]), else a message naming the
/// first one outside.
fn assert_holds_all(name: &str, points: &[DVec3], s: &BoundingSphere) {
    assert!(
        s.radius.is_finite() && s.center.is_finite() && s.radius >= 0.0,
        "{name}: expected a finite sphere, got {s:?}"
    );
    for (k, &p) in points.iter().enumerate() {
        let d = p.distance(s.center);
        assert!(
            d <= s.radius + slack(s),
            "{name}: point {k} = {p} is {d} from the centre {}, outside the \
             radius {} (by {})",
            s.center,
            s.radius,
            d - s.radius
        );
    }
}

/// Every point inside, the radius at most [`FACTOR`] × the smallest
/// sphere's `r_min` (and at least r_min: nothing smaller holds them).
fn check(name: &str, points: &[DVec3], r_min: f64) -> BoundingSphere {
    check_within(name, points, r_min, FACTOR)
}

/// [`check`] with another factor.
fn check_within(
    name: &str, points: &[DVec3], r_min: f64, factor: f64,
) -> BoundingSphere {
    let s = sphere_of_points(points);
    assert_holds_all(name, points, &s);
    let tolerance = 1e-9 * r_min.max(1.0);
    assert!(
        s.radius <= factor * r_min + tolerance,
        "{name}: expected a radius within {factor} × the smallest sphere's \
         {r_min}, got {} ({:.4} ×)",
        s.radius,
        s.radius / r_min
    );
    assert!(
        s.radius >= r_min - tolerance,
        "{name}: a radius {} below the smallest possible {r_min}",
        s.radius
    );
    s
}

/// Points on a sphere, each with its opposite point: the smallest sphere
/// around them is that sphere (two opposite points need its diameter).
fn on_a_sphere(center: DVec3, radius: f64, pairs: usize) -> Vec<DVec3> {
    let mut rng = Rng::new(11);
    (0..pairs)
        .flat_map(|_| {
            let u = rng.unit_vec3();
            [center + radius * u, center - radius * u]
        })
        .collect()
}

/// The eight corners of a box: the smallest sphere is its circumsphere.
fn box_corners(min: DVec3, max: DVec3) -> Vec<DVec3> {
    (0..8)
        .map(|k| {
            DVec3::new(
                if k & 1 == 0 { min.x } else { max.x },
                if k & 2 == 0 { min.y } else { max.y },
                if k & 4 == 0 { min.z } else { max.z },
            )
        })
        .collect()
}

/// A regular tetrahedron (every other corner of the cube [−1, 1]³), turned
/// by `angle` radians about the axis (1, 2, 3), moved to `center`. The
/// smallest sphere is its circumsphere, of radius √3.
fn tetrahedron(center: DVec3, angle: f64) -> Vec<DVec3> {
    let turn =
        DQuat::from_axis_angle(DVec3::new(1.0, 2.0, 3.0).normalize(), angle);
    [
        DVec3::new(1.0, 1.0, 1.0),
        DVec3::new(1.0, -1.0, -1.0),
        DVec3::new(-1.0, 1.0, -1.0),
        DVec3::new(-1.0, -1.0, 1.0),
    ]
    .iter()
    .map(|&v| center + turn * v)
    .collect()
}

#[test]
fn points_on_a_sphere() {
    for (center, radius) in [
        (DVec3::ZERO, 1.0),
        (DVec3::new(1.0, -3.0, 5.0), 2.0),
        (DVec3::new(1e6, 2e6, -1e6), 1e-3),
        (DVec3::splat(1e-6), 1e-9),
    ] {
        let points = on_a_sphere(center, radius, 500);
        let name =
            format!("500 opposite pairs on the sphere {center}, r {radius}");
        let s = check(&name, &points, radius);
        let by_box = BoundingSphere::around_points_by_box(&points);
        assert!(
            s.radius <= by_box.radius,
            "{name}: the tight sphere ({}) is larger than the box's \
             circumsphere ({})",
            s.radius,
            by_box.radius
        );
        // the box's circumsphere of a round cloud: about √3 × too large
        assert!(by_box.radius > 1.6 * radius, "{name}: {by_box:?}");
    }
}

#[test]
fn corners_of_a_box_and_collinear_points() {
    let boxes = [
        (DVec3::ZERO, DVec3::ONE),
        (DVec3::new(-3.0, 0.5, 2.0), DVec3::new(4.0, 0.75, 9.0)),
        (
            DVec3::new(1e6, 1e6, 1e6),
            DVec3::new(1e6 + 1.0, 1e6 + 2.0, 1e6 + 3.0),
        ),
        // flat: a rectangle in the plane z = 0
        (DVec3::new(-2.0, -1.0, 0.0), DVec3::new(2.0, 1.0, 0.0)),
    ];
    for (min, max) in boxes {
        let corners = box_corners(min, max);
        let name = format!("the corners of the box {min}–{max}");
        let r_min = 0.5 * min.distance(max);
        let s = check(&name, &corners, r_min);
        let by_box = BoundingSphere::around_points_by_box(&corners);
        assert!(
            (by_box.radius - r_min).abs() <= 1e-12 * r_min.max(1.0),
            "{name}: the box's circumsphere should be the smallest sphere, \
             radius {r_min}, got {by_box:?}"
        );
        assert!(
            s.radius <= by_box.radius * (1.0 + 1e-12),
            "{name}: expected a radius at most the box's circumsphere's {} \
             (here the smallest sphere), got {}",
            by_box.radius,
            s.radius
        );
    }
    // points on a segment, in a shuffled order: the smallest sphere has
    // the segment as its diameter
    let (a, b) = (DVec3::new(-1.0, 2.0, 0.5), DVec3::new(3.0, -2.0, 4.5));
    let mut rng = Rng::new(5);
    let mut points: Vec<DVec3> =
        (0..200).map(|_| a.lerp(b, rng.unit())).collect();
    points.extend([b, a]);
    points.rotate_left(77);
    let s = check("points on a segment", &points, 0.5 * a.distance(b));
    assert!(
        s.center.distance(a.midpoint(b)) <= 0.15 * a.distance(b),
        "points on a segment: centre {} far from the middle {}",
        s.center,
        a.midpoint(b)
    );
}

/// A regular tetrahedron, turned at several angles and moved: Ritter's
/// worst case. Every pair of corners is a diameter of the same length,
/// so the first sphere is on an edge (radius 0.707 × √3, the smallest
/// sphere's radius being √3) and the two other corners grow it to
/// 1.230 × √3, whichever edge and order. Hence the factor 1.25 here.
///
/// Nor is the box's circumsphere always the larger: at angle 0 the
/// corners are corners of their box, whose circumsphere is then the
/// smallest sphere, 1.23 × smaller than Ritter's.
#[test]
fn a_regular_tetrahedron() {
    for k in 0..12 {
        let angle = f64::from(k) * 0.5;
        let center = DVec3::new(2.0, -1.0, 0.5) * f64::from(k);
        let points = tetrahedron(center, angle);
        check_within(
            &format!("the tetrahedron turned by {angle}"),
            &points,
            3f64.sqrt(),
            1.25,
        );
    }
}

#[test]
fn one_point_duplicates_and_none() {
    let p = DVec3::new(1.5, -2.0, 1e3);
    for count in [1, 2, 10] {
        let s = sphere_of_points(&vec![p; count]);
        assert!(
            s.center.distance(p) <= 1e-12 * p.length() && s.radius <= 1e-9,
            "{count} copies of {p}: expected the point itself, got {s:?}"
        );
    }
    // each corner of a box three times, and one in the middle
    let mut corners = box_corners(DVec3::ZERO, DVec3::new(2.0, 4.0, 4.0));
    corners.extend(corners.clone());
    corners.extend(corners.clone());
    corners.push(DVec3::new(1.0, 2.0, 2.0));
    check("box corners, repeated", &corners, 3.0);
    // the documented answer for no points
    let none = sphere_of_points(&[]);
    assert_eq!(none.radius, 0.0, "no points: radius 0, got {none:?}");
    assert_eq!(none.center, DVec3::ZERO, "no points: at the origin");
    assert_eq!(BoundingSphere::around_points_by_box(&[]), none);
}

/// The bunny's 1,839 vertices: the box's circumsphere, and the tight
/// sphere between half the diameter (nothing smaller holds the two
/// farthest vertices) and the box's circumsphere. The table holds what any
/// correct answer gives. Ritter's radius is 6.579, 1.051 × the
/// half-diameter (the box's circumsphere 1.259 ×); the smallest sphere's
/// lies between the two, and any of them falls in the asserted range.
#[test]
fn the_bunny() {
    let points = bunny().vertices;
    assert_eq!(points.len(), 1839);
    let tight = sphere_of_points(&points);
    assert_holds_all("the bunny", &points, &tight);
    let by_box = BoundingSphere::around_points_by_box(&points);
    assert_holds_all("the bunny (box)", &points, &by_box);
    let half = half_diameter(&points);
    assert!(
        tight.radius >= half * (1.0 - 1e-12)
            && tight.radius <= FACTOR * half
            && tight.radius <= by_box.radius,
        "the bunny: expected a tight radius between the half-diameter \
         {half} and {FACTOR} × that (and below the box's {}), got {}",
        by_box.radius,
        tight.radius
    );
    let mut table = Table::new(&[
        "points",
        "box's circumsphere r",
        "half-diameter",
        "box r / half-diameter",
        "tight r: asserted range",
    ]);
    table.row(&[
        points.len().to_string(),
        num_places(by_box.radius, 3),
        num_places(half, 3),
        num_places(by_box.radius / half, 3),
        format!("{}…{}", num_places(half, 3), num_places(FACTOR * half, 3)),
    ]);
    insta::assert_snapshot!(table.to_string());
}

proptest! {
    #![proptest_config(seeded(256))]

    /// Any cloud, anywhere, at any scale: every point inside, the radius
    /// at least half the diameter (nothing smaller holds the two farthest
    /// points) and at most √3 × that, the worst a box's circumsphere can
    /// do (its diagonal is at most √3 × its longest side).
    #[test]
    fn any_cloud_is_held(
        seed in any::<u64>(),
        count in 1usize..120,
        scale in -6.0..3.0f64,
        offset in -6.0..6.0f64,
    ) {
        let mut rng = Rng::new(seed);
        let (size, shift) = (10f64.powf(scale), 10f64.powf(offset));
        let at = shift * rng.unit_vec3();
        let points: Vec<DVec3> = (0..count)
            .map(|_| at + size * (rng.unit_vec3() * rng.unit()))
            .collect();
        let s = sphere_of_points(&points);
        assert_holds_all("a random cloud", &points, &s);
        let half = half_diameter(&points);
        prop_assert!(
            s.radius >= half * (1.0 - 1e-9) - slack(&s)
                && s.radius <= 3f64.sqrt() * half + slack(&s),
            "a random cloud of {count} points: expected a radius between \
             half the largest distance between two points, {half}, and √3 \
             × that, {}, got {s:?}",
            3f64.sqrt() * half
        );
    }
}
