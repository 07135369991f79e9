//! A bounding volume hierarchy: boxes inside boxes, stored as one flat
//! array of nodes, built top-down by one of the [`Split`] rules.
use raystep_core::{Aabb, Interval, Ray};
use raystep_world::Object;

use crate::bvh_build::build;

/// One node of a [`Bvh`]: a box, and either two children (`count == 0`:
/// the children are nodes `first` and `first + 1`) or a leaf (`count > 0`:
/// the objects `order[first .. first + count]`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BvhNode {
    /// A box around everything below the node.
    pub bounds: Aabb,
    /// The first child (interior) or the first slot of `order` (leaf).
    pub first: u32,
    /// How many objects the leaf holds; 0 for an interior node.
    pub count: u32,
}

impl BvhNode {
    /// Does the node hold objects (rather than two children)?
    pub fn is_leaf(&self) -> bool {
        self.count > 0
    }
}

/// How a node's objects are split in two.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Split {
    /// At the middle of the centroids' box, along its longest axis.
    Midpoint,
    /// At the median centroid along that axis: two halves of equal count.
    Median,
    /// Where the surface area heuristic is lowest, among `bins` equal
    /// slices of the centroids' box on each axis.
    BinnedSah {
        /// How many slices per axis (at least 2).
        bins: usize,
    },
}

impl Split {
    /// `midpoint`, `median`, `SAH, 16 bins`: the name tables show.
    pub fn name(self) -> String {
        match self {
            Split::Midpoint => "midpoint".to_string(),
            Split::Median => "median".to_string(),
            Split::BinnedSah { bins } => format!("SAH, {bins} bins"),
        }
    }
}

/// The cost model of the surface area heuristic: one node visit costs
/// `TRAVERSAL` against one object test's `INTERSECTION` (pbrt's ratio).
pub const TRAVERSAL: f64 = 1.0;
/// See [`TRAVERSAL`].
pub const INTERSECTION: f64 = 1.0;

/// A bounding volume hierarchy over a list of objects' boxes.
///
/// It holds only boxes and indices: the objects are handed to its
/// questions ([`Accelerator`](raystep_world::Accelerator)), the same list
/// it was built for.
#[derive(Clone, Debug, PartialEq)]
pub struct Bvh {
    /// The nodes; the root is node 0 (absent for no objects).
    pub nodes: Vec<BvhNode>,
    /// Object indices in leaf order: each leaf owns a range of it.
    pub order: Vec<u32>,
    /// Objects with no finite box (a plane): tested by every ray, outside
    /// the tree.
    pub unbounded: Vec<u32>,
}

impl Bvh {
    /// The hierarchy over `boxes` (object `i` has box `boxes[i]`), split by
    /// `split`. An object without a finite box (a plane) is kept out of the
    /// tree, in [`Bvh::unbounded`]: it would make every box around it
    /// infinite.
    pub fn build(boxes: &[Aabb], split: Split) -> Bvh {
        build(boxes, split)
    }

    /// The hierarchy over the objects' boxes ([`Shape::bounds`]).
    ///
    /// [`Shape::bounds`]: raystep_core::Shape::bounds
    pub fn for_objects(objects: &[Object], split: Split) -> Bvh {
        let boxes: Vec<Aabb> =
            objects.iter().map(|o| o.shape.bounds()).collect();
        Bvh::build(&boxes, split)
    }

    /// The SAH cost of the whole tree: for each node, its chance of being
    /// visited by a ray that hits the root (its area over the root's)
    /// times its cost (`TRAVERSAL`, or `INTERSECTION` per object of a leaf).
    pub fn sah_cost(&self) -> f64 {
        let Some(root) = self.nodes.first() else {
            return 0.0;
        };
        let whole = root.bounds.surface_area();
        self.nodes
            .iter()
            .map(|node| {
                let p = if whole > 0.0 {
                    node.bounds.surface_area() / whole
                } else {
                    1.0
                };
                if node.is_leaf() {
                    p * INTERSECTION * f64::from(node.count)
                } else {
                    p * TRAVERSAL
                }
            })
            .sum()
    }

    /// The number of nodes from the root to the deepest leaf (0 if empty).
    pub fn depth(&self) -> usize {
        fn below(nodes: &[BvhNode], k: usize) -> usize {
            let node = nodes[k];
            if node.is_leaf() {
                1
            } else {
                let first = node.first as usize;
                1 + below(nodes, first).max(below(nodes, first + 1))
            }
        }
        if self.nodes.is_empty() {
            0
        } else {
            below(&self.nodes, 0)
        }
    }
}

/// Does `ray` meet the node's box within `interval`? The entry `t`.
pub(crate) fn enter(
    node: &BvhNode,
    ray: &Ray,
    interval: Interval,
) -> Option<f64> {
    node.bounds.hit(ray, interval).map(|inside| inside.min)
}
