//! Held-out cases of chapter 6 for `raystep grade` (see
//! `raystep_check::held_out`): refracted directions into and out of the
//! lecture's materials and any index from 1 to 2.5, at every angle from
//! normal incidence to grazing, past the critical angle (total internal
//! reflection) and clear of it; and Schlick's reflectance for the same.
use std::process::ExitCode;

use ch06::{DVec3, REFRACTIVE_INDICES, refract, schlick};
use raystep_check::held_out::{self, Case, Exercise, Rng, short, show3};

fn main() -> ExitCode {
    held_out::main(&[
        Exercise::new("refraction", refraction_case, 1e-9),
        Exercise::new("schlick", schlick_case, 1e-9),
    ])
}

/// Two indices: the ray's side and the other, from the lecture's table
/// (either way across: into the material from vacuum, out of it), equal,
/// or any two from 1 to 2.5.
fn indices(rng: &mut Rng) -> (f64, f64) {
    match rng.below(5) {
        0 | 1 => {
            let (_, n) =
                REFRACTIVE_INDICES[rng.below(REFRACTIVE_INDICES.len())];
            if rng.chance(0.5) { (1.0, n) } else { (n, 1.0) }
        }
        2 => {
            let n = rng.uniform(1.0, 2.5);
            (n, n)
        }
        _ => (rng.uniform(1.0, 2.5), rng.uniform(1.0, 2.5)),
    }
}

/// An angle of incidence θ: normal (0), any, near grazing (90° − 1e-k),
/// exactly grazing (90°).
fn angle(rng: &mut Rng) -> f64 {
    let right = std::f64::consts::FRAC_PI_2;
    match rng.below(8) {
        0 => 0.0,
        1 => right - 10f64.powf(rng.uniform(-8.0, -1.0)),
        2 => right,
        _ => rng.uniform(0.0, right),
    }
}

/// How far sin²φ = (n_θ/n_φ)²·sin²θ is from 1, relatively: where a ray
/// is within rounding of the critical angle, a correct solution may say
/// either; the cases keep clear of that.
fn clear_of_critical(sin_theta: f64, n_theta: f64, n_phi: f64) -> bool {
    let ratio = n_theta / n_phi;
    let sin2_phi = ratio * ratio * sin_theta * sin_theta;
    (sin2_phi - 1.0).abs() > 1e-7
}

/// T for a unit D at angle θ to a random unit N (on D's side), in a
/// random frame; None past the critical angle.
fn refraction_case(rng: &mut Rng, case: &mut Case) {
    let (n, d, n_theta, n_phi) = loop {
        let (n_theta, n_phi) = indices(rng);
        let theta = angle(rng);
        if !clear_of_critical(theta.sin(), n_theta, n_phi) {
            continue;
        }
        let n = if rng.chance(0.2) {
            let mut n = DVec3::ZERO;
            n[rng.below(3)] = if rng.chance(0.5) { 1.0 } else { -1.0 };
            n
        } else {
            rng.unit_vec3()
        };
        let u = n.cross(rng.unit_vec3()).normalize();
        let d = (theta.sin() * u - theta.cos() * n).normalize();
        // the direction as built: its own angle must be clear too
        let sin_theta = d.cross(n).length();
        if d.dot(n) <= 0.0 && clear_of_critical(sin_theta, n_theta, n_phi) {
            break (n, d, n_theta, n_phi);
        }
    };
    case.ask(format!(
        "refract(D = {}, N = {}, n_θ = {}, n_φ = {})",
        show3(d),
        show3(n),
        short(n_theta),
        short(n_phi)
    ));
    match refract(d, n, n_theta, n_phi) {
        Some(t) => case.vec3("T", t),
        None => case.word("total-internal-reflection"),
    }
}

/// R ≈ R₀ + (1 − R₀)(1 − cos α)⁵ for cos θ in [0, 1]: normal incidence,
/// grazing, any; either way across.
fn schlick_case(rng: &mut Rng, case: &mut Case) {
    let (cos_theta, n_theta, n_phi) = loop {
        let (n_theta, n_phi) = indices(rng);
        let cos_theta = match rng.below(6) {
            0 => 1.0,
            1 => 0.0,
            _ => angle(rng).cos().clamp(0.0, 1.0),
        };
        let sin_theta = (1.0 - cos_theta * cos_theta).max(0.0).sqrt();
        if n_theta <= n_phi || clear_of_critical(sin_theta, n_theta, n_phi) {
            break (cos_theta, n_theta, n_phi);
        }
    };
    case.ask(format!(
        "schlick(cos θ = {}, n_θ = {}, n_φ = {})",
        short(cos_theta),
        short(n_theta),
        short(n_phi)
    ));
    case.num("R", schlick(cos_theta, n_theta, n_phi));
}
