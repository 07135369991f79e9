use glam::DVec3;

/// Where a ray met a surface.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Hit {
    /// The ray parameter of the hit: the point is `ray.at(t)`.
    pub t: f64,
    /// The hit point.
    pub point: DVec3,
    /// The surface's unit normal at the hit, as the surface defines it
    /// (a plane's N, a sphere's outward normal): not flipped toward the ray.
    pub normal: DVec3,
}

impl Hit {
    /// The normal turned against `direction`, the direction of the ray that
    /// made the hit: the normal on the side the ray came from, whichever
    /// side of the surface that is.
    pub fn facing(&self, direction: DVec3) -> DVec3 {
        if self.normal.dot(direction) > 0.0 {
            -self.normal
        } else {
            self.normal
        }
    }
}
