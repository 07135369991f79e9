//! Exercise 2: one step of the front-to-back traversal: which child
//! first, when to push the far one, for hand-worked rays at a node cut
//! by the plane x = 2, and the whole walk against brute force.
mod common;

use ch10::{
    Accelerator, DVec3, Interval, KdBuilder, KdCosts, KdTree, Ray, Split, Step,
    kd_disagreements, kd_rays, traversal_step,
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

/// A ray crossing the plane inside the node visits the side it comes
/// from first, up to the plane, and pushes the other.
#[test]
fn near_first_then_far() {
    let up = step(0.0, 1.0, 0.0, 10.0);
    assert_eq!(
        up,
        Step::Both {
            near: 1,
            far: 7,
            near_until: 2.0,
            far_from: 2.0
        }
    );
    let down = step(4.0, -0.5, 0.0, 10.0);
    assert_eq!(
        down,
        Step::Both {
            near: 7,
            far: 1,
            near_until: 4.0,
            far_from: 4.0
        }
    );
}

/// A ray lying in the plane is in both children over the whole range.
#[test]
fn lying_in_the_plane_visits_both_all_along() {
    for d in [0.0, -0.0] {
        assert_eq!(
            step(2.0, d, 0.5, 3.0),
            Step::Both {
                near: 1,
                far: 7,
                near_until: 3.0,
                far_from: 0.5
            }
        );
    }
}

/// Parallel to the plane, off it: only the side it is on, whatever the
/// sign of the zero.
#[test]
fn parallel_off_the_plane_stays_on_its_side() {
    for d in [0.0, -0.0] {
        assert_eq!(step(1.0, d, 0.0, 10.0), Step::One(1));
        assert_eq!(step(3.0, d, 0.0, 10.0), Step::One(7));
    }
}

/// The whole walk, with the student's step, on the bunny and on the
/// catalogue's rays made from its planes: the same answers as brute
/// force.
#[test]
fn the_walk_agrees_with_brute_force_on_the_bunny() {
    let objects: Vec<_> = ch10::kd_scenes(&common::bunny()).remove(0).objects;
    let tree =
        KdTree::for_objects(&objects, KdBuilder::SahEvents, KdCosts::CHOSEN);
    let trees: [&dyn Accelerator; 1] = [&tree];
    let mut wrong = 0;
    for case in kd_rays(&tree, 30, 7) {
        wrong += kd_disagreements(&trees, &objects, &case.rays)[0];
    }
    assert_eq!(wrong, 0);
    // and one ray by hand: down the z axis onto the bunny's middle
    let ray = Ray::new(DVec3::new(-0.02, 0.1, 1.0), DVec3::new(0.0, 0.0, -1.0));
    let hit = tree.closest_hit(&objects, &ray, Interval::FORWARD);
    let brute = ch03::BruteForce.closest_hit(&objects, &ray, Interval::FORWARD);
    assert_eq!(hit.map(|h| h.1.t), brute.map(|h| h.1.t));
    assert!(hit.is_some());
}
