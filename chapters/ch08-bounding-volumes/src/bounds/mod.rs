//! Part 1, bounding volumes: a tight sphere around a point set, an
//! object behind its bound, how tight a bound is (what random lines hit,
//! and what that costs), and a mesh behind one box.

// Exercise 4: a bounding sphere of a point set.
#[cfg_attr(feature = "exercise", path = "../../exercise/sphere_of_points.rs")]
mod sphere_of_points;

// An object behind a bound.
mod bounded;

// How tight a bound is: random lines (from a seeded generator), and
// what they hit.
mod random_lines;
mod split_mix64;

mod tightness;

// Collections of stuff: a mesh behind one box.
mod mesh_bound;

pub use bounded::{Bound, BoundKind, Bounded, TestCounts, bounded_intersect};
pub use mesh_bound::{
    MeshBoxCounts, MeshTriangle, TriangleMesh, mesh_behind_box, mesh_triangle,
};
pub use random_lines::RandomLines;
pub use sphere_of_points::sphere_of_points;
pub use split_mix64::SplitMix64;
pub use tightness::Tightness;
