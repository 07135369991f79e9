//! Held-out cases of chapter 9 for `raystep grade` (see
//! `raystep_check::held_out`): the DDA's setup and its walk through grids
//! of any size of cell, anywhere, for rays from outside and inside, with
//! ±0 components, along planes and grid lines, through corners (exact
//! ties, where x steps before y before z), clipped by the interval, cut
//! short by the visitor, and rays that are no rays (zero or NaN).
use std::ops::ControlFlow;
use std::process::ExitCode;

use ch09::{Aabb, DVec3, Interval, Lattice, Ray, dda_setup, walk};
use raystep_check::held_out::{self, Case, Exercise, Rng, short, show3};

fn main() -> ExitCode {
    held_out::main(&[
        Exercise {
            name: "dda_setup",
            run: dda_setup_case,
            tolerance: 1e-9,
        },
        Exercise {
            name: "walk",
            run: walk_case,
            tolerance: 1e-9,
        },
    ])
}

/// One grid, one ray, one interval, and the scale T of the ray's t.
struct GridCase {
    what: &'static str,
    lattice: Lattice,
    ray: Ray,
    interval: Interval,
    t_scale: f64,
}

/// A grid of 1 to 12 cells per axis, cells of any proportion (0.5 to 8
/// times the scale), its corner within 10 of its sizes of the origin; a
/// ray from inside or outside, now and then with ±0 components; the
/// interval all of t ≥ 0 or a stretch. Kept only if it is clear: the
/// ray meets no two interior planes (of different axes) at t within
/// 1e-9 of each other, nor one within 1e-9 of where it enters or leaves,
/// and enters the box (or misses it) by more than rounding.
fn random_grid(rng: &mut Rng) -> GridCase {
    loop {
        let s = 10f64.powf(rng.uniform(-4.0, 4.0));
        let extent = DVec3::new(
            rng.uniform(0.5, 8.0),
            rng.uniform(0.5, 8.0),
            rng.uniform(0.5, 8.0),
        ) * s;
        let min = rng.vec3(10.0 * extent.max_element());
        let cells = [0; 3].map(|_| 1 + rng.below(12));
        let lattice = Lattice::new(Aabb::new(min, min + extent), cells);
        let centre = min + 0.5 * extent;
        let origin = if rng.chance(0.35) {
            min + extent * DVec3::new(rng.unit(), rng.unit(), rng.unit())
        } else {
            centre + rng.vec3(2.5 * extent.max_element())
        };
        let target =
            min + extent * DVec3::new(rng.unit(), rng.unit(), rng.unit());
        let m = 10f64.powf(rng.uniform(-2.0, 2.0));
        let mut direction = (target - origin).normalize() * m;
        if rng.chance(0.3) {
            direction[rng.below(3)] = if rng.chance(0.5) { 0.0 } else { -0.0 };
        }
        if direction.length() < 1e-3 * m {
            continue;
        }
        let ray = Ray::new(origin, direction);
        let t_scale = extent.max_element() / direction.length();
        let interval =
            match ch08::slab_test(&lattice.bounds, &ray, Interval::FORWARD) {
                Some(inside) if rng.chance(0.4) => {
                    // a stretch that begins or ends inside the grid, or both
                    let span = inside.max - inside.min;
                    let lo = inside.min + span * rng.uniform(-0.5, 0.8);
                    Interval::new(
                        lo.max(0.0),
                        lo + span * rng.uniform(0.1, 1.0),
                    )
                }
                _ => Interval::FORWARD,
            };
        if clear(&lattice, &ray, interval, t_scale) {
            return GridCase {
                what: "a grid anywhere",
                lattice,
                ray,
                interval,
                t_scale,
            };
        }
    }
}

/// The t at which `ray` crosses each interior plane (of each axis), in
/// plain arithmetic.
fn crossings(lattice: &Lattice, ray: &Ray) -> Vec<(f64, usize)> {
    let mut all = Vec::new();
    for axis in 0..3 {
        let d = ray.direction[axis];
        if d == 0.0 {
            continue;
        }
        for i in 1..lattice.cells[axis] {
            let plane =
                lattice.bounds.min[axis] + i as f64 * lattice.size[axis];
            all.push(((plane - ray.origin[axis]) / d, axis));
        }
    }
    all
}

