//! Exercise 5: the SAH cost of one split, on cases computed by hand.
//!
//! Each case is judged with the chapter's costs (both 1, as in the
//! lecture) and with pbrt's (a visit 1/2, a test 1) and a third pair (a
//! visit 3, a test 1/4), so that a solution that mixes the two up, or
//! divides by a cost instead of multiplying, gives another number.
use ch08::{Aabb, DVec3, SahCosts, split_cost};

/// The costs every case is judged with.
const COSTS: [SahCosts; 3] = [
    SahCosts::CHOSEN,
    SahCosts {
        traversal: 0.5,
        intersection: 1.0,
    },
    SahCosts {
        traversal: 3.0,
        intersection: 0.25,
    },
];

fn cube(min: DVec3, side: f64) -> Aabb {
    Aabb::new(min, min + DVec3::splat(side))
}

/// A box as `min–max`.
fn show(b: &Aabb) -> String {
    if b.is_empty() {
        "empty".to_string()
    } else {
        format!("{}–{}", b.min, b.max)
    }
}

/// For each of [`COSTS`], `split_cost(parent, left, n_left, right,
/// n_right, costs)` is `traversal + tests · intersection` to within
/// `tolerance`, `tests` being the expected object tests (the ratio of
/// areas times the counts), else a message with both and why (`why`). A
/// failure is reported at the line that calls it.
#[track_caller]
fn assert_cost(
    (parent, left, n_left, right, n_right): (&Aabb, &Aabb, usize, &Aabb, usize),
    tests: f64, tolerance: f64, why: &str,
) {
    for costs in &COSTS {
        let expected = costs.traversal + tests * costs.intersection;
        let got = split_cost(parent, left, n_left, right, n_right, costs);
        assert!(
            (got - expected).abs() <= tolerance,
            "split_cost(parent {}, left {} with {n_left}, right {} with \
             {n_right}, a visit {} and a test {}): expected {expected} \
             ({} + {tests} tests · {}: {why}), got {got}",
            show(parent),
            show(left),
            show(right),
            costs.traversal,
            costs.intersection,
            costs.traversal,
            costs.intersection,
        );
    }
}

/// A 2 × 1 × 1 box cut into two unit cubes: each child has area 6 of the
/// parent's 10.
#[test]
fn a_box_cut_in_half() {
    let parent = Aabb::new(DVec3::ZERO, DVec3::new(2.0, 1.0, 1.0));
    let (l, r) = (cube(DVec3::ZERO, 1.0), cube(DVec3::X, 1.0));
    assert_cost(
        (&parent, &l, 1, &r, 1),
        (6.0 * 1.0 + 6.0 * 1.0) / 10.0,
        1e-12,
        "(6·1 + 6·1)/10 = 1.2 tests: each child has area 6 of the parent's 10",
    );
    assert_cost(
        (&parent, &l, 3, &r, 5),
        (6.0 * 3.0 + 6.0 * 5.0) / 10.0,
        1e-12,
        "(6·3 + 6·5)/10 = 4.8 tests",
    );
}

/// Children of different sizes and counts: each child's own area weighs
/// its own count (swapping the areas or the counts gives another cost).
#[test]
fn children_of_different_sizes() {
    // a 4 × 1 × 1 box (area 18) cut at x = 1: a unit cube (area 6) and a
    // 3 × 1 × 1 box (area 14)
    let parent = Aabb::new(DVec3::ZERO, DVec3::new(4.0, 1.0, 1.0));
    let l = cube(DVec3::ZERO, 1.0);
    let r = Aabb::new(DVec3::X, DVec3::new(4.0, 1.0, 1.0));
    for (n_left, n_right, why) in [
        (
            1,
            7,
            "(6·1 + 14·7)/18 = 5.777… tests: the small child's 1 object, \
             the large child's 7",
        ),
        (
            7,
            1,
            "(6·7 + 14·1)/18 = 3.111… tests: the small child's 7 objects, \
             the large child's 1",
        ),
    ] {
        let tests = (6.0 * n_left as f64 + 14.0 * n_right as f64) / 18.0;
        assert_cost((&parent, &l, n_left, &r, n_right), tests, 1e-12, why);
    }
}

/// Children as large as the parent: every object is tested, plus the
/// parent's visit.
#[test]
fn children_as_large_as_the_parent() {
    let unit = cube(DVec3::ZERO, 1.0);
    assert_cost(
        (&unit, &unit, 2, &unit, 3),
        5.0,
        0.0,
        "(6·2 + 6·3)/6 = 5 tests: both children certain to be hit",
    );
}

/// An empty side costs nothing: its count is 0 (and an empty box has
/// area 0).
#[test]
fn an_empty_side() {
    let parent = cube(DVec3::ZERO, 2.0); // area 24
    let l = cube(DVec3::ZERO, 1.0); // area 6
    let why = "(6·4 + 0)/24 = 1 test: the empty side adds nothing";
    assert_cost((&parent, &l, 4, &Aabb::EMPTY, 0), 1.0, 0.0, why);
    assert_cost((&parent, &Aabb::EMPTY, 0, &l, 4), 1.0, 0.0, why);
}

/// A parent of zero area (a point, or a segment): both children count as
/// hit for certain.
#[test]
fn a_parent_of_zero_area() {
    let point = Aabb::new(DVec3::ONE, DVec3::ONE);
    assert_cost(
        (&point, &point, 3, &point, 4),
        7.0,
        0.0,
        "a point has area 0: 3 + 4 = 7 tests, every object tested",
    );
    let segment = Aabb::new(DVec3::ZERO, DVec3::X);
    assert_cost(
        (&segment, &segment, 1, &point, 1),
        2.0,
        0.0,
        "a segment has area 0: 1 + 1 = 2 tests, every object tested",
    );
}

/// Far from the origin the ratio of areas is the same.
#[test]
fn far_from_the_origin() {
    let offset = DVec3::splat(1e6);
    let parent = Aabb::new(offset, offset + DVec3::new(2.0, 1.0, 1.0));
    let (l, r) = (cube(offset, 1.0), cube(offset + DVec3::X, 1.0));
    assert_cost(
        (&parent, &l, 1, &r, 1),
        1.2,
        1e-9,
        "the box cut in half, moved to 1e6: 1.2 tests as at the origin",
    );
}
