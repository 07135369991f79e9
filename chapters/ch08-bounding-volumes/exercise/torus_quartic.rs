//! Exercise 3 (★★★): the torus's quartic in t.
use raystep_core::Ray;

// ANCHOR: torus_quartic
/// The coefficients of the quartic f(t) whose roots are the ray's hits
/// with a torus, **lowest degree first**: `[c₀, c₁, c₂, c₃, c₄]` for
/// f(t) = c₀ + c₁t + c₂t² + c₃t³ + c₄t⁴.
///
/// The torus is in its own frame: centred at the origin, around the y
/// axis, with major radius R (centre of the tube to the axis) and minor
/// radius r (the tube's), the points with
///
/// (x² + y² + z² + R² − r²)² = 4R²(x² + z²),
///
/// and `ray` is given in that frame. Put P(t) = O + tD in: f(t) is the
/// left side minus the right side, negative inside the tube and positive
/// outside. The direction need not be a unit vector (then c₄ = |D|⁴).
pub fn torus_quartic(major: f64, minor: f64, ray: &Ray) -> [f64; 5] {
    // TODO:
    // 1. |P|² + R² − r² with P = O + tD is a quadratic a·t² + b·t + c:
    //    a = D·D, b = 2·O·D, c = O·O + R² − r².
    // 2. x² + z² is another quadratic e·t² + g·t + h (only the x and z
    //    parts of O and D).
    // 3. Square the first (a quartic), subtract 4R² times the second, and
    //    return the five coefficients, lowest degree first.
    let _ = (major, minor, ray);
    todo!("ch08 exercise 3: torus_quartic")
}
// ANCHOR_END: torus_quartic
