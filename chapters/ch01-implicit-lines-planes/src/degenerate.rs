use thiserror::Error;

// ANCHOR: degenerate
/// Why no line or plane passes through the given points.
///
/// Returned instead of a line or plane whose normal would be NaN, zero or
/// meaningless.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Error)]
pub enum Degenerate {
    /// A coordinate is NaN or infinite.
    #[error("a coordinate is NaN or infinite")]
    NonFinite,
    /// Two of the points are the same point, so they fix no direction.
    #[error("two of the points coincide")]
    CoincidentPoints,
    /// The three points lie on one line (E₁×E₂ = 0), so they fix no plane.
    #[error("the points are collinear: E1 × E2 is zero")]
    Collinear,
    /// The coordinates are so large that P₁ − P₀ overflows.
    #[error("the points are too far apart: P1 - P0 overflows")]
    Overflow,
}
// ANCHOR_END: degenerate
