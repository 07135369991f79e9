//! Self-intersection: where chapter 4's shadow ray starts. A hit point is
//! rounded, a little above or below its surface; a shadow ray that starts
//! below finds that surface again (acne), and one lifted too far skips a
//! blocker close to the surface (a leak).
//!
//! Each trial is chapter 4's `tests/normal_offset.rs` experiment: a random
//! primary ray hits a surface (a sphere, a tilted plane or a triangle), a
//! light lies in a random direction in front of the hit point, and a
//! parallel blocker, a sheet of paper 3e-4 of the scene's size above the
//! surface, lies between them. The truth is a shadow ray from the unmoved
//! point that tests the blocker only (a sphere, a plane or a triangle
//! cannot shadow itself where the light is in front of it). A strategy
//! fails the trial if its shadow ray meets the surface it starts on, or
//! disagrees with the truth about the blocker.
//!
//! The strategies are chapter 4's [`Offset`]s, named as its tests name
//! them: no offset at all (`TMin(0)`), a fixed t_min (`TMin(1e-4)`), a
//! fixed lift along the normal (`AlongNormal(1e-9)`), and Wächter and
//! Binder's lift by ulps of the point's own coordinates (`ScaleAware`).
use ch02::{InfinitePlane, Plane};
use ch03::Sphere;
use ch04::{Offset, shadow_ray};
use ch08::{SplitMix64, Triangle, TriangleTest};
use raystep_core::{DVec3, Interval, Ray, Shape};

use crate::trials::tangent;
use crate::{Budget, Case, Count, Expect};

const GROUP: &str = "self-intersection";

/// The strategies, in the order of the table.
const OFFSETS: [Offset; 4] = [
    Offset::TMin(0.0),
    Offset::TMin(1e-4),
    Offset::AlongNormal(1e-9),
    Offset::ScaleAware,
];

/// How far each blocker lies above its surface, as a fraction of the
/// scene's size (chapter 4's `GAP`: a sheet of paper on a 1 m table).
const GAP: f64 = 3e-4;

/// How far the light is from the hit point, in scene sizes.
const LIGHT_DISTANCE: f64 = 10.0;

/// This group's cases.
pub fn cases() -> Vec<Case> {
    vec![
        Case {
            group: GROUP,
            name: "shadow ray at scale 1e-6",
            what: "blocker 3e-10 away: fixed t_min and lift skip it (leak); \
                   scale-aware survives",
            run: at_1e_minus_6,
        },
        Case {
            group: GROUP,
            name: "shadow ray at scale 1e-3",
            what: "blocker 3e-7 away: t_min = 1e-4 skips it (leak); the 1e-9 \
                   lift and scale-aware survive",
            run: at_1e_minus_3,
        },
        Case {
            group: GROUP,
            name: "shadow ray at scale 1",
            what: "the scale every fixed ε is made for: only no offset at all \
                   has acne",
            run: at_1,
        },
        Case {
            group: GROUP,
            name: "shadow ray at scale 1e3",
            what: "rounding error ~1e-12, blocker 0.3 away: every offset \
                   survives, no offset has acne",
            run: at_1e3,
        },
        Case {
            group: GROUP,
            name: "shadow ray at scale 1e7",
            what: "error ~1e-8 passes the 1e-9 lift, and t_min at grazing \
                   light (acne); scale-aware survives",
            run: at_1e7,
        },
        Case {
            group: GROUP,
            name: "small object 1e7 from the origin",
            what: "size 1, coordinates 1e7: error ~1e-8, the fixed lift and \
                   t_min get acne; scale-aware survives",
            run: far_from_the_origin,
        },
        Case {
            group: GROUP,
            name: "grazing light",
            what: "light 1e-12…1e-3 rad over the tangent plane: t_min's \
                   re-hit t grows as 1/cos θ; lifts survive",
            run: grazing_light,
        },
        Case {
            group: GROUP,
            name: "floor through the origin, seen from 3e4",
            what: "y ≈ 0 moves by 2⁻⁴⁵ only, its error is ~1e-12: scale-aware \
                   gets acne; fixed ε survive",
            run: floor_through_the_origin,
        },
    ]
}

/// The strategy's name, as chapter 4's tests write it.
fn name(offset: Offset) -> String {
    match offset {
        Offset::TMin(0.0) => "TMin(0)".to_string(),
        Offset::TMin(epsilon) => format!("TMin({epsilon:e})"),
        Offset::AlongNormal(epsilon) => format!("AlongNormal({epsilon:e})"),
        Offset::ScaleAware => "ScaleAware".to_string(),
    }
}

/// A surface, its blocker `GAP·scale` above it, and random primary rays
/// that hit the surface from the blocker's side.
struct Target {
    surface: Box<dyn Shape>,
    blocker: Box<dyn Shape>,
    aim: Box<dyn Fn(&mut SplitMix64) -> Ray>,
}