/// See [`random_grid`].
fn clear(
    lattice: &Lattice, ray: &Ray, interval: Interval, t_scale: f64,
) -> bool {
    let close = |a: f64, b: f64| (a - b).abs() <= 1e-9 * t_scale.max(a.abs());
    let b = &lattice.bounds;
    let hit = ch08::slab_test(b, ray, interval);
    // the box and the interval 1e-9 larger and smaller: the same answer
    let (c, h) = ((b.min + b.max) / 2.0, (b.max - b.min) / 2.0);
    for k in [1.0 - 1e-9, 1.0 + 1e-9] {
        let other = Aabb::new(c - h * k, c + h * k);
        if ch08::slab_test(&other, ray, interval).is_some() != hit.is_some() {
            return false;
        }
        let pad = |x: f64| (k - 1.0) * x.abs().max(t_scale);
        let wider = Interval::new(
            interval.min - pad(interval.min),
            interval.max + pad(interval.max),
        );
        if ch08::slab_test(b, ray, wider).is_some() != hit.is_some() {
            return false;
        }
    }
    let Some(inside) = hit else {
        return true;
    };
    let all = crossings(lattice, ray);
    let inner: Vec<&(f64, usize)> = all
        .iter()
        .filter(|(t, _)| {
            *t >= inside.min - 1e-6 * t_scale
                && *t <= inside.max + 1e-6 * t_scale
        })
        .collect();
    for (k, &&(t, axis)) in inner.iter().enumerate() {
        if close(t, inside.min) || close(t, inside.max) {
            return false;
        }
        for &&(u, other) in &inner[k + 1..] {
            if other != axis && close(t, u) {
                return false;
            }
        }
    }
    // a zero component: the ray's coordinate clear of every plane
    (0..3).all(|axis| {
        ray.direction[axis] != 0.0 || {
            let x = (ray.origin[axis] - b.min[axis]) / lattice.size[axis];
            (x - x.round()).abs() > 1e-9
                || !(0.0..=lattice.cells[axis] as f64).contains(&x.round())
        }
    })
}

/// A grid of power-of-two cells at a binary-fraction corner, and a ray
/// from a binary-fraction point along a direction whose components are
/// 0, ±0, ±1/2, ±1 or ±2: every t exact, so rays along planes and grid
/// lines, from corners and through them, and starting on planes going
/// down are judged by the lecture's tie rules, not by rounding.
fn exact_grid(rng: &mut Rng) -> GridCase {
    let unit = 2f64.powi(rng.below(20) as i32 - 10);
    let cells = [0; 3].map(|_| 1 + rng.below(8));
    let size = DVec3::new(
        2f64.powi(rng.below(3) as i32 - 1),
        2f64.powi(rng.below(3) as i32 - 1),
        2f64.powi(rng.below(3) as i32 - 1),
    ) * unit;
    let min = DVec3::new(
        rng.below(17) as f64 - 8.0,
        rng.below(17) as f64 - 8.0,
        rng.below(17) as f64 - 8.0,
    ) * 0.25
        * unit;
    let n = DVec3::new(cells[0] as f64, cells[1] as f64, cells[2] as f64);
    let lattice = Lattice::new(Aabb::new(min, min + n * size), cells);
    // on planes (whole cells) or between them (half cells), mostly
    // inside the box
    let inside = rng.chance(0.6);
    let coordinate = |rng: &mut Rng, axis: usize| {
        let k = if inside {
            rng.below(2 * cells[axis] + 1) as f64
        } else {
            rng.below(2 * cells[axis] + 5) as f64 - 2.0
        };
        min[axis] + 0.5 * k * size[axis]
    };
    let point =
        DVec3::new(coordinate(rng, 0), coordinate(rng, 1), coordinate(rng, 2));
    let parts = [0.0, -0.0, 0.5, -0.5, 1.0, -1.0, 2.0, -2.0];
    let mut direction = DVec3::ZERO;
    while direction == DVec3::ZERO {
        direction = DVec3::new(
            parts[rng.below(8)],
            parts[rng.below(8)],
            parts[rng.below(8)],
        );
    }
    // from that point, or from a point some steps back along the ray
    // (often outside the box, aimed into it)
    let back = if inside {
        0.5 * rng.below(16) as f64 * unit
    } else {
        0.0
    };
    let origin = point - back * direction;
    let t_scale = (n * size).max_element() / direction.length();
    let interval = match rng.below(4) {
        0 | 1 => Interval::FORWARD,
        2 => Interval::UNIVERSE,
        _ => {
            let lo = 0.5 * rng.below(6) as f64 * unit;
            Interval::new(lo, lo + 0.5 * (1 + rng.below(8)) as f64 * unit)
        }
    };
    GridCase {
        what: "a grid of exact numbers",
        lattice,
        ray: Ray::new(origin, direction),
        interval,
        t_scale,
    }
}

