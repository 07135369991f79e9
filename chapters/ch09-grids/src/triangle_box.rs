//! Does a triangle overlap a box? The separating axis test of
//! Akenine-Möller ("Fast 3D triangle-box overlap testing", 2001): a grid
//! filled with it lists a triangle only in the cells it really passes
//! through, not in every cell of its bounding box.
use raystep_core::{Aabb, DVec3};

// ANCHOR: overlap
/// Do the triangle `v` and the box `b` share a point (touching counts)?
///
/// Two convex shapes are apart exactly when some axis separates their
/// projections. For a triangle and a box, 13 axes are enough to try: the
/// box's three normals, the triangle's normal, and the nine cross
/// products of a triangle edge with a box normal.
pub fn triangle_overlaps_box(v: &[DVec3; 3], b: &Aabb) -> bool {
    // Step 1: the box centred on the origin, half its size `h`.
    let centre = 0.5 * (b.min + b.max);
    let h = 0.5 * (b.max - b.min);
    let v = v.map(|p| p - centre);
    // Step 2: the box's normals: the triangle's own box against it.
    for axis in 0..3 {
        let (lo, hi) = min_max(v.map(|p| p[axis]));
        if lo > h[axis] || hi < -h[axis] {
            return false;
        }
    }
    // Step 3: the triangle's normal: does its plane cut the box?
    let edges = [v[1] - v[0], v[2] - v[1], v[0] - v[2]];
    let normal = edges[0].cross(edges[1]);
    if normal.dot(v[0]).abs() > h.dot(normal.abs()) {
        return false;
    }
    // Step 4: each edge × each box normal.
    for edge in edges {
        for unit in [DVec3::X, DVec3::Y, DVec3::Z] {
            let axis = edge.cross(unit);
            let (lo, hi) = min_max(v.map(|p| axis.dot(p)));
            let radius = h.dot(axis.abs());
            if lo > radius || hi < -radius {
                return false;
            }
        }
    }
    // Step 5: no axis separates them.
    true
}
// ANCHOR_END: overlap

fn min_max(x: [f64; 3]) -> (f64, f64) {
    (x[0].min(x[1]).min(x[2]), x[0].max(x[1]).max(x[2]))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn unit() -> Aabb {
        Aabb::new(DVec3::ZERO, DVec3::ONE)
    }

    #[test]
    fn inside_touching_and_apart() {
        let t = |a: [f64; 3], b: [f64; 3], c: [f64; 3]| {
            [DVec3::from(a), DVec3::from(b), DVec3::from(c)]
        };
        // a small triangle inside
        let inside = t([0.2, 0.2, 0.5], [0.8, 0.2, 0.5], [0.5, 0.8, 0.5]);
        assert!(triangle_overlaps_box(&inside, &unit()));
        // a big triangle whose plane cuts the box, no corner inside
        let big = t([-5.0, -5.0, 0.5], [10.0, -5.0, 0.5], [-5.0, 10.0, 0.5]);
        assert!(triangle_overlaps_box(&big, &unit()));
        // touching a face from outside
        let touch = t([1.0, 0.0, 0.0], [2.0, 0.0, 0.0], [2.0, 1.0, 1.0]);
        assert!(triangle_overlaps_box(&touch, &unit()));
        // its box overlaps the cube, but the triangle passes by a corner:
        // only an edge axis separates them
        let by = t([1.5, 0.8, 0.5], [0.8, 1.5, 0.5], [2.0, 2.0, 0.5]);
        assert!(!triangle_overlaps_box(&by, &unit()));
        // its plane passes by the corner (1, 1, 1)
        let tilt = t([2.0, 0.0, 0.0], [0.0, 2.0, 0.0], [0.0, 0.0, 2.0])
            .map(|p| p + DVec3::splat(0.5));
        assert!(!triangle_overlaps_box(&tilt, &unit()));
    }
}
