//! Held-out cases of chapter 4 for `raystep grade` (see
//! `raystep_check::held_out`): Sᵢ for points on a floor and on balls
//! (seen from outside and from inside), lights in front, behind and
//! exactly in the tangent plane, blockers between, and thin blockers that
//! a large offset jumps over; and the shadow ray lifted along the normal,
//! at every scale.
use std::process::ExitCode;
use std::sync::Arc;

use ch03::{BruteForce, Material};
use ch04::{
    Camera, DVec3, Hit, Light, Object, Offset, World, normal_offset_ray,
    offset_scale_aware, shadow,
};
use raystep_check::held_out::{self, Case, Exercise, Rng, short, show3};
use raystep_scene::Shape as Spec;

fn main() -> ExitCode {
    held_out::main(&[
        Exercise::new("shadow", shadow_case, 1e-12),
        Exercise::new("normal_offset", normal_offset_case, 1e-9),
    ])
}

fn sign(rng: &mut Rng) -> f64 {
    if rng.chance(0.5) { 1.0 } else { -1.0 }
}

/// A world of these scene-file shapes (chapter 3's spheres and planes,
/// searched one by one), all in the default material.
fn world(shapes: &[Spec]) -> World {
    let objects = shapes
        .iter()
        .map(|spec| Object {
            shape: ch03::shape(spec).expect("spheres and planes build"),
            material: 0,
        })
        .collect();
    World {
        objects,
        accelerator: Arc::new(BruteForce),
        materials: vec![Material::default()],
        lights: Vec::new(),
        ambient: DVec3::ZERO,
        background: DVec3::ZERO,
        camera: Camera::look_at(DVec3::Z, DVec3::ZERO, DVec3::Y, 60.0, 1.0),
        width: 1,
        height: 1,
    }
}

/// The parameters (as fractions of the segment from `from` to `to`) where
/// the segment's line meets a sphere, or None if it passes by; and
/// whether it passes within 1e-6 of r of its surface (a graze).
fn sphere_roots(
    center: DVec3, radius: f64, from: DVec3, to: DVec3,
) -> (Option<[f64; 2]>, bool) {
    let d = to - from;
    let f = from - center;
    let a = d.dot(d);
    let b = -f.dot(d);
    let l = f + (b / a) * d;
    let rest = radius * radius - l.dot(l);
    let grazes = rest.abs() < 1e-6 * radius * radius;
    if rest < 0.0 {
        return (None, grazes);
    }
    let disc = a * rest;
    let q = b + b.signum() * disc.sqrt();
    let c = f.dot(f) - radius * radius;
    (Some([c / q, q / a]), grazes)
}

/// One point of a surface, its normal toward the viewer, the hit's own
/// normal, and the world around it.
struct Scene {
    what: String,
    shapes: Vec<Spec>,
    /// The shape the point is on (its roots near 0 are the point itself).
    own: usize,
    point: DVec3,
    normal: DVec3,
    hit_normal: DVec3,
    light: DVec3,
    offset: Offset,
}

/// Is the case clear: no surface within rounding of the shadow ray's
/// ends, none grazed, and N·(light − point) clearly signed or exactly 0?
fn clear(scene: &Scene, s: f64) -> bool {
    let to_light = scene.light - scene.point;
    let facing = scene.normal.dot(to_light);
    if facing != 0.0 && facing.abs() < 1e-9 * to_light.length() {
        return false;
    }
    let length = to_light.length();
    let (from, lo, hi) = match scene.offset {
        Offset::TMin(e) => (scene.point, e / length, 1.0 - e / length),
        Offset::AlongNormal(e) => (scene.point + e * scene.normal, 0.0, 1.0),
        Offset::ScaleAware => {
            (offset_scale_aware(scene.point, scene.normal), 0.0, 1.0)
        }
    };
    if lo >= hi {
        return false;
    }
    let near_end = |t: f64| (t - lo).abs() < 1e-6 || (t - hi).abs() < 1e-6;
    for (k, spec) in scene.shapes.iter().enumerate() {
        match *spec {
            Spec::Sphere { center, radius } => {
                let (roots, grazes) =
                    sphere_roots(center, radius, from, scene.light);
                if grazes && k != scene.own {
                    return false;
                }
                for t in roots.into_iter().flatten() {
                    let own_point = k == scene.own && t.abs() < 1e-7;
                    if !own_point && near_end(t) {
                        return false;
                    }
                }
            }
            Spec::Plane { point, normal } => {
                if k == scene.own {
                    continue;
                }
                let d = scene.light - from;
                let approach = normal.dot(d);
                if approach.abs() < 1e-9 * d.length() {
                    if normal.dot(from - point).abs() < 1e-6 * s {
                        return false;
                    }
                    continue;
                }
                if near_end(-normal.dot(from - point) / approach) {
                    return false;
                }
            }
            _ => unreachable!("only spheres and planes here"),
        }
    }
    true
}

