//! Refraction and media: chapter 6's Snell direction ([`refract`]), its
//! reflectances ([`fresnel`], [`schlick`]) and the stack of media a ray is
//! in ([`Media`]), at the critical angle, head-on, grazing, and through
//! surfaces that coincide.
//!
//! A direction fails if it is NaN, not a unit vector (|len − 1| > 1e-12),
//! on the wrong side of the surface, or reported where total internal
//! reflection (TIR) is the truth, or missing where it is not. A
//! reflectance fails if it is outside [0, 1], or not 1 at TIR.
use std::sync::Arc;

use ch03::{BruteForce, Sphere};
use ch04::offset_scale_aware;
use ch06::{
    CAMERA_MEDIUM, MAX_NESTING, Media, REFRACTIVE_INDICES, critical_angle,
    fresnel, index_of_refraction, refract, schlick,
};
use ch08::SplitMix64;
use raystep_core::{DVec3, Interval, Ray};
use raystep_world::{Accelerator, Object};

use crate::trials::{below, count_failures, per_method, tangent};
use crate::{Budget, Case, Count, Expect};

const GROUP: &str = "refraction and media";

/// How far from unit length a direction may be.
const UNIT: f64 = 1e-12;

/// How far either side of the critical angle the rays go, in radians.
const NEAR_CRITICAL: f64 = 1e-9;

/// Schlick's error that counts as a failure near the critical angle: one
/// percentage point of reflectance.
const SCHLICK_TOLERANCE: f64 = 0.01;

/// How far below the critical angle Schlick is compared, in degrees.
const WINDOW: f64 = 5.0;

/// This group's cases.
pub fn cases() -> Vec<Case> {
    vec![
        Case {
            group: GROUP,
            name: "glass into air at the critical angle",
            what: "θc and θc ± 1e-9 rad: TIR decided by a sin²φ 2e-9 from 1; \
                   refract, fresnel, schlick survive",
            run: critical_glass,
        },
        Case {
            group: GROUP,
            name: "diamond into air at the critical angle",
            what: "θc and θc ± 1e-9 rad, n = 2.417: refract, fresnel and \
                   schlick survive",
            run: critical_diamond,
        },
        Case {
            group: GROUP,
            name: "normal incidence",
            what: "D = −N, no plane of incidence: T = D and R = R₀ from \
                   refract, fresnel, schlick",
            run: normal_incidence,
        },
        Case {
            group: GROUP,
            name: "grazing incidence",
            what: "cos θ ≈ 1e-12, different media: T unit and through, R in \
                   [0, 1]; all three survive",
            run: grazing_incidence,
        },
        Case {
            group: GROUP,
            name: "grazing an index-matched surface",
            what: "n = n, cos θ ≈ 1e-12: 1 − cos²θ rounds to 1; refract and \
                   fresnel (cos²φ as 1 − η² + η²cos²θ) survive, Schlick ≈ 1",
            run: index_matched,
        },
        Case {
            group: GROUP,
            name: "coincident surfaces",
            what: "radii 1 ± 4 ulps: enter one sphere, leave the other; the \
                   stack ends unbalanced (ch06 has no cure)",
            run: coincident_surfaces,
        },
        Case {
            group: GROUP,
            name: "media entered and left in random orders",
            what: "up to 8 overlapping media: the stack returns to vacuum; \
                   the swap rule gets indices wrong",
            run: random_orders,
        },
        Case {
            group: GROUP,
            name: "Schlick near the critical angle",
            what: "5° below θc: Schlick is often off the exact R by > 0.01 \
                   (worst: 0.036 glass, 0.075 diamond)",
            run: schlick_near_critical,
        },
    ]
}

/// An index of refraction from chapter 6's table.
fn ior(name: &str) -> f64 {
    index_of_refraction(name).expect("a material of the table")
}

/// A random surface normal N and a unit tangent U ⟂ N.
fn frame(rng: &mut SplitMix64) -> (DVec3, DVec3) {
    let n = rng.unit_vector();
    (n, tangent(rng, n))
}

/// The ray at angle θ to N: D = sin θ·U − cos θ·N, on N's side.
fn at_angle(n: DVec3, u: DVec3, theta: f64) -> DVec3 {
    (theta.sin() * u - theta.cos() * n).normalize()
}

/// Is `t` a unit direction through the surface (T·N < `below`)?
fn through(t: DVec3, n: DVec3, below: f64) -> bool {
    t.is_finite() && (t.length() - 1.0).abs() <= UNIT && t.dot(n) < below
}

/// What the truth allows at one crossing: TIR, a transmitted ray, or
/// either (at the critical angle itself, where rounding decides).
#[derive(Clone, Copy, PartialEq)]
enum Truth {
    Reflects,
    Transmits,
    Either,
}

