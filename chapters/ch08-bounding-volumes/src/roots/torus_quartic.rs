//! Exercise 3: the torus's quartic in t.
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
    let (o, d) = (ray.origin, ray.direction);
    let rr = major * major;
    // Step 1: |P|² + R² − r² is a quadratic in t: a·t² + b·t + c.
    let a = d.dot(d);
    let b = 2.0 * o.dot(d);
    let c = o.dot(o) + rr - minor * minor;
    // Step 2: so is x² + z², the squared distance to the axis:
    // e·t² + g·t + h.
    let e = d.x * d.x + d.z * d.z;
    let g = 2.0 * (o.x * d.x + o.z * d.z);
    let h = o.x * o.x + o.z * o.z;
    // Step 3: square the first, subtract 4R² times the second.
    [
        c * c - 4.0 * rr * h,
        2.0 * b * c - 4.0 * rr * g,
        b * b + 2.0 * a * c - 4.0 * rr * e,
        2.0 * a * b,
        a * a,
    ]
}
// ANCHOR_END: torus_quartic
