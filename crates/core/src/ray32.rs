use glam::Vec3;

use crate::Ray;

/// A ray in single precision, the form of the benchmark's ray files: six
/// `f32`s. Widened to a [`Ray`] exactly (every `f32` is an `f64`).
///
/// What the mesh structures (chapters 8–11 and the benchmark's peers) are
/// asked with, through `raystep_world::MeshAccelerator`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ray32 {
    /// Where it starts.
    pub origin: Vec3,
    /// Where it goes (any length, not zero).
    pub direction: Vec3,
}

impl Ray32 {
    /// `ray` rounded to single precision.
    pub fn rounded(ray: &Ray) -> Ray32 {
        Ray32 {
            origin: ray.origin.as_vec3(),
            direction: ray.direction.as_vec3(),
        }
    }

    /// The same ray in double precision, exactly.
    pub fn to_ray(self) -> Ray {
        Ray::new(self.origin.as_dvec3(), self.direction.as_dvec3())
    }

    /// Are all six numbers finite, and the direction not zero? Other rays
    /// are answered "no hit" without being traced.
    pub fn is_valid(&self) -> bool {
        self.origin.is_finite()
            && self.direction.is_finite()
            && self.direction != Vec3::ZERO
    }
}
