//! Exercise 2: one step of the front-to-back traversal: which child
//! first, when to push the far one, for hand-worked rays at a node cut
//! by the plane x = 2, and the whole walk against brute force.
mod common;

use ch10::{
    Accelerator, DVec3, Interval, KdBuilder, KdCosts, KdNode, KdTree, Ray,
    Split, Step, traversal_step,
};
use raystep_check::{Table, num};

/// The node's plane x = 2: child 1 below, child 7 above.
const SPLIT: Split = Split {
    plane: 2.0,
    below: 1,
    above: 7,
};

fn step(origin: f64, direction: f64, t_min: f64, t_max: f64) -> Step {
    traversal_step(SPLIT, origin, 1.0 / direction, t_min, t_max)
}

fn shown(s: Step) -> String {
    match s {
        Step::One(child) => format!("only {child}"),
        Step::Both {
            near,
            far,
            near_until,
            far_from,
        } => format!(
            "{near} to t {}, then {far} from t {}",
            num(near_until),
            num(far_from)
        ),
    }
}

#[test]
fn step_table() {
    let mut table =
        Table::new(&["ray", "origin x", "dir x", "t range", "visits"]);
    let cases = [
        ("crosses up", 0.0, 1.0, 0.0, 10.0),
        ("crosses down", 4.0, -1.0, 0.0, 10.0),
        ("crosses after the node", 0.0, 1.0, 0.0, 1.5),
        ("crossed before the node", 0.0, 1.0, 3.0, 10.0),
        ("plane behind, going up", 3.0, 1.0, 0.0, 10.0),
        ("plane behind, going down", 1.0, -1.0, 0.0, 10.0),
        ("starts on the plane, up", 2.0, 1.0, 0.0, 10.0),
        ("starts on the plane, down", 2.0, -1.0, 0.0, 10.0),
        ("parallel, below (+0)", 1.0, 0.0, 0.0, 10.0),
        ("parallel, below (−0)", 1.0, -0.0, 0.0, 10.0),
        ("parallel, above (−0)", 3.0, -0.0, 0.0, 10.0),
        ("lying in the plane (+0)", 2.0, 0.0, 0.0, 10.0),
        ("lying in the plane (−0)", 2.0, -0.0, 0.0, 10.0),
        ("crosses at t_max exactly", 0.0, 1.0, 0.0, 2.0),
        ("crosses at t_min exactly", 0.0, 1.0, 2.0, 10.0),
    ];
    for (name, o, d, t0, t1) in cases {
        let d: f64 = d;
        table.row(&[
            name.to_string(),
            num(o),
            if d == 0.0 && d.is_sign_negative() {
                "-0".into()
            } else {
                num(d)
            },
            format!("{} .. {}", num(t0), num(t1)),
            shown(step(o, d, t0, t1)),
        ]);
    }
    insta::assert_snapshot!(table.to_string());
}

/// Fails with `what: expected …, got …` (both as the table shows them)
/// unless `got` is `expected`, its t values to rounding.
#[track_caller]
fn expect_step(what: &str, got: Step, expected: Step) {
    let close = |a: f64, b: f64| a == b || (a - b).abs() <= 1e-12 * b.abs();
    let same = match (got, expected) {
        (Step::One(a), Step::One(b)) => a == b,
        (
            Step::Both {
                near,
                far,
                near_until,
                far_from,
            },
            Step::Both {
                near: n,
                far: f,
                near_until: u,
                far_from: from,
            },
        ) => {
            (near, far) == (n, f)
                && close(near_until, u)
                && close(far_from, from)
        }
        _ => false,
    };
    assert!(
        same,
        "{what}: expected `{}`, got `{}`",
        shown(expected),
        shown(got)
    );
}

/// A ray crossing the plane inside the node visits the side it comes
/// from first, up to the plane, and pushes the other.
#[test]
fn near_first_then_far() {
    expect_step(
        "from x = 0 along +1 over t 0..10",
        step(0.0, 1.0, 0.0, 10.0),
        Step::Both {
            near: 1,
            far: 7,
            near_until: 2.0,
            far_from: 2.0,
        },
    );
    expect_step(
        "from x = 4 along -0.5 over t 0..10",
        step(4.0, -0.5, 0.0, 10.0),
        Step::Both {
            near: 7,
            far: 1,
            near_until: 4.0,
            far_from: 4.0,
        },
    );
}

/// A ray lying in the plane is in both children over the whole range.
#[test]
fn lying_in_the_plane_visits_both_all_along() {
    for d in [0.0, -0.0] {
        expect_step(
            &format!("lying in the plane x = 2 (dir x {d:?}) over t 0.5..3"),
            step(2.0, d, 0.5, 3.0),
            Step::Both {
                near: 1,
                far: 7,
                near_until: 3.0,
                far_from: 0.5,
            },
        );
    }
}

