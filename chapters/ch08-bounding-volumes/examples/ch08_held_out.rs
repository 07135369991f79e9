//! Held-out cases of chapter 8 for `raystep grade` (see
//! `raystep_check::held_out`): the slab test on the rays that break naive
//! ones (parallel to a slab, origins on its planes, ±0, through edges and
//! corners, NaN) and on any box; the watertight triangle test on random
//! triangles and on fans where rays pass exactly through shared edges and
//! vertices; the torus quartic's coefficients; Ritter's bounding sphere
//! (judged by what any correct sphere must do); the SAH cost of a split;
//! and the near-first walk of a BVH (its answer, and exactly which
//! objects it tests).
use std::process::ExitCode;
use std::sync::{Arc, Mutex};

use ch03::Sphere;
use ch08::{
    Aabb, Builder, Bvh, DVec3, Hit, Interval, Object, Ray, SahCosts, Shape,
    near_first_closest_hit, slab_test, sphere_of_points, split_cost,
    torus_quartic, watertight,
};
use common::half_diameter;
use raystep_check::held_out::{self, Case, Exercise, Rng, short, show3};

// The helpers the chapter's tests judge by, shared rather than copied.
#[path = "../tests/common/mod.rs"]
mod common;

fn main() -> ExitCode {
    held_out::main(&[
        Exercise {
            name: "slab",
            run: slab_case,
            tolerance: 1e-9,
        },
        Exercise {
            name: "watertight",
            run: watertight_case,
            tolerance: 1e-9,
        },
        Exercise {
            name: "torus_quartic",
            run: torus_quartic_case,
            tolerance: 1e-9,
        },
        Exercise {
            name: "sphere_of_points",
            run: sphere_of_points_case,
            tolerance: 1e-9,
        },
        Exercise {
            name: "sah_split",
            run: sah_split_case,
            tolerance: 1e-9,
        },
        Exercise {
            name: "near_first",
            run: near_first_case,
            tolerance: 1e-9,
        },
    ])
}

fn sign(rng: &mut Rng) -> f64 {
    if rng.chance(0.5) { 1.0 } else { -1.0 }
}

fn show_interval(i: Interval) -> String {
    format!("[{}, {}]", short(i.min), short(i.max))
}

fn show_box(b: &Aabb) -> String {
    if b.is_empty() {
        "empty".to_string()
    } else {
        format!("{}–{}", show3(b.min), show3(b.max))
    }
}

// ---------------------------------------------------------------------
// Exercise 1: the slab test.
// ---------------------------------------------------------------------

/// A box whose coordinates are short binary fractions times a power of
/// two, with its size: every answer below is then exact.
fn binary_box(rng: &mut Rng) -> (Aabb, f64) {
    let unit = 2f64.powi(rng.below(50) as i32 - 25);
    let corner = |rng: &mut Rng| (rng.below(65) as f64 - 32.0) / 4.0;
    let min = DVec3::new(corner(rng), corner(rng), corner(rng)) * unit;
    let size = DVec3::new(
        (1 + rng.below(32)) as f64 / 4.0,
        (1 + rng.below(32)) as f64 / 4.0,
        (1 + rng.below(32)) as f64 / 4.0,
    ) * unit;
    (Aabb::new(min, min + size), unit)
}

/// A point of the box at fractions `f` of its extent.
fn point_in(b: &Aabb, f: DVec3) -> DVec3 {
    b.min + f * (b.max - b.min)
}

/// A fraction strictly inside, a short binary one.
fn inside_fraction(rng: &mut Rng) -> f64 {
    (1 + rng.below(7)) as f64 / 8.0
}

/// A direction of `speed` (a power of two, signed) along `axis`, ±0 on
/// the other axes.
fn along(axis: usize, speed: f64, zero: f64) -> DVec3 {
    let mut d = DVec3::splat(zero);
    d[axis] = speed;
    d
}

/// The plain slab test ([`common::plain_slab`]; an empty box missed), to
/// keep the draws and the answers' shape independent of the code judged
/// (which is exercise 1 itself, or a hierarchy walked with it); used only
/// where a margin of 1e-9 makes its rounding irrelevant.
fn plain_slab(b: &Aabb, ray: &Ray, interval: Interval) -> Option<Interval> {
    if b.is_empty() {
        return None;
    }
    common::plain_slab(b, ray, interval)
}

/// Is the answer for this box, ray and interval the same for boxes and
/// intervals a relative 1e-9 larger and smaller (else a correct slab test
/// in another order may answer either way)?
fn robust(b: &Aabb, ray: &Ray, interval: Interval, t_scale: f64) -> bool {
    let answer = plain_slab(b, ray, interval).is_some();
    let grown = |k: f64| {
        let (c, h) = ((b.min + b.max) / 2.0, (b.max - b.min) / 2.0);
        Aabb::new(c - h * k, c + h * k)
    };
    let widen = |k: f64| {
        let pad = |x: f64| 1e-9 * k * x.abs().max(t_scale);
        Interval::new(
            interval.min - pad(interval.min),
            interval.max + pad(interval.max),
        )
    };
    let finite_box = !b.is_empty() && b.min.is_finite() && b.max.is_finite();
    [-1.0, 1.0].iter().all(|&k| {
        (!finite_box
            || plain_slab(&grown(1.0 + 1e-9 * k), ray, interval).is_some()
                == answer)
            && plain_slab(b, ray, widen(k)).is_some() == answer
    })
}

