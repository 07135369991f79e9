//! Random lines through a sphere, the same on every machine: the rays of
//! the tightness measurements.
use std::f64::consts::TAU;

use raystep_core::{DVec3, Ray};

use crate::BoundingSphere;

/// SplitMix64 (Steele, Lea & Flood, 2014): a few lines of deterministic
/// random numbers, the same on every machine for the same seed.
#[derive(Clone, Debug)]
pub struct SplitMix64(u64);

impl SplitMix64 {
    /// The generator started from `seed`.
    pub fn new(seed: u64) -> SplitMix64 {
        SplitMix64(seed)
    }

    /// The next 64 random bits.
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// A number in `[0, 1)`, uniformly.
    pub fn next_f64(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64
    }

    /// A unit vector, uniformly over directions: z = 1 − 2u is uniform on
    /// a sphere (Archimedes), the angle around z uniform too.
    pub fn unit_vector(&mut self) -> DVec3 {
        let z = 1.0 - 2.0 * self.next_f64();
        let phi = TAU * self.next_f64();
        let ring = (1.0 - z * z).max(0.0).sqrt();
        DVec3::new(ring * phi.cos(), ring * phi.sin(), z)
    }
}

// ANCHOR: random_lines
/// Rays along random lines that meet `sphere`, uniformly: every line
/// through the sphere is as likely as any other (the measure of lines
/// that integral geometry uses). Then the chance that a line hits a
/// convex object inside the sphere is the object's surface area over the
/// sphere's (Cauchy–Crofton): 1/3 for a sphere in its box's circumsphere,
/// π/6 for a sphere in its box.
///
/// Each ray starts outside the sphere, so `t ≥ 0` covers all of it.
/// An endless iterator: take as many rays as you need.
#[derive(Clone, Debug)]
pub struct RandomLines {
    sphere: BoundingSphere,
    random: SplitMix64,
}

impl RandomLines {
    /// The lines meeting `sphere`, drawn with this seed.
    pub fn new(sphere: BoundingSphere, seed: u64) -> RandomLines {
        RandomLines {
            sphere,
            random: SplitMix64::new(seed),
        }
    }
}

impl Iterator for RandomLines {
    type Item = Ray;

    fn next(&mut self) -> Option<Ray> {
        let BoundingSphere { center, radius } = self.sphere;
        // Step 1: a direction, uniformly over the unit sphere.
        let direction = self.random.unit_vector();
        // Step 2: a point uniformly on the disc through the centre,
        // perpendicular to it (√u for the distance: uniform in area).
        let (u, v) = direction.any_orthonormal_pair();
        let r = radius * self.random.next_f64().sqrt();
        let angle = TAU * self.random.next_f64();
        let on_disc = center + r * (angle.cos() * u + angle.sin() * v);
        // Step 3: start the ray well before the sphere.
        Some(Ray::new(on_disc - 2.0 * radius * direction, direction))
    }
}
// ANCHOR_END: random_lines
