//! Step 5's kernel for 4-wide nodes: SSE, four boxes per instruction.
//! Every x86-64 CPU has SSE2, so no detection is needed; other CPUs use
//! [`scalar_boxes`](crate::wide::scalar_boxes).
#![cfg(target_arch = "x86_64")]
use std::arch::x86_64::*;

use crate::ray::{FastRay, WIDEN};
use crate::wide::WideNode;

// ANCHOR: boxes4
/// The slab test of a node's four boxes at once: the entry `t`s, and a
/// bit per box the ray meets within `(t_min, t_max)`. The same
/// arithmetic as [`scalar_boxes`](crate::wide::scalar_boxes), lane by
/// lane; `max`/`min` take the accumulator second, so a NaN `t` (0·∞)
/// leaves it unchanged, as `f32::max` does.
#[inline(always)]
pub fn boxes4(
    node: &WideNode<4>, ray: &FastRay, (t_min, t_max): (f32, f32),
) -> ([f32; 4], u32) {
    // SAFETY: SSE2 is part of every x86-64 CPU (the intrinsics are
    // `unsafe` only because they need it); each load reads the four f32s
    // of a [f32; 4] row, the store writes four into a [f32; 4].
    unsafe {
        let mut near = _mm_set1_ps(t_min);
        let mut far = _mm_set1_ps(t_max);
        let widen = _mm_set1_ps(WIDEN);
        for axis in 0..3 {
            let (enter, exit) =
                ray.entry_exit(axis, &node.lo[axis], &node.hi[axis]);
            let enter = _mm_loadu_ps(enter.as_ptr());
            let exit = _mm_loadu_ps(exit.as_ptr());
            let o = _mm_set1_ps(ray.origin[axis]);
            let inverse = _mm_set1_ps(ray.inverse[axis]);
            let t0 = _mm_mul_ps(_mm_sub_ps(enter, o), inverse);
            let t1 =
                _mm_mul_ps(_mm_mul_ps(_mm_sub_ps(exit, o), inverse), widen);
            near = _mm_max_ps(t0, near);
            far = _mm_min_ps(t1, far);
        }
        let mask = _mm_movemask_ps(_mm_cmple_ps(near, far)) as u32;
        let mut t = [0.0; 4];
        _mm_storeu_ps(t.as_mut_ptr(), near);
        (t, mask)
    }
}
// ANCHOR_END: boxes4
