//! The torus: a slow primitive, a quartic in t.
use raystep_core::{Aabb, DVec3, Hit, Interval, Ray, Shape};

use crate::{
    BoundingSphere, Primitive, quartic_roots, roots_in, torus_quartic,
};

/// How a [`Torus`] finds the roots of its quartic.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TorusSolver {
    /// Ferrari's closed form ([`quartic_roots`]) on the quartic built at
    /// the ray's own origin: the textbook method, which loses roots at
    /// grazing rays and far origins.
    ClosedForm,
    /// The bracketed method ([`roots_in`]) on the quartic built at the
    /// ray's entry into the torus's box, on the interval inside the box.
    Bracketed,
}

/// A ring torus: the points at distance `minor` (r) from a circle of
/// radius `major` (R) around `center`, in the plane across `axis`.
///
/// Only ring tori, r < R: with r ≥ R the tube passes through the axis
/// (a horn or spindle torus) and [`Torus::new`] refuses it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Torus {
    center: DVec3,
    major: f64,
    minor: f64,
    solver: TorusSolver,
    /// The torus's frame: `u` and `w` across the unit `axis`.
    u: DVec3,
    axis: DVec3,
    w: DVec3,
}

impl Torus {
    /// The torus around `center` with this axis (any length but 0) and
    /// radii, solved by `solver`; an error names a bad parameter.
    pub fn new(
        center: DVec3, axis: DVec3, major: f64, minor: f64, solver: TorusSolver,
    ) -> Result<Torus, String> {
        if !center.is_finite() {
            return Err(format!("torus: center {center} must be finite"));
        }
        let Some(axis) = axis.try_normalize() else {
            return Err(format!(
                "torus: axis {axis} must be a finite, non-zero vector"
            ));
        };
        for (name, value) in [("major", major), ("minor", minor)] {
            if !(value > 0.0 && value.is_finite()) {
                return Err(format!(
                    "torus: {name} radius {value} must be a positive number"
                ));
            }
        }
        if minor >= major {
            return Err(format!(
                "torus: minor radius {minor} must be smaller than the major \
                 radius {major}: only ring tori are supported (with minor ≥ \
                 major the tube passes through the axis, a horn or spindle \
                 torus)"
            ));
        }
        let (u, w) = axis.any_orthonormal_pair();
        Ok(Torus {
            center,
            major,
            minor,
            solver,
            u,
            axis,
            w,
        })
    }

    /// The same torus, solved by `solver`.
    pub fn with_solver(self, solver: TorusSolver) -> Torus {
        Torus { solver, ..self }
    }

    /// Its centre.
    pub fn center(&self) -> DVec3 {
        self.center
    }

    /// Its unit axis.
    pub fn axis(&self) -> DVec3 {
        self.axis
    }

    /// R, from the axis to the middle of the tube.
    pub fn major(&self) -> f64 {
        self.major
    }

    /// r, the tube's radius.
    pub fn minor(&self) -> f64 {
        self.minor
    }

    /// The root finder it uses.
    pub fn solver(&self) -> TorusSolver {
        self.solver
    }

    /// Every root its solver finds along `ray` with t ≥ 0, in the ray's
    /// own t, sorted (for tests and figures: [`Shape::intersect`] keeps
    /// the first one).
    pub fn roots(&self, ray: &Ray) -> Vec<f64> {
        self.roots_within(&self.local_ray(ray), Interval::FORWARD)
    }

    /// The quartic f(t) along `ray` in the ray's own t, lowest degree
    /// first (the one [`TorusSolver::ClosedForm`] solves; for plots).
    pub fn quartic_along(&self, ray: &Ray) -> [f64; 5] {
        torus_quartic(self.major, self.minor, &self.local_ray(ray))
    }

    /// The outward unit normal at a point on the surface.
    pub fn normal_at(&self, point: DVec3) -> DVec3 {
        let n = torus_normal(self.major, self.minor, self.local_point(point));
        n.x * self.u + n.y * self.axis + n.z * self.w
    }

    fn roots_within(&self, local: &Ray, interval: Interval) -> Vec<f64> {
        match self.solver {
            TorusSolver::ClosedForm => {
                closed_form_roots(self.major, self.minor, local, interval)
            }
            TorusSolver::Bracketed => {
                bracketed_roots(self.major, self.minor, local, interval)
            }
        }
    }

    fn local_point(&self, p: DVec3) -> DVec3 {
        let v = p - self.center;
        DVec3::new(v.dot(self.u), v.dot(self.axis), v.dot(self.w))
    }

    /// The ray in the torus's frame (the same t: the frame is rigid).
    fn local_ray(&self, ray: &Ray) -> Ray {
        let d = ray.direction;
        Ray::new(
            self.local_point(ray.origin),
            DVec3::new(d.dot(self.u), d.dot(self.axis), d.dot(self.w)),
        )
    }
}

