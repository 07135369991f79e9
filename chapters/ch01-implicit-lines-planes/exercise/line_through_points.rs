//! Exercise 1 (★): the implicit line through two points.
//!
//! Fill in the three functions below; `cargo run --release -- check ch01` (or
//! `cargo test -p ch01-implicit-lines-planes --features exercise`) judges them.
use crate::{Degenerate, Line2};
use raystep_core::DVec2;

// ANCHOR: rotate90
/// The rotation R by 90° counter-clockwise: `R·(x, y) = (−y, x)`.
pub fn rotate90(v: DVec2) -> DVec2 {
    // TODO: turn v a quarter turn counter-clockwise.
    let _ = v;
    todo!()
}
// ANCHOR_END: rotate90

impl Line2 {
    // ANCHOR: through
    /// The line through `p0` and `p1`, directed from `p0` to `p1`.
    ///
    /// Fails with [`Degenerate`] when a coordinate is not finite, when the
    /// points coincide (no direction), or when `p1 − p0` overflows.
    pub fn through(p0: DVec2, p1: DVec2) -> Result<Line2, Degenerate> {
        // TODO: follow the lecture: V = (P1 − P0)/|P1 − P0|, N = R·V, and c
        // such that f(P0) = 0. Return Degenerate::NonFinite for NaN/infinite
        // input, ::Overflow if P1 − P0 overflows, ::CoincidentPoints if
        // P0 = P1. The normal must come out a unit vector even for points
        // 1e200 apart or 1e-200 apart: |P1 − P0|² would overflow or vanish,
        // so scale the edge by its largest component before normalising.
        let _ = (p0, p1);
        todo!()
    }
    // ANCHOR_END: through

    // ANCHOR: eval
    /// `f(p) = a·x + b·y + c`: the signed distance of `p` from the line.
    pub fn eval(&self, p: DVec2) -> f64 {
        // TODO: evaluate the implicit equation at p.
        let _ = p;
        todo!()
    }
    // ANCHOR_END: eval
}
