//! Step 6: the triangle test with SIMD. Chapter 8's watertight test,
//! three edges at once: the triangle's three corners sit in three lanes
//! of a 4-lane `f64` register (AVX2), so the shear of the corners and the
//! three edge functions are one instruction each instead of three — the
//! same operations on the same numbers in the same order as
//! [`watertight`](crate::leaf_triangles::watertight), so the same answer
//! bit for bit.
//!
//! Why three corners and not four triangles, as Embree's leaves do: our
//! SAH leaves hold 1.7 triangles on average and a ray tests 1.5 of them
//! (the work table), so four triangles at once would run mostly empty
//! lanes; a triangle always has three corners.
#![cfg(target_arch = "x86_64")]
use std::arch::x86_64::*;

use ch08::{PreparedRay, Shear};
use raystep_core::{DVec2, DVec3, Interval};

use crate::ray::FastRay;

/// Does this CPU have what the test needs (AVX2, for the lane shuffles)?
pub fn available() -> bool {
    is_x86_feature_detected!("avx2")
}

// ANCHOR: triangle_lanes
/// One triangle laid out for the test: per axis, its corners' coordinate
/// in the first three lanes (`rows[axis] = [a, b, c, 0]`), each exactly
/// an `f32`; 48 bytes. Made only where the CPU has AVX2 ([`available`]),
/// which is what makes [`watertight_lanes`] safe to call.
#[derive(Clone, Copy, Debug, PartialEq)]
#[repr(C, align(16))]
pub struct TriangleLanes {
    rows: [[f32; 4]; 3],
}
// ANCHOR_END: triangle_lanes

impl TriangleLanes {
    /// The triangle with corners `v` (`[ax, ay, az, bx, …]`, as step 3
    /// stores them); `None` where the CPU has no AVX2.
    pub fn new(v: &[f32; 9]) -> Option<TriangleLanes> {
        let row = |axis: usize| [v[axis], v[3 + axis], v[6 + axis], 0.0];
        available().then(|| TriangleLanes {
            rows: [row(0), row(1), row(2)],
        })
    }

    /// Its corners, widened to `f64` (exactly).
    pub fn corners(&self) -> [DVec3; 3] {
        let r = &self.rows;
        [0, 1, 2].map(|i| {
            DVec3::new(
                f64::from(r[0][i]),
                f64::from(r[1][i]),
                f64::from(r[2][i]),
            )
        })
    }
}

/// Chapter 8's watertight test of `triangle`, three edges at once: its
/// `t` within `interval`.
#[inline(always)]
pub fn watertight_lanes(
    triangle: &TriangleLanes, ray: &FastRay, interval: Interval,
) -> Option<f64> {
    // SAFETY: a TriangleLanes is made only where the CPU has AVX2
    // (`TriangleLanes::new`).
    unsafe { watertight4(triangle, ray, interval) }
}