/// One ray against one box: a case of the catalogue or a random one.
struct SlabCase {
    what: &'static str,
    b: Aabb,
    ray: Ray,
    interval: Interval,
    /// The scale of t; None for a ray with NaN in it (only "no NaN in
    /// the answer" is asked of it).
    t_scale: Option<f64>,
}

fn slab_catalogue(rng: &mut Rng) -> SlabCase {
    let (b, unit) = binary_box(rng);
    let axis = rng.below(3);
    let (i, j) = ((axis + 1) % 3, (axis + 2) % 3);
    let speed = 2f64.powi(rng.below(5) as i32 - 2) * sign(rng);
    let zero = if rng.chance(0.5) { 0.0 } else { -0.0 };
    let size = b.max - b.min;
    let interval = Interval::FORWARD;
    match rng.below(5) {
        0 => {
            // along an axis from outside, through the box
            let mut f = DVec3::ZERO;
            f[i] = inside_fraction(rng);
            f[j] = inside_fraction(rng);
            let mut o = point_in(&b, f);
            let gap = unit * (1 + rng.below(16)) as f64;
            o[axis] = if speed > 0.0 {
                b.min[axis] - gap
            } else {
                b.max[axis] + gap
            };
            SlabCase {
                what: "along an axis, through the box",
                b,
                ray: Ray::new(o, along(axis, speed, zero)),
                interval,
                t_scale: Some(unit / speed.abs()),
            }
        }
        1 => {
            // along an axis beside the box: one coordinate the next float
            // past a face, or far past it
            let mut f = DVec3::ZERO;
            f[j] = inside_fraction(rng);
            let mut o = point_in(&b, f);
            o[i] = match rng.below(4) {
                0 => b.min[i].next_down(),
                1 => b.max[i].next_up(),
                2 => b.min[i] - 5.0 * unit,
                _ => b.max[i] + 5.0 * unit,
            };
            o[axis] = b.min[axis] - speed.signum() * 7.0 * unit;
            SlabCase {
                what: "along an axis, beside the box",
                b,
                ray: Ray::new(o, along(axis, speed, zero)),
                interval,
                t_scale: Some(unit / speed.abs()),
            }
        }
        2 => {
            // along an axis from inside
            let f = DVec3::new(
                inside_fraction(rng),
                inside_fraction(rng),
                inside_fraction(rng),
            );
            SlabCase {
                what: "along an axis, from inside",
                b,
                ray: Ray::new(point_in(&b, f), along(axis, speed, zero)),
                interval,
                t_scale: Some(unit / speed.abs()),
            }
        }
        3 => {
            // the origin on a slab's plane, the ray lying in that plane
            // (0·∞ = NaN), through the face, along its edge, or beside it
            let plane = if rng.chance(0.5) { b.min[i] } else { b.max[i] };
            let mut o = DVec3::ZERO;
            o[i] = plane;
            o[j] = match rng.below(4) {
                0 => point_in(&b, DVec3::splat(0.375))[j],
                1 => b.min[j],
                2 => b.max[j],
                _ => b.max[j] + size[j],
            };
            o[axis] = if speed > 0.0 {
                b.min[axis] - 2.0 * unit
            } else {
                b.max[axis] + 2.0 * unit
            };
            SlabCase {
                what: "in the plane of a slab (0·∞ = NaN)",
                b,
                ray: Ray::new(o, along(axis, speed, zero)),
                interval,
                t_scale: Some(unit / speed.abs()),
            }
        }
        _ => {
            // on a face, straight in or straight out (touching at t = 0)
            let mut o = point_in(&b, DVec3::splat(0.625));
            o[axis] = if rng.chance(0.5) {
                b.min[axis]
            } else {
                b.max[axis]
            };
            SlabCase {
                what: "starting on a face, straight in or out",
                b,
                ray: Ray::new(o, along(axis, speed, zero)),
                interval,
                t_scale: Some(unit / speed.abs()),
            }
        }
    }
}

