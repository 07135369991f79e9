//! Step 8: leaves of four. Embree's leaves hold their triangles four at
//! a time (Triangle4: each coordinate of the four side by side) and its
//! SAH knows that such a leaf costs about one test, not four; here the
//! binary tree's small subtrees are merged into such leaves when the cost
//! model says a block of four beats the nodes above them, and a leaf's
//! blocks are tested four triangles at once: chapter 8's watertight test
//! in the four `f64` lanes of an AVX2 register, the same operations on the
//! same numbers in the same order as
//! [`watertight`](crate::leaf_triangles::watertight), so the same answer
//! bit for bit. A lane whose edge signs are unsure goes to chapter 8's
//! exact test, as there.
use ch08::{Bvh, BvhNode, MeshHit, PreparedRay, TraceCounts};
use raystep_core::{DVec3, Interval};

use crate::pages::Pages;
use crate::ray::FastRay;

/// A block's test against one node visit in the cost model of the merge:
/// an 8-wide node tests eight boxes in about the time four triangles take
/// (the work table of step 6).
pub const BLOCK_COST: f64 = 1.0;

/// A merged leaf holds at most this many blocks (eight triangles).
pub const MAX_BLOCKS: u32 = 2;

// ANCHOR: merge_leaves
/// `tree` with each subtree merged into one leaf where its blocks of
/// four cost less than its nodes and leaves (the surface area heuristic
/// with a leaf's cost ⌈n/4⌉ × [`BLOCK_COST`]); the triangles keep their
/// order, so each leaf is still a range of it.
pub fn merge_leaves(tree: &Bvh) -> Bvh {
    if tree.nodes.is_empty() {
        return tree.clone();
    }
    // Step 1: bottom up, each node's triangle range and its cheapest cost.
    let mut merged = vec![false; tree.nodes.len()];
    let mut range = vec![(0u32, 0u32); tree.nodes.len()];
    cost(tree, 0, &mut merged, &mut range);
    // Step 2: the nodes again, top down, a merged subtree as one leaf.
    let mut nodes = vec![tree.nodes[0]];
    emit(tree, 0, 0, &merged, &range, &mut nodes);
    Bvh {
        nodes,
        order: tree.order.clone(),
        unbounded: tree.unbounded.clone(),
    }
}
// ANCHOR_END: merge_leaves

/// The blocks of four that `count` triangles take.
fn blocks(count: u32) -> u32 {
    count.div_ceil(4)
}

/// The SAH cost of node `k`'s subtree (unnormalised: areas, not
/// chances), the cheaper of its nodes and of one leaf; fills `merged` and
/// each node's triangle `range`.
fn cost(
    tree: &Bvh, k: usize, merged: &mut [bool], range: &mut [(u32, u32)],
) -> f64 {
    let node = &tree.nodes[k];
    let area = node.bounds.surface_area();
    if node.is_leaf() {
        range[k] = (node.first, node.count);
        return area * BLOCK_COST * f64::from(blocks(node.count));
    }
    let (l, r) = (node.first as usize, node.first as usize + 1);
    let split = area * ch08::TRAVERSAL
        + cost(tree, l, merged, range)
        + cost(tree, r, merged, range);
    let ((first, left), (next, right)) = (range[l], range[r]);
    range[k] = (first, left + right);
    // A leaf is a range of the order: only where the children's are one.
    let contiguous = next == first + left;
    let count = left + right;
    if contiguous && blocks(count) <= MAX_BLOCKS {
        let leaf = area * BLOCK_COST * f64::from(blocks(count));
        if leaf <= split {
            merged[k] = true;
            return leaf;
        }
    }
    split
}

/// Writes node `k` of `tree` at `at` of `nodes`, its children (unless it
/// is merged into a leaf) appended as a pair.
fn emit(
    tree: &Bvh, k: usize, at: usize, merged: &[bool], range: &[(u32, u32)],
    nodes: &mut Vec<BvhNode>,
) {
    let node = tree.nodes[k];
    if node.is_leaf() || merged[k] {
        let (first, count) = range[k];
        nodes[at] = BvhNode {
            bounds: node.bounds,
            first,
            count,
        };
        return;
    }
    let children = nodes.len();
    nodes.extend([tree.nodes[0]; 2]);
    nodes[at] = BvhNode {
        first: children as u32,
        ..node
    };
    let l = node.first as usize;
    emit(tree, l, children, merged, range, nodes);
    emit(tree, l + 1, children + 1, merged, range, nodes);
}

