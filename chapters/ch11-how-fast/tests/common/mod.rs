//! What the appendix's test files share: a mesh's rays and brute force's
//! answers to them, the one comparison of answers, and a tree deeper than
//! the walks' fixed stacks. (The bunny is `raystep_bench::bunny`.)
#![allow(dead_code)]
use ch08::{
    BoundingSphere, Builder, Bvh, Interval, MeshAccelerator, MeshBvh, MeshHit,
    NodePrecision, Ray32, TraceCounts, triangle_boxes,
};
use ch11::FastBvh;
use raystep_bench::{camera_rays, incoherent_rays};
use raystep_core::{Aabb, DVec3};

/// Rays at `triangles`: `camera`² camera rays and `incoherent` rays
/// through their box (seed 11), rounded to `f32`.
pub fn rays(
    triangles: &[[DVec3; 3]], camera: u32, incoherent: usize,
) -> Vec<Ray32> {
    let bounds = Aabb::around(triangles.iter().flatten().copied());
    let sphere = BoundingSphere::around_box(&bounds);
    camera_rays(sphere, camera)
        .iter()
        .chain(&incoherent_rays(bounds, incoherent, 11))
        .map(Ray32::rounded)
        .collect()
}

/// Brute force's answers to `rays`: the closest hit, and whether
/// anything is hit up to half its `t` and up to just past it (or up to
/// 10 for a miss) — the any-hit questions.
pub struct Truth {
    /// The closest hit of each ray.
    pub closest: Vec<Option<MeshHit>>,
    /// Each any-hit question and its answer, ray after ray.
    pub any: Vec<(Interval, bool)>,
}

pub fn truth(triangles: &[[DVec3; 3]], rays: &[Ray32]) -> Truth {
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

/// (closest-hit, any-hit) disagreements of `fast` with brute force's
/// `truth`.
pub fn wrong(fast: &FastBvh, rays: &[Ray32], truth: &Truth) -> (usize, usize) {
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

/// Both miss, or both hit at the same `t`.
pub fn agree(a: Option<MeshHit>, b: Option<MeshHit>) -> bool {
    match (a, b) {
        (None, None) => true,
        (Some(a), Some(b)) => a.t == b.t,
        _ => false,
    }
}

/// 300 slivers, each 0.9 times the last, along x: the SAH peels them
/// off one by one, a tree about 300 deep.
pub fn slivers() -> Vec<[DVec3; 3]> {
    slivers_of(300)
}

/// `n` slivers, as [`slivers`].
pub fn slivers_of(n: i32) -> Vec<[DVec3; 3]> {
    (0..n)
        .map(|k| {
            let x = 0.9f64.powi(k);
            [
                DVec3::new(x, -1.0, 0.0),
                DVec3::new(x, 1.0, -1.0),
                DVec3::new(x, 1.0, 1.0),
            ]
        })
        .collect()
}
