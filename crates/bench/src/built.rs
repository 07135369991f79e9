//! What building a method gave: the structure, asked through the mesh
//! seam, and what it is made of.
use ch08::TreeStats;
use raystep_world::MeshAccelerator;

/// What building gave: the tracer and what it is made of.
pub struct Built {
    /// Asks the structure.
    pub tracer: Box<dyn MeshAccelerator>,
    /// Milliseconds from the triangles' boxes to a tracer.
    pub build_ms: f64,
    /// Bytes of nodes and reordered triangles (`None`: not known).
    pub bytes: Option<usize>,
    /// Our trees only: the tree's shape ([`Bvh::stats`](ch08::Bvh::stats)).
    pub tree: Option<TreeStats>,
}
