//! Spheres and tori where their root finders are fragile: rays that
//! graze a sphere, rays from a million radii away, origins on the
//! sphere; rays that graze a torus's outer equator, the rim of its hole
//! and its top circle, rays along its axis, rays from far away.
//!
//! The truth never uses the methods' formulas. Each ray's hits are the
//! roots of |P(t) − C|² = ρ² for a circle or sphere: for a torus, a ray
//! in a plane y = h across its axis meets it where it meets the two
//! circles of radius R ± √(r² − h²) in that plane. That function is
//! evaluated at the exact point O + tD in double-double arithmetic
//! (about 32 digits) and its sign changes are bisected, so the truth is
//! the exact answer for the ray as given, to ~1e-12.
use ch03::Sphere;
use ch08::{
    DVec3, Ellipsoid, Interval, Ray, SplitMix64, Torus, TorusSolver,
    quadratic_roots,
};

use crate::trials::{count_failures, cube_point, decades, per_method, uniform};
use crate::{Budget, Case, Count, Expect};

const GROUP: &str = "sphere and torus";

/// This group's cases.
pub fn cases() -> Vec<Case> {
    vec![
        Case {
            group: GROUP,
            name: "grazing a sphere",
            what: "rays r·(1 ± 1e-12…1e-3) from the centre: Δ = b² − ac \
                   cancels; chapter 3's form survives",
            run: grazing_a_sphere,
        },
        Case {
            group: GROUP,
            name: "sphere from afar",
            what: "origins 1e6 radii away: b² − ac cancels to noise; chapter \
                   3's Δ from l survives",
            run: sphere_from_afar,
        },
        Case {
            group: GROUP,
            name: "origin on the sphere",
            what: "a ray leaving the surface, t ≥ 1e-6·r: no re-hit at t ≈ 0, \
                   the far hit right; all survive",
            run: origin_on_the_sphere,
        },
        Case {
            group: GROUP,
            name: "torus: grazing the outer equator",
            what: "1e-9…1e-3·r inside or outside the outer equator: a double \
                   root; bracketed survives",
            run: grazing_the_equator,
        },
        Case {
            group: GROUP,
            name: "torus: grazing the hole",
            what: "1e-9…1e-3·r either side of the hole's rim: a close pair or \
                   none; bracketed survives",
            run: grazing_the_hole,
        },
        Case {
            group: GROUP,
            name: "torus: along the axis",
            what: "rays along the axis through the hole, on it or off it: no \
                   root; both survive",
            run: along_the_axis,
        },
        Case {
            group: GROUP,
            name: "torus: tangent to the top circle",
            what: "horizontal rays 1e-9…1e-3·r below or above the top circle; \
                   bracketed survives",
            run: tangent_to_the_top,
        },
        Case {
            group: GROUP,
            name: "torus from afar",
            what: "origins 1e3…1e6 away: the quartic's coefficients cancel; \
                   bracketed (origin moved) survives",
            run: torus_from_afar,
        },
    ]
}

// ---------------------------------------------------------------------
// The truth: double-double arithmetic and bisection.
// ---------------------------------------------------------------------

/// A number as an unevaluated sum hi + lo: about 106 bits; sums and
/// products of doubles exact.
#[derive(Clone, Copy, Debug)]
struct Dd {
    hi: f64,
    lo: f64,
}

impl Dd {
    fn from(x: f64) -> Dd {
        Dd { hi: x, lo: 0.0 }
    }

    /// a + b exactly (Knuth's TwoSum).
    fn sum(a: f64, b: f64) -> Dd {
        let s = a + b;
        let bb = s - a;
        Dd {
            hi: s,
            lo: (a - (s - bb)) + (b - bb),
        }
    }

    /// a·b exactly (the fused multiply-add's remainder).
    fn product(a: f64, b: f64) -> Dd {
        let p = a * b;
        Dd {
            hi: p,
            lo: a.mul_add(b, -p),
        }
    }

    fn normalised(hi: f64, lo: f64) -> Dd {
        let s = hi + lo;
        Dd {
            hi: s,
            lo: lo - (s - hi),
        }
    }

    fn add(self, o: Dd) -> Dd {
        let s = Dd::sum(self.hi, o.hi);
        let t = Dd::sum(self.lo, o.lo);
        let s = Dd::normalised(s.hi, s.lo + t.hi);
        Dd::normalised(s.hi, s.lo + t.lo)
    }

    fn neg(self) -> Dd {
        Dd {
            hi: -self.hi,
            lo: -self.lo,
        }
    }

