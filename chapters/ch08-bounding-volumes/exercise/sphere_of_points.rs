//! Exercise 4 (★★): a tight bounding sphere of a point set (Ritter, 1990).
//!
//! Fill in `sphere_of_points`; `cargo run --release -- check ch08` judges
//! it.
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
    // TODO:
    // 1. No points: radius 0 at the origin. Otherwise y = the point
    //    farthest from an arbitrary one (the first, say).
    // 2. z = the point farthest from y.
    // 3. The sphere with y and z as a diameter: centre (y + z)/2, radius
    //    |y − z|/2.
    // 4. For each point p at distance d > radius from the centre: the new
    //    radius is (radius + d)/2, and the centre moves toward p by
    //    (new radius − old radius).
    // 5. (Optional) the radius measured once more from the final centre,
    //    so that rounding leaves no point just outside.
    let _ = points;
    todo!("ch08 exercise 4: sphere_of_points")
}
// ANCHOR_END: sphere_of_points
