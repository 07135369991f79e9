//! Step 10: a leaf's two blocks at once. Step 8's leaves hold up to two
//! blocks of four triangles; where the CPU has AVX-512, both go into the
//! eight `f64` lanes of one register and are tested by one run of the
//! same instructions: step 8's test's steps (`leaf4.rs`), lane for
//! lane the same operations on the same numbers in the same order, so the
//! same answers bit for bit. The walk stays step 9's, compiled with
//! AVX2; it calls this test (a function compiled with more features than
//! its caller is never inlined into it). It is slower than step 9 on
//! the CPU the appendix measured, and a walk compiled with AVX-512
//! throughout, the test inlined, was slower still: see the appendix.
#![cfg(target_arch = "x86_64")]
use std::arch::x86_64::*;

use ch08::{MeshHit, TraceCounts};
use raystep_core::Interval;

use crate::leaf4::{Blocks4, Tested, Triangle4};
use crate::ray::FastRay;

/// Does this CPU have what the test needs (AVX-512 Foundation, and the
/// AVX2 the rest of the walk uses)?
pub fn available() -> bool {
    is_x86_feature_detected!("avx512f") && is_x86_feature_detected!("avx2")
}

// ANCHOR: test8
/// Two blocks' eight lanes at once: the first block's four in lanes 0–3,
/// the second's in 4–7; the two blocks' results, each as
/// [`test4_scalar`](crate::leaf4::test4_scalar) gives them.
///
/// # Safety
/// The CPU must have AVX-512F ([`available`]).
#[target_feature(enable = "avx512f")]
#[inline]
pub unsafe fn test8(pair: [&Triangle4; 2], ray: &FastRay) -> [Tested; 2] {
    // SAFETY: the caller has checked AVX-512F; each load reads one
    // aligned [f32; 4] row, the store writes eight f64s into a [f64; 8].
    unsafe {
        let [kx, ky, kz] = ray.axes;
        // The origin as an array: glam's `DVec3` indexed by a run-time
        // axis is a `match`, compiled into branches (see `leaf4::test4`).
        let (o, s) = (ray.origin64.to_array(), ray.shear);
        let splat = _mm512_set1_pd;
        // Step 1: the corners sheared, the two blocks' rows side by side
        // (widened from f32 exactly).
        let corner = |c: usize| {
            let p = |axis: usize| {
                let first = _mm_load_ps(pair[0].rows[c][axis].as_ptr());
                let second = _mm_load_ps(pair[1].rows[c][axis].as_ptr());
                let row = _mm512_cvtps_pd(_mm256_set_m128(second, first));
                _mm512_sub_pd(row, splat(o[axis]))
            };
            let (px, py, pz) = (p(kx), p(ky), p(kz));
            let x = _mm512_sub_pd(px, _mm512_mul_pd(splat(s.x), pz));
            let y = _mm512_sub_pd(py, _mm512_mul_pd(splat(s.y), pz));
            (x, y, _mm512_mul_pd(splat(s.z), pz))
        };
        let (a, b, c) = (corner(0), corner(1), corner(2));
        // Step 2: the edge functions, and whether each sign is sure: a
        // bit per lane.
        let abs = |v| _mm512_abs_pd(v);
        let edge = |p: (__m512d, __m512d, __m512d),
                    q: (__m512d, __m512d, __m512d)| {
            let left = _mm512_mul_pd(p.0, q.1);
            let right = _mm512_mul_pd(p.1, q.0);
            let fast = _mm512_sub_pd(left, right);
            let bound = _mm512_mul_pd(
                splat(2.0 * f64::EPSILON),
                _mm512_add_pd(abs(left), abs(right)),
            );
            (fast, _mm512_cmp_pd_mask::<_CMP_GT_OQ>(abs(fast), bound))
        };
        let ((e0, s0), (e1, s1), (e2, s2)) =
            (edge(b, c), edge(c, a), edge(a, b));
        // Step 3: two sure signs that differ: outside.
        let zero = _mm512_setzero_pd();
        let above = |e, s| _mm512_mask_cmp_pd_mask::<_CMP_GT_OQ>(s, e, zero);
        let below = |e, s| _mm512_mask_cmp_pd_mask::<_CMP_LT_OQ>(s, e, zero);
        let positive = above(e0, s0) | above(e1, s1) | above(e2, s2);
        let negative = below(e0, s0) | below(e1, s1) | below(e2, s2);
        let inside = u32::from(!(positive & negative));
        let sure = u32::from(s0 & s1 & s2);
        let unsure = inside & !sure;
        let split = |t: [f64; 8], hit: u32| {
            [0, 4].map(|from| Tested {
                t: std::array::from_fn(|i| t[from + i]),
                hit: (hit >> from) & 0b1111,
                unsure: (unsure >> from) & 0b1111,
            })
        };
        if inside & sure == 0 {
            return split([0.0; 8], 0);
        }
        // Step 4: det, its rounding bound, t: as test4, eight lanes.
        let det = _mm512_add_pd(_mm512_add_pd(e0, e1), e2);
        let size =
            |p: (__m512d, __m512d, __m512d)| _mm512_add_pd(abs(p.0), abs(p.1));
        let (sa, sb, sc) = (size(a), size(b), size(c));
        let across = _mm512_max_pd(_mm512_max_pd(sa, sb), sc);
        let along = _mm512_max_pd(_mm512_max_pd(abs(a.2), abs(b.2)), abs(c.2));
        let sum = _mm512_add_pd(_mm512_add_pd(sa, sb), sc);
        let m = _mm512_add_pd(across, _mm512_div_pd(along, splat(s.z.abs())));
        let noise =
            _mm512_mul_pd(_mm512_mul_pd(splat(16.0 * f64::EPSILON), m), sum);
        let finite =
            _mm512_cmp_pd_mask::<_CMP_LT_OQ>(abs(det), splat(f64::INFINITY));
        let counted =
            _mm512_mask_cmp_pd_mask::<_CMP_NLE_UQ>(finite, abs(det), noise);
        let numerator = _mm512_add_pd(
            _mm512_add_pd(_mm512_mul_pd(e0, a.2), _mm512_mul_pd(e1, b.2)),
            _mm512_mul_pd(e2, c.2),
        );
        let mut t = [0.0; 8];
        _mm512_storeu_pd(t.as_mut_ptr(), _mm512_div_pd(numerator, det));
        split(t, inside & sure & u32::from(counted))
    }
}
// ANCHOR_END: test8

