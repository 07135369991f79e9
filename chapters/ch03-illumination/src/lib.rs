//! # Chapter 3 — illumination
//!
//! The lecture's ray tracer in its first form: for each pixel shoot a ray,
//! for each object ask whether the ray hits it, keep the closest hit, and
//! shade that point with the local model
//!
//! L = ka·Ia + Σᵢ Sᵢ·Iᵢ·[kd·(N·Lᵢ) + ks·(Rᵢ·V)^p] (+ kr·Lr + kt·Lt later).
//!
//! "For each object" is [`BruteForce`], the first implementation of the
//! world's [`Accelerator`]: the tracer asks [`World::closest_hit`], and
//! the speed-up chapters answer the same question faster. [`world`] builds
//! a scene file's world from the shapes taught so far.
//!
//! Student mode: with the feature `exercise` the modules marked below are
//! replaced by the stubs in `exercise/`.

mod brute_force;
mod shading;
mod sphere;
mod trace;
mod world;

// Exercise 1: where a ray meets a sphere.
#[cfg_attr(feature = "exercise", path = "../exercise/sphere_hit.rs")]
mod sphere_hit;
// Exercise 2: the reflection Rᵢ of the light direction.
#[cfg_attr(feature = "exercise", path = "../exercise/reflect.rs")]
mod reflect;
// Exercise 3: the local illumination sum.
#[cfg_attr(feature = "exercise", path = "../exercise/local_shading.rs")]
mod local_shading;

pub use brute_force::BruteForce;
pub use local_shading::shading_terms;
pub use raystep_core::{Aabb, Camera, DVec3, Hit, Interval, Ray, Shape};
pub use raystep_render::{Image, RenderOptions};
pub use raystep_scene::{Light, Material, Scene};
pub use raystep_world::{Accelerator, Object, World, WorldError};
pub use reflect::reflect_light;
pub use shading::{LightSample, ShadingTerms};
pub use sphere::Sphere;
pub use trace::{
    Terms, render, render_with, shade, shade_hit, shade_with, trace,
};
pub use world::{load, parse, shape, world};
