//! The hierarchy made for one thing only: many triangles, and rays given
//! in single precision, as a benchmark (or a production tracer) has them.
//! The same tree as [`Bvh`], copied into a layout the walk reads fast.
use raystep_core::{Aabb, DVec3};

use crate::Bvh;

/// How the boxes of a [`MeshBvh`] are stored, and tested.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum NodePrecision {
    /// `f64` boxes (56-byte nodes), the slab test of part 1 in `f64`.
    Double,
    /// `f32` boxes rounded outward (32-byte nodes), the slab test in `f32`
    /// with the exit widened by 1 + 2γ₃: never misses a box it touches.
    Single,
    /// `f32` boxes rounded to nearest and the slab test without widening:
    /// what a first fast version does, shown for its missed hits.
    SingleNearest,
}

impl NodePrecision {
    /// The three, in the order tables show them.
    pub const ALL: [NodePrecision; 3] = [
        NodePrecision::Double,
        NodePrecision::Single,
        NodePrecision::SingleNearest,
    ];

    /// `f64`, `f32`, `f32 nearest`.
    pub fn name(self) -> &'static str {
        match self {
            NodePrecision::Double => "f64",
            NodePrecision::Single => "f32",
            NodePrecision::SingleNearest => "f32 nearest",
        }
    }
}

/// A node in `f64`: the box as `[min, max]`, then the link (as
/// [`BvhNode`](crate::BvhNode): `count == 0` means children `first` and
/// `first + 1`, else a leaf of triangles `first ..  first + count`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Node64 {
    pub(crate) bounds: [DVec3; 2],
    pub(crate) first: u32,
    pub(crate) count: u32,
}

/// A node in `f32`: 32 bytes, two to a 64-byte cache line.
#[derive(Clone, Copy, Debug, PartialEq)]
#[repr(C, align(32))]
pub(crate) struct Node32 {
    pub(crate) min: [f32; 3],
    pub(crate) first: u32,
    pub(crate) max: [f32; 3],
    pub(crate) count: u32,
}

/// The nodes, in the precision chosen.
#[derive(Clone, Debug, PartialEq)]
pub(crate) enum Nodes {
    Double(Vec<Node64>),
    Single(Vec<Node32>),
    SingleNearest(Vec<Node32>),
}

/// A triangle mesh's hierarchy in the layout the fast walk reads: flat
/// nodes in the precision asked for, and the triangles' corners copied
/// into leaf order, so that a leaf's triangles lie side by side.
#[derive(Clone, Debug, PartialEq)]
pub struct MeshBvh {
    pub(crate) nodes: Nodes,
    /// Corners in leaf order (triangle `k` of the walk is
    /// `ids[k]` of the mesh).
    pub(crate) corners: Vec<[DVec3; 3]>,
    /// The mesh's index of each triangle in leaf order.
    pub(crate) ids: Vec<u32>,
    /// Triangles with no finite box, tested by every ray.
    pub(crate) unbounded: Vec<u32>,
    /// All the mesh's corners, by the mesh's index.
    pub(crate) all: Vec<[DVec3; 3]>,
    /// The longest path from the root to a leaf (the stack's bound).
    pub(crate) depth: usize,
}

impl MeshBvh {
    /// The hierarchy `tree` (built over the triangles' boxes, see
    /// [`triangle_boxes`]) laid out for the fast walk, its boxes stored in
    /// `precision`.
    pub fn new(
        triangles: &[[DVec3; 3]], tree: &Bvh, precision: NodePrecision,
    ) -> MeshBvh {
        let links = tree.nodes.iter().map(|n| (n.bounds, n.first, n.count));
        let nodes = match precision {
            NodePrecision::Double => Nodes::Double(
                links
                    .map(|(b, first, count)| Node64 {
                        bounds: [b.min, b.max],
                        first,
                        count,
                    })
                    .collect(),
            ),
            NodePrecision::Single => Nodes::Single(
                links.map(|(b, f, c)| node32(&b, f, c, outward)).collect(),
            ),
            NodePrecision::SingleNearest => Nodes::SingleNearest(
                links.map(|(b, f, c)| node32(&b, f, c, nearest)).collect(),
            ),
        };
        MeshBvh {
            nodes,
            corners: tree
                .order
                .iter()
                .map(|&i| triangles[i as usize])
                .collect(),
            ids: tree.order.clone(),
            unbounded: tree.unbounded.clone(),
            all: triangles.to_vec(),
            depth: tree.depth(),
        }
    }

    /// How many nodes.
    pub fn node_count(&self) -> usize {
        match &self.nodes {
            Nodes::Double(n) => n.len(),
            Nodes::Single(n) | Nodes::SingleNearest(n) => n.len(),
        }
    }

    /// The bytes the walk reads from: nodes, corners and indices.
    pub fn bytes(&self) -> usize {
        let nodes = match &self.nodes {
            Nodes::Double(n) => n.len() * size_of::<Node64>(),
            Nodes::Single(n) | Nodes::SingleNearest(n) => {
                n.len() * size_of::<Node32>()
            }
        };
        nodes
            + self.corners.len() * size_of::<[DVec3; 3]>()
            + (self.ids.len() + self.unbounded.len()) * size_of::<u32>()
    }
}

/// Each triangle's box, the input of [`Bvh::build`].
pub fn triangle_boxes(triangles: &[[DVec3; 3]]) -> Vec<Aabb> {
    triangles
        .iter()
        .map(|t| Aabb::around(t.iter().copied()))
        .collect()
}

/// An `f32` node from an `f64` box, each bound rounded by `round`.
fn node32(
    b: &Aabb, first: u32, count: u32, round: fn(f64, bool) -> f32,
) -> Node32 {
    Node32 {
        min: b.min.to_array().map(|x| round(x, false)),
        first,
        max: b.max.to_array().map(|x| round(x, true)),
        count,
    }
}

/// `x` in `f32`, rounded up (`up`) or down: the box can only grow.
pub fn outward(x: f64, up: bool) -> f32 {
    let y = x as f32; // to nearest
    match (up, f64::from(y).total_cmp(&x)) {
        (true, std::cmp::Ordering::Less) => y.next_up(),
        (false, std::cmp::Ordering::Greater) => y.next_down(),
        _ => y,
    }
}

/// `x` in `f32`, rounded to nearest (the box may shrink by half an ulp).
fn nearest(x: f64, _up: bool) -> f32 {
    x as f32
}
