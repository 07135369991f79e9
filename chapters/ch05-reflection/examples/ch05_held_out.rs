//! Held-out cases of chapter 5 for `raystep grade` (see
//! `raystep_check::held_out`): reflected directions of rays of any length
//! off surfaces facing either way; and the recursive tracer's colour and
//! ray counts in random worlds of mirror balls and mirror floors, and
//! between two facing mirrors, under both stopping rules (with
//! contributions exactly at the threshold now and then).
use std::process::ExitCode;
use std::sync::Arc;

use ch03::{BruteForce, Material};
use ch05::{
    Camera, DVec3, Object, Path, Ray, Stop, Tracer, World, reflect_ray,
};
use raystep_check::held_out::{self, Case, Exercise, Rng, short, show3};
use raystep_scene::{Light, Shape as Spec};

fn main() -> ExitCode {
    held_out::main(&[
        Exercise::new("reflection", reflection_case, 1e-9),
        Exercise::new("recursion", recursion_case, 1e-9),
    ])
}

fn sign(rng: &mut Rng) -> f64 {
    if rng.chance(0.5) { 1.0 } else { -1.0 }
}

/// A unit normal: along an axis (either way) or any direction.
fn normal(rng: &mut Rng) -> DVec3 {
    if rng.chance(0.3) {
        let mut n = DVec3::ZERO;
        n[rng.below(3)] = sign(rng);
        n
    } else {
        rng.unit_vec3()
    }
}

/// R = D − 2(D·N)N for a D of any length (from 1e-6 to 1e6) toward the
/// surface or away, straight on, grazing, along it; R in units of |D|.
fn reflection_case(rng: &mut Rng, case: &mut Case) {
    let n = normal(rng);
    let length = 10f64.powf(rng.uniform(-6.0, 6.0));
    let u = n.any_orthonormal_vector();
    let d = match rng.below(6) {
        0 => -n,
        1 => {
            // along the surface: exactly, for an axis normal
            let mut d = rng.unit_vec3();
            if let Some(k) = (0..3).find(|&k| n[k].abs() == 1.0) {
                d[k] = 0.0;
                d
            } else {
                u
            }
        }
        2 => (u - 10f64.powf(rng.uniform(-8.0, -1.0)) * n).normalize(),
        _ => rng.unit_vec3(),
    } * length;
    case.ask(format!("reflect_ray(D = {}, N = {})", show3(d), show3(n)));
    case.vec3("R/|D|", reflect_ray(d, n) / length);
}

/// A colour per channel in [lo, hi).
fn colour(rng: &mut Rng, lo: f64, hi: f64) -> DVec3 {
    DVec3::new(
        rng.uniform(lo, hi),
        rng.uniform(lo, hi),
        rng.uniform(lo, hi),
    )
}

/// A reflectance: none, one number, or one per channel; now and then
/// exactly 1 or 1/2 (whose powers meet a threshold exactly).
fn kr(rng: &mut Rng) -> DVec3 {
    match rng.below(7) {
        0 => DVec3::ZERO,
        1 => DVec3::ONE,
        2 => DVec3::splat(0.5),
        3 => DVec3::new(0.5, 0.25, 0.0),
        4 => DVec3::splat(rng.uniform(0.1, 0.95)),
        _ => colour(rng, 0.0, 1.0),
    }
}

/// A material with some of each term and `kr`.
fn material(rng: &mut Rng, kr: DVec3) -> Material {
    Material {
        name: "held-out".to_string(),
        ka: colour(rng, 0.0, 0.5),
        kd: colour(rng, 0.0, 1.0),
        ks: colour(rng, 0.0, 0.6),
        p: rng.uniform(2.0, 120.0),
        kr,
        ..Material::default()
    }
}

/// A world of these shapes (chapter 3's, searched one by one), each with
/// its material, lit by `lights`.
fn world(
    shapes: &[(Spec, Material)], lights: Vec<Light>, ambient: f64,
) -> World {
    let objects = shapes
        .iter()
        .enumerate()
        .map(|(k, (spec, _))| Object {
            shape: ch03::shape(spec).expect("spheres and planes build"),
            material: k,
        })
        .collect();
    World {
        objects,
        accelerator: Arc::new(BruteForce),
        materials: shapes.iter().map(|(_, m)| m.clone()).collect(),
        lights,
        ambient: DVec3::splat(ambient),
        background: DVec3::new(0.3, 0.45, 0.7),
        camera: Camera::look_at(DVec3::Z, DVec3::ZERO, DVec3::Y, 60.0, 1.0),
        width: 1,
        height: 1,
    }
}

/// A stopping rule: a depth from 0 to 6, or a contribution threshold
/// (a power of 1/2 now and then, met exactly by a mirror of kr 1/2).
fn stop(rng: &mut Rng) -> Stop {
    match rng.below(4) {
        0 | 1 => Stop::depth(rng.below(7) as u32),
        2 => Stop::contribution(0.5f64.powi(rng.below(8) as i32)),
        _ => Stop::contribution(10f64.powf(rng.uniform(-4.0, -0.3))),
    }
}

