//! Every step of the appendix against brute force with chapter 8's
//! watertight test (the same test every step runs, so the answers must
//! be the same `t`s exactly): on the bunny's camera and incoherent rays,
//! as closest-hit and any-hit questions; on rays aimed at every shared
//! edge of three surfaces (none may leak); and on rays that are not rays.
mod common;

use common::{agree, bunny};

use ch08::{
    BoundingSphere, Builder, Bvh, EDGE_REACH, Interval, MeshAccelerator,
    MeshBvh, MeshHit, NodePrecision, Ray32, TraceCounts, camera_rays,
    incoherent_rays, leak_surfaces, shared_edge_rays, triangle_boxes,
};
use ch11::{FastBvh, Step};
use raystep_core::glam::Vec3;
use raystep_core::{Aabb, DVec3};

fn rays(triangles: &[[DVec3; 3]]) -> Vec<Ray32> {
    let bounds = Aabb::around(triangles.iter().flatten().copied());
    let sphere = BoundingSphere::around_box(&bounds);
    camera_rays(sphere, 48)
        .iter()
        .chain(&incoherent_rays(bounds, 2000, 11))
        .map(Ray32::rounded)
        .collect()
}

/// Brute force's answers to `rays`: the closest hit, and whether
/// anything is hit up to half its `t` and up to just past it (or up to
/// 10 for a miss) — the any-hit questions.
struct Truth {
    closest: Vec<Option<MeshHit>>,
    any: Vec<(Interval, bool)>,
}

fn truth(triangles: &[[DVec3; 3]], rays: &[Ray32]) -> Truth {
    let tree = Bvh::build(&triangle_boxes(triangles), Builder::Median);
    let brute = MeshBvh::new(triangles, &tree, NodePrecision::Double);
    let closest: Vec<_> = rays
        .iter()
        .map(|ray| brute.brute_force(ray, Interval::FORWARD))
        .collect();
    let any = rays
        .iter()
        .zip(&closest)
        .flat_map(|(ray, hit)| {
            let ends = match hit {
                Some(hit) => vec![0.5 * hit.t, hit.t * (1.0 + 1e-12)],
                None => vec![10.0],
            };
            ends.into_iter().map(|end| {
                let interval = Interval::new(0.0, end);
                (interval, brute.brute_force(ray, interval).is_some())
            })
        })
        .collect();
    Truth { closest, any }
}

/// (closest-hit disagreements, any-hit disagreements) of `step` with
/// brute force's `truth` about `rays`, with its SIMD kernel (where the
/// CPU has it) and with the scalar fallback.
fn disagreements(
    triangles: &[[DVec3; 3]],
    step: Step,
    rays: &[Ray32],
    truth: &Truth,
) -> (usize, usize) {
    let simd = FastBvh::build(triangles, step);
    let scalar = simd.clone().scalar();
    let (a, b) = wrong(&simd, rays, truth);
    let (c, d) = wrong(&scalar, rays, truth);
    (a + c, b + d)
}

/// (closest-hit, any-hit) disagreements of `fast` with brute force's
/// `truth`.
fn wrong(fast: &FastBvh, rays: &[Ray32], truth: &Truth) -> (usize, usize) {
    let mut counts = TraceCounts::default();
    let closest = rays
        .iter()
        .zip(&truth.closest)
        .filter(|(ray, truth)| {
            let ours = fast.closest_hit(ray, Interval::FORWARD, &mut counts);
            !agree(**truth, ours)
        })
        .count();
    let mut asked = truth.any.iter();
    let mut any = 0;
    for (ray, hit) in rays.iter().zip(&truth.closest) {
        for _ in 0..if hit.is_some() { 2 } else { 1 } {
            let &(interval, blocked) = asked.next().unwrap();
            any += usize::from(
                fast.any_hit(ray, interval, &mut counts) != blocked,
            );
        }
    }
    (closest, any)
}

