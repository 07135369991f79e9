//! Exercise 4: a tight bounding sphere of a point set (Ritter, 1990).
use raystep_core::DVec3;

use crate::BoundingSphere;

// ANCHOR: sphere_of_points
/// A bounding sphere of `points`, close to the smallest one, by Ritter's
/// algorithm ("An efficient bounding sphere", Graphics Gems, 1990): find
/// two points far apart, take the sphere on them as a diameter, and grow
/// it for every point still outside. Four passes over the points; the
/// radius is usually 5 to 20 % above the smallest sphere's.
///
/// No points: radius 0 at the origin. The points must be finite.
pub fn sphere_of_points(points: &[DVec3]) -> BoundingSphere {
    let Some(&any) = points.first() else {
        return BoundingSphere {
            center: DVec3::ZERO,
            radius: 0.0,
        };
    };
    // Step 1: the point farthest from an arbitrary one.
    let y = farthest(points, any);
    // Step 2: the point farthest from that one.
    let z = farthest(points, y);
    // Step 3: the sphere that has y and z as a diameter.
    let mut center = 0.5 * (y + z);
    let mut radius = 0.5 * y.distance(z);
    // Step 4: every point outside grows the sphere just enough to hold
    // both the old sphere and the point: the new diameter runs from the
    // point to the far side of the old sphere.
    for &p in points {
        let d = p.distance(center);
        if d > radius {
            let grown = 0.5 * (radius + d);
            center += (p - center) * ((grown - radius) / d);
            radius = grown;
        }
    }
    // Step 5: the centres moved by rounded steps; measure the radius
    // once more from the final centre, with a margin for the rounding of
    // that distance, so every point tests inside.
    let farthest_point = farthest(points, center);
    radius = farthest_point.distance(center) * (1.0 + 4.0 * f64::EPSILON);
    BoundingSphere { center, radius }
}

/// The point of `points` farthest from `from` (`from` itself if none is
/// farther).
fn farthest(points: &[DVec3], from: DVec3) -> DVec3 {
    let mut best = from;
    for &p in points {
        if p.distance_squared(from) > best.distance_squared(from) {
            best = p;
        }
    }
    best
}
// ANCHOR_END: sphere_of_points
