//! # Chapter 6 — refraction
//!
//! The last term of the lecture's formula, kt·Lt: light that comes
//! *through* a transparent surface. The transmitted ray bends by Snell's
//! law, sin θ / sin φ = n_φ / n_θ ([`refract`]), with the indices of
//! refraction of the media on both sides ([`REFRACTIVE_INDICES`]).
//! Past the critical angle ([`critical_angle`]) no light gets through:
//! total internal reflection.
//!
//! A ray leaving an object flips the normal and swaps the indices; with
//! objects inside objects it needs to know what it is in, so every ray
//! carries its [`Media`]. How the light splits between the reflected and
//! the transmitted ray is the lecture's constant kr and kt, or follows
//! the Fresnel equations, exact ([`fresnel`]) or by Schlick's
//! approximation ([`schlick`]).
//!
//! Student mode: with the feature `exercise` the modules marked below are
//! replaced by the stubs in `exercise/`.

mod fresnel;
mod ior;
mod media;
mod trace;

// Exercise 1: the refracted direction.
#[cfg_attr(feature = "exercise", path = "../exercise/refraction.rs")]
mod refraction;
// Exercise 2: Schlick's approximation.
#[cfg_attr(feature = "exercise", path = "../exercise/schlick.rs")]
mod schlick;

pub use ch03::{Object, World};
pub use ch05::{Cut, DEFAULT_STOP, LoggedRay, Path, SAFETY_DEPTH, Stop};
pub use fresnel::{Fresnel, fresnel};
pub use ior::{REFRACTIVE_INDICES, critical_angle, index_of_refraction};
pub use media::{Crossing, MAX_NESTING, Media};
pub use raystep_core::{Camera, DVec3, Hit, Interval, Ray};
pub use raystep_render::{Image, RenderError, RenderOptions};
pub use refraction::refract;
pub use schlick::schlick;
pub use trace::{CAMERA_MEDIUM, RayCounts, Tracer, pixel_tree, render, split};
