//! Held-out cases of chapter 3 for `raystep grade` (see
//! `raystep_check::held_out`): spheres hit from outside and inside, with
//! roots cut off by the interval, grazed just inside and just outside,
//! touched exactly, far away and tiny, left from their surface; mirrored
//! light directions; the local model's terms for random materials and
//! lights, some behind the surface or exactly along it.
use std::process::ExitCode;

use ch03::{
    DVec3, Interval, LightSample, Material, Ray, Sphere, reflect_light,
    shading_terms,
};
use raystep_check::held_out::{self, Case, Exercise, Rng, short, show3};

fn main() -> ExitCode {
    held_out::main(&[
        Exercise::new("sphere_hit", sphere_hit_case, 1e-7),
        Exercise::new("reflect", reflect_case, 1e-9),
        Exercise::new("local_shading", local_shading_case, 1e-9),
    ])
}

/// A size for a case: any decade from 1e-4 to 1e5.
fn scale(rng: &mut Rng) -> f64 {
    rng.magnitude(1e-4, 1e5).abs()
}

/// A unit vector across `d` (unit), at a random angle about it.
fn across(rng: &mut Rng, d: DVec3) -> DVec3 {
    let u = d.any_orthonormal_vector();
    let w = d.cross(u);
    let phi = rng.uniform(0.0, std::f64::consts::TAU);
    (phi.cos() * u + phi.sin() * w).normalize()
}

/// The two roots of |O + tD − C|² = r², by the stable formula, in plain
/// arithmetic here (to keep a case's t clear of the interval's ends).
fn roots(sphere: &Sphere, ray: &Ray) -> Option<(f64, f64)> {
    let f = ray.origin - sphere.center;
    let d = ray.direction;
    let a = d.dot(d);
    let b = -f.dot(d);
    let l = f + (b / a) * d;
    let disc = a * (sphere.radius * sphere.radius - l.dot(l));
    if disc < 0.0 {
        return None;
    }
    let q = b + b.signum() * disc.sqrt();
    let (t0, t1) = ((f.dot(f) - sphere.radius * sphere.radius) / q, q / a);
    Some((t0.min(t1), t0.max(t1)))
}

/// One sphere and one ray, and the scale T of its t.
struct SphereCase {
    what: &'static str,
    sphere: Sphere,
    ray: Ray,
    interval: Interval,
    t_scale: f64,
}

/// A sphere at a random size s: its centre within `reach`·s of the
/// origin in each coordinate, its radius `smallest`·s to 2s; and a length
/// m for the ray's direction, 0.01 to 100.
fn sphere_and_speed(rng: &mut Rng, reach: f64, smallest: f64) -> (Sphere, f64) {
    let s = scale(rng);
    let m = rng.magnitude(0.01, 100.0).abs();
    let sphere =
        Sphere::new(rng.vec3(reach * s), s * rng.uniform(smallest, 2.0));
    (sphere, m)
}

/// From outside, aimed within 0.97 r of the centre (or beside it, past
/// 1.05 r), or away from it; the interval all of t ≥ 0, or cutting off
/// the near root, or both.
fn from_outside(rng: &mut Rng) -> SphereCase {
    let (sphere, m) = sphere_and_speed(rng, 10.0, 0.2);
    let r = sphere.radius;
    let toward = rng.unit_vec3();
    let distance = r * rng.uniform(1.2, 30.0);
    let origin = sphere.center - distance * toward;
    let offset = if rng.chance(0.75) {
        r * rng.uniform(0.0, 0.97)
    } else {
        r * rng.uniform(1.05, 3.0)
    };
    let target = sphere.center + offset * across(rng, toward);
    let away = rng.chance(0.15);
    let direction = (target - origin).normalize() * m;
    let direction = if away { -direction } else { direction };
    let t_scale = distance / m;
    let interval = match rng.below(6) {
        0..=2 => Interval::FORWARD,
        3 => Interval::new(0.0, t_scale * rng.uniform(0.2, 3.0)),
        4 => Interval::new(
            t_scale * rng.uniform(0.0, 1.5),
            t_scale * rng.uniform(1.5, 3.0),
        ),
        _ => Interval::UNIVERSE,
    };
    SphereCase {
        what: if away {
            "pointing away"
        } else {
            "from outside"
        },
        sphere,
        ray: Ray::new(origin, direction),
        interval,
        t_scale,
    }
}

/// From a point inside the sphere, any direction.
fn from_inside(rng: &mut Rng) -> SphereCase {
    let (sphere, m) = sphere_and_speed(rng, 10.0, 0.2);
    let r = sphere.radius;
    let origin = sphere.center + r * rng.uniform(0.0, 0.9) * rng.unit_vec3();
    let interval = if rng.chance(0.7) {
        Interval::FORWARD
    } else {
        Interval::new(-r / m * rng.uniform(0.0, 3.0), f64::INFINITY)
    };
    SphereCase {
        what: "from inside",
        sphere,
        ray: Ray::new(origin, rng.unit_vec3() * m),
        interval,
        t_scale: r / m,
    }
}

