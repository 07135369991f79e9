//! A bounding volume hierarchy: boxes inside boxes, stored as one flat
//! array of nodes; its cost model; and what every builder and every walk
//! shares (the objects it holds, a node's box test). The builders
//! ([`Builder`](crate::Builder)) make it, the walks ask it.
use raystep_core::{Aabb, Interval, Ray};

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

/// The cost model of the surface area heuristic: one node visit costs
/// `TRAVERSAL` against one object test's `INTERSECTION`: equal here
/// (pbrt 4th ed. uses 1/2 : 1, its 3rd edition 1/8 : 1).
pub const TRAVERSAL: f64 = 1.0;
/// See [`TRAVERSAL`].
pub const INTERSECTION: f64 = 1.0;

/// The two costs of the surface area heuristic, as exercise 5 takes them.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SahCosts {
    /// One node visit.
    pub traversal: f64,
    /// One object test.
    pub intersection: f64,
}

impl SahCosts {
    /// The chapter's costs, [`TRAVERSAL`] and [`INTERSECTION`]: every
    /// builder uses them.
    pub const CHOSEN: SahCosts = SahCosts {
        traversal: TRAVERSAL,
        intersection: INTERSECTION,
    };
}

/// The most objects a leaf may hold when the heuristic would rather not
/// split (all centroids equal, say): more are split by count anyway.
pub const MAX_LEAF: usize = 8;

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
        self.leaf_depths()
            .map(|(_, depth)| depth)
            .max()
            .unwrap_or(0)
    }

    /// Each leaf with its depth (the root's is 1), walked with a stack:
    /// a bottom-up tree may be deep.
    pub(crate) fn leaf_depths(&self) -> impl Iterator<Item = (BvhNode, usize)> {
        let mut stack = Vec::new();
        if !self.nodes.is_empty() {
            stack.push((0usize, 1usize));
        }
        std::iter::from_fn(move || {
            while let Some((k, depth)) = stack.pop() {
                let node = self.nodes[k];
                if node.is_leaf() {
                    return Some((node, depth));
                }
                let first = node.first as usize;
                stack.push((first + 1, depth + 1));
                stack.push((first, depth + 1));
            }
            None
        })
    }

    /// The objects of a leaf: its range of [`Bvh::order`].
    pub fn leaf_objects(&self, node: &BvhNode) -> &[u32] {
        &self.order[node.first as usize..(node.first + node.count) as usize]
    }
}

/// Sorts `boxes` into those the tree holds and those it cannot: an object
/// with no finite box (a plane), or an empty one (which a wrong shape
/// might still hit), is asked by every ray. The builders' step 1.
pub(crate) fn bounded_objects(boxes: &[Aabb]) -> (Vec<u32>, Vec<u32>) {
    let (mut order, mut unbounded) = (Vec::new(), Vec::new());
    for (i, b) in boxes.iter().enumerate() {
        let finite = b.min.is_finite() && b.max.is_finite();
        if finite && !b.is_empty() {
            order.push(i as u32);
        } else {
            unbounded.push(i as u32);
        }
    }
    (order, unbounded)
}

/// Does `ray` meet the node's box within `interval` (exercise 1's slab
/// test)? The entry `t`.
pub(crate) fn enter(
    node: &BvhNode, ray: &Ray, interval: Interval,
) -> Option<f64> {
    crate::slab_test(&node.bounds, ray, interval).map(|inside| inside.min)
}
