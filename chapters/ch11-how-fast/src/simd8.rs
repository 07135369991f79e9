//! Step 5's kernel for 8-wide nodes: AVX, eight boxes per instruction,
//! used only where the CPU says it has AVX (checked once, when the tree
//! is built); the walk is compiled a second time with AVX enabled so
//! that the kernel is inlined into it.
#![cfg(target_arch = "x86_64")]
use std::arch::x86_64::*;

use ch08::{MeshHit, Ray32, TraceCounts};
use raystep_core::Interval;

use crate::compressed::CompressedNode;
use crate::ray::{FastRay, WIDEN};
use crate::wide::{Wide, WideNode};

/// Does this CPU have what the kernel needs?
pub fn available() -> bool {
    is_x86_feature_detected!("avx")
}

// ANCHOR: boxes8
/// One axis of the slab test for eight boxes at once: their entry and
/// exit planes on `axis` (ordered by the ray's direction), the near and
/// far ends narrowed, the exit widened as in the scalar test.
///
/// # Safety
/// The CPU must have AVX ([`available`]).
#[inline(always)]
unsafe fn slab8(
    (near, far): (&mut __m256, &mut __m256), (enter, exit): (__m256, __m256),
    ray: &FastRay, axis: usize,
) {
    // SAFETY: the caller has checked AVX.
    unsafe {
        let o = _mm256_set1_ps(ray.origin[axis]);
        let inverse = _mm256_set1_ps(ray.inverse[axis]);
        let t0 = _mm256_mul_ps(_mm256_sub_ps(enter, o), inverse);
        let t1 = _mm256_mul_ps(
            _mm256_mul_ps(_mm256_sub_ps(exit, o), inverse),
            _mm256_set1_ps(WIDEN),
        );
        *near = _mm256_max_ps(t0, *near);
        *far = _mm256_min_ps(t1, *far);
    }
}

/// The eight boxes' entries, and which of them the ray meets
/// (`near ≤ far`) as a mask.
///
/// # Safety
/// The CPU must have AVX ([`available`]).
#[inline(always)]
unsafe fn met8(near: __m256, far: __m256) -> ([f32; 8], u32) {
    // SAFETY: the caller has checked AVX; the store writes eight f32s
    // into a [f32; 8].
    unsafe {
        let hit = _mm256_cmp_ps::<_CMP_LE_OQ>(near, far);
        let mut t = [0.0; 8];
        _mm256_storeu_ps(t.as_mut_ptr(), near);
        (t, _mm256_movemask_ps(hit) as u32)
    }
}

/// The slab test of a node's eight boxes at once, as
/// [`boxes4`](crate::simd4::boxes4) does four.
///
/// # Safety
/// The CPU must have AVX ([`available`]).
#[inline(always)]
unsafe fn boxes8(
    node: &WideNode<8>, ray: &FastRay, (t_min, t_max): (f32, f32),
) -> ([f32; 8], u32) {
    // SAFETY: the caller has checked AVX; each load reads the eight f32s
    // of a [f32; 8] row.
    unsafe {
        let mut near = _mm256_set1_ps(t_min);
        let mut far = _mm256_set1_ps(t_max);
        for axis in 0..3 {
            let (enter, exit) =
                ray.entry_exit(axis, &node.lo[axis], &node.hi[axis]);
            let planes = (
                _mm256_loadu_ps(enter.as_ptr()),
                _mm256_loadu_ps(exit.as_ptr()),
            );
            slab8((&mut near, &mut far), planes, ray, axis);
        }
        met8(near, far)
    }
}
// ANCHOR_END: boxes8

/// [`boxes8`] where this CPU has AVX, `None` elsewhere: for the tests
/// that hold it to the scalar kernel.
pub fn boxes8_where_available(
    node: &WideNode<8>, ray: &FastRay, span: (f32, f32),
) -> Option<([f32; 8], u32)> {
    // SAFETY: called only after the CPU said it has AVX.
    available().then(|| unsafe { boxes8(node, ray, span) })
}

