//! Exercise 1 (★★): the robust slab test.
use raystep_core::{Aabb, Interval, Ray};

/// γ₃ = 3u / (1 − 3u), u = 2⁻⁵³: the largest relative rounding error of a
/// result three floating-point operations away from exact numbers.
#[allow(dead_code)]
const GAMMA_3: f64 =
    3.0 * (f64::EPSILON / 2.0) / (1.0 - 3.0 * (f64::EPSILON / 2.0));

// ANCHOR: slab_test
/// The part of `interval` in which `ray` is inside the box `b`, or None:
/// the lecture's slab test, with the two details that make it robust.
///
/// A box is three *slabs*, each the space between two parallel planes;
/// the ray is inside the box where it is inside all three at once. Per
/// axis it enters its slab at `t_near` and leaves at `t_far`; the answer
/// is the largest entry and the smallest exit, clipped to `interval`.
///
/// * A ray parallel to a slab divides by zero: 1/0 = ±∞. An origin on one
///   of the slab's planes then gives 0·∞ = NaN, so the interval is
///   narrowed in a way NaN never narrows it, and near and far are told
///   apart by the sign bit of 1/d, which NaN does not confuse.
/// * `t_far` is pushed out by `1 + 2γ₃`, more than its rounding error, so
///   a ray through an edge or a corner is never rounded out of the box.
///
/// Every box test of the lecture is this one: the bounding boxes here,
/// the hierarchies' nodes, chapter 9's grid and chapter 10's kd-tree.
pub fn slab_test(b: &Aabb, ray: &Ray, interval: Interval) -> Option<Interval> {
    // TODO: an empty box is never hit. Then start from t0, t1 = interval
    // and for each axis:
    // 1. Where the ray crosses the slab's two planes: with 1/d,
    //    t_near = (min − P₀)·(1/d) and t_far = (max − P₀)·(1/d).
    // 2. Order them by the sign bit of 1/d (`is_sign_negative`), not by
    //    comparing them: going toward −axis the ray enters through max.
    // 3. Widen the exit: t_far ·= 1 + 2γ₃ (`GAMMA_3`).
    // 4. Narrow [t0, t1] so that a NaN leaves it as it is:
    //    `if t_near > t0 { t0 = t_near }`, and the same for t1.
    // 5. If t0 > t1 the ray misses: None.
    // Inside all three slabs: Some([t0, t1]).
    let _ = (b, ray, interval);
    todo!("ch08 exercise 1: slab")
}
// ANCHOR_END: slab_test
