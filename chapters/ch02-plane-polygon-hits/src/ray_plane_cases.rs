//! What a ray does at a plane: the cases exercise 1 tells apart.

// ANCHOR: cases
/// What a ray does at a plane: the lecture's cases.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum RayPlane {
    /// It crosses the plane at parameter `t`, inside the query interval.
    Hit(f64),
    /// It crosses the plane at `t`, but outside the interval: behind the
    /// origin (`t < 0`) or beyond the farthest `t` wanted.
    Outside(f64),
    /// It runs parallel to the plane (N·D = 0) and never meets it.
    Parallel,
    /// It lies in the plane: every point is on it, there is no single hit.
    InPlane,
}
// ANCHOR_END: cases

impl RayPlane {
    /// The parameter of an accepted hit.
    pub fn t(self) -> Option<f64> {
        match self {
            RayPlane::Hit(t) => Some(t),
            _ => None,
        }
    }
}
