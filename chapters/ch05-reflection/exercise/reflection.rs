//! Exercise 1 (★): the direction of the reflected ray.
use raystep_core::DVec3;

// ANCHOR: reflect_ray
/// The lecture's reflected ray direction R = D − 2(D·N)N.
///
/// `d` is the incoming ray's direction D (toward the surface, any length)
/// and `n` the surface's unit normal N (either side: flipping N flips D·N
/// too, and R stays the same). R has D's length, and the angle between R
/// and the surface equals the angle between D and it: the component of D
/// along N changes sign, the component along the surface is kept.
pub fn reflect_ray(d: DVec3, n: DVec3) -> DVec3 {
    // TODO: take away twice D's component along N (D·N times N).
    let _ = (d, n);
    todo!("ch05 exercise 1: reflect_ray")
}
// ANCHOR_END: reflect_ray
