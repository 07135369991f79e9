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

/// The smallest sphere around a triangle: the sphere on its longest edge
/// as a diameter when the corner opposite that edge has an angle of 90°
/// or more (the corner is then inside it), else the sphere through all
/// three corners, centred on the triangle's circumcentre.
pub(crate) fn triangle_sphere(v: &[DVec3; 3]) -> BoundingSphere {
    // Step 1: the longest edge a–b, and c, the corner facing it.
    let [a, b, c] = [0, 1, 2]
        .map(|k| (v[k], v[(k + 1) % 3], v[(k + 2) % 3]))
        .into_iter()
        .max_by(|x, y| {
            x.0.distance_squared(x.1)
                .total_cmp(&y.0.distance_squared(y.1))
        })
        .map(|(a, b, c)| [a, b, c])
        .unwrap_or(*v);
    // Step 2: a right or obtuse angle at c: the edge's sphere holds c.
    let center = if (a - c).dot(b - c) <= 0.0 {
        0.5 * (a + b)
    } else {
        // Step 3: the circumcentre, a + (|ac|²·n×ab + |ab|²·ac×n) / 2|n|²
        // with n = ab × ac, the normal of the triangle's plane.
        let (ab, ac) = (b - a, c - a);
        let n = ab.cross(ac);
        a + (ac.length_squared() * n.cross(ab)
            + ab.length_squared() * ac.cross(n))
            / (2.0 * n.length_squared())
    };
    let farthest = v.iter().map(|p| p.distance(center)).fold(0.0, f64::max);
    BoundingSphere {
        center,
        // a hair larger, so rounding in `contains` never leaves a corner out
        radius: farthest * (1.0 + 4.0 * f64::EPSILON),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Obtuse and right triangles get the sphere on their longest edge;
    /// an acute one the sphere through its corners (equidistant, centred
    /// in its plane); every corner inside, whatever the order.
    #[test]
    fn the_smallest_sphere_around_a_triangle() {
        let v = DVec3::new;
        let obtuse = [v(0.0, 0.0, 0.0), v(4.0, 0.0, 0.0), v(1.0, 1.0, 0.0)];
        let right = [v(0.0, 3.0, 1.0), v(0.0, 0.0, 1.0), v(4.0, 0.0, 1.0)];
        let acute = [v(0.0, 0.0, 0.0), v(2.0, 0.0, 0.0), v(1.0, 1.5, 0.5)];
        for (corners, center, radius) in [
            (obtuse, v(2.0, 0.0, 0.0), 2.0),
            (right, v(2.0, 1.5, 1.0), 2.5),
        ] {
            for turn in 0..3 {
                let c = [0, 1, 2].map(|k| corners[(k + turn) % 3]);
                let s = triangle_sphere(&c);
                assert!(s.center.distance(center) < 1e-12, "{s:?}");
                assert!((s.radius - radius).abs() < 1e-12, "{s:?}");
            }
        }
        let s = triangle_sphere(&acute);
        let d = acute.map(|p| p.distance(s.center));
        assert!((d[0] - d[1]).abs() < 1e-12 && (d[1] - d[2]).abs() < 1e-12);
        let n = (acute[1] - acute[0]).cross(acute[2] - acute[0]);
        assert!((s.center - acute[0]).dot(n).abs() < 1e-12);
        assert!(acute.iter().all(|&p| s.contains(p)));
        assert!(
            s.radius < BoundingSphere::around_box(&Aabb::around(acute)).radius
        );
    }
}
