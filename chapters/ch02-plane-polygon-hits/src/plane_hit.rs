use crate::ray_plane;
use ch01::Plane;
use raystep_core::{Aabb, Hit, Interval, Ray, Shape};

// ANCHOR: cases
/// What a ray does at a plane: the lecture's cases.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum RayPlane {
    /// It crosses the plane at parameter `t`, inside the query interval.
    Hit(f64),
    /// It crosses the plane at `t`, but outside the interval: behind the
    /// origin (`t < 0`) or beyond the farthest `t` wanted.
    Outside(f64),
    /// It runs parallel to the plane (N·D = 0) and never meets it.
    Parallel,
    /// It lies in the plane: every point is on it, there is no single hit.
    InPlane,
}
// ANCHOR_END: cases

impl RayPlane {
    /// The parameter of an accepted hit.
    pub fn t(self) -> Option<f64> {
        match self {
            RayPlane::Hit(t) => Some(t),
            _ => None,
        }
    }
}

/// The hit of `ray` with `plane` within `interval`, if any.
pub fn intersect_plane(
    plane: &Plane,
    ray: &Ray,
    interval: Interval,
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
