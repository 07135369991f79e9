//! Exercise 2 (★): the reflection of the light direction.
//!
//! Fill in `reflect_light`; `cargo run --release -- check ch03` judges it.
use raystep_core::DVec3;

// ANCHOR: reflect
/// The lecture's Rᵢ: the direction to light `l` mirrored about the normal
/// `n`, R = 2(N·L)N − L. Both unit vectors pointing away from the surface;
/// R comes out unit too, at the same angle to N as L on the other side.
pub fn reflect_light(l: DVec3, n: DVec3) -> DVec3 {
    // TODO: mirror l about n. Draw it: the part of L along N stays, the
    // part across N flips sign.
    let _ = (l, n);
    todo!()
}
// ANCHOR_END: reflect
