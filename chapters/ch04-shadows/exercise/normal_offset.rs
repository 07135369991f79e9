//! Exercise 2 (★★): the shadow ray lifted off the surface along the normal.
//!
//! Fill in `normal_offset_ray`; `cargo run --release -- check ch04` judges it.
use raystep_core::{DVec3, Interval, Ray};

// ANCHOR: normal_offset_ray
/// Strategy 2: the shadow ray from `point` toward `light_position`, its
/// origin moved the fixed distance `epsilon` along the unit `normal` (the
/// normal on the light's side).
///
/// The direction runs from the *moved* origin to the light, so t = 1 is
/// still the light; the interval is [0, 1]: from the origin, which is now
/// off the surface, up to the light.
pub fn normal_offset_ray(
    point: DVec3, normal: DVec3, light_position: DVec3, epsilon: f64,
) -> (Ray, Interval) {
    // TODO:
    // 1. The origin: `point` moved `epsilon` along `normal` (toward the
    //    light's side, so it leaves the surface instead of sinking in).
    // 2. The direction: from that origin to the light, not normalised, so
    //    that t = 1 is exactly the light.
    // 3. The interval: Interval::new(0.0, 1.0), everything between the
    //    origin and the light.
    let _ = (point, normal, light_position, epsilon);
    todo!()
}
// ANCHOR_END: normal_offset_ray
