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