// ANCHOR: closed_form_roots
/// The closed form: the quartic from the ray's origin, wherever that is,
/// and Ferrari's formula; the roots in `interval`. (Torus frame.)
fn closed_form_roots(
    major: f64, minor: f64, ray: &Ray, interval: Interval,
) -> Vec<f64> {
    let quartic = torus_quartic(major, minor, ray);
    let mut roots = quartic_roots(quartic);
    roots.retain(|&t| interval.contains(t));
    roots
}
// ANCHOR_END: closed_form_roots

// ANCHOR: bracketed_roots
/// The bracketed method: the roots in `interval`, sorted. (Torus frame.)
fn bracketed_roots(
    major: f64, minor: f64, ray: &Ray, interval: Interval,
) -> Vec<f64> {
    // Step 1: clip the ray to the torus's box (axis-aligned in its own
    // frame), grown by 1% of r: there are no roots outside it. (The tight
    // box touches the torus, and a root on an end of the interval has
    // p ≈ 0 there, a sign the method cannot trust: a ray onto the top of
    // the tube would lose its hit.)
    let pad = 0.01 * minor;
    let (reach, r) = (major + minor + pad, minor + pad);
    let bounds =
        Aabb::new(DVec3::new(-reach, -r, -reach), DVec3::new(reach, r, reach));
    // The whole line's stretch inside the box, not only the interval's:
    // the roots then do not depend on where the interval starts, so a
    // ray asked again from just past a hit (a shadow ray leaving the
    // surface) cannot find a new root of the rounding noise there.
    let Some(inside) = crate::slab_test(&bounds, ray, Interval::UNIVERSE)
    else {
        return Vec::new();
    };
    if !(inside.min.is_finite() && inside.max.is_finite()) {
        return Vec::new(); // a zero direction: no line at all
    }
    // Step 2: move the ray's origin to where it enters the box. From a
    // far origin (|O| = 10⁶) the coefficients grow like |O|⁴ and cancel
    // down to the size of the torus; from the entry they stay small.
    let entry = Ray::new(ray.at(inside.min), ray.direction);
    let quartic = torus_quartic(major, minor, &entry);
    // Step 3: the roots inside the box, in the moved ray's s = t − entry,
    // shifted back to the ray's own t; then those in the interval.
    let mut roots: Vec<f64> = roots_in(&quartic, 0.0, inside.size())
        .into_iter()
        .map(|s| inside.min + s)
        .collect();
    roots.retain(|&t| interval.contains(t));
    roots
}
// ANCHOR_END: bracketed_roots

// ANCHOR: torus_normal
/// The outward unit normal at `p` on the torus (torus frame): the
/// gradient of f = (|p|² + R² − r²)² − 4R²(x² + z²),
/// ∇f = 4(|p|² + R² − r²)·p − 8R²·(x, 0, z), normalised.
fn torus_normal(major: f64, minor: f64, p: DVec3) -> DVec3 {
    let across = DVec3::new(p.x, 0.0, p.z);
    let e = p.length_squared() + major * major - minor * minor;
    let gradient = 4.0 * e * p - 8.0 * major * major * across;
    // On a ring torus the gradient vanishes only off the surface (on the
    // centre circle, or at the centre: a spurious root could land there);
    // then the direction away from the centre circle, or the axis.
    gradient.try_normalize().unwrap_or_else(|| {
        let circle = across.try_normalize().unwrap_or(DVec3::X) * major;
        (p - circle).try_normalize().unwrap_or(DVec3::Y)
    })
}
// ANCHOR_END: torus_normal

/// A torus as an object of a scene: the first root of its solver.
impl Shape for Torus {
    fn intersect(&self, ray: &Ray, interval: Interval) -> Option<Hit> {
        let local = self.local_ray(ray);
        let t = *self.roots_within(&local, interval).first()?;
        let point = ray.at(t);
        let n = torus_normal(self.major, self.minor, local.at(t));
        let normal = n.x * self.u + n.y * self.axis + n.z * self.w;
        Some(Hit { t, point, normal })
    }

    /// The tight box: along each world axis eᵢ the centre circle reaches
    /// R·√(1 − (n·eᵢ)²) from the centre, and the tube r further.
    fn bounds(&self) -> Aabb {
        let n = self.axis;
        let circle = (DVec3::ONE - n * n).max(DVec3::ZERO).map(f64::sqrt);
        let half = self.major * circle + DVec3::splat(self.minor);
        Aabb::new(self.center - half, self.center + half)
    }
}

impl Primitive for Torus {
    fn name(&self) -> &'static str {
        "torus"
    }

    /// Around its centre, radius R + r.
    fn bounding_sphere(&self) -> BoundingSphere {
        BoundingSphere {
            center: self.center,
            radius: self.major + self.minor,
        }
    }
}
