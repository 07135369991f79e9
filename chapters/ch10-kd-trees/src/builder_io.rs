//! What every builder reads (each object's box, cut to a node) and what
//! it writes (nodes and leaf lists, depth first): one pair of types, so
//! that the three builders and the tree's constructors meet only here.
use raystep_core::{Aabb, DVec3};

use crate::{KdCosts, KdNode};

/// What the builders read: each object's box and, for perfect splits,
/// its triangle.
pub(crate) struct Input<'a> {
    pub boxes: &'a [Aabb],
    pub triangles: Option<&'a [[DVec3; 3]]>,
    pub costs: KdCosts,
    pub max_depth: usize,
}

impl Input<'_> {
    /// Object `i`'s box inside `node`.
    pub fn bounds_in(&self, i: u32, node: &Aabb) -> Aabb {
        let cut = intersection(&self.boxes[i as usize], node);
        match self.triangles {
            Some(triangles) => {
                crate::clipped_bounds(&triangles[i as usize], node)
                    .map_or(cut, |clipped| intersection(&clipped, &cut))
            }
            None => cut,
        }
    }
}

/// The box common to `a` and `b`.
pub(crate) fn intersection(a: &Aabb, b: &Aabb) -> Aabb {
    Aabb {
        min: a.min.max(b.min),
        max: a.max.min(b.max),
    }
}

/// What the builders add to: nodes and lists, depth first.
#[derive(Default)]
pub(crate) struct Output {
    pub nodes: Vec<KdNode>,
    pub items: Vec<u32>,
}

impl Output {
    pub fn leaf(&mut self, objects: impl IntoIterator<Item = u32>) {
        let first = self.items.len() as u32;
        self.items.extend(objects);
        // In index order: every builder's leaves read the same.
        self.items[first as usize..].sort_unstable();
        let count = self.items.len() as u32 - first;
        self.nodes.push(KdNode::Leaf { first, count });
    }

    /// An interior node; its child above is filled in by [`Output::above`].
    pub fn split(&mut self, axis: usize, plane: f64) -> usize {
        self.nodes.push(KdNode::Split {
            axis: axis as u8,
            plane,
            above: 0,
        });
        self.nodes.len() - 1
    }

    /// The child above of interior node `node` begins here.
    pub fn above(&mut self, node: usize) {
        let next = self.nodes.len() as u32;
        if let KdNode::Split { above, .. } = &mut self.nodes[node] {
            *above = next;
        }
    }
}
