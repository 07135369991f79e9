use raystep_core::{Aabb, DVec3, Interval, Ray};

/// A sphere used as a bounding volume: only "does the ray come near?"
/// is asked of it, never a normal.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BoundingSphere {
    /// Its centre.
    pub center: DVec3,
    /// Its radius, `≥ 0`.
    pub radius: f64,
}

impl BoundingSphere {
    /// The box's circumsphere: centred on the box, through its corners.
    pub fn around_box(b: &Aabb) -> BoundingSphere {
        BoundingSphere {
            center: 0.5 * (b.min + b.max),
            radius: 0.5 * (b.max - b.min).length(),
        }
    }

    /// The circumsphere of the points' box: the quick bounding sphere, to
    /// compare with a tight one ([`crate::sphere_of_points`]). No points:
    /// radius 0 at the origin.
    pub fn around_points_by_box(points: &[DVec3]) -> BoundingSphere {
        if points.is_empty() {
            return BoundingSphere {
                center: DVec3::ZERO,
                radius: 0.0,
            };
        }
        BoundingSphere::around_box(&Aabb::around(points.iter().copied()))
    }

    /// Is `p` inside or on it?
    pub fn contains(&self, p: DVec3) -> bool {
        (p - self.center).length_squared() <= self.radius * self.radius
    }

    /// The part of `interval` in which `ray` is inside the sphere, or None.
    pub fn hit(&self, ray: &Ray, interval: Interval) -> Option<Interval> {
        // The same quadratic as chapter 3's sphere, in its stable form.
        let oc = ray.origin - self.center;
        let a = ray.direction.length_squared();
        let half_b = oc.dot(ray.direction);
        // c from the part of oc across the ray: no cancellation when the
        // origin is far away.
        let across = oc - (half_b / a) * ray.direction;
        let discriminant =
            a * (self.radius * self.radius - across.length_squared());
        if discriminant.is_nan() || discriminant < 0.0 {
            return None; // a miss (NaN: a ray with a NaN in it)
        }
        let root = discriminant.sqrt();
        let (t0, t1) = ((-half_b - root) / a, (-half_b + root) / a);
        let inside = Interval::new(t0.max(interval.min), t1.min(interval.max));
        (!inside.is_empty()).then_some(inside)
    }
}
