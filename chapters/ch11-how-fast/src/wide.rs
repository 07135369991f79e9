//! Step 5: wide nodes. The binary tree collapsed into nodes of `W`
//! children (4 or 8), each node holding its children's boxes side by side
//! — all the `min x`s, then all the `min y`s, … — so that one SIMD
//! instruction tests one plane of every child at once (Wald et al. 2008,
//! Dammertz et al. 2008; Embree's BVH4 and BVH8).
use ch08::{Bvh, MeshHit, Ray32, TraceCounts, outward};
use raystep_core::{DVec3, Interval};
use smallvec::SmallVec;

use crate::leaf_triangles::Leaves;
use crate::pages::Pages;
use crate::ray::{FastRay, span};

// ANCHOR: wide_node
/// `W` children's boxes in structure-of-arrays form (`lo[axis][child]`),
/// and per child either a node (`count == 0`, `child` its index) or a
/// leaf (`count` triangles from `child`). An empty slot has an empty box
/// (lo = +∞, hi = −∞), which no ray meets.
#[derive(Clone, Copy, Debug, PartialEq)]
#[repr(C, align(64))]
pub struct WideNode<const W: usize> {
    /// The boxes' low corners, one row per axis.
    pub lo: [[f32; W]; 3],
    /// The boxes' high corners.
    pub hi: [[f32; W]; 3],
    /// A node's index or a leaf's first triangle.
    pub child: [u32; W],
    /// A leaf's triangle count; 0 for a node (or an empty slot).
    pub count: [u32; W],
}
// ANCHOR_END: wide_node

/// What the walk asks of a wide node besides its boxes: child `i`'s
/// link, `(child, count)` as in [`WideNode`].
pub trait Links {
    /// Child `i`: a node's index and 0, or a leaf's first triangle and
    /// its count.
    fn link(&self, i: usize) -> (u32, u32);
}

impl<const W: usize> Links for WideNode<W> {
    #[inline(always)]
    fn link(&self, i: usize) -> (u32, u32) {
        (self.child[i], self.count[i])
    }
}

/// A child as the stack holds it: a node or a leaf, and where the ray
/// enters its box.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(crate) struct Entry {
    pub(crate) child: u32,
    pub(crate) count: u32,
    pub(crate) t: f32,
}

/// A wide BVH over a triangle mesh, its nodes of type `N` (plain boxes,
/// or [`compressed`](crate::compressed) ones).
#[derive(Clone, Debug, PartialEq)]
pub struct Wide<const W: usize, N: Copy = WideNode<W>> {
    pub(crate) nodes: Pages<N>,
    /// The root as a child: a node, or a leaf if the tree is one leaf.
    pub(crate) root: Option<Entry>,
    pub(crate) leaves: Leaves,
    /// Step 9: an any-hit walk takes the children hit in the node's
    /// order, without sorting them by distance.
    unordered_any: bool,
}

impl<const W: usize> Wide<W> {
    // ANCHOR: collapse
    /// `tree` collapsed into `W`-wide nodes: each node takes its two
    /// children, then again and again opens the child with the largest
    /// surface area into its own two, until it has `W` children or only
    /// leaves (the greedy collapse of Wald et al. 2008).
    pub fn new(triangles: &[[DVec3; 3]], tree: &Bvh, single: bool) -> Self {
        Wide::with_leaves(tree, Leaves::new(triangles, tree, single))
    }

    /// [`Wide::new`] with its leaves' triangles laid out already.
    pub fn with_leaves(tree: &Bvh, leaves: Leaves) -> Self {
        let mut nodes = Vec::new();
        let root = tree.nodes.first().map(|root| {
            if root.count > 0 {
                Entry {
                    child: root.first,
                    count: root.count,
                    t: 0.0,
                }
            } else {
                collapse(tree, 0, &mut nodes);
                Entry::default()
            }
        });
        Wide {
            nodes: nodes.into(),
            root,
            leaves,
            unordered_any: false,
        }
    }
    // ANCHOR_END: collapse

    /// Step 6: the same tree, its triangles tested three edges at once
    /// where the CPU can.
    pub fn with_lanes(mut self) -> Self {
        self.leaves = self.leaves.with_lanes();
        self
    }

    /// Step 8: the same tree, its leaves in blocks of four (`blocks`),
    /// each leaf's link `(first, count)` turned into `links[first]`
    /// (`(first block, blocks)`).
    pub fn with_blocks(
        mut self, blocks: crate::leaf4::Blocks4, links: &[(u32, u32)],
    ) -> Self {
        let relink = |(child, count): (u32, u32)| match count {
            0 => (child, 0),
            _ => links[child as usize],
        };
        for node in self.nodes.iter_mut() {
            for i in 0..W {
                (node.child[i], node.count[i]) =
                    relink((node.child[i], node.count[i]));
            }
        }
        if let Some(root) = &mut self.root {
            (root.child, root.count) = relink((root.child, root.count));
        }
        self.leaves.blocks = Some(blocks);
        self
    }

