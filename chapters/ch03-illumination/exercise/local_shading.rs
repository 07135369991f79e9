//! Exercise 3 (★★): the lecture's local illumination model.
//!
//! Fill in `shading_terms`; `cargo run --release -- check ch03` judges it.
use crate::{LightSample, ShadingTerms, reflect_light};
use raystep_core::DVec3;
use raystep_scene::Material;

// ANCHOR: shading_terms
/// The local model at a surface point, term by term:
///
/// L = ka·Ia + Σᵢ Sᵢ·Iᵢ·[kd·(N·Lᵢ) + ks·(Rᵢ·V)^p]
///
/// `normal` is N and `to_eye` is V, both unit vectors pointing away from
/// the surface. A light behind the surface (N·Lᵢ ≤ 0) adds nothing, and a
/// reflection pointing away from the eye (Rᵢ·V < 0) adds no highlight:
/// the formula's products would go negative there, and light cannot.
pub fn shading_terms(
    material: &Material, normal: DVec3, to_eye: DVec3, ambient: DVec3,
    lights: &[LightSample],
) -> ShadingTerms {
    // TODO: ambient = ka·Ia (component-wise: DVec3 * DVec3 multiplies per
    // channel). For each light with N·Lᵢ > 0 add Sᵢ·Iᵢ·kd·(N·Lᵢ) to diffuse
    // and Sᵢ·Iᵢ·ks·max(Rᵢ·V, 0)^p to specular, with Rᵢ = reflect_light(Lᵢ, N).
    // Skip lights with N·Lᵢ ≤ 0 entirely (no highlight either).
    let _ = (material, normal, to_eye, ambient, lights, reflect_light);
    todo!()
}
// ANCHOR_END: shading_terms