/// An offset: a fixed t_min or lift (from 1e-9 to 1e-1 of the scene's
/// size), or the scale-aware one.
fn offset(rng: &mut Rng, s: f64) -> Offset {
    let e = s * 10f64.powf(rng.uniform(-9.0, -1.0));
    match rng.below(3) {
        0 => Offset::TMin(e),
        1 => Offset::AlongNormal(e),
        _ => Offset::ScaleAware,
    }
}

/// A few balls of the scene's size anywhere above or through a floor
/// at y = 0.
fn balls(rng: &mut Rng, s: f64) -> Vec<Spec> {
    (0..rng.below(4))
        .map(|_| Spec::Sphere {
            center: DVec3::new(
                rng.uniform(-4.0, 4.0),
                rng.uniform(-0.5, 4.0),
                rng.uniform(-4.0, 4.0),
            ) * s,
            radius: s * rng.uniform(0.1, 1.5),
        })
        .collect()
}

/// A ball on the segment from `from` to `to`, small enough to hold
/// neither end: it shadows one from the other.
fn between(rng: &mut Rng, from: DVec3, to: DVec3) -> Spec {
    let along = rng.uniform(0.1, 0.9);
    let center = from + along * (to - from);
    let reach = (to - from).length() * along.min(1.0 - along);
    Spec::Sphere {
        center,
        radius: reach * rng.uniform(0.05, 0.9),
    }
}

/// A light somewhere around the point: in front of the surface mostly,
/// behind it now and then.
fn light_near(rng: &mut Rng, point: DVec3, normal: DVec3, s: f64) -> DVec3 {
    let d = rng.unit_vec3();
    let d = if d.dot(normal) < 0.0 && rng.chance(0.8) {
        -d
    } else {
        d
    };
    point + s * rng.uniform(0.3, 8.0) * d
}

/// A point of the floor y = 0 (the hit's own normal up or down, the
/// viewer above), balls around, a light, maybe a ball between.
fn on_the_floor(rng: &mut Rng, s: f64) -> Scene {
    let point =
        DVec3::new(rng.uniform(-3.0, 3.0), 0.0, rng.uniform(-3.0, 3.0)) * s;
    let mut shapes = vec![Spec::Plane {
        point: DVec3::ZERO,
        normal: if rng.chance(0.7) { DVec3::Y } else { -DVec3::Y },
    }];
    shapes.extend(balls(rng, s));
    let light = light_near(rng, point, DVec3::Y, s);
    if rng.chance(0.3) {
        shapes.push(between(rng, point, light));
    }
    let hit_normal = if rng.chance(0.7) { DVec3::Y } else { -DVec3::Y };
    Scene {
        what: "a floor point".into(),
        shapes,
        own: 0,
        point,
        normal: DVec3::Y,
        hit_normal,
        light,
        offset: offset(rng, s),
    }
}