/// A sphere, a tilted plane and a triangle, each about `scale` in size,
/// around `shift` (chapter 4's sphere and plane, moved).
fn targets(scale: f64, shift: DVec3) -> Vec<Target> {
    let s = scale;
    // Step 1: a sphere straddling the three coordinate planes (at shift 0),
    // and a sphere GAP·s larger around it.
    let (c, r) = (shift + DVec3::new(0.3, -0.2, 0.1) * s, 1.5 * s);
    let sphere = Target {
        surface: Box::new(Sphere::new(c, r)),
        blocker: Box::new(Sphere::new(c, r + GAP * s)),
        aim: Box::new(move |rng| {
            let eye = c + 4.0 * r * rng.unit_vector();
            let target =
                c + 0.99 * r * rng.next_f64().sqrt() * rng.unit_vector();
            Ray::new(eye, (target - eye).normalize())
        }),
    };
    // Step 2: a tilted plane that misses the origin, and its parallel.
    let p0 = shift + DVec3::new(0.2, -1.0, 0.3) * s;
    let n0 = DVec3::new(0.1, 1.0, -0.2).normalize();
    let plane = |point: DVec3| {
        Box::new(InfinitePlane(Plane {
            normal: n0,
            d: -n0.dot(point),
        }))
    };
    let aim_plane = move |rng: &mut SplitMix64, centre: DVec3, size: f64| {
        let eye = centre + s * (3.0 * n0 + 2.0 * tangent(rng, n0));
        let target = centre + size * rng.next_f64().sqrt() * tangent(rng, n0);
        Ray::new(eye, (target - eye).normalize())
    };
    let plane = Target {
        surface: plane(p0),
        blocker: plane(p0 + GAP * s * n0),
        aim: Box::new(move |rng| aim_plane(rng, p0, 2.0 * s)),
    };
    // Step 3: a triangle in another tilted plane (watertight test), and a
    // triangle three times its size above it; aimed at the disc inside it.
    let q = shift + DVec3::new(-0.4, 0.7, -0.5) * s;
    let n1 = DVec3::new(-0.3, 0.2, 1.0).normalize();
    let (u, v) = n1.any_orthonormal_pair();
    let corners = |centre: DVec3, size: f64| {
        [
            centre + size * 2.0 * u,
            centre + size * (-u + 1.7 * v),
            centre + size * (-u - 1.7 * v),
        ]
    };
    let triangle = |corners| {
        Box::new(
            Triangle::new(corners, TriangleTest::Watertight)
                .expect("the corners fix a plane"),
        )
    };
    let triangle = Target {
        surface: triangle(corners(q, s)),
        blocker: triangle(corners(q + GAP * s * n1, 3.0 * s)),
        aim: Box::new(move |rng| {
            let eye = q + s * (3.0 * n1 + 2.0 * tangent(rng, n1));
            let target =
                q + 0.95 * s * rng.next_f64().sqrt() * tangent(rng, n1);
            Ray::new(eye, (target - eye).normalize())
        }),
    };
    vec![sphere, plane, triangle]
}

/// The floor y = 0 and a sheet GAP·scale above it, seen from 3·scale
/// above (chapter 4's "floor y = 0").
fn floor(scale: f64) -> Target {
    let plane = |height: f64| {
        Box::new(InfinitePlane(Plane {
            normal: DVec3::Y,
            d: -height,
        }))
    };
    Target {
        surface: plane(0.0),
        blocker: plane(GAP * scale),
        aim: Box::new(move |rng| {
            let eye = scale * (3.0 * DVec3::Y + 2.0 * tangent(rng, DVec3::Y));
            let target = 2.0 * scale * tangent(rng, DVec3::Y);
            Ray::new(eye, (target - eye).normalize())
        }),
    }
}

/// A direction uniformly over the hemisphere of the unit `normal` (cos θ
/// uniform on [0, 1]).
fn hemisphere(rng: &mut SplitMix64, normal: DVec3) -> DVec3 {
    let d = rng.unit_vector();
    if d.dot(normal) < 0.0 { -d } else { d }
}

/// A direction at an angle 1e-12 to 1e-3 rad above the tangent plane of
/// the unit `normal`, log-uniformly.
fn grazing(rng: &mut SplitMix64, normal: DVec3) -> DVec3 {
    let cos = 10f64.powf(-12.0 + 9.0 * rng.next_f64());
    let sin = (1.0 - cos * cos).sqrt();
    sin * tangent(rng, normal) + cos * normal
}

