//! Rays lying in a triangle's plane: the case the watertight test must
//! answer with no hit or a hit where the ray crosses the triangle (chapter
//! 8's tests and the stability catalogue draw them alike).
use raystep_core::{DVec3, Ray};

/// A ray in the plane of `v` (to within rounding) and the stretch of `t`
/// over which it is inside the triangle.
///
/// In the triangle's own coordinates (P = V₀ + u·E₁ + w·E₂) the ray
/// starts at `inside` − 3·(cos a, sin a) and runs along (cos a, sin a)
/// for the angle `a`: it starts outside, and its line passes through
/// `inside`. The stretch is where u ≥ 0, w ≥ 0 and u + w ≤ 1.
pub fn ray_in_plane(
    v: &[DVec3; 3], inside: (f64, f64), angle: f64,
) -> (Ray, f64, f64) {
    // Step 1: origin and direction in the triangle's terms, (u, w) and
    // (du, dw).
    let (e1, e2) = (v[1] - v[0], v[2] - v[0]);
    let step = (angle.cos(), angle.sin());
    let start = (inside.0 - 3.0 * step.0, inside.1 - 3.0 * step.1);
    let ray = Ray::new(
        v[0] + start.0 * e1 + start.1 * e2,
        step.0 * e1 + step.1 * e2,
    );
    // Step 2: each of the three conditions s + t·ds ≥ 0 bounds t.
    let (mut lo, mut hi) = (f64::NEG_INFINITY, f64::INFINITY);
    for (s, ds) in [
        (start.0, step.0),
        (start.1, step.1),
        (1.0 - start.0 - start.1, -step.0 - step.1),
    ] {
        if ds > 0.0 {
            lo = lo.max(-s / ds);
        } else if ds < 0.0 {
            hi = hi.min(-s / ds);
        }
    }
    (ray, lo, hi)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Along u: the ray crosses the triangle's inside from u = 0 to
    /// u = 1 − w, three units of t after it starts.
    #[test]
    fn the_stretch_is_where_the_ray_is_inside() {
        let v = [DVec3::ZERO, DVec3::X, DVec3::Y];
        let (ray, lo, hi) = ray_in_plane(&v, (0.2, 0.3), 0.0);
        assert_eq!(ray.origin, DVec3::new(-2.8, 0.3, 0.0));
        assert!((lo - 2.8).abs() < 1e-12 && (hi - 3.5).abs() < 1e-12);
    }
}