/// Is this reflectance right for the truth?
fn reflectance_right(r: f64, truth: Truth) -> bool {
    match truth {
        Truth::Reflects => r == 1.0,
        Truth::Transmits => (0.0..1.0).contains(&r),
        Truth::Either => (0.0..=1.0).contains(&r),
    }
}

/// The two reflectances at cos θ: the exact equations' and Schlick's.
fn reflectances(cos_theta: f64, n_theta: f64, n_phi: f64) -> [f64; 2] {
    [
        fresnel(cos_theta, n_theta, n_phi),
        schlick(cos_theta, n_theta, n_phi),
    ]
}

/// Runs `trial` `budget.rays` times: each says whether refract, fresnel
/// and schlick failed; counted, none of the three allowed to fail.
fn three(
    budget: &Budget, seed: u64, trial: impl FnMut(&mut SplitMix64) -> [bool; 3],
) -> Vec<(Count, Expect)> {
    let failed = count_failures(budget.rays, seed, trial);
    let methods = ["refract", "fresnel", "schlick"];
    per_method(methods, failed, budget.rays as u64, [Expect::Never; 3])
}

/// Rays leaving `material` into air at θc − 1e-9, θc and θc + 1e-9 rad in
/// turn, in random frames.
fn critical(
    budget: &Budget, material: &str, seed: u64,
) -> Vec<(Count, Expect)> {
    let (n_theta, n_phi) = (ior(material), ior("air"));
    let theta_c = critical_angle(n_theta, n_phi).expect("denser than air");
    let mut trial = 0;
    three(budget, seed, |rng| {
        // Step 1: the angle, and what the truth allows there. 1e-9 rad
        // moves sin²φ by 2e-9, ten million times its rounding error.
        let (delta, truth) = match trial % 3 {
            0 => (-NEAR_CRITICAL, Truth::Transmits),
            1 => (0.0, Truth::Either),
            _ => (NEAR_CRITICAL, Truth::Reflects),
        };
        trial += 1;
        let (n, u) = frame(rng);
        let d = at_angle(n, u, theta_c + delta);
        // Step 2: the direction: none past θc, a unit T below it, and at θc
        // either, a T then grazing the surface (|T·N| < 1e-7).
        let right = match (refract(d, n, n_theta, n_phi), truth) {
            (None, Truth::Transmits) => false,
            (None, _) => true,
            (Some(_), Truth::Reflects) => false,
            (Some(t), Truth::Transmits) => through(t, n, 0.0),
            (Some(t), Truth::Either) => through(t, n, 1e-7) && t.dot(n) > -1e-7,
        };
        // Step 3: the reflectances, both formulas.
        let [f, s] = reflectances(-d.dot(n), n_theta, n_phi)
            .map(|r| !reflectance_right(r, truth));
        [!right, f, s]
    })
}

/// Glass (1.5) into air at its critical angle.
fn critical_glass(budget: &Budget) -> Vec<(Count, Expect)> {
    critical(budget, "glass", 0x5EED_0601)
}

/// Diamond (2.417) into air at its critical angle.
fn critical_diamond(budget: &Budget) -> Vec<(Count, Expect)> {
    critical(budget, "diamond", 0x5EED_0602)
}

/// A random material of the table.
fn material(rng: &mut SplitMix64) -> f64 {
    REFRACTIVE_INDICES[below(rng, REFRACTIVE_INDICES.len())].1
}

/// Two random materials of the table, the ray's side and the other; with
/// `distinct`, never the same one twice.
fn two_materials(rng: &mut SplitMix64, distinct: bool) -> (f64, f64) {
    loop {
        let (a, b) = (material(rng), material(rng));
        if !distinct || a != b {
            return (a, b);
        }
    }
}

/// A direction at cos θ log-uniform in [1e-13, 1e-11] to the unit `n`,
/// along the unit tangent `u`: grazing the surface, on N's side.
fn grazing(rng: &mut SplitMix64, n: DVec3, u: DVec3) -> DVec3 {
    let cos = 10f64.powf(-13.0 + 2.0 * rng.next_f64());
    (cos * -n + (1.0 - cos * cos).sqrt() * u).normalize()
}

/// D = −N between random materials: T = D, R = R₀.
fn normal_incidence(budget: &Budget) -> Vec<(Count, Expect)> {
    three(budget, 0x5EED_0603, |rng| {
        // Step 1: straight at the surface, between two random materials.
        let n = rng.unit_vector();
        let d = -n;
        let (n_theta, n_phi) = two_materials(rng, false);
        // Step 2: T goes straight on: T = D.
        let right = refract(d, n, n_theta, n_phi)
            .is_some_and(|t| through(t, n, 0.0) && (t - d).length() <= UNIT);
        // Step 3: R is R₀ = ((n_θ − n_φ)/(n_θ + n_φ))², both formulas.
        let r0 = ((n_theta - n_phi) / (n_theta + n_phi)).powi(2);
        let [f, s] = reflectances(-d.dot(n), n_theta, n_phi)
            .map(|r| (r - r0).abs() > UNIT);
        [!right, f, s]
    })
}

