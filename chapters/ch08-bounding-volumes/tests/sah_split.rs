//! Exercise 5: the SAH cost of one split, on cases computed by hand.
//! The builders use their own copy, so this test alone judges the
//! exercise.
//!
//! Each expected cost is written with the crate's `TRAVERSAL` and
//! `INTERSECTION`: C = TRAVERSAL + (ratio of areas × counts) ·
//! INTERSECTION. Both are 1 (as in the lecture), so a solution that mixes
//! them up, or divides by INTERSECTION instead of multiplying, gives the
//! same numbers and cannot be told apart here.
use ch08::{Aabb, DVec3, INTERSECTION, TRAVERSAL, split_cost};

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

/// `split_cost(parent, left, n_left, right, n_right)` is `expected` to
/// within `tolerance`, else a message with both and why (`why`). A
/// failure is reported at the line that calls it.
#[track_caller]
fn assert_cost(
    (parent, left, n_left, right, n_right): (&Aabb, &Aabb, usize, &Aabb, usize),
    expected: f64,
    tolerance: f64,
    why: &str,
) {
    let got = split_cost(parent, left, n_left, right, n_right);
    assert!(
        (got - expected).abs() <= tolerance,
        "split_cost(parent {}, left {} with {n_left}, right {} with \
         {n_right}): expected {expected} ({why}), got {got}",
        show(parent),
        show(left),
        show(right)
    );
}

/// A 2 × 1 × 1 box cut into two unit cubes: each child has area 6 of the
/// parent's 10.
#[test]
fn a_box_cut_in_half() {
    let parent = Aabb::new(DVec3::ZERO, DVec3::new(2.0, 1.0, 1.0));
    let (l, r) = (cube(DVec3::ZERO, 1.0), cube(DVec3::X, 1.0));
    assert_cost(
        (&parent, &l, 1, &r, 1),
        TRAVERSAL + (6.0 * 1.0 + 6.0 * 1.0) / 10.0 * INTERSECTION,
        1e-12,
        "1 + (6·1 + 6·1)/10 = 2.2: each child has area 6 of the parent's 10",
    );
    assert_cost(
        (&parent, &l, 3, &r, 5),
        TRAVERSAL + (6.0 * 3.0 + 6.0 * 5.0) / 10.0 * INTERSECTION,
        1e-12,
        "1 + (6·3 + 6·5)/10 = 5.8",
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
    assert_cost(
        (&parent, &l, 1, &r, 7),
        TRAVERSAL + (6.0 * 1.0 + 14.0 * 7.0) / 18.0 * INTERSECTION,
        1e-12,
        "1 + (6·1 + 14·7)/18 = 6.777…: the small child's 1 object, the \
         large child's 7",
    );
    assert_cost(
        (&parent, &l, 7, &r, 1),
        TRAVERSAL + (6.0 * 7.0 + 14.0 * 1.0) / 18.0 * INTERSECTION,
        1e-12,
        "1 + (6·7 + 14·1)/18 = 4.111…: the small child's 7 objects, the \
         large child's 1",
    );
}

/// Children as large as the parent: every object is tested, plus the
/// parent's visit.
#[test]
fn children_as_large_as_the_parent() {
    let unit = cube(DVec3::ZERO, 1.0);
    assert_cost(
        (&unit, &unit, 2, &unit, 3),
        TRAVERSAL + 5.0 * INTERSECTION,
        0.0,
        "1 + (6·2 + 6·3)/6 = 6: both children certain to be hit",
    );
}

/// An empty side costs nothing: its count is 0 (and an empty box has
/// area 0).
#[test]
fn an_empty_side() {
    let parent = cube(DVec3::ZERO, 2.0); // area 24
    let l = cube(DVec3::ZERO, 1.0); // area 6
    let why = "1 + (6·4 + 0)/24 = 2: the empty side adds nothing";
    let expected = TRAVERSAL + 1.0 * INTERSECTION;
    assert_cost((&parent, &l, 4, &Aabb::EMPTY, 0), expected, 0.0, why);
    assert_cost((&parent, &Aabb::EMPTY, 0, &l, 4), expected, 0.0, why);
}

/// A parent of zero area (a point, or a segment): both children count as
/// hit for certain.
#[test]
fn a_parent_of_zero_area() {
    let point = Aabb::new(DVec3::ONE, DVec3::ONE);
    assert_cost(
        (&point, &point, 3, &point, 4),
        TRAVERSAL + 7.0 * INTERSECTION,
        0.0,
        "a point has area 0: 1 + (3 + 4) = 8, every object tested",
    );
    let segment = Aabb::new(DVec3::ZERO, DVec3::X);
    assert_cost(
        (&segment, &segment, 1, &point, 1),
        TRAVERSAL + 2.0 * INTERSECTION,
        0.0,
        "a segment has area 0: 1 + (1 + 1) = 3, every object tested",
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
        TRAVERSAL + 1.2 * INTERSECTION,
        1e-9,
        "the box cut in half, moved to 1e6: 2.2 as at the origin",
    );
}