// ANCHOR: leaf_in_pairs
/// A leaf of step 10's walk: [`Blocks4::leaf`], its blocks taken two at
/// a time (a last odd one alone), each pair tested at once.
///
/// # Safety
/// The CPU must have AVX-512F ([`available`]).
#[inline(always)]
pub(crate) unsafe fn leaf(
    blocks: &Blocks4, (first, count): (u32, u32), ray: &FastRay,
    interval: &mut Interval, any: bool, counts: &mut TraceCounts,
) -> Option<MeshHit> {
    let mut closest = None;
    let (mut b, end) = (first as usize, (first + count) as usize);
    while b < end {
        let (tested, n) = if b + 1 < end {
            // SAFETY: the caller has checked AVX-512F.
            let pair = [&blocks.blocks[b], &blocks.blocks[b + 1]];
            (unsafe { test8(pair, ray) }, 2)
        } else {
            ([blocks.test(&blocks.blocks[b], ray), Tested::NONE], 1)
        };
        for &tested in &tested[..n] {
            if blocks.take(b, tested, ray, interval, any, &mut closest, counts)
                && any
            {
                return closest;
            }
            b += 1;
        }
    }
    closest
}
// ANCHOR_END: leaf_in_pairs

/// [`test8`] where this CPU has AVX-512, `None` elsewhere: for the tests
/// that hold it to the lane-by-lane test.
pub fn test8_where_available(
    pair: [&Triangle4; 2], ray: &FastRay,
) -> Option<[Tested; 2]> {
    // SAFETY: called only after the CPU said it has AVX-512F.
    available().then(|| unsafe { test8(pair, ray) })
}