    fn mul(self, o: Dd) -> Dd {
        let p = Dd::product(self.hi, o.hi);
        Dd::normalised(p.hi, p.lo + (self.hi * o.lo + self.lo * o.hi))
    }

    /// Its sign: −1, 0 or 1.
    fn sign(self) -> f64 {
        let x = if self.hi != 0.0 { self.hi } else { self.lo };
        if x > 0.0 {
            1.0
        } else if x < 0.0 {
            -1.0
        } else {
            0.0
        }
    }
}

/// The circle or sphere around `centre` of radius² `rho2` (as a
/// double-double), met by the ray: g(t) = |O + tD − C|² − ρ², computed
/// in double-double from the exact point O + tD.
struct Round {
    centre: DVec3,
    rho2: Dd,
}

impl Round {
    /// The sphere of radius `radius`.
    fn sphere(centre: DVec3, radius: f64) -> Round {
        Round {
            centre,
            rho2: Dd::product(radius, radius),
        }
    }

    /// The circle of radius R + `sign`·w around the y axis, in the plane
    /// y = `height` (the ray lies in it: only x and z count).
    fn circle(height: f64, major: f64, w: f64, sign: f64) -> Round {
        let rho = Dd::sum(major, sign * w);
        Round {
            centre: DVec3::new(0.0, height, 0.0),
            rho2: rho.mul(rho),
        }
    }

    /// g(t), from the exact point O + tD.
    fn g(&self, ray: &Ray, t: f64) -> Dd {
        let mut sum = self.rho2.neg();
        for i in 0..3 {
            let v = Dd::product(t, ray.direction[i])
                .add(Dd::from(ray.origin[i]))
                .add(Dd::from(-self.centre[i]));
            sum = sum.add(v.mul(v));
        }
        sum
    }

    /// The roots of g along `ray`, sorted: none where the line passes
    /// by (g ≥ 0 at its closest point), else the entry and the exit.
    fn roots(&self, ray: &Ray) -> Vec<f64> {
        // Step 1: the closest point, tm, in f64 (g is flat there, so
        // its error does not matter): does the line dip inside?
        let d2 = ray.direction.length_squared();
        let f = ray.origin - self.centre;
        let tm = -f.dot(ray.direction) / d2;
        if self.g(ray, tm).sign() >= 0.0 {
            return Vec::new();
        }
        // Step 2: each root from a guess, bracketed by a sign change.
        let rho2 = self.rho2.hi;
        let half = 1.01 * (rho2 / d2).sqrt();
        let miss2 = (f + tm * ray.direction).length_squared();
        let guess = ((rho2 - miss2).max(0.0) / d2).sqrt();
        [-1.0, 1.0]
            .map(|side| {
                let far = tm + side * half;
                let t = tm + side * guess;
                let width = 1e-10 * half;
                // the bracket from outside (g > 0) to inside (g < 0)
                let (out, inside) = (t + side * width, t - side * width);
                let out = if side * (out - far) < 0.0 { out } else { far };
                let inside = if side * (inside - tm) > 0.0 {
                    inside
                } else {
                    tm
                };
                if self.g(ray, out).sign() > 0.0
                    && self.g(ray, inside).sign() < 0.0
                {
                    self.bisect(ray, out, inside, half)
                } else {
                    self.bisect(ray, far, tm, half)
                }
            })
            .to_vec()
    }

    /// The root between `out` (g > 0) and `inside` (g < 0), down to
    /// 1e-13 of `scale` (or to neighbouring doubles).
    fn bisect(
        &self, ray: &Ray, mut out: f64, mut inside: f64, scale: f64,
    ) -> f64 {
        while (out - inside).abs() > 1e-13 * (scale + out.abs()) {
            let mid = 0.5 * (out + inside);
            if mid == out || mid == inside {
                break;
            }
            match self.g(ray, mid).sign() {
                s if s > 0.0 => out = mid,
                s if s < 0.0 => inside = mid,
                _ => return mid,
            }
        }
        0.5 * (out + inside)
    }
}

// ---------------------------------------------------------------------
// Spheres: four ways to solve the quadratic.
// ---------------------------------------------------------------------

/// The sphere's methods, as the table names them: chapter 3's formulas
/// typed in as they stand, chapter 8's `quadratic_roots` on the
/// coefficients, chapter 3's `Sphere::intersect`, and chapter 8's
/// ellipsoid (its `sphere_roots`) with three equal radii.
const SPHERE_METHODS: [&str; 4] = [
    "sphere (textbook formula)",
    "sphere (quadratic_roots)",
    "sphere (chapter 3)",
    "ellipsoid (sphere_roots)",
];

