//! The kd-tree: space cut by axis-aligned planes, again and again, until
//! each piece (a leaf) holds few objects.
use raystep_core::Aabb;

use crate::KdCosts;

// ANCHOR: node
/// One node of a [`KdTree`], stored depth first: an interior node's
/// child below its plane is the very next node.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum KdNode {
    /// Cut by the plane `x[axis] = plane`.
    Split {
        /// 0, 1 or 2: x, y or z.
        axis: u8,
        /// Where the plane cuts the axis.
        plane: f64,
        /// The index of the child above the plane (the one below is this
        /// node's index + 1).
        above: u32,
    },
    /// A piece of space and the objects that reach into it:
    /// `items[first .. first + count]`.
    Leaf {
        /// Where its list begins in [`KdTree::items`].
        first: u32,
        /// How many objects.
        count: u32,
    },
}
// ANCHOR_END: node

/// How a [`KdTree`] chooses its planes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum KdBuilder {
    /// The middle of the node's longest side (the spatial median): no
    /// look at the objects at all.
    Median,
    /// The SAH's cheapest plane, found by sorting every node's candidate
    /// planes anew: O(N log² N).
    SahSorting,
    /// The same planes, from event lists sorted once at the root and
    /// split in order at every node (Wald and Havran 2006): O(N log N).
    SahEvents,
}

impl KdBuilder {
    /// `median`, `SAH, sorting`, `SAH, events`.
    pub fn name(self) -> &'static str {
        match self {
            KdBuilder::Median => "median",
            KdBuilder::SahSorting => "SAH, sorting",
            KdBuilder::SahEvents => "SAH, events",
        }
    }
}

/// Which box of a triangle the builder weighs in a node.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Clip {
    /// Its bounding box cut to the node.
    Boxes,
    /// "Perfect splits": the box of the part of the triangle inside the
    /// node (the triangle clipped to the node), tighter once a triangle
    /// has been cut.
    Triangles,
}

impl Clip {
    /// `boxes`, `perfect splits`.
    pub fn name(self) -> &'static str {
        match self {
            Clip::Boxes => "boxes",
            Clip::Triangles => "perfect splits",
        }
    }
}

/// The most objects a median tree leaves in a leaf.
pub const MEDIAN_LEAF: usize = 2;

/// A kd-tree over a list of objects' boxes.
#[derive(Clone, Debug, PartialEq)]
pub struct KdTree {
    /// The nodes; the root is node 0.
    pub nodes: Vec<KdNode>,
    /// The leaves' object lists, one after the other.
    pub items: Vec<u32>,
    /// The root's box: every bounded object's box.
    pub bounds: Aabb,
    /// Objects with no finite box (a plane): tested by every ray, outside
    /// the tree.
    pub unbounded: Vec<u32>,
    /// Skip an object this ray already tested (chapter 9's mailbox): an
    /// object cut by a plane is listed on both sides.
    pub mailboxing: bool,
}

/// What a tree is made of, for tables and charts.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct KdStats {
    /// Interior nodes and leaves.
    pub nodes: usize,
    /// Leaves.
    pub leaves: usize,
    /// Leaves with no object.
    pub empty_leaves: usize,
    /// The deepest leaf (the root is depth 0).
    pub depth: usize,
    /// Entries in all leaves (an object in 3 leaves counts 3 times).
    pub entries: usize,
    /// Bytes of nodes and lists.
    pub bytes: usize,
    /// The SAH cost of the whole tree (see [`KdTree::sah_cost`]).
    pub sah_cost: f64,
}

impl KdTree {
    /// The objects of a leaf.
    pub fn leaf_objects(&self, first: u32, count: u32) -> &[u32] {
        &self.items[first as usize..(first + count) as usize]
    }

    /// The box of every node, in node order.
    pub fn node_boxes(&self) -> Vec<Aabb> {
        let mut boxes = vec![self.bounds; self.nodes.len()];
        for (k, node) in self.nodes.iter().enumerate() {
            if let KdNode::Split { axis, plane, above } = *node {
                let (mut below, mut upper) = (boxes[k], boxes[k]);
                below.max[axis as usize] = plane;
                upper.min[axis as usize] = plane;
                boxes[k + 1] = below;
                boxes[above as usize] = upper;
            }
        }
        boxes
    }

    /// The depth of every node, in node order.
    pub fn node_depths(&self) -> Vec<usize> {
        let mut depths = vec![0; self.nodes.len()];
        for (k, node) in self.nodes.iter().enumerate() {
            if let KdNode::Split { above, .. } = *node {
                depths[k + 1] = depths[k] + 1;
                depths[above as usize] = depths[k] + 1;
            }
        }
        depths
    }

    /// The SAH's estimate of a ray's cost through the tree: every node's
    /// chance of being passed, A(node) / A(root), times its own cost (a
    /// step for an interior node, its objects' tests for a leaf).
    pub fn sah_cost(&self, costs: &KdCosts) -> f64 {
        let root = self.bounds.surface_area();
        let boxes = self.node_boxes();
        let chance = |b: &Aabb| {
            if root > 0.0 {
                b.surface_area() / root
            } else {
                1.0
            }
        };
        self.nodes
            .iter()
            .zip(&boxes)
            .map(|(node, b)| match *node {
                KdNode::Split { .. } => costs.traversal * chance(b),
                KdNode::Leaf { count, .. } => {
                    costs.intersection * count as f64 * chance(b)
                }
            })
            .sum()
    }

    /// Bytes of its nodes and lists.
    pub fn bytes(&self) -> usize {
        self.nodes.len() * size_of::<KdNode>()
            + (self.items.len() + self.unbounded.len()) * size_of::<u32>()
    }

    /// Its nodes, leaves, entries and bytes; its SAH cost under `costs`.
    pub fn stats(&self, costs: &KdCosts) -> KdStats {
        let leaves = self
            .nodes
            .iter()
            .filter(|n| matches!(n, KdNode::Leaf { .. }));
        KdStats {
            nodes: self.nodes.len(),
            leaves: leaves.clone().count(),
            empty_leaves: leaves
                .filter(|n| matches!(n, KdNode::Leaf { count: 0, .. }))
                .count(),
            depth: self.node_depths().into_iter().max().unwrap_or(0),
            entries: self.items.len(),
            bytes: self.bytes(),
            sah_cost: self.sah_cost(costs),
        }
    }
}
