use raystep_core::{Aabb, DVec3, Hit, Interval, Ray, Shape};

use super::sphere_roots::sphere_roots;
use crate::{BoundingSphere, Primitive};

/// A capped cylinder: the points within `radius` of the segment from
/// `base` to `top`, with flat discs at both ends. Its axis may point any
/// way.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Cylinder {
    base: DVec3,
    top: DVec3,
    radius: f64,
    /// The unit vector from `base` to `top`.
    axis: DVec3,
    /// The distance from `base` to `top`.
    height: f64,
}

impl Cylinder {
    /// The cylinder around the segment `base`–`top`; refused unless the
    /// points are finite and distinct and the radius positive and finite.
    pub fn new(
        base: DVec3, top: DVec3, radius: f64,
    ) -> Result<Cylinder, String> {
        if !base.is_finite() {
            return Err(format!("base: must be finite, got {base}"));
        }
        if !top.is_finite() {
            return Err(format!("top: must be finite, got {top}"));
        }
        if !(radius > 0.0 && radius.is_finite()) {
            return Err(format!(
                "radius: must be positive and finite, got {radius}"
            ));
        }
        let height = (top - base).length();
        if !(height > 0.0 && height.is_finite()) {
            return Err(format!(
                "top: must differ from base (a cylinder needs an axis), got \
                 {top} for both"
            ));
        }
        Ok(Cylinder {
            base,
            top,
            radius,
            axis: (top - base) / height,
            height,
        })
    }

    /// The centre of the bottom disc.
    pub fn base(&self) -> DVec3 {
        self.base
    }

    /// The centre of the top disc.
    pub fn top(&self) -> DVec3 {
        self.top
    }

    /// The radius of the discs and of the side.
    pub fn radius(&self) -> f64 {
        self.radius
    }

    // ANCHOR: intersect
    /// The first hit of `ray` with the side or a cap in `interval`.
    pub fn intersect(&self, ray: &Ray, interval: Interval) -> Option<Hit> {
        // Step 1: the ray in the frame of the axis: heights z along it and
        // the parts o, d across it (perpendicular to the axis).
        let from_base = ray.origin - self.base;
        let z0 = from_base.dot(self.axis);
        let dz = ray.direction.dot(self.axis);
        let o = from_base - z0 * self.axis;
        let d = ray.direction - dz * self.axis;
        // Step 2: the side, |o + t·d|² = r², between the caps.
        let r = self.radius;
        let side = sphere_roots(o, d, r)
            .into_iter()
            .flatten()
            .filter(|&t| (0.0..=self.height).contains(&(z0 + t * dz)))
            .map(|t| (t, None));
        // Step 3: the caps, the planes z = 0 and z = h, inside the discs;
        // each with its normal, −axis at the base and +axis at the top.
        let caps = [(0.0, -self.axis), (self.height, self.axis)]
            .into_iter()
            .map(|(z, normal)| ((z - z0) / dz, Some(normal)))
            .filter(|&(t, _)| (o + t * d).length_squared() <= r * r);
        // Step 4: the nearest of them in the interval.
        let (t, cap_normal) = side
            .chain(caps)
            .filter(|&(t, _)| interval.contains(t))
            .min_by(|a, b| a.0.total_cmp(&b.0))?;
        // Step 5: the normal: the cap's, or on the side the part of the
        // hit point across the axis, o + t·d, scaled to unit length.
        let normal = cap_normal.unwrap_or_else(|| (o + t * d).normalize());
        Some(Hit {
            t,
            point: ray.at(t),
            normal,
        })
    }
    // ANCHOR_END: intersect
}

/// A cylinder as an object of a scene: its hit, and the tight box of its
/// two cap discs.
impl Shape for Cylinder {
    fn intersect(&self, ray: &Ray, interval: Interval) -> Option<Hit> {
        Cylinder::intersect(self, ray, interval)
    }

    fn bounds(&self) -> Aabb {
        // A disc of radius r around the unit axis a reaches ±r·√(1 − aᵢ²)
        // along axis i. Written as √(aⱼ² + aₖ²), which is the same for a
        // unit a, it does not cancel when aᵢ is close to 1.
        let a = self.axis;
        let reach = DVec3::new(
            (a.y * a.y + a.z * a.z).sqrt(),
            (a.z * a.z + a.x * a.x).sqrt(),
            (a.x * a.x + a.y * a.y).sqrt(),
        ) * self.radius;
        Aabb::around([
            self.base - reach,
            self.base + reach,
            self.top - reach,
            self.top + reach,
        ])
    }
}

/// Its bounding sphere is centred halfway up the axis, through the rims
/// of both caps: radius √((h/2)² + r²).
impl Primitive for Cylinder {
    fn name(&self) -> &'static str {
        "cylinder"
    }

    fn bounding_sphere(&self) -> BoundingSphere {
        BoundingSphere {
            center: 0.5 * (self.base + self.top),
            radius: (0.25 * self.height * self.height
                + self.radius * self.radius)
                .sqrt(),
        }
    }
}
