//! The lecture's refractive indices, which a scene's `ior` may name.

/// The lecture's table of refractive indices, usable by name as `ior`.
pub const REFRACTIVE_INDICES: [(&str, f64); 7] = [
    ("vacuum", 1.0),
    ("air", 1.0003),
    ("water", 1.33),
    ("glass", 1.5),
    ("ice", 1.309),
    ("quartz", 1.544),
    ("diamond", 2.417),
];

/// The index of refraction of a material in [`REFRACTIVE_INDICES`], by
/// name (ASCII case does not matter).
///
/// ```
/// assert_eq!(raystep_scene::index_of_refraction("water"), Some(1.33));
/// assert_eq!(raystep_scene::index_of_refraction("Glass"), Some(1.5));
/// assert_eq!(raystep_scene::index_of_refraction("jelly"), None);
/// ```
pub fn index_of_refraction(name: &str) -> Option<f64> {
    REFRACTIVE_INDICES
        .iter()
        .find(|(n, _)| n.eq_ignore_ascii_case(name))
        .map(|&(_, ior)| ior)
}