/// Forty rays through points of a box's edges and corners from far
/// away, with integer offsets (so each passes exactly through its point
/// at t = 1), each only touching the box there (it comes from outside
/// and leaves outside): the entry and the exit are the same t, and only
/// a widened exit keeps rounding from putting the entry past it.
fn slab_touching(rng: &mut Rng, case: &mut Case) {
    let (b, unit) = binary_box(rng);
    let grid = |rng: &mut Rng| rng.below(1025) as f64 / 1024.0;
    let rays: Vec<Ray> = (0..40)
        .map(|_| {
            let mut f = DVec3::new(grid(rng), grid(rng), grid(rng));
            let first = rng.below(3);
            let pinned = 2 + rng.below(2);
            // +1 where the point is on a min face (inward is +), -1 on a
            // max face
            let mut inward = [0.0; 3];
            for n in 0..pinned {
                let k = (first + n) % 3;
                let on_min = rng.chance(0.5);
                f[k] = if on_min { 0.0 } else { 1.0 };
                inward[k] = if on_min { 1.0 } else { -1.0 };
            }
            let target = point_in(&b, f);
            let reach = [1.0, 30.0, 1000.0][rng.below(3)];
            loop {
                let d = DVec3::new(
                    (rng.uniform(-reach, reach + 1.0)).floor(),
                    (rng.uniform(-reach, reach + 1.0)).floor(),
                    (rng.uniform(-reach, reach + 1.0)).floor(),
                );
                // touching only: along the pinned axes, it neither goes
                // into the box on all of them nor out of it on all
                let ways: Vec<f64> = (0..3)
                    .filter(|&k| inward[k] != 0.0)
                    .map(|k| {
                        (inward[k] * d[k]).signum()
                            * f64::from(u8::from(d[k] != 0.0))
                    })
                    .collect();
                let touching = ways.iter().all(|&w| w != 0.0)
                    && ways.iter().any(|&w| w > 0.0)
                    && ways.iter().any(|&w| w < 0.0);
                if touching && d.x != 0.0 && d.y != 0.0 && d.z != 0.0 {
                    let d = d * unit;
                    break Ray::new(target - d, d);
                }
            }
        })
        .collect();
    case.ask(format!(
        "box {}; 40 rays touching its edges or corners at t = 1, the first \
         from {} along {}",
        show_box(&b),
        show3(rays[0].origin),
        show3(rays[0].direction)
    ));
    for ray in rays {
        match slab_test(&b, &ray, Interval::FORWARD) {
            Some(i) => {
                case.word("hit");
                case.num("t0", i.min);
                case.num("t1", i.max);
            }
            None => case.word("miss"),
        }
    }
}

/// NaN in the origin, the direction or both: no answer is right, only
/// one with NaN in it is wrong.
fn slab_nan(rng: &mut Rng) -> SlabCase {
    let (b, _) = binary_box(rng);
    let nan = |rng: &mut Rng, p: DVec3| {
        let mut p = p;
        let mask = 1 + rng.below(7);
        for axis in 0..3 {
            if mask & (1 << axis) != 0 {
                p[axis] = f64::NAN;
            }
        }
        p
    };
    let o = b.min - (b.max - b.min);
    let d = [
        DVec3::new(1.0, 1.0, 1.0),
        DVec3::new(0.0, 0.0, 1.0),
        DVec3::new(-1.0, 2.0, -0.0),
    ][rng.below(3)];
    let ray = match rng.below(3) {
        0 => Ray::new(nan(rng, o), d),
        1 => Ray::new(o, nan(rng, d)),
        _ => {
            let inside = point_in(&b, DVec3::splat(0.5));
            Ray::new(nan(rng, inside), nan(rng, d))
        }
    };
    SlabCase {
        what: "NaN in the ray",
        b,
        ray,
        interval: Interval::FORWARD,
        t_scale: None,
    }
}

/// Any box, any ray, any interval (kept only if the answer does not
/// change when the box or the interval moves by a relative 1e-9); now and
/// then the empty box or the box of everything.
fn slab_random(rng: &mut Rng) -> SlabCase {
    loop {
        let s = 10f64.powf(rng.uniform(-6.0, 6.0));
        let b = match rng.below(10) {
            0 => Aabb::EMPTY,
            1 => Aabb::EVERYTHING,
            _ => Aabb::new(rng.vec3(10.0 * s), rng.vec3(10.0 * s)),
        };
        let m = 10f64.powf(rng.uniform(-3.0, 3.0));
        let mut d = rng.vec3(m);
        if rng.chance(0.3) {
            d[rng.below(3)] = 0.0;
        }
        let origin = rng.vec3(20.0 * s);
        let target = if rng.chance(0.6) && !b.is_empty() && b.min.is_finite() {
            let f = DVec3::new(rng.unit(), rng.unit(), rng.unit());
            point_in(&b, f)
        } else {
            rng.vec3(10.0 * s)
        };
        let ray = if rng.chance(0.5) {
            Ray::new(origin, (target - origin) / s * m)
        } else {
            Ray::new(origin, d)
        };
        let t_scale = s / ray.direction.length().max(1e-300);
        let interval = match rng.below(4) {
            0 | 1 => Interval::FORWARD,
            2 => Interval::UNIVERSE,
            _ => {
                let lo = t_scale * rng.uniform(-5.0, 5.0);
                Interval::new(lo, lo + t_scale * rng.uniform(0.0, 20.0))
            }
        };
        if robust(&b, &ray, interval, t_scale) {
            return SlabCase {
                what: "any box and ray",
                b,
                ray,
                interval,
                t_scale: Some(t_scale),
            };
        }
    }
}