#[test]
fn every_step_agrees_with_brute_force_on_the_bunny() {
    let triangles = bunny();
    let rays = rays(&triangles);
    let truth = truth(&triangles, &rays);
    for step in Step::ALL {
        assert_eq!(
            disagreements(&triangles, step, &rays, &truth),
            (0, 0),
            "{}",
            step.name()
        );
    }
}

#[test]
fn no_ray_leaks_through_a_shared_edge() {
    let bunny = bunny();
    for surface in leak_surfaces(&bunny) {
        let rays = shared_edge_rays(&surface.triangles, surface.points);
        assert!(rays.len() > 1000, "{}: {} rays", surface.name, rays.len());
        for step in Step::ALL {
            let fast = FastBvh::build(&surface.triangles, step);
            let leaks = rays
                .iter()
                .filter(|ray| {
                    let mut counts = TraceCounts::default();
                    fast.closest_hit(ray, EDGE_REACH, &mut counts).is_none()
                })
                .count();
            assert_eq!(leaks, 0, "{} leaks on {}", step.name(), surface.name);
        }
    }
}

#[test]
fn rays_that_are_not_rays_hit_nothing() {
    let triangles = bunny();
    let centre = Vec3::new(0.0, 0.1, 0.0);
    let bad = [
        Ray32 {
            origin: Vec3::new(f32::NAN, 0.0, 1.0),
            direction: -Vec3::Z,
        },
        Ray32 {
            origin: centre + Vec3::Z,
            direction: Vec3::new(0.0, f32::NAN, -1.0),
        },
        Ray32 {
            origin: centre + Vec3::Z,
            direction: Vec3::ZERO,
        },
        Ray32 {
            origin: Vec3::new(f32::INFINITY, 0.1, 0.0),
            direction: -Vec3::X,
        },
        Ray32 {
            origin: centre + Vec3::Z,
            direction: Vec3::new(0.0, 0.0, f32::NEG_INFINITY),
        },
    ];
    for step in Step::ALL {
        let fast = FastBvh::build(&triangles, step);
        let mut counts = TraceCounts::default();
        for ray in &bad {
            assert_eq!(
                fast.closest_hit(ray, Interval::FORWARD, &mut counts),
                None
            );
            assert!(!fast.any_hit(ray, Interval::FORWARD, &mut counts));
        }
        assert_eq!(counts, TraceCounts::default(), "{}: traced", step.name());
    }
}

#[test]
fn a_deep_tree_and_tiny_scenes_work() {
    // 300 slivers, each 0.9 times the last, along x: the SAH peels them
    // off one by one, a tree far deeper than the walks' fixed stacks.
    let deep: Vec<[DVec3; 3]> = common::slivers();
    let tree = Bvh::build(&triangle_boxes(&deep), Builder::SweepSah);
    assert!(tree.depth() > 64, "depth {}", tree.depth());
    let mut rays = Vec::new();
    for k in 0..200 {
        let y = -0.99 + 0.0099 * k as f32;
        rays.push(Ray32 {
            origin: Vec3::new(2.0, y, 0.01),
            direction: -Vec3::X,
        });
        rays.push(Ray32 {
            origin: Vec3::new(-1.0, y, -0.3),
            direction: Vec3::X,
        });
    }
    let one = vec![deep[0]];
    let empty: Vec<[DVec3; 3]> = Vec::new();
    // a triangle with no finite box, kept outside the tree: a plane-like
    // sliver reaching to infinity across the rays
    let mut outside = deep[..20].to_vec();
    outside.push([
        DVec3::new(0.5, -1.0, -1.0),
        DVec3::new(0.5, 1.0, -1.0),
        DVec3::new(0.5, 0.0, f64::INFINITY),
    ]);
    for scene in [&deep, &one, &empty, &outside] {
        let truth = truth(scene, &rays);
        for step in Step::ALL {
            let wrong = disagreements(scene, step, &rays, &truth);
            assert_eq!(wrong, (0, 0), "{}", step.name());
        }
    }
}