/// A point of a ball (rounded: it may lie an ulp inside or outside),
/// seen from outside (normal outward) or from inside (normal inward).
fn on_a_ball(rng: &mut Rng, s: f64) -> Scene {
    let center = DVec3::new(
        rng.uniform(-3.0, 3.0),
        rng.uniform(1.0, 3.0),
        rng.uniform(-3.0, 3.0),
    ) * s;
    let radius = s * rng.uniform(0.3, 1.0);
    let u = rng.unit_vec3();
    let point = center + radius * u;
    let inside = rng.chance(0.3);
    let normal = if inside { -u } else { u };
    let mut shapes = vec![
        Spec::Plane {
            point: DVec3::ZERO,
            normal: DVec3::Y,
        },
        Spec::Sphere { center, radius },
    ];
    shapes.extend(balls(rng, s));
    let light = if inside && rng.chance(0.6) {
        center + radius * rng.uniform(0.0, 0.9) * rng.unit_vec3()
    } else {
        light_near(rng, point, normal, s)
    };
    if rng.chance(0.25) {
        shapes.push(between(rng, point, light));
    }
    Scene {
        what: if inside {
            "a ball's point seen from inside".into()
        } else {
            "a ball's point".into()
        },
        shapes,
        own: 1,
        point,
        normal,
        hit_normal: u,
        light,
        offset: offset(rng, s),
    }
}

/// A light exactly in the tangent plane of the point (N·(light − point)
/// = 0 to the bit): on the floor's plane, or level with the top (or a
/// side) of a ball whose point is exact (short binary fractions).
fn in_the_tangent_plane(rng: &mut Rng, s: f64) -> Scene {
    let unit = 2f64.powi(s.log2().round() as i32);
    let small = |rng: &mut Rng| (rng.below(17) as f64 - 8.0) / 4.0;
    if rng.chance(0.4) {
        let point = DVec3::new(small(rng), 0.0, small(rng)) * unit;
        let light = DVec3::new(small(rng), 0.0, small(rng)) * unit * 4.0;
        let mut shapes = vec![Spec::Plane {
            point: DVec3::ZERO,
            normal: DVec3::Y,
        }];
        shapes.extend(balls(rng, s));
        return Scene {
            what: "a floor point, the light on the floor's plane".into(),
            shapes,
            own: 0,
            point: if point == light {
                point + DVec3::X
            } else {
                point
            },
            normal: DVec3::Y,
            hit_normal: DVec3::Y,
            light,
            offset: offset(rng, s),
        };
    }
    let center =
        DVec3::new(small(rng), 2.0 + small(rng).abs(), small(rng)) * unit;
    let radius = (1 + rng.below(4)) as f64 * 0.25 * unit;
    let k = rng.below(3);
    let mut n = DVec3::ZERO;
    n[k] = sign(rng);
    let point = center + radius * n;
    let mut away = DVec3::new(small(rng), small(rng), small(rng)) * unit;
    away[k] = 0.0;
    if away == DVec3::ZERO {
        away[(k + 1) % 3] = unit;
    }
    let shapes = vec![
        Spec::Plane {
            point: DVec3::ZERO,
            normal: DVec3::Y,
        },
        Spec::Sphere { center, radius },
    ];
    Scene {
        what: "a ball's exact point, the light in its tangent plane".into(),
        shapes,
        own: 1,
        point,
        normal: n,
        hit_normal: n,
        light: point + 4.0 * away,
        offset: offset(rng, s),
    }
}