fn slab_case(rng: &mut Rng, case: &mut Case) {
    let c = match rng.below(10) {
        0..=3 => slab_catalogue(rng),
        4 => slab_nan(rng),
        5 | 6 => return slab_touching(rng, case),
        _ => slab_random(rng),
    };
    case.ask(format!(
        "{}: box {}, ray from {} along {}, t in {}",
        c.what,
        show_box(&c.b),
        show3(c.ray.origin),
        show3(c.ray.direction),
        show_interval(c.interval)
    ));
    let got = slab_test(&c.b, &c.ray, c.interval);
    match (got, c.t_scale) {
        (None, _) => case.word("miss"),
        (Some(i), Some(t_scale)) => {
            case.word("hit");
            case.num("t0/T", i.min / t_scale);
            case.num("t1/T", i.max / t_scale);
        }
        (Some(i), None) => {
            let within = !i.min.is_nan()
                && !i.max.is_nan()
                && c.interval.min <= i.min
                && i.max <= c.interval.max;
            case.word(if within {
                "hit-without-nan"
            } else {
                "hit-with-nan-or-outside-the-interval"
            });
        }
    }
}

// ---------------------------------------------------------------------
// Exercise 2: the watertight triangle test.
// ---------------------------------------------------------------------

/// The point with barycentric coordinates (1 − u − w, u, w).
fn at(tri: &[DVec3; 3], u: f64, w: f64) -> DVec3 {
    tri[0] + u * (tri[1] - tri[0]) + w * (tri[2] - tri[0])
}

fn show_triangle(tri: &[DVec3; 3]) -> String {
    format!("[{}, {}, {}]", show3(tri[0]), show3(tri[1]), show3(tri[2]))
}

/// A random triangle (not thin) at scale s and a ray aimed at a point
/// clearly inside it or clearly outside it (by 1e-3 of its size in
/// barycentrics), not grazing its plane; the interval all of t ≥ 0, or
/// ending before the hit, or starting after it; now and then pointing
/// away, parallel, or with NaN or ∞ in it.
fn random_triangle(rng: &mut Rng, case: &mut Case) {
    let s = 10f64.powf(rng.uniform(-4.0, 5.0));
    let reach = s * 10f64.powf(rng.uniform(0.0, 3.0));
    let offset = rng.vec3(reach);
    let tri = loop {
        let tri = [0; 3].map(|_| offset + rng.vec3(10.0 * s));
        let (e1, e2) = (tri[1] - tri[0], tri[2] - tri[0]);
        if e1.cross(e2).length() > 0.05 * e1.length() * e2.length() {
            break tri;
        }
    };
    let normal = (tri[1] - tri[0]).cross(tri[2] - tri[0]).normalize();
    let (what, ray, interval) = loop {
        let (mut u, mut w) = (rng.uniform(1e-3, 1.0), rng.uniform(1e-3, 1.0));
        if u + w > 1.0 - 1e-3 {
            (u, w) = (1.0 - u, 1.0 - w);
        }
        let inside = rng.chance(0.6);
        let (u, w) = if inside {
            (u, w)
        } else {
            let past = rng.uniform(1e-3, 1.0);
            match rng.below(3) {
                0 => (u, -past),
                1 => (-past, w),
                _ => (u + past, w + past),
            }
        };
        if !inside && u + w <= 1.0 + 1e-3 && u > 0.0 && w > 0.0 {
            continue;
        }
        let target = at(&tri, u, w);
        let from = target + rng.vec3(30.0 * s) + rng.unit_vec3() * 5.0 * s;
        let direction = (target - from) * 10f64.powf(rng.uniform(-2.0, 2.0));
        if direction.normalize().dot(normal).abs() < 0.05 {
            continue;
        }
        let t_hit = (target - from).length() / direction.length();
        let (what, ray, interval) = match rng.below(8) {
            0 => (
                "ending before the plane",
                Ray::new(from, direction),
                Interval::new(0.0, t_hit * 0.999),
            ),
            1 => (
                "starting after the plane",
                Ray::new(from, direction),
                Interval::new(t_hit * 1.001, f64::INFINITY),
            ),
            2 => (
                "pointing away",
                Ray::new(from, -direction),
                Interval::FORWARD,
            ),
            3 => {
                let along = (tri[1] - tri[0]) * rng.uniform(0.1, 2.0);
                let above = target + normal * s * rng.uniform(0.1, 1.0);
                (
                    "parallel to the plane",
                    Ray::new(above, along),
                    Interval::UNIVERSE,
                )
            }
            4 if rng.chance(0.3) => {
                let mut o = from;
                o[rng.below(3)] = f64::NAN;
                ("a NaN origin", Ray::new(o, direction), Interval::FORWARD)
            }
            4 if rng.chance(0.4) => {
                let mut d = direction;
                d[rng.below(3)] = f64::INFINITY * sign(rng);
                (
                    "an infinite direction",
                    Ray::new(from, d),
                    Interval::FORWARD,
                )
            }
            _ if inside => {
                ("aimed inside", Ray::new(from, direction), Interval::FORWARD)
            }
            _ => (
                "aimed outside",
                Ray::new(from, direction),
                Interval::FORWARD,
            ),
        };
        break (what, ray, interval);
    };
    let tri = if rng.chance(0.5) {
        [tri[0], tri[2], tri[1]]
    } else {
        tri
    };
    case.ask(format!(
        "{what}: triangle {}, ray from {} along {}, t in {}",
        show_triangle(&tri),
        show3(ray.origin),
        show3(ray.direction),
        show_interval(interval)
    ));
    match watertight(&tri, &ray, interval) {
        Some(t) => {
            case.word("hit");
            case.num("t", t);
        }
        None => case.word("miss"),
    }
}

