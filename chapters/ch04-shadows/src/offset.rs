//! Where a shadow ray starts and which t it accepts: three ways to keep a
//! surface from shadowing itself.
use crate::{normal_offset_ray, offset_scale_aware};
use raystep_core::{DVec3, Interval, Ray};

// ANCHOR: offset
/// How a shadow ray avoids finding the surface it starts on.
///
/// The hit point P is rounded: it lies up to a few units in the last place
/// (ulps) of its coordinates above or below the true surface. Started at
/// P, the shadow ray meets its own surface again at some t ≈ 0, half the
/// time at a t just above 0, and the point shadows itself (acne).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Offset {
    /// Strategy 1: start at P, but accept only hits farther than ε: the
    /// ray has a unit direction, so ε is a fixed *distance*, the classic
    /// t_min, and hits within ε of the light are ignored too.
    TMin(f64),
    /// Strategy 2: start at P + ε·N, ε a fixed distance along the normal
    /// (the exercise [`normal_offset_ray`]).
    AlongNormal(f64),
    /// Strategy 3: start a few floating-point steps of P's own coordinates
    /// off the surface ([`offset_scale_aware`], after Wächter & Binder).
    ScaleAware,
}
// ANCHOR_END: offset

// ANCHOR: shadow_ray
/// The shadow ray from the surface point `point` toward a point light at
/// `light_position`, and the interval of t in which a hit blocks the
/// light.
///
/// `normal` is the unit surface normal on the side the light is (the side
/// the ray leaves from). For `TMin` the direction is a unit vector and t
/// is a distance, so the light is at t = |light − P|; for the two offsets
/// the direction runs from the moved origin to the light, so the light is
/// at t = 1. Either way a blocker beyond the light does not count.
pub fn shadow_ray(
    point: DVec3, normal: DVec3, light_position: DVec3, offset: Offset,
) -> (Ray, Interval) {
    match offset {
        // Strategy 1: the ray starts on the surface (or a rounding error
        // below it); hits closer than ε are ignored, and so are hits within
        // ε of the light.
        Offset::TMin(epsilon) => {
            let to_light = light_position - point;
            let distance = to_light.length();
            (
                Ray::new(point, to_light / distance),
                Interval::new(epsilon, distance - epsilon),
            )
        }
        // Strategy 2: lift the origin a fixed distance along the normal.
        Offset::AlongNormal(epsilon) => {
            normal_offset_ray(point, normal, light_position, epsilon)
        }
        // Strategy 3: lift it by an amount that follows P's magnitude.
        Offset::ScaleAware => {
            let origin = offset_scale_aware(point, normal);
            (
                Ray::new(origin, light_position - origin),
                Interval::new(0.0, 1.0),
            )
        }
    }
}
// ANCHOR_END: shadow_ray
