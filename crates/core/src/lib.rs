//! The few types every chapter of the raystep lecture shares.
//!
//! * [`Ray`]: a half-line `P(t) = origin + t·direction`; [`Ray32`], the
//!   same in single precision, as the mesh structures are asked.
//! * [`Interval`]: the range of `t` a query accepts (`t_min..t_max`).
//! * [`Hit`]: where a ray met a surface: `t`, the point and the unit normal.
//! * [`Camera`]: a pinhole camera that makes one ray per pixel.
//! * [`Aabb`]: an axis-aligned box, and the robust ray–box (slab) test.
//! * [`Shape`]: what every surface answers: its hit, and its bounds.
//!
//! All geometry is in `f64` ([`DVec3`], [`DVec2`]): the lecture tests its
//! methods at coordinates from 1e-6 to 1e6 and beyond, where `f32` would
//! hide the effects we want to show behind its own rounding.
#![deny(missing_docs)]

mod bounds;
mod camera;
mod hit;
mod interval;
mod ray;
mod ray32;
mod shape;

pub use bounds::Aabb;
pub use camera::Camera;
pub use hit::Hit;
pub use interval::Interval;
pub use ray::Ray;
pub use ray32::Ray32;
pub use shape::Shape;

/// glam, re-exported so chapters use the same version of it.
pub use glam;
pub use glam::{DAffine3, DVec2, DVec3};