/// Parallel to the plane, off it: only the side it is on, whatever the
/// sign of the zero.
#[test]
fn parallel_off_the_plane_stays_on_its_side() {
    for d in [0.0, -0.0] {
        let what = format!("parallel (dir x {d:?}) over t 0..10");
        let below = step(1.0, d, 0.0, 10.0);
        expect_step(&format!("{what}, at x = 1"), below, Step::One(1));
        let above = step(3.0, d, 0.0, 10.0);
        expect_step(&format!("{what}, at x = 3"), above, Step::One(7));
    }
}

/// `EXIT_SLACK` widens the node by a relative 1e-9 at each end: a plane
/// crossed just after `t_max`, or just before `t_min`, within that slack
/// may be a crossing inside the node moved by rounding, so the ray goes
/// into both children (one child too many is safe, one too few is not).
/// At t 100 the slack is 1e-7; these rays cross 0.5e-7 outside.
#[test]
fn the_slack_keeps_both_children_at_the_ends() {
    for (t_plane, t_min, t_max, what) in [
        (
            100.0 + 0.5e-7,
            0.0,
            100.0,
            "t 100.00000005, over t 0..100 (within \
             the slack EXIT_SLACK·|t_max| = 1e-7 after t_max)",
        ),
        (
            100.0 - 0.5e-7,
            100.0,
            200.0,
            "t 99.99999995, over t 100..200 \
             (within the slack EXIT_SLACK·|t_min| = 1e-7 before t_min)",
        ),
    ] {
        expect_step(
            &format!("crossing x = 2 at {what}"),
            traversal_step(SPLIT, 2.0 - t_plane, 1.0, t_min, t_max),
            Step::Both {
                near: 1,
                far: 7,
                near_until: t_plane,
                far_from: t_plane,
            },
        );
    }
}

/// The slack is relative, so at t 0 there is none, and a crossing at
/// t_max = 0 exactly is not after the node: a ray starting on the plane,
/// in a node it only touches (t 0..0), goes into both children.
#[test]
fn a_crossing_at_t_max_is_not_after_it() {
    expect_step(
        "starting on the plane x = 2 along +1 over t 0..0 (t_plane = \
         t_max = 0, not after it)",
        step(2.0, 1.0, 0.0, 0.0),
        Step::Both {
            near: 1,
            far: 7,
            near_until: 0.0,
            far_from: 0.0,
        },
    );
}

/// The whole walk, with the student's step, on the bunny: the same
/// answers as brute force for rays lying in the root's plane (the step's
/// 0·∞ case: both children all along), rays starting on it, and rays from
/// far away. The tree is the median one: the SAH builders weigh planes
/// with exercise 1's `split_cost`, and this test judges exercise 2 alone.
/// (Every tree on the rays made from all its own planes is
/// `crates/stability`'s test.)
#[test]
fn the_walk_agrees_with_brute_force_on_the_bunny() {
    let objects = common::bunny_objects();
    let tree =
        KdTree::for_objects(&objects, KdBuilder::Median, KdCosts::CHOSEN);
    let KdNode::Split { axis, plane, .. } = tree.nodes[0] else {
        panic!("the bunny's median tree is more than a leaf");
    };
    let (axis, b) = (axis as usize, tree.bounds);
    let mut random = ch08::SplitMix64::new(7);
    let mut rays = Vec::new();
    for k in 0..240 {
        let mut r = || random.next_f64();
        let mut inside = b.min + DVec3::new(r(), r(), r()) * (b.max - b.min);
        let mut direction = random.unit_vector();
        match k % 3 {
            0 => {
                inside[axis] = plane;
                direction[axis] = if k % 2 == 0 { 0.0 } else { -0.0 };
            }
            1 => inside[axis] = plane,
            _ => {}
        }
        let origin = if k % 3 == 2 {
            inside - 4.0 * direction
        } else {
            inside
        };
        rays.push(Ray::new(origin, direction));
    }
    // and one ray by hand: down the z axis onto the bunny's middle
    rays.push(Ray::new(
        DVec3::new(-0.02, 0.1, 1.0),
        DVec3::new(0.0, 0.0, -1.0),
    ));
    let mut wrong = 0;
    for ray in &rays {
        let t = |a: &dyn Accelerator| {
            a.closest_hit(&objects, ray, Interval::FORWARD)
                .map(|h| h.1.t)
        };
        let any = |a: &dyn Accelerator| {
            [Interval::FORWARD, Interval::new(0.0, 1.0)]
                .map(|interval| a.any_hit(&objects, ray, interval))
        };
        let brute = &ch03::BruteForce;
        if t(&tree) != t(brute) || any(&tree) != any(brute) {
            wrong += 1;
        }
    }
    assert!(
        wrong == 0,
        "the kd-tree's walk on the bunny: expected brute force's answers \
         (closest hit, any hit) for all {} rays, got others for {wrong}",
        rays.len()
    );
    let hit = tree.closest_hit(&objects, &rays[240], Interval::FORWARD);
    assert!(
        hit.is_some(),
        "down the z axis onto the bunny's middle: a hit"
    );
}
