//! Exercise 2 (★★★): the watertight ray–triangle test.
#[allow(unused_imports)]
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
    // TODO:
    // 0. A NaN or an infinity anywhere in the ray's origin or direction:
    //    no hit, return None before the shear (which would turn an
    //    infinite direction into 0s: every corner at z = 0, a hit at
    //    t = 0).
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
        // TODO:
        // 1. kz = the axis of D's largest |component| (`max_position`),
        //    kx = kz + 1 and ky = kz + 2 (mod 3); swap kx and ky if
        //    D[kz] < 0 (so the triangle keeps its winding).
        // 2. The shear: Sx = D[kx]/D[kz], Sy = D[ky]/D[kz], Sz = 1/D[kz].
        //    Return `Shear { axes: [kx, ky, kz], shear: (Sx, Sy, Sz) }`.
        let _ = d;
        todo!("ch08 exercise 2: watertight")
    }

    /// Step 3: `vertex` relative to the ray's `origin`, sheared: (x, y)
    /// in the plane across the ray, and z, its distance along the ray.
    #[inline]
    pub fn vertex(&self, origin: DVec3, vertex: DVec3) -> (DVec2, f64) {
        // TODO:
        // 3. P = vertex − origin; sheared (x, y) =
        //    (P[kx] − Sx·P[kz], P[ky] − Sy·P[kz]) and z = Sz·P[kz].
        let _ = (origin, vertex);
        todo!("ch08 exercise 2: watertight")
    }
}
// ANCHOR_END: shear

// ANCHOR: sheared_hit
/// Steps 4–7 of [`watertight`]: the hit `t`, if the origin of the xy plane
/// lies inside the triangle `sheared` by `shear` (each corner as its
/// `(x, y)` across the ray and its `z` along it). Chapter 8's fast walk
/// shears each ray's triangles itself (steps 1–3 once per ray) and then
/// asks this.
pub(crate) fn sheared_hit(
    sheared: [(DVec2, f64); 3], shear: &Shear, interval: Interval,
) -> Option<f64> {
    // TODO:
    // 4. The edge functions at the origin, with `edge_function`:
    //    e0 for b → c, e1 for c → a, e2 for a → b.
    // 5. None if some eᵢ > 0 and some eᵢ < 0 (outside), or if
    //    det = e0 + e1 + e2 is not finite, or if it is 0: the ray lies in
    //    the triangle's plane (seen edge-on), a miss. The shear rounds the
    //    corners, so for such a ray det is rounding noise rather than 0:
    //    count |det| ≤ `shear.det_rounding(&sheared)` as 0.
    // 6. For each eᵢ == 0 the ray is on that edge: None unless the
    //    triangle owns it, `owns_boundary(from, to)` (chapter 2's tie
    //    rule) with the edge walked as listed if det > 0, reversed if
    //    det < 0 (the ray sees the triangle clockwise).
    // 7. t = (e0·za + e1·zb + e2·zc) / det, if the interval contains it.
    let _ = (sheared, shear, interval, edge_function);
    todo!("ch08 exercise 2: watertight")
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
fn edge_function(p: DVec2, q: DVec2) -> f64 {
    // TODO:
    // 1. left = p.x·q.y, right = p.y·q.x, fast = left − right.
    // 2. If |fast| > 2ε·(|left| + |right|) (ε = `f64::EPSILON`), its sign
    //    is sure: return it.
    // 3. Else return `difference_of_products(p.x, q.y, p.y, q.x)`.
    let _ = (p, q, difference_of_products);
    todo!("ch08 exercise 2: watertight")
}
// ANCHOR_END: edge_function

// ANCHOR: difference_of_products
/// `a·b − c·d` to within 2 ulps of the exact value (Kahan's algorithm
/// with fused multiply-adds), so its sign is exact and it is 0 only when
/// `a·b = c·d` exactly.
fn difference_of_products(a: f64, b: f64, c: f64, d: f64) -> f64 {
    // TODO:
    // 1. w = c·d, and its rounding error exactly by an FMA:
    //    error = (−c).mul_add(d, w).
    // 2. a.mul_add(b, −w) + error.
    let _ = (a, b, c, d);
    todo!("ch08 exercise 2: watertight")
}
// ANCHOR_END: difference_of_products