    /// Step 13: the same tree, its nodes and blocks in 2 MB pages where
    /// the system gives them ([`Pages::huge`]).
    pub fn in_huge_pages(mut self) -> Self {
        self.nodes = Pages::huge(&self.nodes);
        self.leaves.blocks = self.leaves.blocks.map(|b| b.in_huge_pages());
        self
    }

    /// Step 9: the same tree, its any-hit walk taking the children hit in
    /// the node's order (a shadow ray wants any blocker, not the nearest).
    pub fn unordered_any(mut self) -> Self {
        self.unordered_any = true;
        self
    }

    /// How many nodes deep the tree is (0: no node, or a leaf alone).
    pub fn depth(&self) -> usize {
        let mut deepest = 0;
        let mut stack = match self.root {
            Some(root) if root.count == 0 => vec![(root.child, 1)],
            _ => vec![],
        };
        while let Some((k, depth)) = stack.pop() {
            deepest = deepest.max(depth);
            let node = &self.nodes[k as usize];
            for i in 0..W {
                // An interior child (an empty slot's box is empty).
                if node.count[i] == 0 && node.lo[0][i] <= node.hi[0][i] {
                    stack.push((node.child[i], depth + 1));
                }
            }
        }
        deepest
    }

    /// The same tree with each node turned into `f(node)`.
    pub fn map_nodes<N: Copy>(
        self, f: impl Fn(&WideNode<W>) -> N,
    ) -> Wide<W, N> {
        Wide {
            nodes: self.nodes.iter().map(f).collect::<Vec<N>>().into(),
            root: self.root,
            leaves: self.leaves,
            unordered_any: self.unordered_any,
        }
    }
}

impl<const W: usize, N: Links + Copy> Wide<W, N> {
    /// How many wide nodes.
    pub fn node_count(&self) -> usize {
        self.nodes.len()
    }

    /// Step 8's blocks, if any, tested lane by lane (the fallback a CPU
    /// without AVX2 gets): for testing the fallback anywhere.
    pub fn lane_by_lane(&mut self) {
        if let Some(blocks) = self.leaves.blocks.take() {
            self.leaves.blocks = Some(blocks.lane_by_lane());
        }
    }

    /// Step 10: step 8's blocks, if any, tested two at once where this
    /// CPU has AVX-512; whether they are.
    pub fn in_pairs(&mut self) -> bool {
        #[cfg(target_arch = "x86_64")]
        let avx512 = crate::pairs512::available();
        #[cfg(not(target_arch = "x86_64"))]
        let avx512 = false;
        self.leaves
            .blocks
            .as_mut()
            .is_some_and(|b| b.in_pairs(avx512))
    }

    /// Bytes of nodes, triangles and indices.
    pub fn bytes(&self) -> usize {
        self.nodes.len() * size_of::<N>() + self.leaves.bytes()
    }

    /// The closest hit (or, `any`, the first hit found) of a prepared ray,
    /// the boxes of each node tested by `boxes`: it returns the entry `t`
    /// of every child and a bit per child whose box the ray meets within
    /// the span. Generic and always inlined, so that each kernel's caller
    /// (compiled with its CPU features) gets a walk of its own.
    #[inline(always)]
    pub(crate) fn walk(
        &self, ray: &FastRay, interval: Interval, any: bool,
        counts: &mut TraceCounts,
        boxes: impl Fn(&N, &FastRay, (f32, f32)) -> ([f32; W], u32),
    ) -> Option<MeshHit> {
        // Step 9's any-hit walk is compiled apart, without the sort.
        if any && self.unordered_any {
            self.walk_with::<true>(ray, interval, any, counts, boxes)
        } else {
            self.walk_with::<false>(ray, interval, any, counts, boxes)
        }
    }

    /// [`Wide::walk`], the children hit sorted nearest first unless
    /// `UNSORTED`.
    #[inline(always)]
    fn walk_with<const UNSORTED: bool>(
        &self, ray: &FastRay, interval: Interval, any: bool,
        counts: &mut TraceCounts,
        boxes: impl Fn(&N, &FastRay, (f32, f32)) -> ([f32; W], u32),
    ) -> Option<MeshHit> {
        // Step 1: triangles outside the tree (none in a finite mesh).
        let mut interval = interval;
        let outside = &self.leaves.outside;
        let mut closest = outside.closest(ray, &mut interval, any, counts);
        if any && closest.is_some() {
            return closest;
        }
        // ANCHOR: wide_walk
        // The stack: 64 children on the call stack (not cleared for each
        // ray), more on the heap.
        let mut stack: SmallVec<[Entry; 64]> = SmallVec::new();
        let mut span = span(interval);
        // The nearest child hit goes straight on, the others wait (step
        // 9: for any hit, the last in the node's order).
        let mut next = Some(self.root?);
        loop {
            let entry = match next.take() {
                Some(entry) => entry,
                None => match stack.pop() {
                    // Step 2: a child entered beyond the closest hit
                    // holds nothing closer (the bound its box test used,
                    // now shorter).
                    Some(entry) if entry.t > span.1 => continue,
                    Some(entry) => entry,
                    None => break,
                },
            };
            counts.nodes += 1;
            if entry.count > 0 {
                // Step 3: a leaf: its triangles, side by side.
                let leaf = (entry.child, entry.count);
                let hit =
                    self.leaves.leaf(leaf, ray, &mut interval, any, counts);
                if hit.is_some() {
                    span = crate::ray::span(interval);
                    closest = hit;
                    if any {
                        return closest;
                    }
                }
                continue;
            }
            // Step 4: all W boxes at once; the children hit, sorted
            // farthest first: the nearest is taken next, the others
            // pushed.
            let node = &self.nodes[entry.child as usize];
            let (t, mut mask) = boxes(node, ray, span);
            let mut hit = [Entry::default(); W];
            let mut n = 0;
            while mask != 0 {
                let i = mask.trailing_zeros() as usize;
                mask &= mask - 1;
                let (child, count) = node.link(i);
                let e = Entry {
                    child,
                    count,
                    t: t[i],
                };
                // insertion sort, farthest first
                let mut j = n;
                while !UNSORTED && j > 0 && hit[j - 1].t < e.t {
                    hit[j] = hit[j - 1];
                    j -= 1;
                }
                hit[j] = e;
                n += 1;
            }
            let Some((nearest, others)) = hit[..n].split_last() else {
                continue;
            };
            for e in others {
                self.prefetch(e);
                stack.push(*e);
            }
            next = Some(*nearest);
        }
        // ANCHOR_END: wide_walk
        closest
    }

