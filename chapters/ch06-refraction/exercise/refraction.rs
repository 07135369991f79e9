//! Exercise 1 (★★): the refracted direction, by Snell's law.
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
    // TODO:
    // 1. cos θ = −D·N; sin²φ = (n_θ/n_φ)²·(1 − cos²θ) by Snell's law.
    // 2. If sin²φ > 1 there is no refracted ray: return None.
    // 3. Otherwise T = η·(D + cos θ·N) − cos φ·N with η = n_θ/n_φ and
    //    cos φ = √(1 − sin²φ).
    let _ = (d, n, n_theta, n_phi);
    todo!("ch06 exercise 1: refract")
}
// ANCHOR_END: refract
