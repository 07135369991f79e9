//! The grid against brute force on rays no tracer should trace. (The
//! grid on every kind of dangerous ray, with and without mailboxing, is
//! `crates/stability`'s: its rays are made there.)
mod common;

use ch03::BruteForce;
use ch09::{Accelerator, DVec3, Grid, Interval, Resolution};
use raystep_bench::uniform_spheres;

use common::sphere_objects;

/// Rays no tracer should trace: NaN or infinite numbers, a zero
/// direction. The grid answers them as brute force does, and returns.
#[test]
fn broken_rays_end_the_walk() {
    let objects = sphere_objects(&uniform_spheres(50, 4));
    let grid = Grid::for_objects(&objects, Resolution::Rule);
    let rays = [
        ch09::Ray::new(DVec3::NAN, DVec3::X),
        ch09::Ray::new(DVec3::ZERO, DVec3::new(f64::NAN, 1.0, 0.0)),
        ch09::Ray::new(DVec3::ZERO, DVec3::ZERO),
        ch09::Ray::new(DVec3::ZERO, DVec3::new(f64::INFINITY, 1.0, 0.0)),
        ch09::Ray::new(DVec3::splat(f64::INFINITY), DVec3::X),
    ];
    let short = Interval::new(0.0, 1.0);
    for ray in &rays {
        let t = |a: &dyn Accelerator| {
            a.closest_hit(&objects, ray, Interval::FORWARD)
                .map(|(_, h)| h.t)
        };
        assert_eq!(t(&grid), t(&BruteForce), "closest hit, {ray:?}");
        for interval in [Interval::FORWARD, short] {
            assert_eq!(
                grid.any_hit(&objects, ray, interval),
                BruteForce.any_hit(&objects, ray, interval),
                "any hit within {interval:?}, {ray:?}"
            );
        }
    }
}