/// cos θ ≈ 1e-12 between two different materials.
fn grazing_incidence(budget: &Budget) -> Vec<(Count, Expect)> {
    three(budget, 0x5EED_0604, |rng| {
        // Step 1: cos θ ≈ 1e-12, between two different media.
        let (n, u) = frame(rng);
        let d = grazing(rng, n, u);
        let (n_theta, n_phi) = two_materials(rng, true);
        // Step 2: into a denser medium a unit T through the surface that
        // obeys Snell's law; out of a denser one, TIR.
        let truth = if n_theta > n_phi {
            Truth::Reflects
        } else {
            Truth::Transmits
        };
        let right = match (refract(d, n, n_theta, n_phi), truth) {
            (Some(t), Truth::Transmits) => {
                let snell =
                    n_theta * d.cross(n).length() - n_phi * t.cross(n).length();
                through(t, n, 0.0) && snell.abs() <= UNIT
            }
            (None, Truth::Reflects) => true,
            _ => false,
        };
        // Step 3: R in [0, 1], 1 at TIR.
        let [f, s] = reflectances(-d.dot(n), n_theta, n_phi)
            .map(|r| !reflectance_right(r, truth));
        [!right, f, s]
    })
}

/// cos θ ≈ 1e-12 with the same index on both sides: no surface at all.
fn index_matched(budget: &Budget) -> Vec<(Count, Expect)> {
    let mut counts = three(budget, 0x5EED_0608, |rng| {
        // Step 1: cos θ ≈ 1e-12, the same medium on both sides (as the
        // stack gives between overlapping objects, or after a mismatch).
        let (n, u) = frame(rng);
        let d = grazing(rng, n, u);
        let index = material(rng);
        // Step 2: no surface, no bending: T = D (within chapter 6's 1e-9).
        let right = refract(d, n, index, index).is_some_and(|t| {
            t.is_finite()
                && (t.length() - 1.0).abs() <= UNIT
                && (t - d).length() <= 1e-9
        });
        // Step 3: no surface, no reflection: R = 0.
        let [f, s] = reflectances(-d.dot(n), index, index)
            .map(|r| !(0.0..=UNIT).contains(&r));
        [!right, f, s]
    });
    // chapter 6's `fresnel` sums cos²φ as (1 − η²) + η²cos²θ, which is
    // cos²θ itself for η = 1 (1 − η²(1 − cos²θ) would round to 0 here and
    // report total reflection): built to survive. Schlick's curve ignores
    // n and rises to 1.
    counts[2].1 = Expect::Shown;
    counts
}

/// The most surfaces one walk crosses before it counts as lost.
const MAX_CROSSINGS: usize = 32;

/// Follows `ray` through `objects` (with indices `iors`) the way chapter
/// 6's tracer follows its transmitted ray: the closest hit, the crossing
/// of the media stack, Snell's direction from a scale-aware offset origin
/// (or the mirror direction at TIR, in the same media). Returns whether
/// every crossing agreed with the stack and the ray left everything with
/// the stack empty again.
fn walk(objects: &[Object], iors: &[f64], ray: Ray) -> bool {
    let open = Media::new(CAMERA_MEDIUM);
    let (mut ray, mut media, mut consistent) = (ray, open, true);
    for _ in 0..MAX_CROSSINGS {
        // Step 1: the closest hit (the lecture's loop); none: out.
        let Some((object, hit)) =
            BruteForce.closest_hit(objects, &ray, Interval::FORWARD)
        else {
            return consistent && media == open;
        };
        // Step 2: entering or leaving, and the crossing of the stack.
        let d = ray.direction.normalize();
        let normal = hit.facing(d);
        let entering = hit.normal.dot(d) < 0.0;
        let crossing = media.cross(object, iors[object], entering);
        consistent &= crossing.consistent;
        // Step 3: on through the surface, or back at TIR.
        ray = match refract(d, normal, crossing.n_theta, crossing.n_phi) {
            Some(t) => {
                media = crossing.beyond;
                Ray::new(offset_scale_aware(hit.point, -normal), t)
            }
            None => Ray::new(
                offset_scale_aware(hit.point, normal),
                d - 2.0 * d.dot(normal) * normal,
            ),
        };
    }
    false // lost: more crossings than two spheres can give
}

