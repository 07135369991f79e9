//! Exercise 1: Sᵢ, whether a hit point sees a light.
use crate::{Offset, occluded, shadow_ray};
use ch03::World;
use raystep_core::{DVec3, Hit};
use raystep_scene::Light;

// ANCHOR: shadow
/// Sᵢ for `light` at `hit`: 1 if the light reaches the point, 0 if it is
/// in shadow.
///
/// `normal` is the hit's unit normal turned toward the viewer (what
/// `ch03::shade_with` passes), and `offset` says how the shadow ray keeps
/// clear of the surface it starts on.
pub fn shadow(
    world: &World, hit: &Hit, normal: DVec3, light: &Light, offset: Offset,
) -> f64 {
    // Step 1: a light behind the surface (N·L ≤ 0) is blocked by the
    // surface itself; no ray needed.
    if normal.dot(light.position - hit.point) <= 0.0 {
        return 0.0;
    }
    // Step 2: the shadow ray from the point to the light, t = 1 at the light.
    let (ray, interval) = shadow_ray(hit.point, normal, light.position, offset);
    // Step 3: any blocker between them puts the point in shadow.
    if occluded(world, &ray, interval) {
        0.0
    } else {
        1.0
    }
}
// ANCHOR_END: shadow
