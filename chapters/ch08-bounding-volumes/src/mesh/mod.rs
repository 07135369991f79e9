//! Part 2, the mesh fast path: a hierarchy over many triangles laid out
//! for `f32` rays ([`MeshBvh`]), each ray prepared once
//! ([`PreparedRay`]), the walk asked through the mesh seam, and brute
//! force, which every mesh structure must agree with.

// The layout: the tree's nodes in the precision asked for.
mod mesh_bvh;

// Step 1 of every walk: the ray prepared; one candidate step.
mod prepared_ray;

// Brute force, and the fast walk.
mod brute_force;

mod mesh_trace;

pub use brute_force::MeshBruteForce;
pub use mesh_bvh::{MeshBvh, NodePrecision, outward, triangle_boxes};
pub use prepared_ray::{Closest, PreparedRay};
