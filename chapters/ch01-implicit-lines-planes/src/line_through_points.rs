//! Exercise 1: the implicit line through two points.
use crate::{Degenerate, Line2};
use raystep_core::DVec2;

// ANCHOR: rotate90
/// The rotation R by 90° counter-clockwise: `R·(x, y) = (−y, x)`.
pub fn rotate90(v: DVec2) -> DVec2 {
    DVec2::new(-v.y, v.x)
}
// ANCHOR_END: rotate90

impl Line2 {
    // ANCHOR: through
    /// The line through `p0` and `p1`, directed from `p0` to `p1`.
    ///
    /// Fails with [`Degenerate`] when a coordinate is not finite, when the
    /// points coincide (no direction), or when `p1 − p0` overflows.
    pub fn through(p0: DVec2, p1: DVec2) -> Result<Line2, Degenerate> {
        if !(p0.is_finite() && p1.is_finite()) {
            return Err(Degenerate::NonFinite);
        }
        // Step 1: the edge P₁ − P₀; zero means there is no direction.
        let edge = p1 - p0;
        if !edge.is_finite() {
            return Err(Degenerate::Overflow);
        }
        let largest = edge.abs().max_element();
        if largest == 0.0 {
            return Err(Degenerate::CoincidentPoints);
        }
        // Step 2: V = (P₁ − P₀) / |P₁ − P₀|. Dividing by the largest
        // component first keeps |edge|² from overflowing or underflowing.
        let direction = (edge / largest).normalize();
        // Step 3: N = R·V, the direction turned 90°.
        let normal = rotate90(direction);
        // Step 4: c from P₀: f(P₀) = N·P₀ + c = 0.
        let c = -normal.dot(p0);
        Ok(Line2 {
            direction,
            normal,
            c,
        })
    }
    // ANCHOR_END: through

    // ANCHOR: eval
    /// `f(p) = a·x + b·y + c`: the signed distance of `p` from the line.
    pub fn eval(&self, p: DVec2) -> f64 {
        self.normal.dot(p) + self.c
    }
    // ANCHOR_END: eval
}
