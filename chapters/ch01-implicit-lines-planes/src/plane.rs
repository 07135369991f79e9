use raystep_core::DVec3;

/// An implicit plane: the points P where `f(P) = N·P + d = 0`.
///
/// N is a unit vector, so `f(P)` is the signed distance from the plane:
/// positive on the side N points to.
///
/// Build one with [`Plane::through`] and evaluate it with [`Plane::eval`]
/// (both in `plane_through_points.rs`, exercise 2).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Plane {
    /// N: the unit normal, `E₁×E₂ / |E₁×E₂|`.
    pub normal: DVec3,
    /// d, chosen so that the plane passes through P₀: `d = −N·P₀`.
    pub d: f64,
}

// ANCHOR: collinear_sine
/// Below this sine of the angle between E₁ and E₂ the points count as
/// collinear: the rounding of the inputs alone could then turn the normal
/// by more than about 1e-4 rad (for coordinates about as large as the
/// edges; a small triangle far from the origin, |P| ≫ |E|, is worse by the
/// factor |P|/|E|).
pub const COLLINEAR_SINE: f64 = 1e-12;
// ANCHOR_END: collinear_sine