// ANCHOR: watertight4
/// The test itself (see [`watertight_lanes`]); lane `i` holds corner `i`
/// in step 1 and edge function `eᵢ` in step 2.
///
/// # Safety
/// The CPU must have AVX2 ([`available`]).
#[inline(always)]
unsafe fn watertight4(
    triangle: &TriangleLanes, ray: &FastRay, interval: Interval,
) -> Option<f64> {
    // SAFETY: the caller has checked AVX2; each load reads one aligned
    // [f32; 4] row, each store writes four f64s into a [f64; 4].
    unsafe {
        // Step 1: the three corners sheared at once (chapter 8's steps
        // 1–3): p = v − o, x = p[kx] − sx·p[kz], y = …, z = sz·p[kz].
        let [kx, ky, kz] = ray.axes;
        // The origin as an array: glam's `DVec3` indexed by a run-time
        // axis is a `match`, compiled into branches (see `leaf4::test4`).
        let (o, s) = (ray.origin64.to_array(), ray.shear);
        let p = |axis: usize| {
            let row = _mm_load_ps(triangle.rows[axis].as_ptr());
            _mm256_sub_pd(_mm256_cvtps_pd(row), _mm256_set1_pd(o[axis]))
        };
        let (px, py, pz) = (p(kx), p(ky), p(kz));
        let x = _mm256_sub_pd(px, _mm256_mul_pd(_mm256_set1_pd(s.x), pz));
        let y = _mm256_sub_pd(py, _mm256_mul_pd(_mm256_set1_pd(s.y), pz));
        let z = _mm256_mul_pd(_mm256_set1_pd(s.z), pz);
        // Step 2: the edges b → c, c → a, a → b: the corners rotated by
        // one lane (b, c, a) and by two (c, a, b); each edge function
        // p.x·q.y − p.y·q.x, and whether its sign is sure.
        let next = |v| _mm256_permute4x64_pd::<0b11_00_10_01>(v);
        let after = |v| _mm256_permute4x64_pd::<0b11_01_00_10>(v);
        let left = _mm256_mul_pd(next(x), after(y));
        let right = _mm256_mul_pd(next(y), after(x));
        let fast = _mm256_sub_pd(left, right);
        let sign = _mm256_set1_pd(-0.0);
        let abs = |v| _mm256_andnot_pd(sign, v);
        let bound = _mm256_mul_pd(
            _mm256_set1_pd(2.0 * f64::EPSILON),
            _mm256_add_pd(abs(left), abs(right)),
        );
        let sure = _mm256_cmp_pd::<_CMP_GT_OQ>(abs(fast), bound);
        let zero = _mm256_setzero_pd();
        let bits = |v| _mm256_movemask_pd(v) & 0b111;
        let positive =
            bits(_mm256_and_pd(sure, _mm256_cmp_pd::<_CMP_GT_OQ>(fast, zero)));
        let negative =
            bits(_mm256_and_pd(sure, _mm256_cmp_pd::<_CMP_LT_OQ>(fast, zero)));
        // Step 3: two sure signs that differ: outside.
        if positive != 0 && negative != 0 {
            return None;
        }
        if bits(sure) != 0b111 {
            // Step 4: an unsure sign: chapter 8's exact test decides.
            return PreparedRay::new(&ray.ray)
                .triangle(&triangle.corners(), interval);
        }
        // Step 5: t, as chapter 8 computes it, in its order of sums; no
        // hit where det is within rounding of 0 (a ray in the triangle's
        // plane), that rounding from the same corners as chapter 8's.
        let (mut e, mut ez) = ([0.0; 4], [0.0; 4]);
        _mm256_storeu_pd(e.as_mut_ptr(), fast);
        _mm256_storeu_pd(ez.as_mut_ptr(), _mm256_mul_pd(fast, z));
        let det = e[0] + e[1] + e[2];
        if !det.is_finite() || det.abs() <= det_rounding(ray, x, y, z) {
            return None;
        }
        let t = (ez[0] + ez[1] + ez[2]) / det;
        interval.contains(t).then_some(t)
    }
}
// ANCHOR_END: watertight4

/// Chapter 8's [`Shear::det_rounding`] of the corners sheared into the
/// lanes `x`, `y`, `z`: the same numbers, so the same bound.
///
/// # Safety
/// The CPU must have AVX (AVX2 implies it).
#[inline(always)]
unsafe fn det_rounding(
    ray: &FastRay, x: __m256d, y: __m256d, z: __m256d,
) -> f64 {
    let (mut xs, mut ys, mut zs) = ([0.0; 4], [0.0; 4], [0.0; 4]);
    // SAFETY: the caller has checked AVX; each store writes four f64s into
    // a [f64; 4].
    unsafe {
        _mm256_storeu_pd(xs.as_mut_ptr(), x);
        _mm256_storeu_pd(ys.as_mut_ptr(), y);
        _mm256_storeu_pd(zs.as_mut_ptr(), z);
    }
    let sheared = [0, 1, 2].map(|i| (DVec2::new(xs[i], ys[i]), zs[i]));
    let shear = Shear {
        axes: ray.axes,
        shear: ray.shear,
    };
    shear.det_rounding(&sheared)
}
