//! Exercise 2 (★): the implicit plane through three points.
//!
//! Fill in the two functions below; `cargo run --release -- check ch01` judges them.
use crate::{COLLINEAR_SINE, Degenerate, Plane};
use raystep_core::DVec3;

impl Plane {
    // ANCHOR: through
    /// The plane through `p0`, `p1`, `p2`, with N = E₁×E₂/|E₁×E₂| (so
    /// the points run counter-clockwise seen from the side N points to).
    ///
    /// Fails with [`Degenerate`] when a coordinate is not finite, two points
    /// coincide, the points are collinear, or the edges overflow.
    pub fn through(
        p0: DVec3, p1: DVec3, p2: DVec3,
    ) -> Result<Plane, Degenerate> {
        // TODO: E1 = P1 − P0, E2 = P2 − P0, N = E1×E2/|E1×E2|, d = −N·P0.
        // Errors: Degenerate::NonFinite (NaN/infinite input), ::Overflow
        // (an edge overflows), ::CoincidentPoints (two points equal),
        // ::Collinear when |E1×E2| ≤ COLLINEAR_SINE·|E1|·|E2|. Scale each
        // edge by its largest component before the cross product so that
        // edges of length 1e-200 or 1e200 still give a unit normal.
        let _ = (p0, p1, p2, COLLINEAR_SINE);
        todo!()
    }
    // ANCHOR_END: through

    // ANCHOR: eval
    /// `f(p) = N·p + d`: the signed distance of `p` from the plane.
    pub fn eval(&self, p: DVec3) -> f64 {
        // TODO: evaluate the implicit equation at p.
        let _ = p;
        todo!()
    }
    // ANCHOR_END: eval
}
