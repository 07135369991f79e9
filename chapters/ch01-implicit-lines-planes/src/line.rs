use raystep_core::DVec2;

/// An implicit line in 2D: the points where `f(x, y) = a·x + b·y + c = 0`.
///
/// `(a, b)` is the unit normal N, so for any point `f` is the signed
/// distance to the line: positive on the side N points to (left of the
/// direction V), negative on the other.
///
/// Build one with [`Line2::through`] and evaluate it with [`Line2::eval`]
/// (both in `line_through_points.rs`, exercise 1).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Line2 {
    /// V: the unit direction from P₀ toward P₁.
    pub direction: DVec2,
    /// N = R·V: V turned 90° counter-clockwise; `(a, b)` of the equation.
    pub normal: DVec2,
    /// c, chosen so that the line passes through P₀.
    pub c: f64,
}

impl Line2 {
    /// The coefficients `(a, b, c)` of `a·x + b·y + c = 0`.
    pub fn coefficients(&self) -> (f64, f64, f64) {
        (self.normal.x, self.normal.y, self.c)
    }
}
