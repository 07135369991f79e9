use raystep_core::{Aabb, DVec3, Hit, Interval, Ray, Shape};

/// A sphere: the points at distance `radius` from `center`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sphere {
    /// The centre C.
    pub center: DVec3,
    /// The radius r (positive).
    pub radius: f64,
}

impl Sphere {
    /// The sphere with this centre and radius.
    pub const fn new(center: DVec3, radius: f64) -> Sphere {
        Sphere { center, radius }
    }

    /// The outward unit normal at a point on the sphere: (P − C) / r.
    pub fn normal_at(&self, point: DVec3) -> DVec3 {
        (point - self.center) / self.radius
    }
}

/// A sphere as an object of a scene: its hit (exercise 1), and the cube
/// around it.
impl Shape for Sphere {
    fn intersect(&self, ray: &Ray, interval: Interval) -> Option<Hit> {
        Sphere::intersect(self, ray, interval)
    }

    fn bounds(&self) -> Aabb {
        let r = DVec3::splat(self.radius);
        Aabb::new(self.center - r, self.center + r)
    }
}
