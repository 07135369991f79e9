//! Deterministic random numbers, the same on every machine: what the
//! random lines of the tightness measurements are drawn from.
use std::f64::consts::TAU;

use raystep_core::DVec3;

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