/// A ray passing the centre at r·(1 − δ) (a hit) or r·(1 + δ) (a miss),
/// δ from 1e-1 down to 1e-10 (never below what the construction's own
/// rounding can move).
fn grazing(rng: &mut Rng) -> SphereCase {
    let (sphere, m) = sphere_and_speed(rng, 3.0, 0.5);
    let r = sphere.radius;
    let d = rng.unit_vec3();
    let side = across(rng, d);
    let back = r * rng.uniform(2.0, 20.0);
    let reach = (sphere.center.abs().max_element() + back) / r;
    let smallest = (1e4 * f64::EPSILON * reach).max(1e-10);
    let delta = 10f64.powf(rng.uniform(smallest.log10(), -1.0));
    let hits = rng.chance(0.5);
    let offset = if hits { 1.0 - delta } else { 1.0 + delta };
    let origin = sphere.center + r * offset * side - back * d;
    SphereCase {
        what: if hits {
            "grazing, just inside"
        } else {
            "grazing, just outside"
        },
        sphere,
        ray: Ray::new(origin, d * m),
        interval: Interval::FORWARD,
        t_scale: back / m,
    }
}

/// A sphere 1e4 to 1e7 radii from the ray's origin, aimed within 0.95 r
/// of its centre: b² and a·c cancel in the textbook discriminant (by far
/// more than the 1e-7 of r its hit point may be off here).
fn far_away(rng: &mut Rng) -> SphereCase {
    let r = scale(rng);
    let m = rng.magnitude(0.01, 100.0).abs();
    let distance = r * 10f64.powf(rng.uniform(4.0, 7.0));
    let toward = rng.unit_vec3();
    let origin = rng.vec3(r);
    let sphere = Sphere::new(origin + distance * toward, r);
    let target =
        sphere.center + r * rng.uniform(0.0, 0.95) * across(rng, toward);
    SphereCase {
        what: "far away",
        sphere,
        ray: Ray::new(origin, (target - origin).normalize() * m),
        interval: Interval::FORWARD,
        t_scale: distance / m,
    }
}

/// From a point of the surface (rounded) inward, as a refracted ray
/// starts: the near root is rounding noise about 0, cut off by the
/// interval; the far side must come out precise.
fn from_the_surface(rng: &mut Rng) -> SphereCase {
    let (sphere, m) = sphere_and_speed(rng, 10.0, 0.2);
    let r = sphere.radius;
    let normal = rng.unit_vec3();
    let origin = sphere.center + r * normal;
    let direction = (rng.unit_vec3() - 2.0 * normal).normalize() * m;
    SphereCase {
        what: "from the surface inward",
        sphere,
        ray: Ray::new(origin, direction),
        interval: Interval::new(1e-6 * r / m, f64::INFINITY),
        t_scale: r / m,
    }
}

/// A ray that only touches the sphere, its discriminant exactly 0 (short
/// binary fractions along an axis): one double root, a hit.
fn touching(rng: &mut Rng) -> SphereCase {
    let unit = 2f64.powi(rng.below(40) as i32 - 20);
    let small = |rng: &mut Rng| (rng.below(33) as f64 - 16.0) / 4.0;
    let center = DVec3::new(small(rng), small(rng), small(rng)) * unit;
    let r = (1 + rng.below(8)) as f64 * 0.5 * unit;
    let i = rng.below(3);
    let j = (i + 1 + rng.below(2)) % 3;
    let away = (1 + rng.below(16)) as f64 * 0.5 * unit;
    let along = if rng.chance(0.5) { 1.0 } else { -1.0 };
    let m = 2f64.powi(rng.below(7) as i32 - 3);
    let mut origin = center;
    origin[i] += if rng.chance(0.5) { r } else { -r };
    origin[j] -= along * away;
    let mut direction = DVec3::ZERO;
    direction[j] = along * m;
    SphereCase {
        what: "touching (discriminant exactly 0)",
        sphere: Sphere::new(center, r),
        ray: Ray::new(origin, direction),
        interval: Interval::FORWARD,
        t_scale: away / m,
    }
}

fn show_interval(i: Interval) -> String {
    format!("[{}, {}]", short(i.min), short(i.max))
}

/// Is `t` within 1e-6 of an end of the interval (where a correct
/// solution could round to either side)?
fn near_an_end(t: f64, i: Interval) -> bool {
    [i.min, i.max].iter().any(|&end| {
        end.is_finite() && (t - end).abs() <= 1e-6 * t.abs().max(end.abs())
    })
}

