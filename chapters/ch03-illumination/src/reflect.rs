//! Exercise 2: the reflection of the light direction.
use raystep_core::DVec3;

// ANCHOR: reflect
/// The lecture's Rᵢ: the direction to light `l` mirrored about the normal
/// `n`, R = 2(N·L)N − L. Both unit vectors pointing away from the surface;
/// R comes out unit too, at the same angle to N as L on the other side.
pub fn reflect_light(l: DVec3, n: DVec3) -> DVec3 {
    2.0 * n.dot(l) * n - l
}
// ANCHOR_END: reflect