/// `(a, b, c)` with `c` along `axis` and `a`, `b` along the two axes after
/// it (a cyclic turn of x, y, z: windings are kept).
fn on_axis(axis: usize, (a, b, c): (f64, f64, f64)) -> DVec3 {
    let mut p = DVec3::ZERO;
    (p[(axis + 1) % 3], p[(axis + 2) % 3], p[axis]) = (a, b, c);
    p
}

/// A flat fan of triangles around a centre, in the plane
/// coordinate[axis] = h, every coordinate a short binary fraction (times
/// a power of two), some triangles wound the other way; rays along
/// binary-fraction directions exactly through the centre, a shared
/// edge's midpoint or quarter point, or a rim vertex: every edge function
/// there is exactly 0, and the tie rule gives the point to exactly one
/// triangle.
fn fan(rng: &mut Rng, case: &mut Case) {
    let unit = 2f64.powi(rng.below(40) as i32 - 20);
    let axis = rng.below(3);
    let h = (rng.below(17) as f64 - 8.0) / 4.0;
    let (triangles, targets) = loop {
        let centre = (
            (rng.below(9) as f64 - 4.0) / 4.0,
            (rng.below(9) as f64 - 4.0) / 4.0,
        );
        let n = 3 + rng.below(5);
        let mut angles: Vec<f64> = (0..n)
            .map(|_| rng.uniform(0.0, std::f64::consts::TAU))
            .collect();
        angles.sort_by(f64::total_cmp);
        let rim: Vec<(f64, f64)> = angles
            .iter()
            .map(|a| {
                let r = 2.0 + rng.below(5) as f64 / 2.0;
                (
                    centre.0 + (r * a.cos() * 4.0).round() / 4.0,
                    centre.1 + (r * a.sin() * 4.0).round() / 4.0,
                )
            })
            .collect();
        // a proper fan: every rim pair turns left around the centre, by a
        // clear angle (exact arithmetic on these fractions)
        let turn = |p: (f64, f64), q: (f64, f64)| {
            (p.0 - centre.0) * (q.1 - centre.1)
                - (p.1 - centre.1) * (q.0 - centre.0)
        };
        let ok = (0..n).all(|k| turn(rim[k], rim[(k + 1) % n]) >= 0.5);
        if !ok {
            continue;
        }
        let point = |(a, b): (f64, f64)| on_axis(axis, (a, b, h)) * unit;
        let c = point(centre);
        let triangles: Vec<[DVec3; 3]> = (0..n)
            .map(|k| {
                let (p, q) = (point(rim[k]), point(rim[(k + 1) % n]));
                if rng.chance(0.3) {
                    [c, q, p]
                } else {
                    [c, p, q]
                }
            })
            .collect();
        let mut targets = vec![c];
        for &corner in &rim {
            let p = point(corner);
            targets.push(0.5 * (c + p));
            targets.push(0.75 * c + 0.25 * p);
            targets.push(p);
        }
        break (triangles, targets);
    };
    let target = targets[rng.below(targets.len())];
    let small = |rng: &mut Rng| (rng.below(13) as f64 - 6.0) / 8.0;
    let lead = [1.0, 2.0][rng.below(2)] * sign(rng);
    let d = on_axis(axis, (small(rng), small(rng), lead)) * unit;
    let ray = Ray::new(target - 4.0 * d, d);
    let shown: Vec<String> = triangles.iter().map(show_triangle).collect();
    case.ask(format!(
        "a flat fan {}; ray from {} along {} through {}",
        shown.join(", "),
        show3(ray.origin),
        show3(ray.direction),
        show3(target)
    ));
    for tri in &triangles {
        match watertight(tri, &ray, Interval::FORWARD) {
            Some(t) => {
                case.word("hit");
                case.num("t", t);
            }
            None => case.word("miss"),
        }
    }
}

/// Two triangles sharing an edge whose fast edge function (two rounded
/// products subtracted) is exactly 0 while the exact one is −2⁻¹⁰⁴ of
/// the scale: only the exact fallback gives the ray to the right one.
/// Scaled by a power of two, turned to any axis and either direction.
fn tiny_edge_function(rng: &mut Rng, case: &mut Case) {
    let u = f64::EPSILON;
    let unit = 2f64.powi(rng.below(40) as i32 - 20);
    let axis = rng.below(3);
    let put = |x: f64, y: f64, z: f64| on_axis(axis, (x, y, z)) * unit;
    let p = put(1.0 + u, 1.0 + 2.0 * u, 0.0);
    let q = put(-1.0, -(1.0 + u), 0.0);
    let a = [p, q, put(1.0, -1.0, 0.0)];
    let b = [q, p, put(-1.0, 1.0, 0.0)];
    let up = sign(rng);
    let ray = Ray::new(put(0.0, 0.0, -up), put(0.0, 0.0, up));
    case.ask(format!(
        "triangles A {} and B {} sharing an edge the ray from {} along {} \
         passes 2⁻¹⁰⁴ inside B",
        show_triangle(&a),
        show_triangle(&b),
        show3(ray.origin),
        show3(ray.direction)
    ));
    for tri in [a, b] {
        match watertight(&tri, &ray, Interval::FORWARD) {
            Some(t) => {
                case.word("hit");
                case.num("t", t);
            }
            None => case.word("miss"),
        }
    }
}

