//! Step 2: chapter 8's tree in compact single-precision nodes, walked in
//! an order the ray's direction decides.
//!
//! Chapter 8's walk tests both children's boxes at their parent and
//! sorts them by entry `t`. Here (as in pbrt) each node is tested when it
//! is reached, and of two children the one on the ray's side of the
//! split is taken first: the sign of the direction along the split axis
//! says which, with no comparison of `t`s. The far child waits on an
//! explicit stack; nothing recurses.
use ch08::{Bvh, MeshHit, Ray32, TraceCounts, outward};
use raystep_core::{Aabb, DVec3, Interval};
use smallvec::SmallVec;

use crate::leaf_triangles::Leaves;
use crate::ray::{FastRay, WIDEN, span};

/// `meta`'s high bit: an interior node (its low bits: the split axis, and
/// bit 2 set when the first child lies on the axis's high side).
const INTERIOR: u32 = 1 << 31;

// ANCHOR: node
/// 32 bytes, two to a cache line: the box rounded outward to `f32`, and
/// either a leaf's triangles `first .. first + meta` or an interior
/// node's children `first` and `first + 1` with its split axis.
#[derive(Clone, Copy, Debug, PartialEq)]
#[repr(C, align(32))]
pub struct Node {
    min: [f32; 3],
    first: u32,
    max: [f32; 3],
    meta: u32,
}
// ANCHOR_END: node

/// A binary BVH over a triangle mesh, compact and ordered.
#[derive(Clone, Debug, PartialEq)]
pub struct Binary {
    nodes: Vec<Node>,
    /// The triangles of its leaves, and those outside it.
    leaves: Leaves,
}

impl Binary {
    /// `tree` (built over `triangles`' boxes) in compact nodes; the
    /// leaves' triangles in `f32` if `single` (and exact).
    pub fn new(triangles: &[[DVec3; 3]], tree: &Bvh, single: bool) -> Binary {
        let nodes = tree
            .nodes
            .iter()
            .map(|n| {
                let meta = if n.count > 0 {
                    n.count
                } else {
                    let (a, b) = (n.first as usize, n.first as usize + 1);
                    split_meta(&tree.nodes[a].bounds, &tree.nodes[b].bounds)
                };
                Node {
                    min: n.bounds.min.to_array().map(|x| outward(x, false)),
                    first: n.first,
                    max: n.bounds.max.to_array().map(|x| outward(x, true)),
                    meta,
                }
            })
            .collect();
        Binary {
            nodes,
            leaves: Leaves::new(triangles, tree, single),
        }
    }

    /// The closest hit (or, `ANY`, the first found) within `interval`.
    #[inline(always)]
    pub(crate) fn trace<const ANY: bool>(
        &self, ray: &Ray32, interval: Interval, counts: &mut TraceCounts,
    ) -> Option<MeshHit> {
        let ray = self.leaves.ray(ray)?;
        self.walk(&ray, interval, ANY, counts)
    }

    /// Nodes, and the bytes of everything the walk reads.
    pub fn node_count(&self) -> usize {
        self.nodes.len()
    }

    /// Bytes of nodes, triangles and indices.
    pub fn bytes(&self) -> usize {
        self.nodes.len() * size_of::<Node>() + self.leaves.bytes()
    }

    // ANCHOR: walk
    /// The walk: the closest hit, or (`any`) the first one found.
    fn walk(
        &self, ray: &FastRay, interval: Interval, any: bool,
        counts: &mut TraceCounts,
    ) -> Option<MeshHit> {
        // Step 1: triangles outside the tree (none in a finite mesh).
        let mut interval = interval;
        let outside = &self.leaves.outside;
        let mut closest = outside.closest(ray, &mut interval, any, counts);
        if any && closest.is_some() {
            return closest;
        }
        if self.nodes.is_empty() {
            return closest;
        }
        // Step 2: the stack holds far children: 64 on the call stack
        // (not cleared for each ray), more on the heap.
        let mut stack: SmallVec<[u32; 64]> = SmallVec::new();
        let mut span = span(interval);
        let mut k = 0;
        loop {
            counts.nodes += 1;
            let node = &self.nodes[k];
            // Step 3: the node's own box, against the interval so far.
            if slab(node, ray, span) {
                if node.meta & INTERIOR != 0 {
                    // Step 4: the child on the ray's side first: the
                    // sign of the direction along the split axis.
                    let axis = (node.meta & 3) as usize;
                    let high_first = (node.meta >> 2) & 1;
                    let near = ray.negative[axis] as u32 ^ high_first;
                    stack.push(node.first + (1 - near));
                    k = (node.first + near) as usize;
                    continue;
                }
                // Step 5: a leaf: its triangles lie side by side.
                let leaf = (node.first, node.meta);
                let hit =
                    self.leaves.leaf(leaf, ray, &mut interval, any, counts);
                if hit.is_some() {
                    span = crate::ray::span(interval);
                    closest = hit;
                    if any {
                        return closest;
                    }
                }
            }
            match stack.pop() {
                Some(next) => k = next as usize,
                None => return closest,
            }
        }
    }
    // ANCHOR_END: walk
}

/// The split axis of two children (where their centres lie farthest
/// apart) and whether the first lies on its high side, as `meta`.
fn split_meta(a: &Aabb, b: &Aabb) -> u32 {
    let (ca, cb) = (a.min + a.max, b.min + b.max);
    let axis = (cb - ca).abs().max_position();
    INTERIOR | axis as u32 | (u32::from(ca[axis] > cb[axis]) << 2)
}

// ANCHOR: slab
/// Chapter 8's robust slab test in `f32`: does the ray meet the box
/// within `(t_min, t_max)`? NaN (0·∞, an origin in a plane the ray runs
/// along) is ignored by `max`/`min`.
#[inline]
fn slab(node: &Node, ray: &FastRay, (t_min, t_max): (f32, f32)) -> bool {
    let bounds = [node.min, node.max];
    let (mut near, mut far) = (t_min, t_max);
    #[allow(clippy::needless_range_loop)] // one axis of four arrays
    for axis in 0..3 {
        let s = ray.negative[axis];
        let o = ray.origin[axis];
        let t0 = (bounds[s][axis] - o) * ray.inverse[axis];
        let t1 = (bounds[1 - s][axis] - o) * ray.inverse[axis];
        near = near.max(t0);
        far = far.min(t1 * WIDEN);
    }
    near <= far
}
// ANCHOR_END: slab
