//! The lecture's table of indices of refraction, and the critical angle.
pub use raystep_scene::{REFRACTIVE_INDICES, index_of_refraction};

// ANCHOR: critical_angle
/// The critical angle θc for light going from index `n_theta` into index
/// `n_phi`, in radians: sin θc = n_φ / n_θ. Past it Snell's law asks for
/// sin φ > 1 and all the light is reflected (total internal reflection).
/// None when n_θ ≤ n_φ: going into a denser medium, every angle refracts.
pub fn critical_angle(n_theta: f64, n_phi: f64) -> Option<f64> {
    (n_theta > n_phi).then(|| (n_phi / n_theta).asin())
}
// ANCHOR_END: critical_angle
