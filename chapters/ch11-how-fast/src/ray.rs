//! Step 2's ray: everything a walk needs from the ray alone, computed
//! once per ray — the box test's origin, reciprocal direction and which
//! planes it enters through, and the watertight test's shear.
use ch08::{PreparedRay, Ray32, outward};
use raystep_core::Interval;

/// γ₃ for `f32`: a slab's exit widened by 1 + 2γ₃ never loses a box the
/// ray touches (Ize, JCGT 2013; chapter 8, part 1).
const GAMMA3: f32 = 3.0 * (f32::EPSILON / 2.0) / (1.0 - 1.5 * f32::EPSILON);

/// The factor every exit `t` of a box test is multiplied by.
pub const WIDEN: f32 = 1.0 + 2.0 * GAMMA3;

/// A ray ready for the fast walks.
pub struct FastRay {
    /// The origin in `f32`.
    pub origin: [f32; 3],
    /// 1/d per axis (±∞ for a zero component).
    pub inverse: [f32; 3],
    /// Per axis, 1 if the ray goes toward −axis: then it enters a box
    /// through the box's max plane.
    pub negative: [usize; 3],
    /// Chapter 8's watertight test, prepared (its shear in `f64`).
    pub exact: PreparedRay,
}

impl FastRay {
    /// `None` for a ray with a NaN, an infinity or a zero direction: it
    /// is answered "no hit" without being traced, as chapter 8 does.
    #[inline]
    pub fn new(ray: &Ray32) -> Option<FastRay> {
        if !ray.is_valid() {
            return None;
        }
        let inverse = ray.direction.to_array().map(|x| 1.0 / x);
        Some(FastRay {
            origin: ray.origin.to_array(),
            inverse,
            negative: inverse.map(|x| usize::from(x.is_sign_negative())),
            exact: PreparedRay::new(ray),
        })
    }
}

/// The interval as the box tests take it: its ends in `f32` rounded
/// outward, the end widened as every exit is.
#[inline]
pub fn span(interval: Interval) -> (f32, f32) {
    (
        outward(interval.min, false),
        outward(interval.max, true) * WIDEN,
    )
}

/// The farthest entry `t` a box test lets through for an interval ending
/// at `t_max`: a box popped later that starts beyond it holds nothing
/// closer (the `f32` widening, and the entry's rounding back to `f64`).
#[inline]
pub fn reach(t_max: f64) -> f64 {
    t_max * (1.0 + 4.0 * f64::from(GAMMA3))
}
