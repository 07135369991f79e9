//! Exercise 2 (★★): the edge test for a convex polygon.
//!
//! Fill in both functions; `cargo run --release -- check ch02` judges them.
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
    // TODO: order the endpoints (compare (x, y) tuples) into from → to,
    // take N = rotate90(to − from) (ch01's R, no normalising), return
    // N·(p − from), with the sign flipped if you swapped a and b.
    let _ = (a, b, p, rotate90);
    todo!()
}
// ANCHOR_END: edge_function

// ANCHOR: inside_convex
/// Is `p` inside the convex polygon whose vertices `ccw` run
/// counter-clockwise? Inside means on the inner side of every edge: f ≥ 0
/// for all of them, where f = 0 counts only if the polygon owns that edge
/// ([`owns_boundary`]).
pub fn inside_convex(ccw: &[DVec2], p: DVec2) -> bool {
    // TODO: for each edge a → b (the last one closes back to the first
    // vertex; skip repeated vertices), compute f = edge_function(a, b, p).
    // Outside if f < 0, if f = 0 and !owns_boundary(a, b), or if f is NaN.
    // Fewer than 3 vertices: nothing is inside.
    let _ = (ccw, p, owns_boundary);
    todo!()
}
// ANCHOR_END: inside_convex
