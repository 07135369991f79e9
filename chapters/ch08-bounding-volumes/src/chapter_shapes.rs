//! The fast primitives earlier chapters taught, as this chapter's
//! [`Primitive`]s: chapter 3's sphere and chapter 2's polygon.
use ch02::Polygon;
use ch03::Sphere;
use raystep_core::{Aabb, DVec3, Shape};

use crate::{BoundingSphere, Primitive};

/// Chapter 3's sphere: its own bounding sphere.
impl Primitive for Sphere {
    fn name(&self) -> &'static str {
        "sphere"
    }

    fn bounding_sphere(&self) -> BoundingSphere {
        BoundingSphere {
            center: self.center,
            radius: self.radius,
        }
    }
}

/// Chapter 2's polygon: the sphere around the centre of its box through
/// the vertex farthest from it, which is never larger than the box's
/// circumsphere and usually smaller.
impl Primitive for Polygon {
    fn name(&self) -> &'static str {
        "polygon"
    }

    fn bounding_sphere(&self) -> BoundingSphere {
        sphere_around(&self.bounds(), self.vertices())
    }
}

/// The sphere centred on the box `b` of `points` through the point
/// farthest from that centre. It contains every point, so the convex hull
/// of them too (a polygon, a triangle).
pub(crate) fn sphere_around(b: &Aabb, points: &[DVec3]) -> BoundingSphere {
    let center = 0.5 * (b.min + b.max);
    let farthest = points
        .iter()
        .map(|&p| p.distance(center))
        .fold(0.0, f64::max);
    BoundingSphere {
        center,
        // a hair larger, so rounding in `contains` never leaves the
        // farthest point out
        radius: farthest * (1.0 + 4.0 * f64::EPSILON),
    }
}
