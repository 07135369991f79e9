//! Exercise 1: the robust slab test.
use raystep_core::{Aabb, Interval, Ray};

/// γ₃ = 3u / (1 − 3u), u = 2⁻⁵³: the largest relative rounding error of a
/// result three floating-point operations away from exact numbers.
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
    if b.is_empty() {
        return None;
    }
    let (mut t0, mut t1) = (interval.min, interval.max);
    for axis in 0..3 {
        // Step 1: where the ray crosses the slab's two planes.
        let inverse = 1.0 / ray.direction[axis];
        let mut t_near = (b.min[axis] - ray.origin[axis]) * inverse;
        let mut t_far = (b.max[axis] - ray.origin[axis]) * inverse;
        // Step 2: order them by the sign bit of 1/d: going toward −axis the
        // ray enters through the max plane (a direction of −0 included).
        if inverse.is_sign_negative() {
            std::mem::swap(&mut t_near, &mut t_far);
        }
        // Step 3: widen the exit by more than its rounding error.
        t_far *= 1.0 + 2.0 * GAMMA_3;
        // Step 4: narrow the interval; a NaN fails both comparisons and so
        // leaves it as it is (the ray lies in the slab's plane).
        if t_near > t0 {
            t0 = t_near;
        }
        if t_far < t1 {
            t1 = t_far;
        }
        // Step 5: empty: the ray left one slab before it entered another.
        if t0 > t1 {
            return None;
        }
    }
    Some(Interval::new(t0, t1))
}
// ANCHOR_END: slab_test