fn watertight_case(rng: &mut Rng, case: &mut Case) {
    match rng.below(10) {
        0..=4 => random_triangle(rng, case),
        5..=8 => fan(rng, case),
        _ => tiny_edge_function(rng, case),
    }
}

// ---------------------------------------------------------------------
// Exercise 3: the torus quartic.
// ---------------------------------------------------------------------

/// The coefficients for a random torus and ray (origin inside the tube,
/// near the torus or far away; direction of any length), each in units of
/// its natural size L⁴⁻ᵏ·|D|ᵏ with L = |O| + R + r.
fn torus_quartic_case(rng: &mut Rng, case: &mut Case) {
    let s = 10f64.powf(rng.uniform(-3.0, 3.0));
    let major = s * rng.uniform(0.5, 3.0);
    let minor = major * rng.uniform(0.05, 0.95);
    let origin = match rng.below(4) {
        0 => {
            // inside the tube
            let phi = rng.uniform(0.0, std::f64::consts::TAU);
            let ring = DVec3::new(phi.cos(), 0.0, phi.sin()) * major;
            ring + rng.unit_vec3() * minor * rng.uniform(0.0, 0.9)
        }
        1 => DVec3::ZERO,
        2 => rng.vec3(100.0 * major),
        _ => rng.vec3(3.0 * major),
    };
    let m = 10f64.powf(rng.uniform(-2.0, 2.0));
    let direction = if rng.chance(0.2) {
        let mut d = DVec3::ZERO;
        d[rng.below(3)] = m * sign(rng);
        d
    } else {
        rng.unit_vec3() * m
    };
    let ray = Ray::new(origin, direction);
    case.ask(format!(
        "torus_quartic(R = {}, r = {}, ray from {} along {})",
        short(major),
        short(minor),
        show3(origin),
        show3(direction)
    ));
    let c = torus_quartic(major, minor, &ray);
    let size = origin.length() + major + minor;
    for (k, ck) in c.iter().enumerate() {
        let natural = size.powi(4 - k as i32) * m.powi(k as i32);
        case.num(&format!("c{k}/L^{}D^{k}", 4 - k), ck / natural);
    }
}

// ---------------------------------------------------------------------
// Exercise 4: a bounding sphere of points.
// ---------------------------------------------------------------------

/// A point set: on a sphere in opposite pairs (the smallest sphere known),
/// a box's corners (its circumsphere the smallest), points on a segment
/// (the segment the diameter), a cloud, one point repeated, none.
fn point_set(rng: &mut Rng) -> (&'static str, Vec<DVec3>, Option<f64>) {
    let s = 10f64.powf(rng.uniform(-6.0, 3.0));
    let reach = s * 10f64.powf(rng.uniform(-1.0, 4.0));
    let at = rng.vec3(reach);
    match rng.below(7) {
        0 | 1 => {
            let pairs = 2 + rng.below(60);
            let points = (0..pairs)
                .flat_map(|_| {
                    let u = rng.unit_vec3();
                    [at + s * u, at - s * u]
                })
                .collect();
            ("opposite pairs on a sphere", points, Some(s))
        }
        2 => {
            let size = DVec3::new(rng.unit(), rng.unit(), rng.unit()) * s;
            let size = if rng.chance(0.3) {
                DVec3::new(size.x, size.y, 0.0)
            } else {
                size
            };
            let points: Vec<DVec3> = (0..8)
                .map(|k| {
                    at + DVec3::new(
                        if k & 1 == 0 { 0.0 } else { size.x },
                        if k & 2 == 0 { 0.0 } else { size.y },
                        if k & 4 == 0 { 0.0 } else { size.z },
                    )
                })
                .collect();
            let r = 0.5 * size.length();
            ("the corners of a box", points, Some(r))
        }
        3 => {
            let (a, b) = (at, at + rng.unit_vec3() * s);
            let mut points: Vec<DVec3> = (0..2 + rng.below(40))
                .map(|_| a.lerp(b, rng.unit()))
                .collect();
            points.push(a);
            points.push(b);
            let turn = rng.below(points.len());
            points.rotate_left(turn);
            ("points on a segment", points, Some(0.5 * a.distance(b)))
        }
        4 | 5 => {
            let count = 1 + rng.below(120);
            let points = (0..count)
                .map(|_| at + s * rng.unit_vec3() * rng.unit())
                .collect();
            ("a cloud", points, None)
        }
        _ => {
            let count = rng.below(4);
            ("one point repeated (or none)", vec![at; count], Some(0.0))
        }
    }
}