/// Runs `trials` shadow rays over `targets` in turn, each toward a light
/// `LIGHT_DISTANCE·scale` away in a direction drawn by `light`, and counts
/// each strategy's failures: its ray meets the surface it starts on
/// (acne), or differs from the truth about the blocker (a leak).
fn failures(
    targets: &[Target], scale: f64, light: fn(&mut SplitMix64, DVec3) -> DVec3,
    trials: usize, seed: u64,
) -> Vec<(Count, Offset)> {
    let mut rng = SplitMix64::new(seed);
    let mut failed = [0u64; OFFSETS.len()];
    let mut done = 0;
    while done < trials {
        let target = &targets[done % targets.len()];
        // Step 1: a primary ray and its hit (rays that miss are drawn again).
        let primary = (target.aim)(&mut rng);
        let Some(hit) = target.surface.intersect(&primary, Interval::FORWARD)
        else {
            continue;
        };
        done += 1;
        // Step 2: the light, in front of the surface as the ray sees it.
        let normal = hit.facing(primary.direction);
        let light_position =
            hit.point + LIGHT_DISTANCE * scale * light(&mut rng, normal);
        // Step 3: the truth, from the unmoved point: the blocker only.
        let truth = target
            .blocker
            .intersect(
                &Ray::new(hit.point, light_position - hit.point),
                Interval::new(0.0, 1.0),
            )
            .is_some();
        // Step 4: each strategy's shadow ray, against both surfaces.
        for (offset, failed) in OFFSETS.iter().zip(&mut failed) {
            let (ray, interval) =
                shadow_ray(hit.point, normal, light_position, *offset);
            let acne = target.surface.intersect(&ray, interval).is_some();
            let blocked = target.blocker.intersect(&ray, interval).is_some();
            if acne || blocked != truth {
                *failed += 1;
            }
        }
    }
    OFFSETS
        .iter()
        .zip(failed)
        .map(|(&offset, f)| {
            (Count::new(name(offset), f, trials as u64), offset)
        })
        .collect()
}

/// The counts, each strategy marked `Never` if it is in `survivors`.
fn marked(
    counts: Vec<(Count, Offset)>, survivors: &[Offset],
) -> Vec<(Count, Expect)> {
    counts
        .into_iter()
        .map(|(count, offset)| {
            let expect = if survivors.contains(&offset) {
                Expect::Never
            } else {
                Expect::Shown
            };
            (count, expect)
        })
        .collect()
}

/// Sphere, plane and triangle at `scale` about the origin, the light
/// anywhere in front.
fn at_scale(budget: &Budget, scale: f64) -> Vec<(Count, Offset)> {
    let targets = targets(scale, DVec3::ZERO);
    failures(&targets, scale, hemisphere, budget.rays, 0x5EED_0401)
}

/// Scale 1e-6: only the scale-aware offset is built for it.
fn at_1e_minus_6(budget: &Budget) -> Vec<(Count, Expect)> {
    marked(at_scale(budget, 1e-6), &[Offset::ScaleAware])
}

/// Scale 1e-3: the 1e-9 lift still fits under the blocker.
fn at_1e_minus_3(budget: &Budget) -> Vec<(Count, Expect)> {
    let survivors = [Offset::AlongNormal(1e-9), Offset::ScaleAware];
    marked(at_scale(budget, 1e-3), &survivors)
}

/// Scales 1 and 1e3: where every fixed ε of the lecture is meant to work.
const FIXED_EPSILONS_WORK: [Offset; 3] = [
    Offset::TMin(1e-4),
    Offset::AlongNormal(1e-9),
    Offset::ScaleAware,
];

/// Scale 1.
fn at_1(budget: &Budget) -> Vec<(Count, Expect)> {
    marked(at_scale(budget, 1.0), &FIXED_EPSILONS_WORK)
}

/// Scale 1e3.
fn at_1e3(budget: &Budget) -> Vec<(Count, Expect)> {
    marked(at_scale(budget, 1e3), &FIXED_EPSILONS_WORK)
}

/// Scale 1e7: only the scale-aware offset is built for it.
fn at_1e7(budget: &Budget) -> Vec<(Count, Expect)> {
    marked(at_scale(budget, 1e7), &[Offset::ScaleAware])
}

/// Objects of size 1 around (1e7, 6e6, −8e6).
fn far_from_the_origin(budget: &Budget) -> Vec<(Count, Expect)> {
    let shift = DVec3::new(1e7, 0.6e7, -0.8e7);
    let targets = targets(1.0, shift);
    let counts = failures(&targets, 1.0, hemisphere, budget.rays, 0x5EED_0402);
    marked(counts, &[Offset::ScaleAware])
}

/// Scale 1, the light 1e-12 to 1e-3 rad above the tangent plane.
fn grazing_light(budget: &Budget) -> Vec<(Count, Expect)> {
    let targets = targets(1.0, DVec3::ZERO);
    let counts = failures(&targets, 1.0, grazing, budget.rays, 0x5EED_0403);
    marked(counts, &[Offset::AlongNormal(1e-9), Offset::ScaleAware])
}

/// The floor y = 0 at scale 1e4: the scale-aware offset's known weakness
/// (chapter 4's `src/scale_aware.rs`).
fn floor_through_the_origin(budget: &Budget) -> Vec<(Count, Expect)> {
    let targets = [floor(1e4)];
    let counts = failures(&targets, 1e4, hemisphere, budget.rays, 0x5EED_0404);
    marked(counts, &[Offset::TMin(1e-4), Offset::AlongNormal(1e-9)])
}
