use raystep_core::DVec3;

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