/// What any correct bounding sphere does: it holds every point (to
/// rounding, 1e-12 of its size), is no smaller than half the diameter and
/// no larger than √3 times that (what a box's circumsphere can be), and,
/// where the smallest sphere is known, within 1.5 times its radius (Ritter
/// stays within 1.25); no points: radius 0 at the origin.
fn sphere_of_points_case(rng: &mut Rng, case: &mut Case) {
    let (what, points, smallest) = point_set(rng);
    let shown: Vec<String> =
        points.iter().take(12).map(|&p| show3(p)).collect();
    case.ask(format!(
        "{what}: {} points {}{}",
        points.len(),
        shown.join(", "),
        if points.len() > 12 { ", …" } else { "" }
    ));
    let sphere = sphere_of_points(&points);
    if points.is_empty() {
        case.num("radius", sphere.radius);
        case.vec3("centre", sphere.center);
        return;
    }
    let finite = sphere.radius.is_finite()
        && sphere.center.is_finite()
        && sphere.radius >= 0.0;
    case.word(if finite { "finite" } else { "not-finite" });
    let slack = 1e-12 * (sphere.radius + sphere.center.abs().max_element());
    let holds = points
        .iter()
        .all(|p| p.distance(sphere.center) <= sphere.radius + slack);
    case.word(if holds {
        "holds-every-point"
    } else {
        "leaves-a-point-out"
    });
    let half = half_diameter(&points);
    let fits = sphere.radius >= half * (1.0 - 1e-9) - slack
        && sphere.radius <= 3f64.sqrt() * half + slack;
    case.word(if fits {
        "between-half-diameter-and-sqrt3-times"
    } else {
        "too-small-or-too-large"
    });
    if let Some(r_min) = smallest {
        let rounding = 1e-12 * (r_min + sphere.center.abs().max_element());
        let tight = sphere.radius <= 1.5 * r_min + rounding;
        case.word(if tight {
            "within-1.5-of-smallest"
        } else {
            "loose"
        });
    }
}

// ---------------------------------------------------------------------
// Exercise 5: the SAH cost of a split.
// ---------------------------------------------------------------------

/// A parent box cut into two along an axis, or two children anywhere
/// (overlapping, an empty one), or a parent of zero area (a point, a
/// segment); counts from 0 to 40.
fn sah_split_case(rng: &mut Rng, case: &mut Case) {
    let s = 10f64.powf(rng.uniform(-3.0, 3.0));
    let reach = s * 10f64.powf(rng.uniform(0.0, 6.0));
    let offset = rng.vec3(reach);
    let some_box = |rng: &mut Rng| {
        let a = offset + rng.vec3(s);
        Aabb::new(a, a + DVec3::new(rng.unit(), rng.unit(), rng.unit()) * s)
    };
    let (what, parent, left, right) = match rng.below(5) {
        0 | 1 => {
            let parent = some_box(rng);
            let axis = rng.below(3);
            let cut = parent.min[axis]
                + rng.unit() * (parent.max[axis] - parent.min[axis]);
            let (mut l, mut r) = (parent, parent);
            l.max[axis] = cut;
            r.min[axis] = cut;
            ("a box cut in two", parent, l, r)
        }
        2 => {
            let (l, r) = (some_box(rng), some_box(rng));
            ("two children anywhere", l.union(r), l, r)
        }
        3 => {
            let parent = some_box(rng);
            let l = some_box(rng);
            let (l, r) = if rng.chance(0.5) {
                (l, Aabb::EMPTY)
            } else {
                (Aabb::EMPTY, l)
            };
            ("an empty child", parent, l, r)
        }
        _ => {
            let p = offset;
            let parent = if rng.chance(0.5) {
                Aabb::new(p, p)
            } else {
                let mut q = p;
                q[rng.below(3)] += s;
                Aabb::new(p, q)
            };
            ("a parent of zero area", parent, parent, parent)
        }
    };
    let n_left = if left.is_empty() { 0 } else { rng.below(41) };
    let n_right = if right.is_empty() { 0 } else { rng.below(41) };
    // The chapter's costs, pbrt's, or any two.
    let costs = match rng.below(3) {
        0 => SahCosts::CHOSEN,
        1 => SahCosts {
            traversal: 0.5,
            intersection: 1.0,
        },
        _ => SahCosts {
            traversal: rng.uniform(0.05, 4.0),
            intersection: rng.uniform(0.05, 4.0),
        },
    };
    case.ask(format!(
        "{what}: split_cost(parent {}, left {} with {n_left}, right {} with \
         {n_right}, a visit {} and a test {})",
        show_box(&parent),
        show_box(&left),
        show_box(&right),
        short(costs.traversal),
        short(costs.intersection),
    ));
    case.num(
        "cost",
        split_cost(&parent, &left, n_left, &right, n_right, &costs),
    );
}

// ---------------------------------------------------------------------
// Exercise 6: the near-first walk.
// ---------------------------------------------------------------------

/// Chapter 3's sphere that writes its index into a shared log each time a
/// ray is tested against it.
#[derive(Debug)]
struct Logged {
    sphere: Sphere,
    index: usize,
    log: Arc<Mutex<Vec<usize>>>,
}

impl Shape for Logged {
    fn intersect(&self, ray: &Ray, interval: Interval) -> Option<Hit> {
        self.log
            .lock()
            .unwrap_or_else(|e| e.into_inner())
            .push(self.index);
        self.sphere.intersect(ray, interval)
    }

