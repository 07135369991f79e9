//! Exercise 2: the implicit plane through three points.
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
        if !(p0.is_finite() && p1.is_finite() && p2.is_finite()) {
            return Err(Degenerate::NonFinite);
        }
        // Step 1: the edges E₁ = P₁ − P₀ and E₂ = P₂ − P₀.
        let e1 = p1 - p0;
        let e2 = p2 - p0;
        if !(e1.is_finite() && e2.is_finite()) {
            return Err(Degenerate::Overflow);
        }
        if e1 == DVec3::ZERO || e2 == DVec3::ZERO || p1 == p2 {
            return Err(Degenerate::CoincidentPoints);
        }
        // Step 2: E₁×E₂, with each edge first scaled to a largest component
        // of 1 so the product neither overflows nor underflows.
        let a = e1 / e1.abs().max_element();
        let b = e2 / e2.abs().max_element();
        let cross = a.cross(b);
        // Step 3: collinear points give E₁×E₂ = 0 — up to rounding, so
        // compare |a×b| = |a||b| sin θ with |a||b|.
        if cross.length() <= COLLINEAR_SINE * a.length() * b.length() {
            return Err(Degenerate::Collinear);
        }
        // Step 4: N = E₁×E₂ / |E₁×E₂|.
        let normal = cross.normalize();
        // Step 5: d from P₀: f(P₀) = N·P₀ + d = 0.
        let d = -normal.dot(p0);
        Ok(Plane { normal, d })
    }
    // ANCHOR_END: through

    // ANCHOR: eval
    /// `f(p) = N·p + d`: the signed distance of `p` from the plane.
    pub fn eval(&self, p: DVec3) -> f64 {
        self.normal.dot(p) + self.d
    }
    // ANCHOR_END: eval
}
