//! Exercise 2: the shadow ray lifted off the surface along the normal.
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
    // Step 1: lift the origin off the surface, toward the light's side.
    let origin = point + epsilon * normal;
    // Step 2: aim at the light from there (t = 1 at the light).
    let direction = light_position - origin;
    // Step 3: every t from the origin to the light counts.
    (Ray::new(origin, direction), Interval::new(0.0, 1.0))
}
// ANCHOR_END: normal_offset_ray