    fn bounds(&self) -> Aabb {
        Shape::bounds(&self.sphere)
    }
}

/// Two children of one interior node that the ray enters at the same t
/// (a starting point inside both, or a shared face): the order of the
/// two is then the walk's choice, and so is what it tests.
fn has_entry_ties(bvh: &Bvh, ray: &Ray, interval: Interval) -> bool {
    bvh.nodes.iter().any(|node| {
        if node.is_leaf() {
            return false;
        }
        let entry = |k: u32| {
            plain_slab(&bvh.nodes[k as usize].bounds, ray, interval)
                .map(|inside| inside.min)
        };
        matches!(
            (entry(node.first), entry(node.first + 1)),
            (Some(a), Some(b)) if (a - b).abs() <= 1e-9 * a.abs().max(b.abs())
        )
    })
}

/// Spheres in a cloud (and a plane outside the tree now and then), a BVH
/// by one of the builders, and a ray from outside the cloud or inside it,
/// over all of t ≥ 0 or part of it: the closest hit, and (without a
/// plane, and where no two children are entered at the same t) exactly
/// which spheres the walk tested.
fn near_first_case(rng: &mut Rng, case: &mut Case) {
    let s = 10f64.powf(rng.uniform(-3.0, 3.0));
    let count = rng.below(120);
    let log = Arc::new(Mutex::new(Vec::new()));
    let spread = rng.uniform(2.0, 20.0);
    let mut spheres: Vec<(DVec3, f64)> = (0..count)
        .map(|_| (rng.vec3(spread * s), s * rng.uniform(0.1, 1.5)))
        .collect();
    if rng.chance(0.15) {
        // a row, as the tests have it
        spheres = (0..count)
            .map(|k| (DVec3::new(3.0 * k as f64, 0.0, 0.0) * s, s))
            .collect();
    }
    let mut objects: Vec<Object> = spheres
        .iter()
        .enumerate()
        .map(|(index, &(center, radius))| Object {
            shape: Arc::new(Logged {
                sphere: Sphere::new(center, radius),
                index,
                log: Arc::clone(&log),
            }),
            material: 0,
        })
        .collect();
    let plane = rng.chance(0.15);
    let plane_height = s * rng.uniform(-spread, spread);
    let at = rng.below(objects.len() + 1);
    if plane {
        objects.insert(
            at,
            Object {
                shape: Arc::new(ch02::InfinitePlane(ch02::Plane {
                    normal: DVec3::Y,
                    d: -plane_height,
                })),
                material: 0,
            },
        );
    }
    let builders = [
        Builder::Median,
        Builder::Midpoint,
        Builder::BinnedSah { bins: 8 },
        Builder::SweepSah,
        Builder::Agglomerative,
        Builder::Ploc { radius: 4 },
    ];
    let builder = builders[rng.below(builders.len())];
    let bvh = Bvh::for_objects(&objects, builder);
    let origin = if rng.chance(0.7) {
        rng.unit_vec3() * 2.0 * spread * s * 1.8
    } else {
        rng.vec3(spread * s)
    };
    let target = match spheres.get(rng.below(spheres.len().max(1))) {
        Some(&(center, radius)) if rng.chance(0.6) => {
            center + rng.unit_vec3() * radius * rng.uniform(0.0, 1.2)
        }
        _ => rng.vec3(spread * s),
    };
    let m = 10f64.powf(rng.uniform(-2.0, 2.0));
    let direction = (target - origin).normalize() * m;
    let ray = Ray::new(origin, direction);
    let t_scale = spread * s / m;
    let interval = match rng.below(4) {
        0 | 1 => Interval::FORWARD,
        2 => Interval::new(0.0, t_scale * rng.uniform(0.5, 4.0)),
        _ => Interval::new(t_scale * rng.uniform(0.0, 2.0), f64::INFINITY),
    };
    let shown: Vec<String> = spheres
        .iter()
        .map(|&(c, r)| format!("{} r {}", show3(c), short(r)))
        .collect();
    case.ask(format!(
        "{} spheres [{}]{}; BVH by {}; ray from {} along {}, t in {}",
        spheres.len(),
        shown.join("; "),
        if plane {
            format!(
                ", and the plane y = {} as object {at}",
                short(plane_height)
            )
        } else {
            String::new()
        },
        builder.name(),
        show3(origin),
        show3(direction),
        show_interval(interval)
    ));
    let ties = has_entry_ties(&bvh, &ray, interval);
    log.lock().unwrap_or_else(|e| e.into_inner()).clear();
    let hit = near_first_closest_hit(&bvh, &objects, &ray, interval);
    match hit {
        Some((index, hit)) => {
            case.word("hit");
            case.word(format!("object-{index}"));
            case.num("t/T", hit.t / t_scale);
        }
        None => case.word("none"),
    }
    if !plane && !ties {
        let mut tested =
            std::mem::take(&mut *log.lock().unwrap_or_else(|e| e.into_inner()));
        tested.sort_unstable();
        let list: Vec<String> = tested.iter().map(|k| k.to_string()).collect();
        case.word(format!("tested:{}", list.join(",")));
    }
}
