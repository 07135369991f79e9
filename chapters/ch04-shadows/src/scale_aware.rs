//! Strategy 3: an offset that follows the size of the coordinates, after
//! C. Wächter and N. Binder, "A Fast and Robust Method for Avoiding
//! Self-Intersection", Ray Tracing Gems (2019), chapter 6.
//!
//! The rounding error of a computed point is a few ulps (units in the last
//! place) of its coordinates: 1e-16 of them at 1, 1e-10 at a million,
//! 1e-22 at a millionth. A fixed ε is too small for the second and too
//! large for the third. Moving each coordinate by a fixed *number of ulps*
//! instead moves it by an amount that grows and shrinks with the
//! coordinate, at every scale.
//!
//! Their code is for `f32`. Its three constants, and what they become
//! for `f64`:
//!
//! * `int_scale() = 256`: how many ulps a coordinate moves when the normal
//!   points straight along its axis. A rounding error counted *in ulps*
//!   depends on how many operations made the point, not on the format's
//!   precision, so the count carries over unchanged: [`INT_SCALE`] = 256.
//!   In `f64` 256 ulps are 5.7e-14 of the coordinate (in `f32` 3e-5), so
//!   the offset is far too small to jump over a real blocker.
//! * `origin() = 1/32`: near zero the ulps shrink without bound (down to
//!   5e-324 in `f64`), while the point's error does not, because it comes
//!   from the other numbers of the computation (the ray's origin, the
//!   surface's position). So a coordinate closer to 0 than this moves by
//!   a fixed amount instead. The threshold is a distance, not a precision:
//!   [`ORIGIN`] = 1/32 unchanged.
//! * `float_scale() = 1/65536`: that fixed amount. At |x| = 1/32 an `f32`
//!   ulp is 2⁻²⁸, so 256 of them are 2⁻²⁰, and 2⁻¹⁶ is 16 times that, a
//!   margin for the error from elsewhere. Keeping the same relation to the
//!   ulp at the threshold means scaling by the ratio of the two formats'
//!   ulps, 2⁻⁵² / 2⁻²³ = 2⁻²⁹: [`FLOAT_SCALE`] = 2⁻¹⁶·2⁻²⁹ = 2⁻⁴⁵ ≈ 2.8e-14.
//!
//! What it assumes: a point's error is a few ulps of *its own*
//! coordinates, or below 2⁻⁴⁵ where they are near zero. Wächter and Binder
//! compute a triangle's hit point from its vertices to make that true.
//! Our points come from the ray equation P₀ + t·D, whose error follows
//! |P₀| and |t·D|, up to 10 times larger than P in our scenes, which 256
//! ulps still cover. Where it fails: a coordinate that is near zero only
//! because the surface passes through the origin (a floor at y = 0) while
//! the camera is far away, say 1e4: the error of y is then ≈ 1e-12, far
//! above 2⁻⁴⁵. Chapter 4's acne scene therefore keeps its floor at
//! y = −1; `tests/normal_offset.rs` shows the failure on a plane through
//! the origin.
use raystep_core::DVec3;

// ANCHOR: constants
/// Below this |coordinate| the offset is [`FLOAT_SCALE`]·n, not ulps
/// (Wächter & Binder's `origin()`, the same for `f64`).
pub const ORIGIN: f64 = 1.0 / 32.0;
/// The fixed offset near zero: their `float_scale()` 2⁻¹⁶ scaled by
/// 2⁻²⁹, the ratio of an `f64` ulp to an `f32` ulp.
pub const FLOAT_SCALE: f64 = 1.0 / (65536.0 * 536_870_912.0); // 2⁻⁴⁵
/// Ulps per unit of the normal's component (their `int_scale()`, the same
/// for `f64`: an error counted in ulps does not depend on the precision).
pub const INT_SCALE: f64 = 256.0;
// ANCHOR_END: constants

// ANCHOR: offset_scale_aware
/// `point` moved off its surface along the unit `normal` (on the side the
/// ray leaves from), each coordinate by `INT_SCALE·nᵢ` ulps of itself, or
/// by `FLOAT_SCALE·nᵢ` where it is closer to zero than [`ORIGIN`].
pub fn offset_scale_aware(point: DVec3, normal: DVec3) -> DVec3 {
    DVec3::new(
        offset_coordinate(point.x, normal.x),
        offset_coordinate(point.y, normal.y),
        offset_coordinate(point.z, normal.z),
    )
}

/// One coordinate `p` moved by `INT_SCALE·n` ulps (or `FLOAT_SCALE·n`
/// near zero).
fn offset_coordinate(p: f64, n: f64) -> f64 {
    // Step 1: near zero, a fixed distance.
    if p.abs() < ORIGIN {
        return p + FLOAT_SCALE * n;
    }
    // Step 2: elsewhere, whole ulps. The bits of a positive f64, read as
    // an integer, count up with its value: adding k to them steps k ulps
    // up (and across a power of two the ulp doubles by itself). The cast
    // truncates toward zero, like their float-to-int conversion, so
    // |n| < 1/256 moves nothing.
    let ulps = (INT_SCALE * n) as i64;
    let bits = p.to_bits() as i64;
    // For a negative p the bits count up with |p|: moving toward +n's
    // side means fewer steps from zero.
    let moved = if p < 0.0 { bits - ulps } else { bits + ulps };
    f64::from_bits(moved as u64)
}
// ANCHOR_END: offset_scale_aware

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn constants_are_the_f32_ones_adapted() {
        assert_eq!(FLOAT_SCALE, 2f64.powi(-45));
        // at the threshold, FLOAT_SCALE is 16 × INT_SCALE ulps, as in f32
        let ulp_at_origin = ORIGIN * f64::EPSILON;
        assert_eq!(FLOAT_SCALE / (INT_SCALE * ulp_at_origin), 16.0);
    }

    #[test]
    fn moves_by_ulps_toward_the_normal() {
        for p in [1.0, -1.0, 3.7e6, -2.5e-1, ORIGIN] {
            let up = offset_coordinate(p, 1.0);
            let down = offset_coordinate(p, -1.0);
            assert!(up > p && down < p, "{p}");
            // 256 ulps of p, within a factor 2 (an exponent boundary)
            let ulp = p.abs() * f64::EPSILON;
            assert!((up - p) >= 128.0 * ulp && (up - p) <= 512.0 * ulp, "{p}");
        }
        assert_eq!(offset_coordinate(0.0, 1.0), FLOAT_SCALE);
        assert_eq!(offset_coordinate(5.0, 0.001), 5.0); // 0.256 ulps: none
        // a point well inside a coordinate moves only along the normal
        let p = DVec3::new(2.0, -3.0, 0.5);
        let moved = offset_scale_aware(p, DVec3::Y);
        assert_eq!((moved.x, moved.z), (p.x, p.z));
        assert!(moved.y > p.y);
    }
}
