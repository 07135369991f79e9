//! An object behind a bound answers exactly what the object answers, and
//! tests the object only for the rays that hit the bound.
mod common;

use ch03::Sphere;
use ch08::{
    Aabb, Bound, BoundKind, Bounded, DVec3, Interval, Primitive, RandomLines,
    Ray, Shape, TestCounts,
};
use common::{TestPolygon, equilateral};
use raystep_bench::sampling_sphere;

/// Rays of every kind at `object`: random lines through the sphere around
/// it, the same rays started from its centre (inside every bound), and
/// with a short interval that ends before or inside the object.
fn rays_at(object: &dyn Shape) -> Vec<(Ray, Interval)> {
    let around = sampling_sphere(object);
    let mut rays = Vec::new();
    for ray in RandomLines::new(around, 3).take(20_000) {
        rays.push((ray, Interval::FORWARD));
        rays.push((Ray::new(around.center, ray.direction), Interval::FORWARD));
        let middle = (ray.origin - around.center).length();
        rays.push((ray, Interval::new(0.0, middle)));
        rays.push((ray, Interval::new(middle, f64::INFINITY)));
    }
    rays
}

/// For each bound kind around a sphere and a triangle: the same hit as the
/// object's own for every ray (bit for bit: the object is asked about the
/// same interval), the bound tested once per ray, the object once per
/// bound hit.
#[test]
fn a_bounded_object_answers_what_the_object_answers() {
    let objects: [fn() -> Box<dyn Primitive>; 2] = [
        || Box::new(Sphere::new(DVec3::new(1.0, 2.0, -3.0), 0.7)),
        || Box::new(TestPolygon::new(&equilateral(1.5))),
    ];
    for make in objects {
        let object = make();
        let rays = rays_at(object.as_ref());
        for kind in BoundKind::ALL {
            let bounded = Bounded::around(make(), kind);
            assert_eq!(bounded.bounds(), object.bounds());
            let mut counts = TestCounts::default();
            let (mut differences, mut bound_hits, mut hits) = (0, 0, 0);
            for &(ray, interval) in &rays {
                let own = object.intersect(&ray, interval);
                let behind =
                    bounded.intersect_counted(&ray, interval, &mut counts);
                differences += usize::from(own != behind);
                differences +=
                    usize::from(behind != bounded.intersect(&ray, interval));
                bound_hits +=
                    u64::from(bounded.bound().hit(&ray, interval).is_some());
                hits += usize::from(own.is_some());
            }
            let name = format!("{} in its {}", object.name(), kind.name());
            assert_eq!(differences, 0, "{name}");
            assert!(hits > 1000, "{name}: only {hits} hits, a weak test");
            assert_eq!(
                counts,
                TestCounts {
                    bound: rays.len() as u64,
                    object: bound_hits
                },
                "{name}"
            );
            assert!(counts.object < counts.bound, "{name}: {counts:?}");
        }
    }
}

/// The gate works: behind a box that misses part of the object, the hits
/// there are lost and the object is never tested for those rays.
#[test]
fn a_bound_decides_which_rays_reach_the_object() {
    let sphere = Sphere::new(DVec3::ZERO, 1.0);
    // only the half x ≥ 0.5 of the sphere is inside this box
    let half = Bound::Box(Aabb::new(DVec3::new(0.5, -1.0, -1.0), DVec3::ONE));
    let bounded = Bounded::new(Box::new(sphere), half);
    let mut counts = TestCounts::default();
    let at = |x: f64| Ray::new(DVec3::new(x, 0.0, 5.0), DVec3::NEG_Z);
    assert!(
        bounded
            .intersect_counted(&at(0.8), Interval::FORWARD, &mut counts)
            .is_some()
    );
    assert!(
        bounded
            .intersect_counted(&at(-0.8), Interval::FORWARD, &mut counts)
            .is_none()
    );
    assert!(sphere.intersect(&at(-0.8), Interval::FORWARD).is_some());
    assert_eq!(
        counts,
        TestCounts {
            bound: 2,
            object: 1
        }
    );
    // the hit is the sphere's own, at z = √(1 − 0.8²) = 0.6
    let hit = bounded.intersect(&at(0.8), Interval::FORWARD).unwrap();
    assert!((hit.t - 4.4).abs() < 1e-12, "{hit:?}");
}

/// `Bounded::boxed` puts a shape behind its own box, and the bounds of a
/// bounded object are the object's.
#[test]
fn boxed_uses_the_object_box() {
    let triangle = TestPolygon::new(&[
        DVec3::new(0.0, 0.0, 0.0),
        DVec3::new(1.0, 0.0, 1.0),
        DVec3::new(0.0, 2.0, 0.5),
    ]);
    let b = triangle.bounds();
    let boxed = Bounded::boxed(Box::new(triangle));
    assert_eq!(boxed.bound(), Bound::Box(b));
    assert_eq!(boxed.bounds(), b);
    assert_eq!(boxed.object().bounds(), b);
}
