//! Exercise 1: the refracted direction, by Snell's law.
use raystep_core::DVec3;

// ANCHOR: refract
/// The direction T of the refracted ray, or None on total internal
/// reflection.
///
/// `d` is the unit direction D of the incoming ray and `n` the unit normal
/// N on its side (N·D ≤ 0). The ray travels in a medium of index
/// `n_theta` and enters one of index `n_phi`. With θ the angle between −D
/// and N and φ the angle between T and −N, Snell's law in the lecture's
/// notation is
///
/// sin θ / sin φ = n_φ / n_θ.
///
/// T is a unit vector, in the plane of D and N.
pub fn refract(d: DVec3, n: DVec3, n_theta: f64, n_phi: f64) -> Option<DVec3> {
    // Step 1: cos θ, and sin²φ from Snell: sin φ = (n_θ/n_φ)·sin θ.
    let eta = n_theta / n_phi;
    let cos_theta = (-d.dot(n)).min(1.0);
    let sin2_phi = eta * eta * (1.0 - cos_theta * cos_theta).max(0.0);
    // Step 2: past the critical angle there is no φ: total internal
    // reflection, no transmitted ray.
    if sin2_phi > 1.0 {
        return None;
    }
    let cos_phi = (1.0 - sin2_phi).sqrt();
    // Step 3: T = η·(D + cos θ·N) − cos φ·N: D's part along the surface
    // scaled by η (that is Snell's law), plus cos φ straight into the
    // surface.
    Some(eta * (d + cos_theta * n) - cos_phi * n)
}
// ANCHOR_END: refract
