//! Held-out cases of chapter 10 for `raystep grade` (see
//! `raystep_check::held_out`): the SAH cost of a split plane for any
//! node (flat, a segment, a point), any plane, any counts (an empty side
//! among them) and any constants; and one traversal step for rays that
//! cross the plane inside the node, before it, after it, behind the
//! origin, within the slack at either end, parallel to it (either zero)
//! or lying in it.
use std::process::ExitCode;

use ch09::EXIT_SLACK;
use ch10::{Aabb, DVec3, KdCosts, Split, Step, split_cost, traversal_step};
use raystep_check::held_out::{self, Case, Exercise, Rng, short, show3};

fn main() -> ExitCode {
    held_out::main(&[
        Exercise::new("split_cost", split_cost_case, 1e-9),
        Exercise::new("traversal_step", traversal_step_case, 1e-9),
    ])
}

fn sign(rng: &mut Rng) -> f64 {
    if rng.chance(0.5) { 1.0 } else { -1.0 }
}

/// The chapter's constants, or made-up ones (a bonus from 0 to 0.9).
fn costs(rng: &mut Rng) -> KdCosts {
    match rng.below(4) {
        0 => KdCosts::PBRT_V3,
        1 => KdCosts::WALD_HAVRAN,
        _ => KdCosts {
            traversal: rng.uniform(0.1, 20.0),
            intersection: rng.uniform(0.1, 100.0),
            empty_bonus: rng.uniform(0.0, 0.9),
            depth_factor: 2.0,
        },
    }
}

/// A node (a box of any proportions anywhere, or flat, or a segment, or
/// a point), a plane across it along an axis (inside it, or on one of
/// its faces), and counts on each side (none on one side now and then).
fn split_cost_case(rng: &mut Rng, case: &mut Case) {
    let s = 10f64.powf(rng.uniform(-4.0, 4.0));
    let reach = s * 10f64.powf(rng.uniform(0.0, 4.0));
    let corner = rng.vec3(reach);
    let mut extent = DVec3::new(rng.unit(), rng.unit(), rng.unit()) * s;
    let what = match rng.below(8) {
        0 => {
            extent[rng.below(3)] = 0.0;
            "a flat node"
        }
        1 => {
            let keep = rng.below(3);
            for axis in 0..3 {
                if axis != keep {
                    extent[axis] = 0.0;
                }
            }
            "a segment (area 0)"
        }
        2 => {
            extent = DVec3::ZERO;
            "a point (area 0)"
        }
        _ => "a box",
    };
    let node = Aabb::new(corner, corner + extent);
    let axis = rng.below(3);
    let plane = match rng.below(6) {
        0 => node.min[axis],
        1 => node.max[axis],
        _ => node.min[axis] + rng.unit() * (node.max[axis] - node.min[axis]),
    };
    let count = |rng: &mut Rng| {
        if rng.chance(0.2) { 0 } else { rng.below(60) }
    };
    let (n_below, n_above) = (count(rng), count(rng));
    let costs = costs(rng);
    case.ask(format!(
        "{what}: split_cost({}–{}, axis {axis}, plane {}, {n_below} below, \
         {n_above} above, costs {}/{}/{})",
        show3(node.min),
        show3(node.max),
        short(plane),
        short(costs.traversal),
        short(costs.intersection),
        short(costs.empty_bonus)
    ));
    let cost = split_cost(&node, axis, plane, n_below, n_above, &costs);
    case.num("cost", cost);
}