/// Rays through a water sphere and a glass sphere whose surfaces
/// coincide to within 4 ulps, walked as chapter 6's tracer walks them.
fn coincident_surfaces(budget: &Budget) -> Vec<(Count, Expect)> {
    let centre = DVec3::new(0.3, -0.2, 0.1);
    let iors = [ior("water"), ior("glass")];
    let failed = count_failures(budget.rays, 0x5EED_0605, |rng| {
        // Step 1: a water sphere of radius 1 and a glass sphere whose radius
        // is 1 within 4 ulps (made by another computation, say).
        let ulps = below(rng, 9) as i64 - 4;
        let radius = f64::from_bits((1f64.to_bits() as i64 + ulps) as u64);
        let objects = [1.0, radius].map(|r| Object {
            shape: Arc::new(Sphere::new(centre, r)),
            material: 0,
        });
        // Step 2: a random line through them, from outside.
        let eye = centre + 3.0 * rng.unit_vector();
        let target = centre + 0.9 * rng.next_f64().sqrt() * rng.unit_vector();
        let ray = Ray::new(eye, (target - eye).normalize());
        [!walk(&objects, &iors, ray)]
    });
    per_method(["Media"], failed, budget.rays as u64, [Expect::Shown])
}

/// The lecture's rule without a stack: entering, n_θ is the camera's
/// medium and n_φ the object's; leaving, the two swapped.
fn swap_rule(ior: f64, entering: bool) -> (f64, f64) {
    if entering {
        (CAMERA_MEDIUM, ior)
    } else {
        (ior, CAMERA_MEDIUM)
    }
}

/// The stack, and the swap rule, over random sequences of crossings.
fn random_orders(budget: &Budget) -> Vec<(Count, Expect)> {
    let failed = count_failures(budget.rays, 0x5EED_0606, |rng| {
        // Step 1: 1 to 8 objects (random ids and indices), each entered and
        // left once, in a random order of the 2n crossings.
        let count = 1 + below(rng, MAX_NESTING);
        let mut outside: Vec<(usize, f64)> = (0..count)
            .map(|i| (1000 * i + below(rng, 1000), material(rng)))
            .collect();
        // `inside` is the truth: the objects around the ray, innermost last.
        let mut inside: Vec<(usize, f64)> = Vec::new();
        let (mut media, mut stack_right, mut swap_right) =
            (Media::new(CAMERA_MEDIUM), true, true);
        while !(outside.is_empty() && inside.is_empty()) {
            let current = |inside: &[(usize, f64)]| {
                inside.last().map_or(CAMERA_MEDIUM, |o| o.1)
            };
            let n_theta = current(&inside);
            // Step 2: enter one of the objects outside, or leave one inside.
            let enter = inside.is_empty()
                || (!outside.is_empty() && rng.next_f64() < 0.5);
            let (from, to) = if enter {
                (&mut outside, &mut inside)
            } else {
                (&mut inside, &mut outside)
            };
            let at = below(rng, from.len());
            let (object, index) = from.remove(at);
            if enter {
                to.push((object, index));
            }
            let truth = (n_theta, current(&inside));
            // Step 3: the stack's crossing, and the swap rule's, against it.
            let c = media.cross(object, index, enter);
            stack_right &= c.consistent && (c.n_theta, c.n_phi) == truth;
            media = c.beyond;
            swap_right &= swap_rule(index, enter) == truth;
        }
        // Step 4: out of everything, the stack is the open again.
        stack_right &= media == Media::new(CAMERA_MEDIUM);
        [!stack_right, !swap_right]
    });
    let methods = ["Media", "swap rule"];
    let expect = [Expect::Never, Expect::Shown];
    per_method(methods, failed, budget.rays as u64, expect)
}

/// Schlick against the exact R up to 5° below the critical angle.
fn schlick_near_critical(budget: &Budget) -> Vec<(Count, Expect)> {
    let mut trial = 0;
    let failed = count_failures(budget.rays, 0x5EED_0607, |rng| {
        // Step 1: out of glass or diamond into air, up to 5° below θc.
        let material = ["glass", "diamond"][trial % 2];
        trial += 1;
        let (n_theta, n_phi) = (ior(material), ior("air"));
        let theta_c = critical_angle(n_theta, n_phi).expect("denser than air");
        let theta = theta_c - WINDOW.to_radians() * rng.next_f64();
        // Step 2: Schlick against the exact equations.
        let c = theta.cos();
        let error =
            (schlick(c, n_theta, n_phi) - fresnel(c, n_theta, n_phi)).abs();
        [error > SCHLICK_TOLERANCE]
    });
    per_method(["schlick"], failed, budget.rays as u64, [Expect::Shown])
}