/// A floor point under a thin blocker, the plane y = g (g from 1e-4 to
/// 1e-1 of the scene's size): a t_min or a lift larger than the gap
/// jumps over it (a leak); the scale-aware offset never does.
fn under_a_thin_blocker(rng: &mut Rng, s: f64) -> Scene {
    let gap = s * 10f64.powf(rng.uniform(-4.0, -1.0));
    let point =
        DVec3::new(rng.uniform(-3.0, 3.0), 0.0, rng.uniform(-3.0, 3.0)) * s;
    let mut d = rng.unit_vec3();
    d.y = d.y.abs().max(0.2);
    let light = point + s * rng.uniform(1.0, 8.0) * d.normalize();
    let e = gap * 10f64.powf(rng.uniform(-1.5, 1.5));
    let offset = match rng.below(3) {
        0 => Offset::TMin(e),
        1 => Offset::AlongNormal(e),
        _ => Offset::ScaleAware,
    };
    Scene {
        what: format!(
            "a floor point under a thin blocker at y = {}",
            short(gap)
        ),
        shapes: vec![
            Spec::Plane {
                point: DVec3::ZERO,
                normal: DVec3::Y,
            },
            Spec::Plane {
                point: gap * DVec3::Y,
                normal: DVec3::Y,
            },
        ],
        own: 0,
        point,
        normal: DVec3::Y,
        hit_normal: DVec3::Y,
        light,
        offset,
    }
}

fn show_shapes(shapes: &[Spec]) -> String {
    let shown: Vec<String> = shapes
        .iter()
        .map(|spec| match spec {
            Spec::Sphere { center, radius } => {
                format!("ball {} r {}", show3(*center), short(*radius))
            }
            Spec::Plane { point, normal } => {
                format!("plane through {} N {}", show3(*point), show3(*normal))
            }
            _ => String::new(),
        })
        .collect();
    shown.join("; ")
}

/// Sᵢ at one point for one light.
fn shadow_case(rng: &mut Rng, case: &mut Case) {
    let kinds: [fn(&mut Rng, f64) -> Scene; 4] = [
        on_the_floor,
        on_a_ball,
        in_the_tangent_plane,
        under_a_thin_blocker,
    ];
    let weights = [0, 0, 0, 1, 1, 1, 2, 2, 3, 3];
    let kind = kinds[weights[rng.below(weights.len())]];
    let scene = loop {
        let s = 10f64.powf(rng.uniform(-3.0, 4.0));
        let scene = kind(rng, s);
        if clear(&scene, s) {
            break scene;
        }
    };
    case.ask(format!(
        "{}: point {}, normal {} (the hit's own {}), light {}, {:?}; {}",
        scene.what,
        show3(scene.point),
        show3(scene.normal),
        show3(scene.hit_normal),
        show3(scene.light),
        scene.offset,
        show_shapes(&scene.shapes)
    ));
    let world = world(&scene.shapes);
    let hit = Hit {
        t: 1.0,
        point: scene.point,
        normal: scene.hit_normal,
    };
    let light = Light {
        position: scene.light,
        intensity: DVec3::ONE,
    };
    let si = shadow(&world, &hit, scene.normal, &light, scene.offset);
    case.num("S", si);
}

/// The lifted shadow ray: its origin and direction in units of the
/// case's size, and its interval.
fn normal_offset_case(rng: &mut Rng, case: &mut Case) {
    let s = 10f64.powf(rng.uniform(-6.0, 6.0));
    let point = if rng.chance(0.2) {
        // coordinates near zero next to large ones
        DVec3::new(s * rng.uniform(-1.0, 1.0), s * 1e-9, 0.0)
    } else {
        rng.vec3(s)
    };
    let normal = if rng.chance(0.2) {
        let mut n = DVec3::ZERO;
        n[rng.below(3)] = sign(rng);
        n
    } else {
        rng.unit_vec3()
    };
    let to = {
        let d = rng.unit_vec3();
        if d.dot(normal) < 0.0 { -d } else { d }
    };
    let light = point + s * rng.uniform(0.1, 10.0) * to;
    let epsilon = s * 10f64.powf(rng.uniform(-6.0, -1.0));
    case.ask(format!(
        "normal_offset_ray(P = {}, N = {}, light = {}, ε = {})",
        show3(point),
        show3(normal),
        show3(light),
        short(epsilon)
    ));
    let (ray, interval) = normal_offset_ray(point, normal, light, epsilon);
    case.vec3("origin/s", ray.origin / s);
    case.vec3("direction/s", ray.direction / s);
    case.num("t_min", interval.min);
    case.num("t_max", interval.max);
}