/// Chapter 3's formulas typed in as they stand, the form its text warns
/// against: Δ = b² − a·c and t = (b ± √Δ)/a; the nearer root in the
/// interval, else the farther.
fn textbook(sphere: &Sphere, ray: &Ray, interval: Interval) -> Option<f64> {
    let d = ray.direction;
    let f = ray.origin - sphere.center;
    let a = d.dot(d);
    let b = -f.dot(d);
    let c = f.dot(f) - sphere.radius * sphere.radius;
    let discriminant = b * b - a * c;
    if discriminant < 0.0 {
        return None;
    }
    let root = discriminant.sqrt();
    [(b - root) / a, (b + root) / a]
        .into_iter()
        .find(|&t| interval.contains(t))
}

/// The first hit of each sphere method within `interval`.
fn sphere_hits(
    sphere: &Sphere, ray: &Ray, interval: Interval,
) -> [Option<f64>; 4] {
    let d = ray.direction;
    let f = ray.origin - sphere.center;
    let r2 = sphere.radius * sphere.radius;
    let coefficients = [f.dot(f) - r2, 2.0 * f.dot(d), d.dot(d)];
    let ellipsoid = Ellipsoid::new(sphere.center, DVec3::splat(sphere.radius))
        .expect("a sphere is an ellipsoid");
    [
        textbook(sphere, ray, interval),
        quadratic_roots(coefficients)
            .into_iter()
            .find(|&t| interval.contains(t)),
        sphere.intersect(ray, interval).map(|hit| hit.t),
        ellipsoid.intersect(ray, interval).map(|hit| hit.t),
    ]
}

/// A sphere method fails a ray if it misses where the truth hits, hits
/// where it misses, or puts the hit more than 1e-6·r along the ray
/// from the truth's.
fn sphere_failures(
    sphere: &Sphere, ray: &Ray, interval: Interval,
) -> [bool; 4] {
    let truth = Round::sphere(sphere.center, sphere.radius)
        .roots(ray)
        .into_iter()
        .find(|&t| interval.contains(t));
    let length = ray.direction.length();
    sphere_hits(sphere, ray, interval).map(|t| match (t, truth) {
        (None, None) => false,
        (Some(t), Some(want)) => {
            (t - want).abs() * length > 1e-6 * sphere.radius
        }
        _ => true,
    })
}

/// A sphere of radius 1e-2…1e2 around a point within 10 radii of the
/// origin.
fn random_sphere(rng: &mut SplitMix64) -> Sphere {
    let radius = decades(rng, -2.0, 2.0);
    Sphere::new(10.0 * radius * cube_point(rng), radius)
}

/// One count per sphere method: the textbook formula and the textbook
/// discriminant are shown, chapter 3's form (twice) must survive.
fn per_sphere_method(
    failures: [u64; 4], trials: usize,
) -> Vec<(Count, Expect)> {
    let expect = [Expect::Shown, Expect::Shown, Expect::Never, Expect::Never];
    per_method(SPHERE_METHODS, failures, trials as u64, expect)
}

/// Rays passing the centre at r·(1 − δ) (two roots √(2δ)·r either side
/// of the closest point) or r·(1 + δ) (none), δ = 1e-12…1e-3, from
/// 2…100 radii before the closest point.
fn grazing_a_sphere(budget: &Budget) -> Vec<(Count, Expect)> {
    let failures = count_failures(budget.rays, 0x17_0101, |rng| {
        let sphere = random_sphere(rng);
        let d = rng.unit_vector();
        let (u, w) = d.any_orthonormal_pair();
        let angle = uniform(rng, 0.0, std::f64::consts::TAU);
        let side = angle.cos() * u + angle.sin() * w;
        let delta = decades(rng, -12.0, -3.0);
        let pass = if rng.next_f64() < 0.5 {
            1.0 - delta
        } else {
            1.0 + delta
        };
        let lead = uniform(rng, 2.0, 100.0) * sphere.radius;
        let origin = sphere.center + pass * sphere.radius * side - lead * d;
        sphere_failures(&sphere, &Ray::new(origin, d), Interval::FORWARD)
    });
    per_sphere_method(failures, budget.rays)
}

