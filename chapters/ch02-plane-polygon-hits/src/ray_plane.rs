//! Exercise 1: where a ray meets a plane.
use crate::{RayPlane, zero_within_rounding};
use ch01::Plane;
use raystep_core::{Interval, Ray};

// ANCHOR: ray_plane
/// Classifies how `ray` meets `plane`, accepting hits with `t` in `interval`.
pub fn ray_plane(plane: &Plane, ray: &Ray, interval: Interval) -> RayPlane {
    // Step 1: N·D, how fast the ray approaches the plane.
    let approach = plane.normal.dot(ray.direction);
    // Step 2: N·P₀ + d, the signed distance of the ray's origin.
    let distance = plane.eval(ray.origin);
    // Step 3: N·D = 0 (within its rounding error): parallel. The ray lies
    // in the plane if its origin does, else it never meets it.
    if zero_within_rounding(
        approach,
        plane.normal.abs().dot(ray.direction.abs()),
    ) {
        let magnitude =
            plane.normal.abs().dot(ray.origin.abs()) + plane.d.abs();
        return if zero_within_rounding(distance, magnitude) {
            RayPlane::InPlane
        } else {
            RayPlane::Parallel
        };
    }
    // Step 4: t = −(N·P₀ + d) / (N·D).
    let t = -distance / approach;
    // Step 5: only a t inside the interval is a hit (t < 0 is behind the
    // origin).
    if interval.contains(t) {
        RayPlane::Hit(t)
    } else {
        RayPlane::Outside(t)
    }
}
// ANCHOR_END: ray_plane
