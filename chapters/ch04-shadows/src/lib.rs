//! # Chapter 4 — shadows
//!
//! Chapter 3 lit every point by every light (Sᵢ = 1). Here Sᵢ comes from a
//! *shadow ray*: from the hit point toward light i. If anything lies on
//! it before the light, the point is in shadow, Sᵢ = 0; otherwise Sᵢ = 1.
//!
//! The question a shadow ray asks is weaker than a primary ray's: not
//! "what is the closest hit?" but "is there any hit at all?", so the loop
//! over the objects stops at the first blocker ([`occluded`]).
//!
//! The catch is where the shadow ray starts. The hit point is rounded, so
//! it lies a little above or below the surface it came from, and a shadow
//! ray from below finds that very surface at t ≈ 0: the point shadows
//! itself, a speckle called *shadow acne*. [`Offset`] names three ways
//! around it, [`shadow_ray`] builds the ray for each, and
//! [`shadow_errors`] counts how often each one gets a pixel wrong in
//! [`scaled_scene`] made tiny or huge.
//!
//! Student mode: with the feature `exercise` the modules marked below are
//! replaced by the stubs in `exercise/`.

mod occluded;
mod offset;
mod scale_aware;
mod scenes;
mod shadow_errors;
mod trace;

// Exercise 1: Sᵢ, the visibility of one light from a hit.
#[cfg_attr(feature = "exercise", path = "../exercise/shadow.rs")]
mod shadow;
// Exercise 2: the shadow ray that starts a little off the surface.
#[cfg_attr(feature = "exercise", path = "../exercise/normal_offset.rs")]
mod normal_offset;

pub use ch03::{Object, ShadingTerms, World};
pub use normal_offset::normal_offset_ray;
pub use occluded::occluded;
pub use offset::{Offset, shadow_ray};
pub use raystep_core::{Camera, DVec3, Hit, Interval, Ray, Shape};
pub use raystep_render::{Image, RenderError, RenderOptions};
pub use raystep_scene::Light;
pub use scale_aware::{FLOAT_SCALE, INT_SCALE, ORIGIN, offset_scale_aware};
pub use scenes::{ACNE_SCENE, TWO_LIGHTS_SCENE, scaled, scaled_scene};
pub use shadow::shadow;
pub use shadow_errors::{ShadowErrors, Verdict, shadow_errors, verdict};
pub use trace::{render, shade, trace};
