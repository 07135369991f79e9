//! # Chapter 05 — reflection
//!
//! The lecture's formula has a term the local model of chapters 03–04
//! left out: kr·Lr, the light Lr that arrives along the mirror direction,
//! scaled by the surface's reflectance kr. Lr is whatever a ray shot in
//! that direction sees, so the tracer calls itself: a *recursive* ray,
//! R = D − 2(D·N)N ([`reflect_direction`]).
//!
//! Recursion needs a rule to stop. The lecture gives two ([`Stop`]):
//! a maximum depth, or a ray's *contribution*, the product of the k's
//! along its path ([`Path::weight`]), falling below a threshold. The
//! tracer counts the rays each rule spends ([`RayCounts`]) and can keep
//! one pixel's whole ray tree for a figure ([`RayLog::recording`]).
//!
//! Student mode: with the feature `exercise` the modules marked below are
//! replaced by the stubs in `exercise/`.

pub mod chart;
mod local;
mod log;
pub mod measure;
mod render;
mod stop;

// Exercise 1: the reflected direction.
#[cfg_attr(feature = "exercise", path = "../exercise/reflection.rs")]
mod reflection;
// Exercise 2: the recursion with both stopping rules.
#[cfg_attr(feature = "exercise", path = "../exercise/recursion.rs")]
mod recursion;

pub mod figures;

pub use ch03::{Object, Shape, World};
pub use local::local_light;
pub use log::{LoggedRay, RayCounts, RayKind, RayLog};
pub use raystep_core::{Camera, DVec3, Hit, Interval, Ray};
pub use raystep_render::{Image, RenderError, RenderOptions};
pub use recursion::trace;
pub use reflection::reflect_direction;
pub use render::{pixel_tree, render};
pub use stop::{Cut, DEFAULT_STOP, Path, SAFETY_DEPTH, Stop};
