//! Step 11: a walk with a shorter critical path. A ray's walk is a chain:
//! a node's boxes cannot be tested before its address is known, and its
//! address is a load that waits on the box test of the node above. The
//! CPU overlaps everything else, so what a node costs is the length of
//! that chain, and what breaks it (a mispredicted branch). This walk
//! takes work off the chain and out of the loop, the way Embree's and
//! tinybvh's walks do:
//!
//! - the far plane's widening folded into the ray's reciprocal, once per
//!   ray (one multiplication fewer between a node's load and its mask);
//! - each axis's entry and exit rows chosen once per ray, as offsets
//!   into the node, not once per node;
//! - one, two and more children hit taken by separate, short branches
//!   (most nodes have one or two), the waiting children on a plain array
//!   sized from the tree's depth, the count of nodes kept in a register.
//!
//! The boxes met are those step 9's test meets, give or take a rounding
//! (see [`FarRay`]); the triangles are step 8's blocks, so every `t` is
//! still bit for bit the watertight test's.
#![cfg(target_arch = "x86_64")]
use std::arch::x86_64::*;
use std::mem::MaybeUninit;

use ch08::{MeshHit, Ray32, TraceCounts};
use raystep_core::Interval;

use crate::ray::{FastRay, WIDEN, span};
use crate::wide::{Entry, Wide, WideNode};

/// How many children the walk's array holds: enough for a tree of depth
/// [`MAX_DEPTH`] (at most seven wait at each level).
const STACK: usize = 256;

/// The deepest tree the walk takes; a deeper one keeps step 9's walk.
pub const MAX_DEPTH: usize = (STACK - 1) / 7;

/// Does the walk take `tree` on this CPU: AVX2 (as step 8's blocks),
/// and a tree no deeper than [`MAX_DEPTH`]?
pub fn takes(tree: &Wide<8>) -> bool {
    is_x86_feature_detected!("avx2") && tree.depth() <= MAX_DEPTH
}

/// The ray as the walk's box test takes it, computed once per ray.
///
/// The exit plane's distance is `(exit − o) × (1/d × WIDEN)` instead of
/// step 5's `((exit − o) × 1/d) × WIDEN`: both are the exact distance
/// times `WIDEN` times four roundings (the subtraction, the reciprocal,
/// two products), so the widening still covers them (Ize 2013) and no box
/// the ray meets is lost; one product is off the chain.
struct FarRay {
    origin: [__m256; 3],
    inverse: [__m256; 3],
    inverse_far: [__m256; 3],
    /// Per axis, the byte offsets in a [`WideNode`] of the row the ray
    /// enters through and of the row it leaves through.
    enter: [usize; 3],
    exit: [usize; 3],
}

impl FarRay {
    /// # Safety
    /// The CPU must have AVX ([`takes`] checks more).
    #[inline(always)]
    unsafe fn new(ray: &FastRay) -> FarRay {
        let row = size_of::<[f32; 8]>();
        // The rows of a node: lo x, lo y, lo z, then hi x, hi y, hi z.
        let lo = |axis: usize| axis * row;
        let hi = |axis: usize| (3 + axis) * row;
        // SAFETY: the caller has checked AVX.
        let splat = |v: [f32; 3]| v.map(|x| unsafe { _mm256_set1_ps(x) });
        FarRay {
            origin: splat(ray.origin),
            inverse: splat(ray.inverse),
            inverse_far: splat(ray.inverse.map(|x| x * WIDEN)),
            enter: [0, 1, 2].map(|a| ray.entry_exit(a, lo(a), hi(a)).0),
            exit: [0, 1, 2].map(|a| ray.entry_exit(a, lo(a), hi(a)).1),
        }
    }
}