// ANCHOR: triangle4
/// Four triangles side by side: `rows[corner][axis]` holds that
/// coordinate of each, every one exactly an `f32`, and then their indices
/// in the mesh; 160 bytes. An empty lane (a leaf of fewer than four in
/// its last block) repeats lane 0 and is never read.
#[derive(Clone, Copy, Debug, PartialEq)]
#[repr(C, align(16))]
pub struct Triangle4 {
    /// Corner, axis, lane.
    pub rows: [[[f32; 4]; 3]; 3],
    /// Each lane's triangle, its index in the mesh (`u32::MAX` for an
    /// empty lane). Beside the corners, not in an array of their own: a
    /// hit's index was a cache miss of its own (60 % of the leaf's time
    /// outside the test, in a profile of step 11).
    pub ids: [u32; 4],
}
// ANCHOR_END: triangle4

impl Triangle4 {
    /// Lane `i`'s corners, widened to `f64` (exactly).
    pub fn corners(&self, i: usize) -> [DVec3; 3] {
        let r = &self.rows;
        [0, 1, 2].map(|c| {
            DVec3::new(
                f64::from(r[c][0][i]),
                f64::from(r[c][1][i]),
                f64::from(r[c][2][i]),
            )
        })
    }
}

/// The leaves' triangles in blocks of four, in leaf order.
#[derive(Clone, Debug, PartialEq)]
pub struct Blocks4 {
    /// The blocks.
    pub blocks: Pages<Triangle4>,
    /// How many lanes of each block hold a triangle (1 to 4).
    pub lanes: Vec<u8>,
    /// Tested with AVX2 (checked when built), else lane by lane.
    simd: bool,
    /// Step 10: a leaf's blocks tested two at once with AVX-512 (set
    /// only where the CPU has it).
    pairs: bool,
}

/// What a leaf's link becomes: `(first block, blocks)` for the leaf whose
/// first triangle is at each slot of the order.
pub type BlockLinks = Vec<(u32, u32)>;

impl Blocks4 {
    /// The leaves of `tree` (built over `triangles`' boxes) in blocks of
    /// four, and each leaf's link; `None` if a coordinate is not exactly
    /// an `f32` (step 3's condition).
    pub fn new(
        triangles: &[[DVec3; 3]], tree: &Bvh,
    ) -> Option<(Blocks4, BlockLinks)> {
        let exact = |x: f64| f64::from(x as f32) == x;
        let (mut blocks, mut lanes) = (Vec::new(), Vec::new());
        let mut links = vec![(0, 0); tree.order.len()];
        let leaves: Vec<(usize, usize)> = (tree.nodes.iter())
            .filter(|n| n.is_leaf())
            .map(|n| (n.first as usize, n.count as usize))
            .collect();
        for (k, &(first, count)) in leaves.iter().enumerate() {
            // The triangles are read in the tree's order, all over the
            // mesh: a later leaf's asked for from memory now.
            #[cfg(target_arch = "x86_64")]
            if let Some(&(first, count)) = leaves.get(k + 4) {
                for &id in &tree.order[first..first + count] {
                    crate::prefetch::prefetch(&triangles[id as usize]);
                }
            }
            let start = blocks.len() as u32;
            for chunk in tree.order[first..first + count].chunks(4) {
                // An empty lane repeats the first triangle (and is never
                // read: its id is none).
                let mut block = Triangle4 {
                    rows: [[[0.0; 4]; 3]; 3],
                    ids: std::array::from_fn(|lane| {
                        chunk.get(lane).copied().unwrap_or(u32::MAX)
                    }),
                };
                for lane in 0..4 {
                    let id = chunk.get(lane).copied().unwrap_or(chunk[0]);
                    let triangle = &triangles[id as usize];
                    for (c, corner) in triangle.iter().enumerate() {
                        for axis in 0..3 {
                            if !exact(corner[axis]) {
                                return None;
                            }
                            block.rows[c][axis][lane] = corner[axis] as f32;
                        }
                    }
                }
                blocks.push(block);
                lanes.push(chunk.len() as u8);
            }
            let end = blocks.len() as u32;
            links[first] = (start, end - start);
        }
        let built = Blocks4 {
            blocks: blocks.into(),
            lanes,
            simd: avx2(),
            pairs: false,
        };
        Some((built, links))
    }

    /// Their bytes: blocks (with their ids), lane counts.
    pub fn bytes(&self) -> usize {
        self.blocks.len() * (size_of::<Triangle4>() + 1)
    }