/// One node along its axis, a ray and the stretch [t_min, t_max] it is
/// inside the node: which child first, when to push the other.
fn traversal_step_case(rng: &mut Rng, case: &mut Case) {
    let s = 10f64.powf(rng.uniform(-4.0, 4.0));
    let below = rng.below(1000) as u32;
    let above = loop {
        let above = rng.below(1000) as u32;
        if above != below {
            break above;
        }
    };
    let plane = rng.uniform(-10.0, 10.0) * s;
    let m = 10f64.powf(rng.uniform(-3.0, 3.0));
    let t_unit = s / m;
    // where the ray crosses the plane, and the node's stretch
    let t_min = if rng.chance(0.3) {
        0.0
    } else {
        t_unit * rng.uniform(-2.0, 5.0)
    };
    let t_max = t_min + t_unit * rng.uniform(0.0, 5.0);
    // now and then a node the ray only touches at t = 0 (there is no
    // slack at 0: a crossing at t_max = 0 is not after the node)
    let (t_min, t_max) = if rng.chance(0.08) {
        (0.0, 0.0)
    } else {
        (t_min, t_max)
    };
    let (what, origin, direction) = match rng.below(14) {
        0..=2 => {
            let t = t_min + (t_max - t_min) * rng.uniform(0.05, 0.95);
            ("crossing inside the node", t, m * sign(rng))
        }
        3 => (
            "crossing after the node",
            t_max + t_unit * rng.uniform(0.01, 3.0),
            m * sign(rng),
        ),
        4 => (
            "crossing before the node",
            t_min - t_unit * rng.uniform(0.01, 3.0),
            m * sign(rng),
        ),
        5 | 12 | 13 => {
            // within the slack after t_max or before t_min (one child too
            // many is safe), or just beyond it
            let (end, away) = if rng.chance(0.5) {
                (t_max, 1.0)
            } else {
                (t_min, -1.0)
            };
            let k = [0.0, 0.3, 0.7, 1.5, 3.0][rng.below(5)];
            let t = end + away * k * EXIT_SLACK * end.abs();
            (
                "crossing at the node's end, or within its slack",
                t,
                m * sign(rng),
            )
        }
        6 => {
            // the plane at t = 0: starting on it
            ("starting on the plane", 0.0, m * sign(rng))
        }
        7 | 8 => {
            // parallel (+0 or −0), on either side
            let zero = if rng.chance(0.5) { 0.0 } else { -0.0 };
            let side = s * rng.uniform(0.01, 5.0) * sign(rng);
            let origin = plane + side;
            return step(
                case,
                "parallel to the plane",
                Split {
                    plane,
                    below,
                    above,
                },
                origin,
                zero,
                t_min,
                t_max,
            );
        }
        9 => {
            let zero = if rng.chance(0.5) { 0.0 } else { -0.0 };
            return step(
                case,
                "lying in the plane",
                Split {
                    plane,
                    below,
                    above,
                },
                plane,
                zero,
                t_min,
                t_max,
            );
        }
        _ => {
            let t = t_unit * rng.uniform(-5.0, 10.0);
            ("any crossing", t, m * sign(rng))
        }
    };
    // the origin from which the ray reaches the plane at t = `origin`
    let crossing = origin;
    let origin = plane - crossing * direction;
    let split = Split {
        plane,
        below,
        above,
    };
    // keep the crossing clear of the ends' slack thresholds, where the
    // rounding of t_plane could decide (the exact ends and points inside
    // the slack are fine)
    let t_plane = (plane - origin) * (1.0 / direction);
    let thresholds = [
        t_max + EXIT_SLACK * t_max.abs(),
        t_min - EXIT_SLACK * t_min.abs(),
    ];
    let unclear = thresholds.iter().any(|&edge| {
        edge != 0.0 && (t_plane - edge).abs() <= 1e-6 * EXIT_SLACK * edge.abs()
    });
    if unclear {
        return traversal_step_case(rng, case);
    }
    step(case, what, split, origin, direction, t_min, t_max);
}

/// Asks the step and records what it says.
fn step(
    case: &mut Case, what: &str, split: Split, origin: f64, direction: f64,
    t_min: f64, t_max: f64,
) {
    let inverse = 1.0 / direction;
    case.ask(format!(
        "{what}: plane {} (child {} below, {} above), origin {}, direction \
         {} (inverse {}), t in [{}, {}]",
        short(split.plane),
        split.below,
        split.above,
        short(origin),
        if direction == 0.0 && direction.is_sign_negative() {
            "-0".to_string()
        } else {
            short(direction)
        },
        short(inverse),
        short(t_min),
        short(t_max)
    ));
    match traversal_step(split, origin, inverse, t_min, t_max) {
        Step::One(child) => {
            case.word("one");
            case.word(format!("child-{child}"));
        }
        Step::Both {
            near,
            far,
            near_until,
            far_from,
        } => {
            case.word("both");
            case.word(format!("near-{near}"));
            case.word(format!("far-{far}"));
            let t_unit = (t_max - t_min).abs().max(t_max.abs()).max(1e-300);
            case.num("near_until/T", near_until / t_unit);
            case.num("far_from/T", far_from / t_unit);
        }
    }
}
