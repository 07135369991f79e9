//! A built tree's shape in numbers, for the tables that compare the
//! builders.
use super::tree::{Bvh, BvhNode};

/// The shape of a [`Bvh`] ([`Bvh::stats`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TreeStats {
    /// Nodes, interior and leaves.
    pub nodes: usize,
    /// Leaves.
    pub leaves: usize,
    /// Nodes from the root to the deepest leaf (the root alone: 1).
    pub depth: usize,
    /// The leaves' mean depth over that of a perfectly balanced tree with
    /// as many leaves, log₂(leaves) + 1: 1 for a balanced tree, more for
    /// a lopsided one (0 for an empty tree).
    pub balance: f64,
    /// [`Bvh::sah_cost`].
    pub sah_cost: f64,
    /// Bytes of nodes and object indices.
    pub bytes: usize,
    /// The most objects in one leaf.
    pub max_leaf: usize,
    /// The mean number of objects per leaf (0 for an empty tree).
    pub mean_leaf: f64,
}

impl Bvh {
    /// The tree's shape: sizes, depth, balance, SAH cost and memory.
    pub fn stats(&self) -> TreeStats {
        let (mut leaves, mut depth, mut depths) = (0, 0, 0);
        let (mut objects, mut max_leaf) = (0, 0);
        for (leaf, d) in self.leaf_depths() {
            leaves += 1;
            depth = depth.max(d);
            depths += d;
            objects += leaf.count as usize;
            max_leaf = max_leaf.max(leaf.count as usize);
        }
        let per_leaf = |total: usize| {
            if leaves == 0 {
                0.0
            } else {
                total as f64 / leaves as f64
            }
        };
        TreeStats {
            nodes: self.nodes.len(),
            leaves,
            depth,
            balance: per_leaf(depths) / ((leaves as f64).log2() + 1.0),
            sah_cost: self.sah_cost(),
            bytes: self.nodes.len() * size_of::<BvhNode>()
                + (self.order.len() + self.unbounded.len()) * size_of::<u32>(),
            max_leaf,
            mean_leaf: per_leaf(objects),
        }
    }
}
