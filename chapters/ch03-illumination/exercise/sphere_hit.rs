//! Exercise 1 (★★): where a ray meets a sphere.
//!
//! Fill in `intersect`; `cargo run --release -- check ch03` judges it.
use crate::Sphere;
use raystep_core::{Hit, Interval, Ray};

impl Sphere {
    // ANCHOR: intersect
    /// The first hit of `ray` with the sphere whose `t` lies in `interval`.
    ///
    /// Solves |P₀ + t·D − C|² = r², a quadratic a·t² − 2b·t + c = 0 with
    /// a = D·D, b = −(P₀ − C)·D, c = |P₀ − C|² − r², in the form that
    /// keeps its precision for grazing rays and far-away spheres
    /// (Haines et al., Ray Tracing Gems, ch. 7).
    pub fn intersect(&self, ray: &Ray, interval: Interval) -> Option<Hit> {
        // TODO: with f = P0 − C, a = D·D, b = −f·D:
        // 1. The discriminant. The textbook b² − a·c cancels catastrophically
        //    for a sphere 1e7 away (two numbers near 1e14 whose difference
        //    is about 1). Compute it as a·(r² − |l|²) with l = f + (b/a)·D,
        //    the vector from C to the ray's closest point. Negative: no hit.
        // 2. The roots without cancellation: q = b + sign(b)·√discriminant,
        //    t = c/q and t = q/a (c = f·f − r²); sort them.
        // 3. Return the nearer t inside `interval`, else the farther one,
        //    else None. The Hit's normal is the outward self.normal_at(point).
        let _ = (ray, interval);
        todo!()
    }
    // ANCHOR_END: intersect
}
