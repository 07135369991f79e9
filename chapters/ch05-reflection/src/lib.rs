//! # Chapter 5 — reflection
//!
//! The lecture's formula has a term the local model of chapters 3–4
//! left out: kr·Lr, the light Lr that arrives along the mirror direction,
//! scaled by the surface's reflectance kr. Lr is whatever a ray shot in
//! that direction sees, so the tracer calls itself: a *recursive* ray,
//! R = D − 2(D·N)N ([`reflect_ray`]).
//!
//! Recursion needs a rule to stop. The lecture gives two ([`Stop`]):
//! a maximum depth, or a ray's *contribution*, the product of the k's
//! along its path ([`Path::weight`]), falling below a threshold. A
//! [`Tracer`] carries one pixel's trace: it counts the rays each rule
//! spends ([`RayCounts`]) and can keep the pixel's whole ray tree for a
//! figure ([`Tracer::recording`]).
//!
//! Student mode: with the feature `exercise` the modules marked below are
//! replaced by the stubs in `exercise/`.

mod ray_tree;
mod stop;
mod trace;

// Exercise 1: the reflected direction.
#[cfg_attr(feature = "exercise", path = "../exercise/reflection.rs")]
mod reflection;
// Exercise 2: the recursion with both stopping rules.
#[cfg_attr(feature = "exercise", path = "../exercise/recursion.rs")]
mod recursion;

pub use ch03::{Object, World};
pub use ray_tree::{LoggedRay, RayCounts, RayLog};
pub use raystep_core::{Camera, DVec3, Hit, Interval, Ray};
pub use raystep_render::{Image, RenderError, RenderOptions};
pub use reflection::reflect_ray;
pub use stop::{Cut, DEFAULT_STOP, Path, SAFETY_DEPTH, Stop};
pub use trace::{Tracer, pixel_tree, ray_tree, render, trace_counted};
