//! The kd-tree: space cut by axis-aligned planes, again and again, until
//! each piece (a leaf) holds few objects.
use raystep_core::{Aabb, DVec3};
use raystep_world::Object;

use crate::{KdCosts, build_events, build_sorting, median};

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

/// The deepest any tree goes, whatever the rule gives (the traversal's
/// stack holds one entry per level).
pub const MAX_DEPTH: usize = 60;

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

/// Does the box hold a finite, non-empty stretch of space?
fn is_bounded(b: &Aabb) -> bool {
    !b.is_empty() && b.min.is_finite() && b.max.is_finite()
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

impl KdTree {
    /// The tree over `boxes` (object `i` has box `boxes[i]`), cut by
    /// `builder` with the cost model `costs` (the median builder uses
    /// only its depth rule). Objects without a finite box go to [`KdTree::unbounded`].
    pub fn build(boxes: &[Aabb], builder: KdBuilder, costs: KdCosts) -> KdTree {
        build(boxes, None, builder, costs)
    }

    /// The tree over triangles; with [`Clip::Triangles`], perfect splits.
    pub fn for_triangles(
        triangles: &[[DVec3; 3]],
        builder: KdBuilder,
        costs: KdCosts,
        clip: Clip,
    ) -> KdTree {
        let boxes: Vec<Aabb> = triangles
            .iter()
            .map(|t| Aabb::around(t.iter().copied()))
            .collect();
        let clip = (clip == Clip::Triangles).then_some(triangles);
        build(&boxes, clip, builder, costs)
    }

    /// The tree over the objects' boxes ([`Shape::bounds`]).
    ///
    /// [`Shape::bounds`]: raystep_core::Shape::bounds
    pub fn for_objects(
        objects: &[Object],
        builder: KdBuilder,
        costs: KdCosts,
    ) -> KdTree {
        let boxes: Vec<Aabb> =
            objects.iter().map(|o| o.shape.bounds()).collect();
        KdTree::build(&boxes, builder, costs)
    }

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

/// Sorts out the unbounded objects, then hands the rest to a builder.
fn build(
    boxes: &[Aabb],
    triangles: Option<&[[DVec3; 3]]>,
    builder: KdBuilder,
    costs: KdCosts,
) -> KdTree {
    let (inside, unbounded): (Vec<u32>, Vec<u32>) =
        (0..boxes.len() as u32).partition(|&i| is_bounded(&boxes[i as usize]));
    let bounds = inside
        .iter()
        .map(|&i| boxes[i as usize])
        .reduce(Aabb::union)
        .unwrap_or(Aabb::EMPTY);
    let input = Input {
        boxes,
        triangles,
        costs,
        max_depth: costs.max_depth(inside.len()),
    };
    let mut out = Output::default();
    match builder {
        KdBuilder::Median => median::build(&input, &inside, bounds, &mut out),
        KdBuilder::SahSorting => {
            build_sorting::build(&input, &inside, bounds, &mut out)
        }
        KdBuilder::SahEvents => {
            build_events::build(&input, &inside, bounds, &mut out)
        }
    }
    KdTree {
        nodes: out.nodes,
        items: out.items,
        bounds,
        unbounded,
        mailboxing: true,
    }
}