fn describe(c: &GridCase) -> String {
    format!(
        "{}: the box {}–{} in {}×{}×{} cells; ray from {} along {}, t in \
         [{}, {}]",
        c.what,
        show3(c.lattice.bounds.min),
        show3(c.lattice.bounds.max),
        c.lattice.cells[0],
        c.lattice.cells[1],
        c.lattice.cells[2],
        show3(c.ray.origin),
        show3(c.ray.direction),
        short(c.interval.min),
        short(c.interval.max)
    )
}

/// The setup: the first cell, the steps, t_max and t_delta (in units of
/// the case's T), t_enter and t_exit; or none.
fn dda_setup_case(rng: &mut Rng, case: &mut Case) {
    let c = match rng.below(10) {
        0..=4 => random_grid(rng),
        _ => exact_grid(rng),
    };
    case.ask(describe(&c));
    match dda_setup(&c.lattice, &c.ray, c.interval) {
        Some(d) => {
            case.word(format!(
                "cell:{},{},{}",
                d.cell[0], d.cell[1], d.cell[2]
            ));
            case.word(format!(
                "step:{},{},{}",
                d.step[0], d.step[1], d.step[2]
            ));
            case.vec3("t_max/T", d.t_max / c.t_scale);
            case.vec3("t_delta/T", d.t_delta / c.t_scale);
            case.num("t_enter/T", d.t_enter / c.t_scale);
            case.num("t_exit/T", d.t_exit / c.t_scale);
        }
        None => case.word("none"),
    }
}

/// A ray that is no ray: a zero direction (it stays in its cell: one
/// visit), or NaN in it (any walk that ends within the grid's cells is
/// right).
fn no_ray(rng: &mut Rng) -> (GridCase, bool) {
    let mut c = exact_grid(rng);
    let nan = rng.chance(0.4);
    let inside = c.lattice.bounds.min
        + (c.lattice.bounds.max - c.lattice.bounds.min) * DVec3::splat(0.375);
    c.ray = if nan {
        let mut o = inside;
        let mut d = DVec3::new(1.0, 0.5, 0.0);
        if rng.chance(0.5) {
            o[rng.below(3)] = f64::NAN;
        } else {
            d[rng.below(3)] = f64::NAN;
        }
        Ray::new(o, d)
    } else {
        Ray::new(inside, DVec3::ZERO)
    };
    c.interval = Interval::FORWARD;
    c.what = if nan {
        "a ray with NaN in it"
    } else {
        "a ray of zero direction"
    };
    (c, nan)
}

/// Every cell the walk visits, in order, with its index and t in and out
/// (in units of T); the visitor breaks after a random number of visits
/// now and then; a walk that goes on past every cell a ray could cross
/// is cut and said to run away.
fn walk_case(rng: &mut Rng, case: &mut Case) {
    let (c, nan) = match rng.below(10) {
        0..=3 => (random_grid(rng), false),
        4..=7 => (exact_grid(rng), false),
        _ => no_ray(rng),
    };
    let most = c.lattice.cells.iter().sum::<usize>() + 2;
    let stop_after = if rng.chance(0.25) {
        Some(1 + rng.below(most / 2))
    } else {
        None
    };
    case.ask(format!(
        "{}{}",
        describe(&c),
        stop_after.map_or(String::new(), |k| format!(
            "; the visitor breaks at visit {k}"
        ))
    ));
    let mut visits = Vec::new();
    let mut runaway = false;
    walk(&c.lattice, &c.ray, c.interval, |v| {
        visits.push(v);
        if visits.len() > most {
            runaway = true;
            return ControlFlow::Break(());
        }
        if stop_after == Some(visits.len()) {
            ControlFlow::Break(())
        } else {
            ControlFlow::Continue(())
        }
    });
    if runaway {
        case.word("runaway");
        return;
    }
    if nan {
        case.word("ended");
        return;
    }
    case.num("visits", visits.len() as f64);
    for v in visits {
        case.word(format!("cell:{},{},{}", v.cell[0], v.cell[1], v.cell[2]));
        case.word(format!("index:{}", v.index));
        case.num("t_in/T", v.t_in / c.t_scale);
        case.num("t_out/T", v.t_out / c.t_scale);
    }
}
