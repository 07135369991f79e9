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
            // Where the edge crosses z = NEAR, computed from its corner in
            // front: a neighbour walking the shared edge the other way gets
            // the same corner bit for bit, so the fill rule still holds.
            let (front, back) = if a_in { (a, b) } else { (b, a) };
            let t = (NEAR - front.z) / (back.z - front.z);
            let mut p = front + (back - front) * t;
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

    #[test]
    fn neighbours_get_the_same_corner_on_a_shared_clipped_edge() {
        // The edge p → q crosses the near plane; one triangle walks it p → q,
        // its neighbour q → p. Both must cut it at the same point, bit for bit.
        let p = DVec3::new(0.3, -0.7, 2.9);
        let q = DVec3::new(-1.1, 0.45, -0.37);
        let (left, right) =
            (DVec3::new(-2.0, 1.0, 3.0), DVec3::new(2.0, -1.0, 1.7));
        let cut = |corners| {
            let out = clip_near(corners);
            out.iter()
                .copied()
                .filter(|v| v.z == NEAR)
                .collect::<Vec<_>>()
        };
        let one = cut([p, q, left]);
        let other = cut([q, p, right]);
        let on_edge =
            |v: &DVec3| other.iter().any(|w| w.to_array() == v.to_array());
        assert_eq!(
            one.iter().filter(|v| on_edge(v)).count(),
            1,
            "{one:?} {other:?}"
        );
    }
}
