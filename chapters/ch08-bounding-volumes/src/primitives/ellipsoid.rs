use raystep_core::{Aabb, DVec3, Hit, Interval, Ray, Shape};

use super::sphere_roots::sphere_roots;
use crate::{BoundingSphere, Primitive};

/// An axis-aligned ellipsoid: the points p with
/// Σ ((pᵢ − cᵢ) / rᵢ)² = 1, a unit sphere stretched by `radii` along x, y
/// and z.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ellipsoid {
    center: DVec3,
    radii: DVec3,
}

impl Ellipsoid {
    /// The ellipsoid with this centre and these semi-axes; refused unless
    /// the centre is finite and every radius positive and finite.
    pub fn new(center: DVec3, radii: DVec3) -> Result<Ellipsoid, String> {
        if !center.is_finite() {
            return Err(format!("center: must be finite, got {center}"));
        }
        let positive = radii.cmpgt(DVec3::ZERO).all() && radii.is_finite();
        if !positive {
            return Err(format!(
                "radii: must be positive and finite, got {radii}"
            ));
        }
        Ok(Ellipsoid { center, radii })
    }

    /// Its centre.
    pub fn center(&self) -> DVec3 {
        self.center
    }

    /// Its semi-axes along x, y and z.
    pub fn radii(&self) -> DVec3 {
        self.radii
    }

    // ANCHOR: intersect
    /// The first hit of `ray` with the ellipsoid in `interval`.
    pub fn intersect(&self, ray: &Ray, interval: Interval) -> Option<Hit> {
        // Step 1: the ray scaled into the unit sphere's space. Scaling
        // keeps t: the point at t maps to the point at t.
        let o = (ray.origin - self.center) / self.radii;
        let d = ray.direction / self.radii;
        // Step 2: |o + t·d|² = 1, chapter 3's stable quadratic for a unit
        // sphere at the origin.
        let roots = sphere_roots(o, d, 1.0);
        // Step 3: the nearer root in the interval.
        let t = roots
            .into_iter()
            .flatten()
            .filter(|&t| interval.contains(t))
            .min_by(f64::total_cmp)?;
        // Step 4: the normal from the gradient of the implicit function,
        // (p − c) / r² component by component, made unit length.
        let point = ray.at(t);
        let gradient = (point - self.center) / (self.radii * self.radii);
        Some(Hit {
            t,
            point,
            normal: gradient.normalize(),
        })
    }
    // ANCHOR_END: intersect
}

/// An ellipsoid as an object of a scene: its hit, and the box of its
/// semi-axes.
impl Shape for Ellipsoid {
    fn intersect(&self, ray: &Ray, interval: Interval) -> Option<Hit> {
        Ellipsoid::intersect(self, ray, interval)
    }

    fn bounds(&self) -> Aabb {
        Aabb::new(self.center - self.radii, self.center + self.radii)
    }
}

/// Its bounding sphere: around the centre, with the largest semi-axis as
/// radius.
impl Primitive for Ellipsoid {
    fn name(&self) -> &'static str {
        "ellipsoid"
    }

    fn bounding_sphere(&self) -> BoundingSphere {
        BoundingSphere {
            center: self.center,
            radius: self.radii.max_element(),
        }
    }
}
