//! Exercise 5: the SAH cost of one split, on cases computed by hand.
//! The builders use their own copy, so this test alone judges the
//! exercise.
use ch08::{Aabb, DVec3, INTERSECTION, TRAVERSAL, split_cost};

fn cube(min: DVec3, side: f64) -> Aabb {
    Aabb::new(min, min + DVec3::splat(side))
}

/// A 2 × 1 × 1 box cut into two unit cubes: each child has area 6 of the
/// parent's 10.
#[test]
fn a_box_cut_in_half() {
    let parent = Aabb::new(DVec3::ZERO, DVec3::new(2.0, 1.0, 1.0));
    let (l, r) = (cube(DVec3::ZERO, 1.0), cube(DVec3::X, 1.0));
    assert_eq!(TRAVERSAL, 1.0);
    assert_eq!(INTERSECTION, 1.0);
    // 1 + (6·1 + 6·1)/10 = 2.2
    assert!((split_cost(&parent, &l, 1, &r, 1) - 2.2).abs() < 1e-12);
    // 1 + (6·3 + 6·5)/10 = 5.8
    assert!((split_cost(&parent, &l, 3, &r, 5) - 5.8).abs() < 1e-12);
}

/// Children as large as the parent: every object is tested, plus the
/// parent's visit.
#[test]
fn children_as_large_as_the_parent() {
    let unit = cube(DVec3::ZERO, 1.0);
    assert_eq!(split_cost(&unit, &unit, 2, &unit, 3), 6.0);
}

/// An empty side costs nothing: its count is 0 (and an empty box has
/// area 0).
#[test]
fn an_empty_side() {
    let parent = cube(DVec3::ZERO, 2.0); // area 24
    let l = cube(DVec3::ZERO, 1.0); // area 6
    assert_eq!(split_cost(&parent, &l, 4, &Aabb::EMPTY, 0), 2.0);
    assert_eq!(split_cost(&parent, &Aabb::EMPTY, 0, &l, 4), 2.0);
}

/// A parent of zero area (a point, or a segment): both children count as
/// hit for certain.
#[test]
fn a_parent_of_zero_area() {
    let point = Aabb::new(DVec3::ONE, DVec3::ONE);
    assert_eq!(split_cost(&point, &point, 3, &point, 4), 8.0);
    let segment = Aabb::new(DVec3::ZERO, DVec3::X);
    assert_eq!(split_cost(&segment, &segment, 1, &point, 1), 3.0);
}

/// Far from the origin the ratio of areas is the same.
#[test]
fn far_from_the_origin() {
    let offset = DVec3::splat(1e6);
    let parent = Aabb::new(offset, offset + DVec3::new(2.0, 1.0, 1.0));
    let (l, r) = (cube(offset, 1.0), cube(offset + DVec3::X, 1.0));
    assert!((split_cost(&parent, &l, 1, &r, 1) - 2.2).abs() < 1e-9);
}