/// Rays from 1e6 radii away in a random direction, aimed at points of
/// the disc across the sphere (uniform in area, out to 0.999·r).
fn sphere_from_afar(budget: &Budget) -> Vec<(Count, Expect)> {
    let failures = count_failures(budget.rays, 0x17_0102, |rng| {
        let sphere = random_sphere(rng);
        let origin = sphere.center + 1e6 * sphere.radius * rng.unit_vector();
        let (u, w) =
            (sphere.center - origin).normalize().any_orthonormal_pair();
        let reach = 0.999 * sphere.radius * rng.next_f64().sqrt();
        let angle = uniform(rng, 0.0, std::f64::consts::TAU);
        let target =
            sphere.center + reach * (angle.cos() * u + angle.sin() * w);
        let ray = Ray::new(origin, (target - origin).normalize());
        sphere_failures(&sphere, &ray, Interval::FORWARD)
    });
    per_sphere_method(failures, budget.rays)
}

/// Origins on the sphere (C + r·n, rounded), in directions at least
/// 1e-3 off the tangent plane, inward or outward, asking for t ≥ 1e-6·r:
/// the root at t ≈ 0 is excluded, the far one (inward) must be found.
fn origin_on_the_sphere(budget: &Budget) -> Vec<(Count, Expect)> {
    let failures = count_failures(budget.rays, 0x17_0103, |rng| {
        let sphere = random_sphere(rng);
        let n = rng.unit_vector();
        let origin = sphere.center + sphere.radius * n;
        let d = loop {
            let d = rng.unit_vector();
            if d.dot(n).abs() >= 1e-3 {
                break d;
            }
        };
        let interval = Interval::new(1e-6 * sphere.radius, f64::INFINITY);
        sphere_failures(&sphere, &Ray::new(origin, d), interval)
    });
    let mut counts = per_sphere_method(failures, budget.rays);
    // even the textbook formula survives: the cancellation it suffers
    // here is ε·|b|, far below t_min
    counts.iter_mut().for_each(|(_, e)| *e = Expect::Never);
    counts
}

// ---------------------------------------------------------------------
// Tori: the closed form against the bracketed method.
// ---------------------------------------------------------------------

/// The torus's two solvers, in the chapter's order, with their names.
const TORUS_METHODS: [(TorusSolver, &str); 2] = [
    (TorusSolver::ClosedForm, "torus (closed form)"),
    (TorusSolver::Bracketed, "torus (bracketed)"),
];

/// A ring torus around the y axis at the origin: R = 0.5…2 and
/// r = 0.1…0.6 of it.
fn random_torus(rng: &mut SplitMix64) -> (f64, f64) {
    let major = uniform(rng, 0.5, 2.0);
    (major, major * uniform(rng, 0.1, 0.6))
}

/// A torus solver fails a ray if it misses a root of the truth (none of
/// its roots within 1e-6·r, one to one) or finds a root the truth has
/// not. `truth` holds the roots with t ≥ 0.
fn torus_failures(
    major: f64, minor: f64, ray: &Ray, truth: &[f64],
) -> [bool; 2] {
    let within = 1e-6 * minor / ray.direction.length();
    TORUS_METHODS.map(|(solver, _)| {
        let torus = Torus::new(DVec3::ZERO, DVec3::Y, major, minor, solver)
            .expect("a ring torus");
        let mut found = torus.roots(ray);
        if found.len() != truth.len() {
            return true;
        }
        found.sort_by(f64::total_cmp);
        found
            .iter()
            .zip(truth)
            .any(|(t, want)| (t - want).abs() > within)
    })
}

/// The roots with t ≥ 0, sorted, of a ray lying in the plane y = h
/// across the axis of the torus (R, r): where it meets the circles of
/// radius R ± √(r² − h²) in that plane.
fn roots_in_a_plane(major: f64, minor: f64, ray: &Ray) -> Vec<f64> {
    let h = ray.origin.y;
    if h.abs() >= minor {
        return Vec::new();
    }
    // (r − h)(r + h): r − h is exact near the top, where it matters
    let w = ((minor - h) * (minor + h)).sqrt();
    let mut roots: Vec<f64> = [1.0, -1.0]
        .into_iter()
        .flat_map(|sign| Round::circle(h, major, w, sign).roots(ray))
        .filter(|&t| t >= 0.0)
        .collect();
    roots.sort_by(f64::total_cmp);
    roots
}

/// A ray in the plane y = `height`, along the horizontal direction at
/// `angle`, passing the axis at `pass` and starting `lead` before the
/// closest point.
fn level_ray(height: f64, angle: f64, pass: f64, lead: f64) -> Ray {
    let d = DVec3::new(angle.cos(), 0.0, angle.sin());
    let side = DVec3::new(-angle.sin(), 0.0, angle.cos());
    let origin = pass * side - lead * d;
    Ray::new(DVec3::new(origin.x, height, origin.z), d)
}

