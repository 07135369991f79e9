//! Exercise 2 (★): Schlick's approximation of the Fresnel reflectance.

// ANCHOR: schlick
/// Schlick's approximation of [`fresnel`](crate::fresnel):
///
/// R ≈ R₀ + (1 − R₀)·(1 − cos α)⁵,  R₀ = ((n_θ − n_φ) / (n_θ + n_φ))²
///
/// R₀ is the exact reflectance at normal incidence. α is the angle on the
/// *less dense* side: θ when the ray goes into the denser medium
/// (n_θ ≤ n_φ), else the refracted angle φ. Taking θ there would put the
/// steep rise at the wrong angle, since R reaches 1 at the critical angle,
/// not at 90°. Past the critical angle R = 1.
pub fn schlick(cos_theta: f64, n_theta: f64, n_phi: f64) -> f64 {
    // TODO:
    // 1. R₀ = ((n_θ − n_φ) / (n_θ + n_φ))².
    // 2. cos α = cos θ if n_θ ≤ n_φ; otherwise cos φ from Snell's law,
    //    sin²φ = (n_θ/n_φ)²·(1 − cos²θ), and if sin²φ ≥ 1 return 1.
    // 3. R₀ + (1 − R₀)·(1 − cos α)⁵.
    let _ = (cos_theta, n_theta, n_phi);
    todo!("ch06 exercise 2: schlick")
}
// ANCHOR_END: schlick
