//! Exercise 2: Schlick's approximation of the Fresnel reflectance.

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
    // Step 1: R₀ at normal incidence.
    let r0 = ((n_theta - n_phi) / (n_theta + n_phi)).powi(2);
    // Step 2: cos α, the angle on the less dense side.
    let cos_theta = cos_theta.clamp(0.0, 1.0);
    let cos_alpha = if n_theta <= n_phi {
        cos_theta
    } else {
        let sin2_phi =
            (n_theta / n_phi).powi(2) * (1.0 - cos_theta * cos_theta);
        if sin2_phi >= 1.0 {
            return 1.0; // total internal reflection
        }
        (1.0 - sin2_phi).sqrt()
    };
    // Step 3: the fifth-power rise from R₀ toward 1.
    r0 + (1.0 - r0) * (1.0 - cos_alpha).powi(5)
}
// ANCHOR_END: schlick
