use raystep_core::{DVec3, Interval, Ray};

// ANCHOR: moller_trumbore
/// The `t` at which `ray` hits the triangle `v` within `interval`, by
/// Möller & Trumbore (1997): solve P₀ + t·D = V₀ + u·E₁ + v·E₂ for
/// (t, u, v) by Cramer's rule, and accept u ≥ 0, v ≥ 0, u + v ≤ 1.
///
/// Fast, and no plane is stored; but the edges are tested with rounded
/// barycentric coordinates, so a ray through an edge shared by two
/// triangles may hit both or neither (counted in `tests/watertight.rs`).
pub fn moller_trumbore(
    v: &[DVec3; 3], ray: &Ray, interval: Interval,
) -> Option<f64> {
    // Step 1: the edges from V₀, and the determinant det = E₁·(D × E₂).
    let e1 = v[1] - v[0];
    let e2 = v[2] - v[0];
    let p = ray.direction.cross(e2);
    let det = e1.dot(p);
    if det == 0.0 || !det.is_finite() {
        return None; // the ray is parallel to the triangle's plane
    }
    let inverse = 1.0 / det;
    // Step 2: u, the weight of V₁, from S = P₀ − V₀.
    let s = ray.origin - v[0];
    let u = s.dot(p) * inverse;
    if !(0.0..=1.0).contains(&u) {
        return None;
    }
    // Step 3: v, the weight of V₂.
    let q = s.cross(e1);
    let v_weight = ray.direction.dot(q) * inverse;
    if v_weight < 0.0 || u + v_weight > 1.0 || v_weight.is_nan() {
        return None;
    }
    // Step 4: t, and whether the interval accepts it.
    let t = e2.dot(q) * inverse;
    interval.contains(t).then_some(t)
}
// ANCHOR_END: moller_trumbore
