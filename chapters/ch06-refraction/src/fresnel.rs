//! How much light a dielectric surface reflects: the exact Fresnel
//! equations, and the choice of formula for the tracer.
use crate::schlick;

// ANCHOR: fresnel
/// The fraction R of unpolarised light reflected where a ray meets the
/// surface between index `n_theta` (its side) and `n_phi` at angle θ,
/// `cos_theta` = cos θ ∈ [0, 1]. The rest, 1 − R, is transmitted.
///
/// The Fresnel equations for the two polarisations, with φ from Snell's
/// law, averaged:
///
/// rₛ = (n_θ cos θ − n_φ cos φ) / (n_θ cos θ + n_φ cos φ)
/// rₚ = (n_φ cos θ − n_θ cos φ) / (n_φ cos θ + n_θ cos φ)
/// R = (rₛ² + rₚ²) / 2
///
/// Past the critical angle R = 1: total internal reflection. With the
/// same index on both sides there is no surface: R = 0 (below 90°).
pub fn fresnel(cos_theta: f64, n_theta: f64, n_phi: f64) -> f64 {
    // Step 1: cos²φ = 1 − sin²φ = 1 − η²(1 − cos²θ) by Snell's law
    // (η = n_θ/n_φ), summed as (1 − η²) + η²cos²θ: near 90°, 1 − cos²θ
    // rounds to 1 and cos φ would come out 0; this way cos²φ is cos²θ
    // itself when η = 1.
    let cos_theta = cos_theta.clamp(0.0, 1.0);
    let eta2 = (n_theta / n_phi).powi(2);
    let cos2_phi = (1.0 - eta2) + eta2 * cos_theta * cos_theta;
    // Step 2: no φ past the critical angle: total internal reflection.
    if cos2_phi <= 0.0 {
        return 1.0;
    }
    // Step 3: the two polarisations' amplitudes, and their mean power.
    let cos_phi = cos2_phi.sqrt();
    let rs = (n_theta * cos_theta - n_phi * cos_phi)
        / (n_theta * cos_theta + n_phi * cos_phi);
    let rp = (n_phi * cos_theta - n_theta * cos_phi)
        / (n_phi * cos_theta + n_theta * cos_phi);
    0.5 * (rs * rs + rp * rp)
}
// ANCHOR_END: fresnel

// ANCHOR: fresnel_choice
/// How the tracer splits a transparent surface's kt between the reflected
/// and the transmitted ray.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Fresnel {
    /// The lecture's formula as written: kr·Lr + kt·Lt, constant k's.
    Off,
    /// kt·R of the light goes to the reflected ray and kt·(1 − R) to the
    /// transmitted one, R from the exact equations ([`fresnel`]).
    Exact,
    /// The same split with Schlick's approximation of R ([`schlick`]).
    Schlick,
}

impl Fresnel {
    /// R for this choice (0 for `Off`).
    pub fn reflectance(self, cos_theta: f64, n_theta: f64, n_phi: f64) -> f64 {
        match self {
            Fresnel::Off => 0.0,
            Fresnel::Exact => fresnel(cos_theta, n_theta, n_phi),
            Fresnel::Schlick => schlick(cos_theta, n_theta, n_phi),
        }
    }
}
// ANCHOR_END: fresnel_choice