/// Runs `trials` level rays made by `ray` from a random torus (R, r),
/// and counts each solver's failures against the truth.
fn torus_case(
    budget: &Budget, seed: u64, ray: fn(&mut SplitMix64, f64, f64) -> Ray,
) -> Vec<(Count, Expect)> {
    let failures = count_failures(budget.rays, seed, |rng| {
        let (major, minor) = random_torus(rng);
        let ray = ray(rng, major, minor);
        let truth = roots_in_a_plane(major, minor, &ray);
        torus_failures(major, minor, &ray, &truth)
    });
    per_torus_method(failures, budget.rays)
}

/// One count per solver: the closed form shown, the bracketed method
/// must survive.
fn per_torus_method(failures: [u64; 2], trials: usize) -> Vec<(Count, Expect)> {
    let names = TORUS_METHODS.map(|(_, name)| name);
    per_method(
        names,
        failures,
        trials as u64,
        [Expect::Shown, Expect::Never],
    )
}

/// δ = 1e-9…1e-3, either side, and a lead of 4…100·R.
fn offset_and_lead(rng: &mut SplitMix64, major: f64, minor: f64) -> (f64, f64) {
    let sign = if rng.next_f64() < 0.5 { -1.0 } else { 1.0 };
    let delta = sign * decades(rng, -9.0, -3.0) * minor;
    (delta, decades(rng, 4f64.log10(), 2.0) * major)
}

/// Rays in the equatorial plane passing the axis at R + r ∓ δ: two
/// roots close together inside, none outside.
fn grazing_the_equator(budget: &Budget) -> Vec<(Count, Expect)> {
    torus_case(budget, 0x17_0104, |rng, major, minor| {
        let (delta, lead) = offset_and_lead(rng, major, minor);
        let angle = uniform(rng, 0.0, std::f64::consts::TAU);
        level_ray(0.0, angle, major + minor + delta, lead)
    })
}

/// Rays in the equatorial plane passing the axis at R − r ± δ: a brief
/// dip into the hole (four roots, the middle two close) or none (two).
fn grazing_the_hole(budget: &Budget) -> Vec<(Count, Expect)> {
    torus_case(budget, 0x17_0105, |rng, major, minor| {
        let (delta, lead) = offset_and_lead(rng, major, minor);
        let angle = uniform(rng, 0.0, std::f64::consts::TAU);
        level_ray(0.0, angle, major - minor + delta, lead)
    })
}

/// Horizontal rays at height r ∓ δ passing the axis at R, tangent to
/// the top circle: two roots below it, none above.
fn tangent_to_the_top(budget: &Budget) -> Vec<(Count, Expect)> {
    torus_case(budget, 0x17_0106, |rng, major, minor| {
        let (delta, lead) = offset_and_lead(rng, major, minor);
        let angle = uniform(rng, 0.0, std::f64::consts::TAU);
        level_ray(minor + delta, angle, major, lead)
    })
}

/// Rays in the equatorial plane from 1e3…1e6 away, passing the axis
/// anywhere within 0.99·(R + r): two or four roots.
fn torus_from_afar(budget: &Budget) -> Vec<(Count, Expect)> {
    torus_case(budget, 0x17_0107, |rng, major, minor| {
        let angle = uniform(rng, 0.0, std::f64::consts::TAU);
        let pass = uniform(rng, 0.0, 0.99) * (major + minor);
        level_ray(0.0, angle, pass, decades(rng, 3.0, 6.0))
    })
}

/// Rays along the axis, toward the torus from above or below (2…1000·R
/// away), on the axis or off it by up to 0.99·(R − r): no roots.
fn along_the_axis(budget: &Budget) -> Vec<(Count, Expect)> {
    let failures = count_failures(budget.rays, 0x17_0108, |rng| {
        let (major, minor) = random_torus(rng);
        let side = if rng.next_f64() < 0.5 { 1.0 } else { -1.0 };
        let off = if rng.next_f64() < 0.1 {
            0.0
        } else {
            uniform(rng, 0.0, 0.99) * (major - minor)
        };
        let angle = uniform(rng, 0.0, std::f64::consts::TAU);
        let height = side * decades(rng, 2f64.log10(), 3.0) * major;
        let ray = Ray::new(
            DVec3::new(off * angle.cos(), height, off * angle.sin()),
            DVec3::new(0.0, -side, 0.0),
        );
        torus_failures(major, minor, &ray, &[])
    });
    let mut counts = per_torus_method(failures, budget.rays);
    counts[0].1 = Expect::Never; // no odd terms: the closed form's easy case
    counts
}