/// One ray and one sphere: hit or miss, t in units of the case's scale,
/// and the normal at the hit.
fn sphere_hit_case(rng: &mut Rng, case: &mut Case) {
    let kinds: [fn(&mut Rng) -> SphereCase; 6] = [
        from_outside,
        from_inside,
        grazing,
        far_away,
        from_the_surface,
        touching,
    ];
    let weights = [0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 5];
    let kind = kinds[weights[rng.below(weights.len())]];
    let c = loop {
        let c = kind(rng);
        let clear = roots(&c.sphere, &c.ray).is_none_or(|(t0, t1)| {
            !near_an_end(t0, c.interval) && !near_an_end(t1, c.interval)
        });
        if clear {
            break c;
        }
    };
    case.ask(format!(
        "{}: sphere at {} of radius {}, ray from {} along {}, t in {}",
        c.what,
        show3(c.sphere.center),
        short(c.sphere.radius),
        show3(c.ray.origin),
        show3(c.ray.direction),
        show_interval(c.interval)
    ));
    match c.sphere.intersect(&c.ray, c.interval) {
        Some(hit) => {
            case.word("hit");
            case.num("t/T", hit.t / c.t_scale);
            case.vec3("normal", hit.normal);
        }
        None => case.word("miss"),
    }
}

/// The mirror of a unit light direction about a unit normal: any two
/// directions, the light overhead, grazing, below the surface.
fn reflect_case(rng: &mut Rng, case: &mut Case) {
    let n = if rng.chance(0.2) {
        let mut n = DVec3::ZERO;
        n[rng.below(3)] = if rng.chance(0.5) { 1.0 } else { -1.0 };
        n
    } else {
        rng.unit_vec3()
    };
    let l = match rng.below(5) {
        0 => n,
        1 => {
            let g = 10f64.powf(rng.uniform(-8.0, -1.0));
            (across(rng, n) + g * n).normalize()
        }
        _ => rng.unit_vec3(),
    };
    case.ask(format!("reflect_light(L = {}, N = {})", show3(l), show3(n)));
    case.vec3("R", reflect_light(l, n));
}

/// A colour per channel in [lo, hi).
fn colour(rng: &mut Rng, lo: f64, hi: f64) -> DVec3 {
    DVec3::new(
        rng.uniform(lo, hi),
        rng.uniform(lo, hi),
        rng.uniform(lo, hi),
    )
}

/// A random material: ka, kd, ks per channel, a Phong exponent from 1 to
/// 200 (whole or not).
fn material(rng: &mut Rng) -> Material {
    let p = if rng.chance(0.5) {
        (1 + rng.below(100)) as f64
    } else {
        rng.uniform(1.0, 200.0)
    };
    Material {
        name: "held-out".to_string(),
        ka: colour(rng, 0.0, 1.0),
        kd: colour(rng, 0.0, 1.0),
        ks: colour(rng, 0.0, 1.0),
        p,
        ..Material::default()
    }
}

/// One light seen from a point with normal `n`: in front, behind, exactly
/// along the surface (an axis normal, a light with no part along it), or
/// mirrored toward the eye (a highlight); never within 1e-9 of the
/// tangent plane unless exactly in it.
fn light(
    rng: &mut Rng, n: DVec3, eye: DVec3, axis: Option<usize>,
) -> LightSample {
    let direction = loop {
        let l = match rng.below(6) {
            0 => {
                // toward the mirror of the eye: a highlight
                let mirror = 2.0 * n.dot(eye) * n - eye;
                (mirror + 0.2 * rng.unit_vec3()).normalize()
            }
            1 => match axis {
                Some(k) => {
                    let mut l = rng.unit_vec3();
                    l[k] = 0.0;
                    l.normalize()
                }
                None => rng.unit_vec3(),
            },
            _ => rng.unit_vec3(),
        };
        let cosine = n.dot(l);
        if cosine == 0.0 || cosine.abs() > 1e-9 {
            break l;
        }
    };
    LightSample {
        direction,
        intensity: colour(rng, 0.0, 2.0),
        visibility: if rng.chance(0.8) { 1.0 } else { 0.0 },
    }
}

/// The local model's three terms for a random material, normal, eye and
/// up to four lights.
fn local_shading_case(rng: &mut Rng, case: &mut Case) {
    let material = material(rng);
    let (n, axis) = if rng.chance(0.3) {
        let k = rng.below(3);
        let mut n = DVec3::ZERO;
        n[k] = if rng.chance(0.5) { 1.0 } else { -1.0 };
        (n, Some(k))
    } else {
        (rng.unit_vec3(), None)
    };
    let eye = {
        let e = rng.unit_vec3();
        if e.dot(n) < 0.0 { -e } else { e }
    };
    let ambient = colour(rng, 0.0, 1.0);
    let lights: Vec<LightSample> = (0..rng.below(5))
        .map(|_| light(rng, n, eye, axis))
        .collect();
    let shown: Vec<String> = lights
        .iter()
        .map(|l| {
            format!(
                "L {} I {} S {}",
                show3(l.direction),
                show3(l.intensity),
                l.visibility
            )
        })
        .collect();
    case.ask(format!(
        "ka {}, kd {}, ks {}, p {}; N {}, V {}, Ia {}; lights [{}]",
        show3(material.ka),
        show3(material.kd),
        show3(material.ks),
        short(material.p),
        show3(n),
        show3(eye),
        show3(ambient),
        shown.join("; ")
    ));
    let terms = shading_terms(&material, n, eye, ambient, &lights);
    case.vec3("ambient", terms.ambient);
    case.vec3("diffuse", terms.diffuse);
    case.vec3("specular", terms.specular);
}
