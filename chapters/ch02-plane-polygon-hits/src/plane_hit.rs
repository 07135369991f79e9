//! A plane as a surface: the hit of a ray, and the plane as a scene's
//! object.
use crate::ray_plane;
use ch01::Plane;
use raystep_core::{Aabb, Hit, Interval, Ray, Shape};

/// The hit of `ray` with `plane` within `interval`, if any.
pub fn intersect_plane(
    plane: &Plane, ray: &Ray, interval: Interval,
) -> Option<Hit> {
    let t = ray_plane(plane, ray, interval).t()?;
    Some(Hit {
        t,
        point: ray.at(t),
        normal: plane.normal,
    })
}

/// A plane as an object of a scene (chapter 3 on): chapter 1's plane, hit
/// by [`intersect_plane`], with no bounds. (A newtype, because the plane
/// itself is chapter 1's and knows nothing of rays.)
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct InfinitePlane(pub Plane);

impl Shape for InfinitePlane {
    fn intersect(&self, ray: &Ray, interval: Interval) -> Option<Hit> {
        intersect_plane(&self.0, ray, interval)
    }

    fn bounds(&self) -> Aabb {
        Aabb::EVERYTHING
    }
}
