//! Exercise 6: the near-first walk. It finds the same closest hit as
//! brute force, respects the interval and the objects outside the tree,
//! and — the point of visiting the nearer child first — opens only the
//! boxes before the first hit along a row of spheres, whichever way the
//! ray runs.
mod common;

use std::sync::Arc;
use std::sync::atomic::{AtomicUsize, Ordering};

use ch03::{BruteForce, Sphere};
use ch08::{
    Aabb, Accelerator, Bvh, DVec3, Hit, Interval, MAX_LEAF, Object, Ray, Shape,
    near_first_closest_hit,
};
use common::Rng;

/// A sphere that counts how often a ray is tested against it.
#[derive(Debug)]
struct Counted {
    sphere: Sphere,
    tests: Arc<AtomicUsize>,
}

impl Shape for Counted {
    fn intersect(&self, ray: &Ray, interval: Interval) -> Option<Hit> {
        self.tests.fetch_add(1, Ordering::Relaxed);
        self.sphere.intersect(ray, interval)
    }

    fn bounds(&self) -> Aabb {
        Shape::bounds(&self.sphere)
    }
}

/// `count` unit spheres at x = 0, 3, 6, …, sharing one test counter.
fn row(count: usize) -> (Vec<Object>, Arc<AtomicUsize>) {
    let tests = Arc::new(AtomicUsize::new(0));
    let objects = (0..count)
        .map(|k| Object {
            shape: Arc::new(Counted {
                sphere: Sphere::new(DVec3::new(3.0 * k as f64, 0.0, 0.0), 1.0),
                tests: Arc::clone(&tests),
            }),
            material: 0,
        })
        .collect();
    (objects, tests)
}

fn sphere(center: DVec3, radius: f64) -> Object {
    Object {
        shape: Arc::new(Sphere::new(center, radius)),
        material: 0,
    }
}

/// The object and t of a closest hit, for comparing.
fn answer(hit: Option<(usize, Hit)>) -> Option<(usize, f64)> {
    hit.map(|(i, hit)| (i, hit.t))
}

#[test]
fn along_a_row_only_the_boxes_before_the_first_hit_are_opened() {
    let (objects, tests) = row(64);
    let bvh = Bvh::for_objects(&objects, ch08::Builder::Median);
    // Along +x from x = −10 the first sphere is hit at t = 9; along −x
    // from x = 200 the last one (centre 189) at t = 10.
    let cases = [
        (DVec3::new(-10.0, 0.0, 0.0), DVec3::X, 0, 9.0),
        (DVec3::new(200.0, 0.0, 0.0), -DVec3::X, 63, 10.0),
    ];
    for (origin, direction, first, t) in cases {
        tests.store(0, Ordering::Relaxed);
        let ray = Ray::new(origin, direction);
        let hit =
            near_first_closest_hit(&bvh, &objects, &ray, Interval::FORWARD);
        assert_eq!(answer(hit), Some((first, t)), "along {direction}");
        // Near first, the first leaf reached holds the first sphere, and
        // every other box begins beyond t: one leaf's tests. Far first, or
        // in a fixed order, a ray the other way tests all 64.
        let tested = tests.load(Ordering::Relaxed);
        assert!(
            tested <= MAX_LEAF,
            "along {direction}: {tested} sphere tests, one leaf holds at \
             most {MAX_LEAF}"
        );
    }
}

#[test]
fn the_interval_bounds_the_answer() {
    let (objects, _) = row(8);
    let bvh = Bvh::for_objects(&objects, ch08::Builder::Median);
    let ray = Ray::new(DVec3::new(-10.0, 0.0, 0.0), DVec3::X);
    let walk = |interval| {
        answer(near_first_closest_hit(&bvh, &objects, &ray, interval))
    };
    // Ending before the first sphere: nothing. Starting inside it: its
    // far side (t = 11). Starting after it: the second sphere.
    assert_eq!(walk(Interval::new(0.0, 8.5)), None);
    assert_eq!(walk(Interval::new(10.0, f64::INFINITY)), Some((0, 11.0)));
    assert_eq!(walk(Interval::new(11.5, f64::INFINITY)), Some((1, 12.0)));
}

#[test]
fn no_tree_and_objects_outside_it() {
    let ray = Ray::new(DVec3::new(0.0, 5.0, 0.0), -DVec3::Y);
    // Nothing at all.
    let none = Bvh::for_objects(&[], ch08::Builder::Median);
    let hit = near_first_closest_hit(&none, &[], &ray, Interval::FORWARD);
    assert!(hit.is_none());
    // A plane (outside the tree) nearer than the sphere, then farther.
    for (plane_y, expected) in [(2.0, (0, 3.0)), (-2.0, (1, 4.0))] {
        let objects = vec![
            Object {
                shape: Arc::new(ch02::InfinitePlane(ch02::Plane {
                    normal: DVec3::Y,
                    d: -plane_y,
                })),
                material: 0,
            },
            sphere(DVec3::ZERO, 1.0),
        ];
        let bvh = Bvh::for_objects(&objects, ch08::Builder::Median);
        assert_eq!(bvh.unbounded, vec![0], "the plane stays outside");
        let hit =
            near_first_closest_hit(&bvh, &objects, &ray, Interval::FORWARD);
        assert_eq!(answer(hit), Some(expected), "plane at y = {plane_y}");
    }
}

#[test]
fn seeded_rays_find_what_brute_force_finds() {
    let mut rng = Rng(8);
    let objects: Vec<Object> = (0..300)
        .map(|_| {
            let c = DVec3::new(
                rng.range(-20.0, 20.0),
                rng.range(-20.0, 20.0),
                rng.range(-20.0, 20.0),
            );
            sphere(c, rng.range(0.1, 3.0))
        })
        .collect();
    let mut disagreements = 0;
    for split in [ch08::Builder::Median, ch08::Builder::BinnedSah { bins: 16 }]
    {
        let bvh = Bvh::for_objects(&objects, split);
        for _ in 0..2000 {
            let origin = 40.0 * rng.unit_vector();
            let target = DVec3::new(
                rng.range(-20.0, 20.0),
                rng.range(-20.0, 20.0),
                rng.range(-20.0, 20.0),
            );
            let ray = Ray::new(origin, target - origin);
            let expected =
                BruteForce.closest_hit(&objects, &ray, Interval::FORWARD);
            let actual =
                near_first_closest_hit(&bvh, &objects, &ray, Interval::FORWARD);
            if answer(expected) != answer(actual) {
                disagreements += 1;
            }
        }
    }
    assert_eq!(disagreements, 0, "of 4000 rays");
}