/// Balls (mirrors among them) over a floor that may be a mirror (its
/// plane's normal up or down), one or two lights, and a ray from above
/// aimed at a ball or the floor.
fn balls_and_floor(rng: &mut Rng) -> (Vec<(Spec, Material)>, Vec<Light>, Ray) {
    let s = 10f64.powf(rng.uniform(-2.0, 3.0));
    let floor_kr = if rng.chance(0.5) {
        kr(rng)
    } else {
        DVec3::ZERO
    };
    let mut shapes = vec![(
        Spec::Plane {
            point: DVec3::ZERO,
            normal: DVec3::Y * sign(rng),
        },
        material(rng, floor_kr),
    )];
    for _ in 0..1 + rng.below(4) {
        let center = DVec3::new(
            rng.uniform(-3.0, 3.0),
            rng.uniform(0.5, 2.5),
            rng.uniform(-3.0, 3.0),
        ) * s;
        let radius = s * rng.uniform(0.2, 0.5).min(0.9 * center.y / s);
        let k = kr(rng);
        shapes.push((Spec::Sphere { center, radius }, material(rng, k)));
    }
    let lights = (0..1 + rng.below(2))
        .map(|_| Light {
            position: DVec3::new(
                rng.uniform(-5.0, 5.0),
                rng.uniform(3.0, 8.0),
                rng.uniform(-5.0, 5.0),
            ) * s,
            intensity: colour(rng, 0.3, 1.0),
        })
        .collect();
    let eye = DVec3::new(
        rng.uniform(-6.0, 6.0),
        rng.uniform(1.0, 6.0),
        rng.uniform(-6.0, 6.0),
    ) * s;
    let k = rng.below(shapes.len());
    let target = match shapes[k].0 {
        Spec::Sphere { center, radius } => {
            center + radius * rng.uniform(0.0, 0.9) * rng.unit_vec3()
        }
        _ => {
            DVec3::new(rng.uniform(-4.0, 4.0), 0.0, rng.uniform(-4.0, 4.0)) * s
        }
    };
    let length = rng.uniform(0.5, 2.0);
    let ray = Ray::new(eye, (target - eye).normalize() * length);
    (shapes, lights, ray)
}

/// Two parallel mirror planes facing each other (along a random axis,
/// a random distance apart), lit from the side, and a ray between them
/// at a random slant: a chain of reflections that only a rule ends.
fn facing_mirrors(rng: &mut Rng) -> (Vec<(Spec, Material)>, Vec<Light>, Ray) {
    let s = 10f64.powf(rng.uniform(-2.0, 3.0));
    let axis = rng.below(3);
    let mut n = DVec3::ZERO;
    n[axis] = 1.0;
    let gap = s * rng.uniform(0.5, 2.0);
    let k = kr(rng);
    let m = material(rng, k);
    let other = if rng.chance(0.7) {
        m.clone()
    } else {
        let k = kr(rng);
        material(rng, k)
    };
    let shapes = vec![
        (
            Spec::Plane {
                point: gap * n,
                normal: -n,
            },
            m,
        ),
        (
            Spec::Plane {
                point: -gap * n,
                normal: n,
            },
            other,
        ),
    ];
    let side = n.any_orthonormal_vector();
    let light = Light {
        position: side * s * rng.uniform(2.0, 6.0)
            + n * gap * rng.uniform(-0.9, 0.9),
        intensity: colour(rng, 0.3, 1.0),
    };
    let slant = if rng.chance(0.4) {
        DVec3::ZERO
    } else {
        n.cross(side) * rng.uniform(-0.3, 0.3)
    };
    let ray = Ray::new(
        n * gap * rng.uniform(-0.5, 0.5),
        (n * sign(rng) + slant).normalize(),
    );
    (shapes, vec![light], ray)
}

fn show_world(shapes: &[(Spec, Material)], lights: &[Light]) -> String {
    let mut parts: Vec<String> = shapes
        .iter()
        .map(|(spec, m)| {
            let shape = match spec {
                Spec::Sphere { center, radius } => {
                    format!("ball {} r {}", show3(*center), short(*radius))
                }
                Spec::Plane { point, normal } => format!(
                    "plane through {} N {}",
                    show3(*point),
                    show3(*normal)
                ),
                _ => String::new(),
            };
            format!(
                "{shape} (ka {} kd {} ks {} p {} kr {})",
                show3(m.ka),
                show3(m.kd),
                show3(m.ks),
                short(m.p),
                show3(m.kr)
            )
        })
        .collect();
    parts.extend(lights.iter().map(|l| {
        format!("light {} I {}", show3(l.position), show3(l.intensity))
    }));
    parts.join("; ")
}

/// The colour one primary ray sees under a stopping rule, and the rays
/// its trace shot and cut.
fn recursion_case(rng: &mut Rng, case: &mut Case) {
    let (shapes, lights, ray) = if rng.chance(0.35) {
        facing_mirrors(rng)
    } else {
        balls_and_floor(rng)
    };
    let ambient = rng.uniform(0.0, 0.3);
    let stop = stop(rng);
    case.ask(format!(
        "{}; ambient {}; ray from {} along {}; {:?}",
        show_world(&shapes, &lights),
        short(ambient),
        show3(ray.origin),
        show3(ray.direction),
        stop
    ));
    let world = world(&shapes, lights, ambient);
    let tracer = Tracer::new(&world, stop);
    let colour = tracer.trace(&ray, Path::PRIMARY);
    let counts = tracer.counts();
    case.vec3("colour", colour);
    case.num("primary", counts.primary as f64);
    case.num("reflected", counts.secondary as f64);
    case.num("shadow", counts.shadow as f64);
    case.num("cut-by-depth", counts.cut_by_depth as f64);
    case.num("cut-by-contribution", counts.cut_by_contribution as f64);
}
