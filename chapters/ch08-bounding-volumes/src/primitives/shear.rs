//! The watertight test's view of a ray (exercise 2 fills in its steps):
//! the axes it renames and the shear that turns the ray into the z axis.
use raystep_core::{DVec2, DVec3};

/// Steps 1 and 2 of [`watertight`](crate::watertight) for one direction:
/// kept per ray by the walks, which shear every triangle they test with
/// it ([`Shear::of`], [`Shear::vertex`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Shear {
    /// kx, ky, kz: kz the axis the ray goes along most.
    pub axes: [usize; 3],
    /// (D[kx]/D[kz], D[ky]/D[kz], 1/D[kz]): the shear that takes the
    /// direction to (0, 0, 1).
    pub shear: DVec3,
}

// ANCHOR: det_rounding
impl Shear {
    /// How far rounding can put the watertight test's det = e₀ + e₁ + e₂
    /// of the corners `sheared` by this shear (each `(x, y)` and `z`, as
    /// [`Shear::vertex`] gives them) from its exact value. A ray lying in
    /// the triangle's plane has det = 0 exactly; computed, it comes out as
    /// noise of either sign, at most this big.
    pub fn det_rounding(&self, sheared: &[(DVec2, f64); 3]) -> f64 {
        // Step 1: m, the largest |coordinate| of a corner P = V − O:
        // |P[kz]| = |z / Sz|, and |P[kx]|, |P[ky]| ≤ |x| + |y| + |P[kz]|
        // since |Sx|, |Sy| ≤ 1.
        let (mut across, mut along, mut sum) = (0.0f64, 0.0f64, 0.0);
        for (xy, z) in sheared {
            let size = xy.x.abs() + xy.y.abs();
            (across, along) = (across.max(size), along.max(z.abs()));
            sum += size;
        }
        let m = across + along / self.shear.z.abs();
        // Step 2: each of x and y is off by at most 3ε·m (P, the product
        // and the difference each round once); that moves an edge function
        // by at most 3ε·m times the |x| + |y| of its two corners, and its
        // own rounding and the sum's add at most 8ε·m·Σ: det is off by at
        // most 14ε·m·Σ(|xᵢ| + |yᵢ|). 16 for the terms in ε².
        16.0 * f64::EPSILON * m * sum
    }
}
// ANCHOR_END: det_rounding
