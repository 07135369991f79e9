//! Exercise 1 (★★): Sᵢ, whether a hit point sees a light.
//!
//! Fill in `shadow`; `cargo run --release -- check ch04` judges it.
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
    // TODO:
    // 1. If the light is behind the surface (normal · (light.position −
    //    hit.point) ≤ 0), the surface itself blocks it: return 0.
    // 2. Build the shadow ray with shadow_ray(hit.point, normal,
    //    light.position, offset). It returns the ray and the interval of t
    //    that counts (t = 1 is the light: a blocker beyond it does not).
    // 3. occluded(world, &ray, interval) says whether anything blocks it:
    //    0.0 if so, 1.0 if not.
    let _ = (world, hit, normal, light, offset, occluded, shadow_ray);
    todo!()
}
// ANCHOR_END: shadow