    /// Asks the CPU to load a waiting leaf's blocks (its `count` blocks
    /// from `first`) while the walk goes on.
    #[cfg(target_arch = "x86_64")]
    #[inline(always)]
    pub fn prefetch(&self, (first, count): (u32, u32)) {
        let blocks = &self.blocks[first as usize..(first + count) as usize];
        for block in blocks {
            crate::prefetch::prefetch(block);
        }
    }

    /// Step 13: the same blocks, in 2 MB pages where the system gives
    /// them ([`Pages::huge`]).
    pub fn in_huge_pages(mut self) -> Blocks4 {
        self.blocks = Pages::huge(&self.blocks);
        self
    }

    /// Tested lane by lane whatever the CPU (for the tests that hold the
    /// AVX2 kernel to it).
    pub fn lane_by_lane(mut self) -> Blocks4 {
        self.simd = false;
        self.pairs = false;
        self
    }

    /// Step 10: a leaf's blocks to be tested two at once
    /// ([`pairs512`](crate::pairs512)), if `avx512` (which must say
    /// whether the CPU has AVX-512F) and they are tested with AVX2;
    /// whether they will be.
    pub(crate) fn in_pairs(&mut self, avx512: bool) -> bool {
        self.pairs = self.simd && avx512;
        self.pairs
    }

    /// Are they tested two at once (step 10)?
    #[inline(always)]
    pub fn pairs(&self) -> bool {
        self.pairs
    }

    // ANCHOR: leaf4
    /// A leaf of the walk: its `count` blocks from `first`, each tested
    /// four triangles at once, then its lanes taken in order exactly as
    /// [`Leaves::leaf`](crate::leaf_triangles::Leaves::leaf) takes
    /// triangles: each hit within `interval` shortens it; the closest hit
    /// (or, `any`, the first).
    #[inline(always)]
    pub fn leaf(
        &self, (first, count): (u32, u32), ray: &FastRay,
        interval: &mut Interval, any: bool, counts: &mut TraceCounts,
    ) -> Option<MeshHit> {
        let mut closest = None;
        for b in first as usize..(first + count) as usize {
            let tested = self.test(&self.blocks[b], ray);
            if self.take(b, tested, ray, interval, any, &mut closest, counts)
                && any
            {
                return closest;
            }
        }
        closest
    }

    /// Block `b`'s lanes, as [`test4`] found them, taken in order: each
    /// hit within `interval` shortens it and becomes `closest`; whether
    /// one did (with `any`, the first ends the block).
    #[inline(always)]
    #[allow(clippy::too_many_arguments)]
    pub(crate) fn take(
        &self, b: usize, tested: Tested, ray: &FastRay,
        interval: &mut Interval, any: bool, closest: &mut Option<MeshHit>,
        counts: &mut TraceCounts,
    ) -> bool {
        let block = &self.blocks[b];
        let lanes = usize::from(self.lanes[b]);
        counts.triangles += lanes as u64;
        let mut found = false;
        // Only the lanes hit or unsure, in order (most blocks: none).
        let mut left = (tested.hit | tested.unsure) & ((1 << lanes) - 1);
        while left != 0 {
            let lane = left.trailing_zeros() as usize;
            left &= left - 1;
            let t = match tested.lane(lane) {
                Lane::Miss => continue,
                Lane::Unsure => {
                    let corners = block.corners(lane);
                    let exact = PreparedRay::new(&ray.ray);
                    match exact.triangle(&corners, *interval) {
                        Some(t) => t,
                        None => continue,
                    }
                }
                Lane::Hit(t) if interval.contains(t) => t,
                Lane::Hit(_) => continue,
            };
            *interval = interval.with_max(t);
            *closest = Some(MeshHit {
                triangle: block.ids[lane],
                t,
            });
            found = true;
            if any {
                break;
            }
        }
        found
    }
    // ANCHOR_END: leaf4

    /// The four lanes of `block`, with AVX2 where built so.
    #[inline(always)]
    pub(crate) fn test(&self, block: &Triangle4, ray: &FastRay) -> Tested {
        #[cfg(target_arch = "x86_64")]
        if self.simd {
            // SAFETY: `simd` is set only where the CPU has AVX2.
            return unsafe { test4(block, ray) };
        }
        test4_scalar(block, ray)
    }
}

/// What the test says of one lane.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Lane {
    /// Outside the triangle, or the ray in its plane.
    Miss,
    /// An edge sign within rounding of 0: chapter 8's exact test decides.
    Unsure,
    /// Inside, at this `t` (not yet checked against the interval).
    Hit(f64),
}

/// The four lanes' results: `t`, and a bit per lane for a hit and for
/// an unsure sign.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Tested {
    pub(crate) t: [f64; 4],
    pub(crate) hit: u32,
    pub(crate) unsure: u32,
}

