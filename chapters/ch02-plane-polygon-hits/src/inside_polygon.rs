//! Exercise 2: the edge test for a convex polygon.
use crate::owns_boundary;
use ch01::rotate90;
use raystep_core::DVec2;

// ANCHOR: edge_function
/// The edge function of the edge `a → b` at `p`: chapter 1's implicit
/// line through `a` and `b` before normalising, `N = R·(b − a)` and
/// `f(p) = N·(p − a)`. Positive to the left of the edge; it is the signed
/// distance times |b − a|, and the inside test needs only its sign.
///
/// Two things make it exact where it matters. Measured from an endpoint,
/// f is exactly 0 at *both* endpoints (`N·(b − a)` multiplies the same
/// numbers twice), so a shared vertex is on every edge through it to the
/// last bit. And the endpoints are taken in one fixed order (the smaller
/// `(x, y)` first), with the sign flipped if that reverses the edge, so
/// the two polygons sharing an edge get exactly opposite values.
pub fn edge_function(a: DVec2, b: DVec2, p: DVec2) -> f64 {
    // Step 1: put the endpoints in a fixed order.
    let (from, to, sign) = if (a.x, a.y) <= (b.x, b.y) {
        (a, b, 1.0)
    } else {
        (b, a, -1.0)
    };
    // Step 2: the normal N = R·(to − from), not normalised.
    let normal = rotate90(to - from);
    // Step 3: f = N·(p − from), with the sign of the edge as given.
    sign * normal.dot(p - from)
}
// ANCHOR_END: edge_function

// ANCHOR: inside_convex
/// Is `p` inside the convex polygon whose vertices `ccw` run
/// counter-clockwise? Inside means on the inner side of every edge: f ≥ 0
/// for all of them, where f = 0 counts only if the polygon owns that edge
/// ([`owns_boundary`]).
pub fn inside_convex(ccw: &[DVec2], p: DVec2) -> bool {
    if ccw.len() < 3 {
        return false;
    }
    for (i, &a) in ccw.iter().enumerate() {
        let b = ccw[(i + 1) % ccw.len()];
        if a == b {
            continue; // a repeated vertex is no edge
        }
        let f = edge_function(a, b, p);
        // Outside this edge, on it but not owning it, or NaN: outside.
        let inner_side = f > 0.0 || (f == 0.0 && owns_boundary(a, b));
        if !inner_side {
            return false;
        }
    }
    true
}
// ANCHOR_END: inside_convex
