//! # Chapter 1 — implicit lines and planes
//!
//! A line in 2D and a plane in 3D, each written implicitly as "the points
//! where f is zero":
//!
//! * line through P₀, P₁: `f(x, y) = a·x + b·y + c` with `(a, b) = N`;
//! * plane through P₀, P₁, P₂: `f(P) = N·P + d`.
//!
//! With a unit N the sign of f says which side a point is on and |f| is
//! its distance. Every later chapter stands on these two: chapter 2 hits
//! planes and tests polygon edges with lines.
//!
//! Student mode: with the feature `exercise` the modules marked below are
//! replaced by the stubs in `exercise/`.

mod degenerate;
mod line;
mod plane;

// Exercise 1: the line through two points.
#[cfg_attr(feature = "exercise", path = "../exercise/line_through_points.rs")]
mod line_through_points;
// Exercise 2: the plane through three points.
#[cfg_attr(feature = "exercise", path = "../exercise/plane_through_points.rs")]
mod plane_through_points;

pub use degenerate::Degenerate;
pub use line::Line2;
pub use line_through_points::rotate90;
pub use plane::{COLLINEAR_SINE, Plane};
pub use raystep_core::{DVec2, DVec3};