// ANCHOR: short_boxes
/// The eight boxes of `node` within `(t_min, t_max)`: where the ray
/// enters each, and a bit per box it meets.
///
/// # Safety
/// The CPU must have AVX.
#[inline(always)]
unsafe fn boxes(
    node: &WideNode<8>, ray: &FarRay, t_min: __m256, t_max: __m256,
) -> (__m256, u32) {
    let base: *const u8 = (node as *const WideNode<8>).cast();
    // SAFETY: the caller has checked AVX; every offset is that of one of
    // the node's six rows of eight f32s (`FarRay::new`).
    unsafe {
        let row = |offset: usize| _mm256_loadu_ps(base.add(offset).cast());
        let mut near = t_min;
        let mut far = t_max;
        for axis in 0..3 {
            let o = ray.origin[axis];
            let t0 = _mm256_sub_ps(row(ray.enter[axis]), o);
            let t1 = _mm256_sub_ps(row(ray.exit[axis]), o);
            near = _mm256_max_ps(_mm256_mul_ps(t0, ray.inverse[axis]), near);
            far = _mm256_min_ps(_mm256_mul_ps(t1, ray.inverse_far[axis]), far);
        }
        let met = _mm256_cmp_ps::<_CMP_LE_OQ>(near, far);
        (near, _mm256_movemask_ps(met) as u32)
    }
}
// ANCHOR_END: short_boxes

/// [`boxes`] where this CPU has AVX, `None` elsewhere: for the tests
/// that hold it to the exact slab test.
pub fn boxes_where_available(
    node: &WideNode<8>, ray: &FastRay, (t_min, t_max): (f32, f32),
) -> Option<([f32; 8], u32)> {
    is_x86_feature_detected!("avx").then(|| {
        // SAFETY: the CPU said it has AVX.
        unsafe {
            let (near, mask) = boxes(
                node,
                &FarRay::new(ray),
                _mm256_set1_ps(t_min),
                _mm256_set1_ps(t_max),
            );
            let mut t = [0.0; 8];
            _mm256_storeu_ps(t.as_mut_ptr(), near);
            (t, mask)
        }
    })
}

/// The children waiting, nearest on top: an array on the call stack, not
/// cleared for each ray.
struct Stack {
    entries: [MaybeUninit<Entry>; STACK],
    len: usize,
}

impl Stack {
    #[inline(always)]
    fn push(&mut self, entry: Entry) {
        // A tree no deeper than MAX_DEPTH never fills it (`Wide::depth`);
        // the index is checked all the same.
        self.entries[self.len] = MaybeUninit::new(entry);
        self.len += 1;
    }

    #[inline(always)]
    fn pop(&mut self) -> Option<Entry> {
        self.len = self.len.checked_sub(1)?;
        // SAFETY: every entry below `len` was written by `push`.
        Some(unsafe { self.entries[self.len].assume_init() })
    }

    /// Entries `from..len`, sorted nearest last (insertion sort).
    #[inline(always)]
    fn sort_from(&mut self, from: usize) {
        for i in from + 1..self.len {
            // SAFETY: entries below `len` are written.
            let e = unsafe { self.entries[i].assume_init() };
            let mut j = i;
            // SAFETY: as above (j − 1 < i < len).
            while j > from
                && unsafe { self.entries[j - 1].assume_init() }.t < e.t
            {
                self.entries[j] = self.entries[j - 1];
                j -= 1;
            }
            self.entries[j] = MaybeUninit::new(e);
        }
    }
}

