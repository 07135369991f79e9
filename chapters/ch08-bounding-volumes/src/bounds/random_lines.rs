//! Random lines through a sphere, the same on every machine: the rays of
//! the tightness measurements.
use std::f64::consts::TAU;

use raystep_core::Ray;

use crate::{BoundingSphere, SplitMix64};

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
