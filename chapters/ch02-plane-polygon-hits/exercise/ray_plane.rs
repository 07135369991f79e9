//! Exercise 1 (★): where a ray meets a plane.
//!
//! Fill in `ray_plane`; `cargo run --release -- check ch02` judges it.
use crate::{RayPlane, zero_within_rounding};
use ch01::Plane;
use raystep_core::{Interval, Ray};

// ANCHOR: ray_plane
/// Classifies how `ray` meets `plane`, accepting hits with `t` in `interval`.
pub fn ray_plane(plane: &Plane, ray: &Ray, interval: Interval) -> RayPlane {
    // TODO: t = −(N·P0 + d) / (N·D), with the lecture's cases:
    // - N·D = 0: the ray is parallel. It lies in the plane (RayPlane::InPlane)
    //   if N·P0 + d = 0, else it never meets it (RayPlane::Parallel).
    //   "= 0" means zero within rounding: use zero_within_rounding(value,
    //   magnitude) with magnitude N.abs()·D.abs() for N·D, and
    //   N.abs()·P0.abs() + |d| for N·P0 + d.
    // - t in `interval` → RayPlane::Hit(t); otherwise RayPlane::Outside(t)
    //   (e.g. t < 0: the plane is behind the origin). Use interval.contains(t):
    //   the interval is closed, so a ray starting on the plane is Hit(0).
    let _ = (plane, ray, interval, zero_within_rounding);
    todo!()
}
// ANCHOR_END: ray_plane
