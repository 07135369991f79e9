//! Part 1, fast primitives: the box and its slab test, the quadric
//! roots that a cylinder and an ellipsoid share, triangles by two tests
//! (Möller–Trumbore, and the watertight test with its shear), and the
//! fast primitives of earlier chapters as this chapter's primitives.

// The box, hit by the robust slab test.
mod axis_box;
// Exercise 1: the robust slab test.
#[cfg_attr(feature = "exercise", path = "../../exercise/slab.rs")]
mod slab;

// Quadrics: the sphere's roots, and the shapes that reuse them.
mod sphere_roots;

mod cylinder;
mod ellipsoid;

// Triangles: two tests, one type.
mod moller_trumbore;
mod shear;
// Exercise 2: the watertight ray–triangle test.
#[cfg_attr(feature = "exercise", path = "../../exercise/watertight.rs")]
mod watertight;

mod triangle;

// Chapter 3's sphere and chapter 2's polygon as primitives.
mod chapter_shapes;

pub use axis_box::AxisBox;
pub use cylinder::Cylinder;
pub use ellipsoid::Ellipsoid;
pub use moller_trumbore::moller_trumbore;
pub use shear::Shear;
pub use slab::slab_test;
pub use triangle::{Triangle, TriangleTest};
pub use watertight::watertight;
// Steps 4–7 of the watertight test, which the fast walk of part 2 asks
// with its own ray's shear.
pub(crate) use watertight::sheared_hit;