impl Tested {
    /// No lane hit, none unsure.
    pub const NONE: Tested = Tested {
        t: [0.0; 4],
        hit: 0,
        unsure: 0,
    };

    /// Lane `i`.
    #[inline(always)]
    pub fn lane(&self, i: usize) -> Lane {
        if self.hit & (1 << i) != 0 {
            Lane::Hit(self.t[i])
        } else if self.unsure & (1 << i) != 0 {
            Lane::Unsure
        } else {
            Lane::Miss
        }
    }
}

/// The lane-by-lane test: [`watertight`](crate::leaf_triangles::watertight)'s
/// arithmetic, without the interval (the leaf checks it in order).
#[inline(always)]
pub fn test4_scalar(block: &Triangle4, ray: &FastRay) -> Tested {
    let shear = ch08::Shear {
        axes: ray.axes,
        shear: ray.shear,
    };
    let mut tested = Tested {
        t: [0.0; 4],
        hit: 0,
        unsure: 0,
    };
    for lane in 0..4 {
        let [(a, za), (b, zb), (c, zc)] = block
            .corners(lane)
            .map(|vertex| shear.vertex(ray.origin64, vertex));
        let edge = |p: raystep_core::DVec2, q: raystep_core::DVec2| {
            let (left, right) = (p.x * q.y, p.y * q.x);
            let fast = left - right;
            let sure =
                fast.abs() > 2.0 * f64::EPSILON * (left.abs() + right.abs());
            (fast, sure)
        };
        let [(e0, s0), (e1, s1), (e2, s2)] =
            [edge(b, c), edge(c, a), edge(a, b)];
        let positive = (s0 && e0 > 0.0) || (s1 && e1 > 0.0) || (s2 && e2 > 0.0);
        let negative = (s0 && e0 < 0.0) || (s1 && e1 < 0.0) || (s2 && e2 < 0.0);
        if positive && negative {
            continue;
        }
        if !(s0 && s1 && s2) {
            tested.unsure |= 1 << lane;
            continue;
        }
        let sheared = [(a, za), (b, zb), (c, zc)];
        let (det, noise) = (e0 + e1 + e2, shear.det_rounding(&sheared));
        if !det.is_finite() || det.abs() <= noise {
            continue;
        }
        tested.t[lane] = (e0 * za + e1 * zb + e2 * zc) / det;
        tested.hit |= 1 << lane;
    }
    tested
}

