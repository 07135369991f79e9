//! Exercise 3: the lecture's local illumination model.
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
    // Step 1: the ambient term ka·Ia.
    let mut terms = ShadingTerms {
        ambient: material.ka * ambient,
        ..ShadingTerms::default()
    };
    for light in lights {
        // Step 2: N·Lᵢ, the cosine of the light's angle of incidence.
        let n_dot_l = normal.dot(light.direction);
        if n_dot_l <= 0.0 {
            continue; // the light is behind the surface
        }
        let incoming = light.visibility * light.intensity;
        // Step 3: diffuse, kd·(N·Lᵢ).
        terms.diffuse += incoming * material.kd * n_dot_l;
        // Step 4: specular, ks·(Rᵢ·V)^p with Rᵢ the mirrored Lᵢ.
        let r_dot_v =
            reflect_light(light.direction, normal).dot(to_eye).max(0.0);
        terms.specular += incoming * material.ks * r_dot_v.powf(material.p);
    }
    terms
}
// ANCHOR_END: shading_terms