    /// Step 5: a waiting node's memory asked for now, used later (step 8:
    /// a waiting leaf's blocks too).
    #[inline(always)]
    pub(crate) fn prefetch(&self, e: &Entry) {
        #[cfg(target_arch = "x86_64")]
        if e.count == 0 {
            crate::prefetch::prefetch(&self.nodes[e.child as usize]);
        } else if let Some(blocks) = &self.leaves.blocks {
            blocks.prefetch((e.child, e.count));
        }
    }

    /// The closest hit (or, `ANY`, the first found), boxes tested by
    /// `boxes` (see [`Wide::walk`]).
    #[inline(always)]
    pub(crate) fn trace<const ANY: bool>(
        &self, ray: &Ray32, interval: Interval, counts: &mut TraceCounts,
        boxes: impl Fn(&N, &FastRay, (f32, f32)) -> ([f32; W], u32),
    ) -> Option<MeshHit> {
        let ray = self.leaves.ray(ray)?;
        self.walk(&ray, interval, ANY, counts, boxes)
    }
}

/// Collapses the binary node `k` (interior) into a wide node appended to
/// `nodes`, and its interior children after it; returns its index.
fn collapse<const W: usize>(
    tree: &Bvh, k: usize, nodes: &mut Vec<WideNode<W>>,
) -> u32 {
    // Step 1: open the largest interior child until W children.
    let first = tree.nodes[k].first as usize;
    let mut children = vec![first, first + 1];
    while children.len() < W {
        let open = children
            .iter()
            .enumerate()
            .filter(|(_, c)| tree.nodes[**c].count == 0)
            .max_by(|(_, a), (_, b)| {
                let area = |c: usize| tree.nodes[c].bounds.surface_area();
                area(**a).total_cmp(&area(**b))
            })
            .map(|(i, _)| i);
        let Some(i) = open else { break };
        let c = tree.nodes[children[i]].first as usize;
        children.splice(i..=i, [c, c + 1]);
    }
    // Step 2: the node, its interior children filled in after it.
    let index = nodes.len();
    nodes.push(WideNode {
        lo: [[f32::INFINITY; W]; 3],
        hi: [[f32::NEG_INFINITY; W]; 3],
        child: [0; W],
        count: [0; W],
    });
    for (slot, &c) in children.iter().enumerate() {
        let n = &tree.nodes[c];
        let child = if n.count > 0 {
            n.first
        } else {
            collapse(tree, c, nodes)
        };
        let node = &mut nodes[index];
        for axis in 0..3 {
            node.lo[axis][slot] = outward(n.bounds.min[axis], false);
            node.hi[axis][slot] = outward(n.bounds.max[axis], true);
        }
        node.child[slot] = child;
        node.count[slot] = n.count;
    }
    index as u32
}

// ANCHOR: scalar_boxes
/// The box test of every child, one after another: the fallback for any
/// CPU, and the reference the SIMD kernels must match bit for bit.
#[inline(always)]
pub fn scalar_boxes<const W: usize>(
    node: &WideNode<W>, ray: &FastRay, (t_min, t_max): (f32, f32),
) -> ([f32; W], u32) {
    let mut near = [t_min; W];
    let mut mask = 0;
    #[allow(clippy::needless_range_loop)] // one child of several arrays
    for i in 0..W {
        let mut far = t_max;
        for axis in 0..3 {
            let (t0, t1) = ray.slab(axis, node.lo[axis][i], node.hi[axis][i]);
            near[i] = near[i].max(t0);
            far = far.min(t1);
        }
        mask |= u32::from(near[i] <= far) << i;
    }
    (near, mask)
}
// ANCHOR_END: scalar_boxes
