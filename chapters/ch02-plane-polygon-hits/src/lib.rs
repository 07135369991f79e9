//! # Chapter 2 — plane and polygon hits
//!
//! A ray `P(t) = P₀ + t·D` meets the plane `N·P + d = 0` at
//! `t = −(N·P₀ + d) / (N·D)`. Whether the hit is inside a polygon lying
//! in that plane is a 2D question: drop the coordinate the normal points
//! along most, and test the projected point against the projected edges,
//! each edge an implicit line from chapter 1.
//!
//! Student mode: with the feature `exercise` the modules marked below are
//! replaced by the stubs in `exercise/`.

mod crossing;
mod fill_rule;
mod hit_map;
mod plane_hit;
mod polygon;
mod project;
mod ray_plane_cases;
mod rounding;

// Exercise 1: where a ray meets a plane, and the cases where it does not.
#[cfg_attr(feature = "exercise", path = "../exercise/ray_plane.rs")]
mod ray_plane;
// Exercise 2: is a point inside a convex polygon (the edge test)?
#[cfg_attr(feature = "exercise", path = "../exercise/inside_polygon.rs")]
mod inside_polygon;

pub use ch01::{Degenerate, Line2, Plane};
pub use crossing::inside_crossing;
pub use fill_rule::owns_boundary;
pub use hit_map::{HitMap, closest_hit, demo_camera, demo_scene, hit_map};
pub use inside_polygon::{edge_function, inside_convex};
pub use plane_hit::{InfinitePlane, intersect_plane};
pub use polygon::{Polygon, PolygonError};
pub use project::{dominant_axis, project};
pub use ray_plane::ray_plane;
pub use ray_plane_cases::RayPlane;
pub use raystep_core::{Aabb, Camera, DVec2, DVec3, Hit, Interval, Ray, Shape};
pub use rounding::zero_within_rounding;
