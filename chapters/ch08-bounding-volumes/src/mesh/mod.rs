//! Part 2, the mesh fast path: a hierarchy over many triangles laid out
//! for `f32` rays ([`MeshBvh`]), each ray prepared once
//! ([`PreparedRay`]), the walk asked through the mesh seam, and brute
//! force, which every mesh structure must agree with.
//!
//! Then meshes in scenes: a mesh's triangles as objects, flat or smoothly
//! shaded ([`SmoothTriangle`]), flattened into the world
//! ([`placed_triangles`]) or placed many times without a copy, through a
//! two-level hierarchy ([`Blas`], [`MeshInstance`]).

// The layout: the tree's nodes in the precision asked for.
mod mesh_bvh;

// Step 1 of every walk: the ray prepared; one candidate step.
mod prepared_ray;

// Brute force, and the fast walk.
mod brute_force;

mod mesh_trace;

// Meshes in scenes: smooth shading, the triangles placed, and instances
// (the bottom level shared, one object per placement).
mod smooth_triangle;

mod placed_triangles;

mod blas;
mod instance;

pub use blas::Blas;
pub use brute_force::MeshBruteForce;
pub use instance::MeshInstance;
pub use mesh_bvh::{MeshBvh, NodePrecision, outward, triangle_boxes};
pub use placed_triangles::{PlacedTriangle, placed_triangles};
pub use prepared_ray::{Closest, PreparedRay};
pub use smooth_triangle::{SmoothTriangle, barycentric};
