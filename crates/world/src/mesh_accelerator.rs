use raystep_core::{Interval, Ray32};

// ANCHOR: mesh_accelerator
/// The twin of [`Accelerator`](crate::Accelerator) for triangle meshes:
/// the same two questions, asked of a structure built over many
/// triangles, with the benchmark's single-precision rays, answering which
/// triangle (its index in the mesh) and counting the work.
///
/// Chapter 8's `MeshBvh` is the first implementation; chapter 9's
/// `MeshGrid`, chapter 10's `MeshKd` and every step of chapter 11's
/// `FastBvh` follow, and the benchmark's peers (obvhs, bvh, Embree)
/// answer through it too. `raystep bench`, the stability catalogue and
/// the tests ask every structure through these two methods, so none of
/// them wraps a structure again.
///
/// Every implementation tests triangles with chapter 8's watertight test
/// (Embree excepted: its own), answers a ray with a NaN, an infinity or a
/// zero direction "no hit" without tracing it, and adds what the walk
/// cost to `counts`.
pub trait MeshAccelerator: Sync {
    /// The closest hit of `ray` within `interval`.
    fn closest_hit(
        &self, ray: &Ray32, interval: Interval, counts: &mut TraceCounts,
    ) -> Option<MeshHit>;

    /// Does any triangle meet `ray` within `interval`? (A shadow ray.)
    fn any_hit(
        &self, ray: &Ray32, interval: Interval, counts: &mut TraceCounts,
    ) -> bool;
}
// ANCHOR_END: mesh_accelerator

/// A hit of the mesh: which triangle (the mesh's index) and where.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MeshHit {
    /// The triangle's index in the mesh.
    pub triangle: u32,
    /// The ray's parameter at the hit.
    pub t: f64,
}

/// What one walk did: the work a ray costs.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct TraceCounts {
    /// Nodes taken from the stack and looked at (interior or leaf); for a
    /// grid, the cells visited.
    pub nodes: u64,
    /// Ray–triangle tests.
    pub triangles: u64,
}

impl TraceCounts {
    /// Both counts added.
    pub fn add(&mut self, other: TraceCounts) {
        self.nodes += other.nodes;
        self.triangles += other.triangles;
    }
}
