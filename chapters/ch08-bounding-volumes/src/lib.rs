//! # Chapter 8 — bounding volumes (part 1: fast and slow primitives)
//!
//! "Ray tracing speed-ups": some primitives are fast to intersect —
//! spheres, boxes, cylinders, ellipsoids, polygons and triangles — and
//! some are slow — a torus (a quartic in t), a cubic surface, blobby
//! objects — and need robust root finding. A bounding volume (a sphere or
//! a box) around something slow or big is cheap to test *versus* the cost
//! of what is inside; the tighter it fits, the more rays it turns away.
//!
//! Student mode: with the feature `exercise` the modules marked below are
//! replaced by the stubs in `exercise/`.

mod bounding_sphere;
mod primitive;

pub use bounding_sphere::BoundingSphere;
pub use primitive::Primitive;
pub use raystep_core::{Aabb, DVec3, Hit, Interval, Ray, Shape};

// ---------------------------------------------------------------------
// Fast primitives: the box's slab test, cylinder, ellipsoid, triangles.
// ---------------------------------------------------------------------

// ---------------------------------------------------------------------
// Slow primitives: polynomial roots, the torus, the saddle, blobs.
// ---------------------------------------------------------------------

mod blobby;
mod bracketed;
mod closed_form;
mod polynomial;
mod saddle;
mod torus;
// Exercise 3: the torus quartic's coefficients.
#[cfg_attr(feature = "exercise", path = "../exercise/torus_quartic.rs")]
mod torus_quartic;

pub use blobby::{Ball, Blobby, WYVILL};
pub use bracketed::roots_in;
pub use closed_form::{cubic_roots, quadratic_roots, quartic_roots};
pub use polynomial::{derivative, horner, multiply};
pub use saddle::{Saddle, saddle_cubic};
pub use torus::{Torus, TorusSolver};
pub use torus_quartic::torus_quartic;

// ---------------------------------------------------------------------
// Bounding volumes: spheres around point sets, tightness, meshes.
// ---------------------------------------------------------------------

// ---------------------------------------------------------------------
// Scene files: every primitive from TOML.
// ---------------------------------------------------------------------