/// The closest hit (or, `ANY`, the first found) of `ray` in `tree`, a
/// tree of step 8's blocks no deeper than [`MAX_DEPTH`].
///
/// # Safety
/// The CPU must have AVX2 ([`takes`]).
#[target_feature(enable = "avx2")]
pub fn trace<const ANY: bool>(
    tree: &Wide<8>, ray: &Ray32, interval: Interval, counts: &mut TraceCounts,
) -> Option<MeshHit> {
    let ray = tree.leaves.ray(ray)?;
    // SAFETY: this function runs only on a CPU with AVX2.
    let far_ray = unsafe { FarRay::new(&ray) };
    let mut interval = interval;
    // Step 1: triangles outside the tree (none in a finite mesh).
    let mut closest =
        tree.leaves
            .outside
            .closest(&ray, &mut interval, ANY, counts);
    if ANY && closest.is_some() {
        return closest;
    }
    let mut span = span(interval);
    let (t_min, mut t_max) = (_mm256_set1_ps(span.0), _mm256_set1_ps(span.1));
    let mut stack = Stack {
        entries: [const { MaybeUninit::uninit() }; STACK],
        len: 0,
    };
    let mut nodes = 0;
    let mut entry = tree.root?;
    // ANCHOR: short_walk
    loop {
        nodes += 1;
        if entry.count > 0 {
            // Step 2: a leaf: its blocks.
            let leaf = (entry.child, entry.count);
            let hit =
                leaf_apart::<ANY>(tree, leaf, &ray, &mut interval, counts);
            if hit.is_some() {
                closest = hit;
                if ANY {
                    break;
                }
                span = crate::ray::span(interval);
                t_max = _mm256_set1_ps(span.1);
            }
        } else {
            // Step 3: the eight boxes; the children met taken by how
            // many they are.
            let node = &tree.nodes[entry.child as usize];
            // The links' cache line asked for with the boxes' lines, not
            // when the mask names a child (the line after the boxes).
            _mm_prefetch::<_MM_HINT_T0>(node.child.as_ptr().cast());
            // SAFETY: this function runs only on a CPU with AVX2.
            let (near, mut mask) =
                unsafe { boxes(node, &far_ray, t_min, t_max) };
            if mask != 0 {
                let i = mask.trailing_zeros() as usize;
                mask &= mask - 1;
                if mask == 0 {
                    // One child met: straight on, no stack (and no need
                    // of its entry t, which only a waiting child needs).
                    entry = Entry {
                        child: node.child[i],
                        count: node.count[i],
                        t: 0.0,
                    };
                    continue;
                }
                let mut t = [0.0; 8];
                // SAFETY: AVX; eight f32s into a [f32; 8].
                unsafe { _mm256_storeu_ps(t.as_mut_ptr(), near) };
                let child = |i: usize| Entry {
                    child: node.child[i],
                    count: node.count[i],
                    t: t[i],
                };
                let first = child(i);
                let second = child(mask.trailing_zeros() as usize);
                mask &= mask - 1;
                if mask == 0 {
                    // Two: the nearer on, the farther waits (for any
                    // hit, step 9's order: the second on).
                    let (near, far) = if ANY || second.t <= first.t {
                        (second, first)
                    } else {
                        (first, second)
                    };
                    tree.prefetch(&far);
                    stack.push(far);
                    entry = near;
                    continue;
                }
                // Three or more: all wait, sorted, the nearest taken.
                let from = stack.len;
                for e in [first, second] {
                    tree.prefetch(&e);
                    stack.push(e);
                }
                while mask != 0 {
                    let e = child(mask.trailing_zeros() as usize);
                    mask &= mask - 1;
                    tree.prefetch(&e);
                    stack.push(e);
                }
                if !ANY {
                    stack.sort_from(from);
                }
            }
        }
        // Step 4: the nearest child waiting; one entered beyond the
        // closest hit holds nothing closer.
        loop {
            match stack.pop() {
                Some(e) if e.t > span.1 => continue,
                Some(e) => {
                    entry = e;
                    break;
                }
                None => {
                    counts.nodes += nodes;
                    return closest;
                }
            }
        }
    }
    // ANCHOR_END: short_walk
    counts.nodes += nodes;
    closest
}

/// A leaf's blocks, called rather than inlined: inlined, the block test's
/// registers pushed the walk's ray out of registers onto the stack
/// (+2 % on camera and incoherent rays out of line, one bench run).
#[inline(never)]
#[target_feature(enable = "avx2")]
fn leaf_apart<const ANY: bool>(
    tree: &Wide<8>, leaf: (u32, u32), ray: &FastRay, interval: &mut Interval,
    counts: &mut TraceCounts,
) -> Option<MeshHit> {
    tree.leaves.leaf(leaf, ray, interval, ANY, counts)
}
