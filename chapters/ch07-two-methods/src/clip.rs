//! The near plane: a rasterizer can only divide by the depth of points in
//! front of the eye. Triangles are cut at z = NEAR in view coordinates.
use raystep_core::DVec3;

/// The near plane's depth, in scene units: what is closer to the eye is
/// not drawn.
pub const NEAR: f64 = 1e-3;

// ANCHOR: clip
/// The part of a triangle (corners in view coordinates) with z ≥ [`NEAR`]:
/// no corner if it is all behind, the triangle itself if it is all in
/// front, otherwise a triangle or a quadrilateral (one of Sutherland and
/// Hodgman's steps, for one plane), corners in the same order.
pub fn clip_near(corners: [DVec3; 3]) -> Vec<DVec3> {
    let mut out = Vec::with_capacity(4);
    for i in 0..3 {
        let (a, b) = (corners[i], corners[(i + 1) % 3]);
        let (a_in, b_in) = (a.z >= NEAR, b.z >= NEAR);
        if a_in {
            out.push(a);
        }
        if a_in != b_in {
            // where the edge a → b crosses z = NEAR
            let t = (NEAR - a.z) / (b.z - a.z);
            let mut p = a + (b - a) * t;
            p.z = NEAR; // exactly on the plane, whatever the rounding
            out.push(p);
        }
    }
    out
}
// ANCHOR_END: clip

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn in_front_behind_and_across() {
        let front = [
            DVec3::new(0.0, 0.0, 1.0),
            DVec3::new(1.0, 0.0, 2.0),
            DVec3::new(0.0, 1.0, 3.0),
        ];
        assert_eq!(clip_near(front), front.to_vec());
        let behind = front.map(|v| DVec3::new(v.x, v.y, -v.z));
        assert!(clip_near(behind).is_empty());
        // one corner behind: a quadrilateral; two behind: a triangle
        let one = [front[0], front[1], DVec3::new(0.0, 1.0, -1.0)];
        let quad = clip_near(one);
        assert_eq!(quad.len(), 4);
        assert!(quad.iter().all(|v| v.z >= NEAR));
        let two = [
            front[0],
            DVec3::new(1.0, 0.0, -2.0),
            DVec3::new(0.0, 1.0, -1.0),
        ];
        let tri = clip_near(two);
        assert_eq!(tri.len(), 3);
        assert_eq!(tri.iter().filter(|v| v.z == NEAR).count(), 2);
    }
}