/// The closest hit (or, `ANY`, the first found), the walk compiled
/// with AVX.
///
/// # Safety
/// The CPU must have AVX ([`available`]).
#[target_feature(enable = "avx")]
pub fn trace<const ANY: bool>(
    tree: &Wide<8>, ray: &Ray32, interval: Interval, counts: &mut TraceCounts,
) -> Option<MeshHit> {
    // SAFETY (of the closure's call): this function runs only on a CPU
    // with AVX, which its callers check.
    tree.trace::<ANY>(ray, interval, counts, |n, r, s| unsafe {
        boxes8(n, r, s)
    })
}

/// [`trace`], the walk compiled with AVX2: for step 6, whose triangle
/// test needs AVX2 ([`simd_triangle`](crate::simd_triangle)).
///
/// # Safety
/// The CPU must have AVX2 ([`available_avx2`]).
#[target_feature(enable = "avx2")]
pub fn trace_avx2<const ANY: bool>(
    tree: &Wide<8>, ray: &Ray32, interval: Interval, counts: &mut TraceCounts,
) -> Option<MeshHit> {
    // SAFETY: as in `trace` (AVX2 includes AVX).
    tree.trace::<ANY>(ray, interval, counts, |n, r, s| unsafe {
        boxes8(n, r, s)
    })
}

/// Does this CPU have what the compressed nodes' kernel needs (AVX2, to
/// widen bytes to eight 32-bit lanes)?
pub fn available_avx2() -> bool {
    is_x86_feature_detected!("avx2")
}

// ANCHOR: compressed_boxes8
/// The slab test of a compressed node's eight boxes at once: each plane
/// decoded (bytes widened to `f32`, times the scale, plus the origin —
/// exact, see [`compressed`](crate::compressed)), then as
/// [`boxes8`].
///
/// # Safety
/// The CPU must have AVX2 ([`available_avx2`]).
#[inline(always)]
unsafe fn compressed_boxes8(
    node: &CompressedNode, ray: &FastRay, (t_min, t_max): (f32, f32),
) -> ([f32; 8], u32) {
    // SAFETY: the caller has checked AVX2; each 64-bit load reads the
    // eight bytes of a [u8; 8] row, the store writes eight f32s into a
    // [f32; 8].
    unsafe {
        let mut near = _mm256_set1_ps(t_min);
        let mut far = _mm256_set1_ps(t_max);
        for axis in 0..3 {
            let (enter, exit) =
                ray.entry_exit(axis, &node.qlo[axis], &node.qhi[axis]);
            let scale = _mm256_set1_ps(f32::from_bits(
                ((i32::from(node.exponent[axis]) + 127) as u32) << 23,
            ));
            let origin = _mm256_set1_ps(node.origin[axis]);
            let decode = |q: &[u8; 8]| {
                let bytes = _mm_loadl_epi64(q.as_ptr().cast());
                let q = _mm256_cvtepi32_ps(_mm256_cvtepu8_epi32(bytes));
                _mm256_add_ps(_mm256_mul_ps(q, scale), origin)
            };
            let planes = (decode(enter), decode(exit));
            slab8((&mut near, &mut far), planes, ray, axis);
        }
        let (t, mask) = met8(near, far);
        (t, mask & u32::from(node.valid))
    }
}
// ANCHOR_END: compressed_boxes8

/// [`compressed_boxes8`] where this CPU has AVX2, `None` elsewhere: for
/// the tests that hold it to the scalar kernel.
pub fn compressed_boxes8_where_available(
    node: &CompressedNode, ray: &FastRay, span: (f32, f32),
) -> Option<([f32; 8], u32)> {
    // SAFETY: called only after the CPU said it has AVX2.
    available_avx2().then(|| unsafe { compressed_boxes8(node, ray, span) })
}

/// The closest hit (or, `ANY`, the first found) in a compressed tree,
/// the walk compiled with AVX2.
///
/// # Safety
/// The CPU must have AVX2 ([`available_avx2`]).
#[target_feature(enable = "avx2")]
pub fn trace_compressed<const ANY: bool>(
    tree: &Wide<8, CompressedNode>, ray: &Ray32, interval: Interval,
    counts: &mut TraceCounts,
) -> Option<MeshHit> {
    // SAFETY (of the closure's call): this function runs only on a CPU
    // with AVX2, which its callers check.
    tree.trace::<ANY>(ray, interval, counts, |n, r, s| unsafe {
        compressed_boxes8(n, r, s)
    })
}
