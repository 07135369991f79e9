//! The stable quadratic of chapter 3's sphere, for the shapes that are a
//! sphere in disguise: the ellipsoid (a unit sphere in a stretched space)
//! and the cylinder's side (a circle across its axis).
use raystep_core::DVec3;

// ANCHOR: sphere_roots
/// The roots t of |o + t·d|² = r², in the stable form of chapter 3's
/// sphere: the discriminant from the closest approach l, and the second
/// root as c/q. None where d = 0 (for the cylinder: a ray along its axis)
/// or where the line passes the sphere by; one root, 0, where it starts on
/// the sphere and touches it there.
pub(crate) fn sphere_roots(o: DVec3, d: DVec3, r: f64) -> [Option<f64>; 2] {
    let a = d.dot(d);
    if a == 0.0 {
        return [None, None]; // no direction: no line
    }
    let b = -o.dot(d);
    // b² − a·c = a·(r² − |l|²), l = o + (b/a)·d the closest approach
    let l = o + (b / a) * d;
    let discriminant = a * (r * r - l.dot(l));
    if discriminant.is_nan() || discriminant < 0.0 {
        return [None, None];
    }
    let c = o.dot(o) - r * r;
    let q = b + b.signum() * discriminant.sqrt();
    if q == 0.0 {
        return [Some(0.0), None]; // starts on it, tangent to it
    }
    [Some(c / q), Some(q / a)]
}
// ANCHOR_END: sphere_roots
