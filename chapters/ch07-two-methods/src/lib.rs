//! # Chapter 7 — two rendering methods
//!
//! The lecture's two loops, on the same triangles, with the same camera and
//! the same shading:
//!
//! * **rasterization** — for each object, for each pixel in its
//!   projection, test the z-value, shade: [`rasterize`];
//! * **ray casting** — for each pixel, shoot a ray, for each object test
//!   it, keep the closest, shade: [`raycast`].
//!
//! Both write colour, depth and object-id [`Buffers`]; [`compare`] checks
//! that their ids differ only on edges, where the two sampling rules meet.
//!
//! Student mode: with the feature `exercise` the modules marked below are
//! replaced by the stubs in `exercise/`.

mod agree;
mod buffers;
mod clip;
mod depth_buffer;
mod project;
mod raster;
mod raycast;
mod scenes;
mod shade;
mod stage;

// Exercise 1: the edge functions and the fill rule.
#[cfg_attr(feature = "exercise", path = "../exercise/coverage.rs")]
mod coverage;
// Exercise 2: the depth test, and depth interpolated under perspective.
#[cfg_attr(feature = "exercise", path = "../exercise/depth_test.rs")]
mod depth_test;

pub use agree::{Agreement, ON_EDGE, compare, edge_distance};
pub use buffers::Buffers;
pub use ch03::{Object, World};
pub use clip::{NEAR, clip_near};
pub use coverage::{barycentric, covers};
pub use depth_buffer::DepthBuffer;
pub use depth_test::perspective_depth;
pub use project::Projection;
pub use raster::{RasterCounts, rasterize};
pub use raycast::raycast;
pub use raystep_core::{Camera, DVec2, DVec3, Ray};
pub use raystep_render::Image;
pub use raystep_scene::{Mesh, MeshError};
pub use scenes::{SHAPES, shapes};
pub use shade::shade_pixel;
pub use stage::{Stage, StageError, Triangle};