// ANCHOR: test4
/// The four lanes at once (see [`test4_scalar`], which it matches bit
/// for bit): each step one instruction for four triangles.
///
/// # Safety
/// The CPU must have AVX2.
///
/// Compiled with AVX2 itself, so that the closures below are too (a
/// closure of an `#[inline(always)]` function without it would call
/// every intrinsic instead of inlining it: seven times slower).
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
#[inline]
unsafe fn test4(block: &Triangle4, ray: &FastRay) -> Tested {
    use std::arch::x86_64::*;
    // SAFETY: the caller has checked AVX2; each load reads one aligned
    // [f32; 4] row, each store writes four f64s into a [f64; 4].
    unsafe {
        let [kx, ky, kz] = ray.axes;
        let (o, s) = (ray.origin64, ray.shear);
        let splat = _mm256_set1_pd;
        // Step 1: the corners sheared: p = v − o, x = p[kx] − sx·p[kz],
        // y = p[ky] − sy·p[kz], z = sz·p[kz], four triangles per register.
        // The origin's three coordinates taken from an array: indexing
        // glam's `DVec3` by a run-time axis is a `match`, and took a third
        // of this test's instructions (branches picking o[kx] for each
        // corner and axis; counted with callgrind).
        let o = o.to_array();
        let (ox, oy, oz) = (splat(o[kx]), splat(o[ky]), splat(o[kz]));
        let corner = |c: usize| {
            let p = |axis: usize, o| {
                let row = _mm_load_ps(block.rows[c][axis].as_ptr());
                _mm256_sub_pd(_mm256_cvtps_pd(row), o)
            };
            let (px, py, pz) = (p(kx, ox), p(ky, oy), p(kz, oz));
            let x = _mm256_sub_pd(px, _mm256_mul_pd(splat(s.x), pz));
            let y = _mm256_sub_pd(py, _mm256_mul_pd(splat(s.y), pz));
            (x, y, _mm256_mul_pd(splat(s.z), pz))
        };
        let (a, b, c) = (corner(0), corner(1), corner(2));
        // Step 2: the edge functions, and whether each sign is sure.
        let sign = splat(-0.0);
        let abs = |v| _mm256_andnot_pd(sign, v);
        let edge = |p: (__m256d, __m256d, __m256d),
                    q: (__m256d, __m256d, __m256d)| {
            let left = _mm256_mul_pd(p.0, q.1);
            let right = _mm256_mul_pd(p.1, q.0);
            let fast = _mm256_sub_pd(left, right);
            let bound = _mm256_mul_pd(
                splat(2.0 * f64::EPSILON),
                _mm256_add_pd(abs(left), abs(right)),
            );
            (fast, _mm256_cmp_pd::<_CMP_GT_OQ>(abs(fast), bound))
        };
        let ((e0, s0), (e1, s1), (e2, s2)) =
            (edge(b, c), edge(c, a), edge(a, b));
        // Step 3: two sure signs that differ: outside.
        let zero = _mm256_setzero_pd();
        let signed = |e, s, gt: bool| {
            let cmp = if gt {
                _mm256_cmp_pd::<_CMP_GT_OQ>(e, zero)
            } else {
                _mm256_cmp_pd::<_CMP_LT_OQ>(e, zero)
            };
            _mm256_and_pd(s, cmp)
        };
        let any3 = |x, y, z| _mm256_or_pd(_mm256_or_pd(x, y), z);
        let positive = any3(
            signed(e0, s0, true),
            signed(e1, s1, true),
            signed(e2, s2, true),
        );
        let negative = any3(
            signed(e0, s0, false),
            signed(e1, s1, false),
            signed(e2, s2, false),
        );
        let outside =
            _mm256_movemask_pd(_mm256_and_pd(positive, negative)) as u32;
        let sure = _mm256_and_pd(_mm256_and_pd(s0, s1), s2);
        let sure = _mm256_movemask_pd(sure) as u32;
        let inside = !outside & 0b1111;
        let unsure = inside & !sure & 0b1111;
        // Most blocks a ray reaches hold no triangle it meets: done
        // before the divisions.
        if inside & sure == 0 {
            return Tested {
                t: [0.0; 4],
                hit: 0,
                unsure,
            };
        }
        // Step 4: det = e₀ + e₁ + e₂ and its rounding bound
        // (`Shear::det_rounding`: the same sums and maxima in the same
        // order), t = (e₀·za + e₁·zb + e₂·zc) / det.
        let det = _mm256_add_pd(_mm256_add_pd(e0, e1), e2);
        let size =
            |p: (__m256d, __m256d, __m256d)| _mm256_add_pd(abs(p.0), abs(p.1));
        let (sa, sb, sc) = (size(a), size(b), size(c));
        let across = _mm256_max_pd(_mm256_max_pd(sa, sb), sc);
        let along = _mm256_max_pd(_mm256_max_pd(abs(a.2), abs(b.2)), abs(c.2));
        let sum = _mm256_add_pd(_mm256_add_pd(sa, sb), sc);
        let m = _mm256_add_pd(across, _mm256_div_pd(along, splat(s.z.abs())));
        let noise =
            _mm256_mul_pd(_mm256_mul_pd(splat(16.0 * f64::EPSILON), m), sum);
        let finite =
            _mm256_cmp_pd::<_CMP_LT_OQ>(abs(det), splat(f64::INFINITY));
        let above = _mm256_cmp_pd::<_CMP_NLE_UQ>(abs(det), noise);
        let counted = _mm256_movemask_pd(_mm256_and_pd(finite, above)) as u32;
        let numerator = _mm256_add_pd(
            _mm256_add_pd(_mm256_mul_pd(e0, a.2), _mm256_mul_pd(e1, b.2)),
            _mm256_mul_pd(e2, c.2),
        );
        let mut t = [0.0; 4];
        _mm256_storeu_pd(t.as_mut_ptr(), _mm256_div_pd(numerator, det));
        Tested {
            t,
            hit: inside & sure & counted,
            unsure,
        }
    }
}
// ANCHOR_END: test4

/// [`test4`] where this CPU has AVX2, `None` elsewhere: for the tests
/// that hold it to [`test4_scalar`].
pub fn test4_where_available(
    block: &Triangle4, ray: &FastRay,
) -> Option<Tested> {
    #[cfg(target_arch = "x86_64")]
    if avx2() {
        // SAFETY: the CPU said it has AVX2.
        return Some(unsafe { test4(block, ray) });
    }
    let _ = (block, ray);
    None
}

/// Has this CPU AVX2? (Always no off x86-64.)
fn avx2() -> bool {
    #[cfg(target_arch = "x86_64")]
    {
        is_x86_feature_detected!("avx2")
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        false
    }
}
