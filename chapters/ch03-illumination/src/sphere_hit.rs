//! Exercise 1: where a ray meets a sphere.
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
        let d = ray.direction;
        let f = ray.origin - self.center;
        let a = d.dot(d);
        let b = -f.dot(d);
        // Step 1: the discriminant b² − a·c = a·(r² − |l|²), where l runs from
        // the centre to the point of the ray's line closest to it. Computed
        // from l, not as b² − a·c, it does not cancel catastrophically when
        // b² and a·c are huge and nearly equal (a sphere far away).
        let l = f + (b / a) * d;
        let r2 = self.radius * self.radius;
        let discriminant = a * (r2 - l.dot(l));
        if discriminant < 0.0 {
            return None; // the line passes the sphere by
        }
        // Step 2: the two roots without subtracting nearly equal numbers:
        // q = b + sign(b)·√Δ, then t = c/q and t = q/a.
        let c = f.dot(f) - r2;
        let q = b + b.signum() * discriminant.sqrt();
        let (mut t_near, mut t_far) = (c / q, q / a);
        if q == 0.0 {
            // origin on the sphere and ray tangent: one double root at 0
            (t_near, t_far) = (0.0, 0.0);
        }
        if t_near > t_far {
            std::mem::swap(&mut t_near, &mut t_far);
        }
        // Step 3: the nearer root in the interval, else the farther one.
        let t = [t_near, t_far]
            .into_iter()
            .find(|&t| interval.contains(t))?;
        let point = ray.at(t);
        Some(Hit {
            t,
            point,
            normal: self.normal_at(point),
        })
    }
    // ANCHOR_END: intersect
}
