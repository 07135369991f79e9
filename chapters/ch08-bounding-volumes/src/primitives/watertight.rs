//! Exercise 2: the watertight ray–triangle test.
use ch02::owns_boundary;
use raystep_core::{DVec2, DVec3, Interval, Ray};

use crate::Shear;

// ANCHOR: watertight
/// The `t` at which `ray` hits the triangle `v` within `interval`, by the
/// watertight test of Woop, Benthin & Wald (JCGT 2(1), 2013).
///
/// The ray is turned into the z axis by a shear, so the question "does it
/// pass through the triangle?" becomes "is the origin of the xy plane
/// inside the sheared triangle?", answered by chapter 2's edge functions.
/// Two triangles that share an edge shear its two vertices to the same
/// numbers and compute its edge function from them alike, so they always
/// agree on which side of the edge the ray passes: no ray leaks through.
/// A ray exactly on an edge (an edge function exactly 0) counts for the
/// one triangle that owns the edge (chapter 2's tie rule), and at a shared
/// vertex for one triangle of its fan: no ray hits twice either.
///
/// A ray with a NaN or an infinity hits nothing, and neither does a ray
/// lying in the triangle's plane (the paper's det = 0).
pub fn watertight(
    v: &[DVec3; 3], ray: &Ray, interval: Interval,
) -> Option<f64> {
    // Step 0: no hit for a NaN or an infinity in the ray. (The shear would
    // turn an infinite direction into 0s: every corner at z = 0, and a
    // hit at t = 0.)
    if !(ray.origin.is_finite() && ray.direction.is_finite()) {
        return None;
    }
    // Steps 1 and 2: the ray's axes and shear.
    let shear = Shear::of(ray.direction);
    // Step 3: each vertex sheared.
    let sheared = v.map(|vertex| shear.vertex(ray.origin, vertex));
    // Steps 4–7.
    sheared_hit(sheared, &shear, interval)
}
// ANCHOR_END: watertight

// ANCHOR: shear
impl Shear {
    /// Steps 1 and 2 of [`watertight`] for the direction `d`, once per
    /// ray.
    pub fn of(d: DVec3) -> Shear {
        // Step 1: kz, the axis the ray goes along most, and kx, ky after
        // it, swapped when it goes toward −kz so the triangle keeps its
        // winding.
        let kz = d.abs().max_position();
        let (mut kx, mut ky) = ((kz + 1) % 3, (kz + 2) % 3);
        if d[kz] < 0.0 {
            std::mem::swap(&mut kx, &mut ky);
        }
        // Step 2: the shear that takes the direction to (0, 0, 1).
        let shear = DVec3::new(d[kx] / d[kz], d[ky] / d[kz], 1.0 / d[kz]);
        Shear {
            axes: [kx, ky, kz],
            shear,
        }
    }

    /// Step 3: `vertex` relative to the ray's `origin`, sheared: (x, y)
    /// in the plane across the ray, and z, its distance along the ray.
    #[inline]
    pub fn vertex(&self, origin: DVec3, vertex: DVec3) -> (DVec2, f64) {
        let ([kx, ky, kz], s) = (self.axes, self.shear);
        let p = vertex - origin;
        let xy = DVec2::new(p[kx] - s.x * p[kz], p[ky] - s.y * p[kz]);
        (xy, s.z * p[kz])
    }
}
// ANCHOR_END: shear

// ANCHOR: sheared_hit
/// Steps 4–7 of [`watertight`]: the hit `t`, if the origin of the xy plane
/// lies inside the triangle `sheared` by `shear` (each corner as its
/// `(x, y)` across the ray and its `z` along it). Chapter 8's fast walk
/// shears each ray's triangles itself (steps 1–3 once per ray) and then
/// asks this. (Inlined: the appendix's walks call it through
/// [`PreparedRay::triangle`](crate::PreparedRay::triangle) from another
/// crate.)
#[inline]
pub(crate) fn sheared_hit(
    sheared: [(DVec2, f64); 3], shear: &Shear, interval: Interval,
) -> Option<f64> {
    let [(a, za), (b, zb), (c, zc)] = sheared;
    // Step 4: the edge functions at the origin, each with an exact sign:
    // e0 for the edge b → c facing vertex a, e1 for c → a, e2 for a → b.
    let e = [
        edge_function(b, c),
        edge_function(c, a),
        edge_function(a, b),
    ];
    // Step 5: outside if they disagree in sign. Edge-on if det is 0: the
    // ray lies in the triangle's plane, and counts as a miss (as in the
    // paper; in a closed mesh the neighbours' edges meet it). The shear
    // rounds the corners, so such a ray's det is rounding noise, not 0:
    // within `det_rounding` of 0 is 0.
    let some_positive = e.iter().any(|&e| e > 0.0);
    let some_negative = e.iter().any(|&e| e < 0.0);
    if some_positive && some_negative {
        return None;
    }
    let det = e[0] + e[1] + e[2];
    if !det.is_finite() || det.abs() <= shear.det_rounding(&sheared) {
        return None;
    }
    // Step 6: an edge function of 0 puts the ray on that edge: it counts
    // only if the triangle owns the edge, walked counter-clockwise (the
    // other way round when the ray sees the triangle clockwise, det < 0).
    let edges = [(b, c), (c, a), (a, b)];
    for (&e, &(from, to)) in e.iter().zip(&edges) {
        let (from, to) = if det > 0.0 { (from, to) } else { (to, from) };
        if e == 0.0 && !owns_boundary(from, to) {
            return None;
        }
    }
    // Step 7: t, the vertices' distances weighted by the barycentric
    // coordinates eᵢ / det.
    let t = (e[0] * za + e[1] * zb + e[2] * zc) / det;
    interval.contains(t).then_some(t)
}
// ANCHOR_END: sheared_hit

// ANCHOR: edge_function
/// Chapter 2's edge function of the edge `p → q` at the origin,
/// `p.x·q.y − p.y·q.x`: positive if the origin is to the left of the edge,
/// 0 on its line, with its sign exact.
///
/// Computed fast first. The paper falls back to higher precision where
/// that value is exactly 0; with no wider float than f64 we fall back to
/// Kahan's determinant ([`difference_of_products`]), and do so wherever
/// the fast value is within its rounding error of 0, so its sign is never
/// wrong — that is what keeps a shared *vertex* watertight as well.
#[inline]
fn edge_function(p: DVec2, q: DVec2) -> f64 {
    // Step 1: the fast value: two rounded products and their difference.
    let (left, right) = (p.x * q.y, p.y * q.x);
    let fast = left - right;
    // Step 2: its rounding error is below 2ε·(|left| + |right|); beyond
    // that its sign is sure.
    if fast.abs() > 2.0 * f64::EPSILON * (left.abs() + right.abs()) {
        return fast;
    }
    // Step 3: the fallback, exact in sign and 0 only on the line.
    difference_of_products(p.x, q.y, p.y, q.x)
}
// ANCHOR_END: edge_function

// ANCHOR: difference_of_products
/// `a·b − c·d` to within 2 ulps of the exact value (Kahan's algorithm
/// with fused multiply-adds), so its sign is exact and it is 0 only when
/// `a·b = c·d` exactly.
fn difference_of_products(a: f64, b: f64, c: f64, d: f64) -> f64 {
    // Step 1: c·d rounded, and its rounding error, which an FMA gives
    // exactly: error = w − c·d.
    let w = c * d;
    let error = (-c).mul_add(d, w);
    // Step 2: a·b − w with one rounding, then the error put back.
    a.mul_add(b, -w) + error
}
// ANCHOR_END: difference_of_products
