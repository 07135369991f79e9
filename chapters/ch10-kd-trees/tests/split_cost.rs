//! Exercise 1: the SAH cost of one split plane, for hand-worked nodes
//! and both published sets of constants.
use ch10::{Aabb, DVec3, KdCosts, split_cost};
use proptest::prelude::*;
use raystep_check::{Table, num_places, seeded};

/// The box [0, 4] × [0, 2] × [0, 1]: area 2·(8 + 2 + 4) = 28.
fn node() -> Aabb {
    Aabb::new(DVec3::ZERO, DVec3::new(4.0, 2.0, 1.0))
}

/// Plain constants that make the arithmetic easy to follow by hand.
const UNIT: KdCosts = KdCosts {
    traversal: 1.0,
    intersection: 1.0,
    empty_bonus: 0.5,
    depth_factor: 2.0,
};

#[test]
fn cost_table() {
    let mut table = Table::new(&[
        "node",
        "axis",
        "plane",
        "below",
        "above",
        "1/1/0.5",
        "1/80/0.5",
        "15/20/0.8",
    ]);
    let flat = Aabb::new(DVec3::ZERO, DVec3::new(4.0, 0.0, 0.0));
    let cases = [
        ("4×2×1", node(), 0, 1.0, 3, 5),
        ("4×2×1", node(), 0, 2.0, 4, 4),
        ("4×2×1", node(), 0, 3.0, 8, 0),
        ("4×2×1", node(), 1, 0.5, 0, 8),
        ("4×2×1", node(), 2, 0.5, 2, 6),
        ("a line", flat, 0, 1.0, 2, 3),
    ];
    for (name, b, axis, plane, n_below, n_above) in cases {
        let cost = |costs| {
            num_places(split_cost(&b, axis, plane, n_below, n_above, &costs), 4)
        };
        table.row(&[
            name.to_string(),
            ["x", "y", "z"][axis].to_string(),
            plane.to_string(),
            n_below.to_string(),
            n_above.to_string(),
            cost(UNIT),
            cost(KdCosts::PBRT_V3),
            cost(KdCosts::WALD_HAVRAN),
        ]);
    }
    insta::assert_snapshot!(table.to_string());
}

/// Fails with `what: expected …, got …` unless `got` is `expected` to
/// rounding (a cost summed in another order may differ in its last bits).
#[track_caller]
fn expect_cost(what: &str, got: f64, expected: f64) {
    assert!(
        (got - expected).abs() <= 1e-12 * expected.abs(),
        "{what}: expected {expected}, got {got}"
    );
}

/// Cutting the 4×2×1 box at x = 1: the child below is 1×2×1 (area 10),
/// the one above 3×2×1 (area 22), of 28. With 3 objects below and 5
/// above: 1 + (10·3 + 22·5)/28 = 1 + 140/28 = 6.
#[test]
fn by_hand() {
    expect_cost(
        "4×2×1 cut at x = 1, 3 objects below and 5 above, costs 1/1/0.5: \
         1 + (10·3 + 22·5)/28",
        split_cost(&node(), 0, 1.0, 3, 5, &UNIT),
        6.0,
    );
    // all 8 objects on one side, 4×2×1 cut at x = 3: below 3×2×1 (22):
    // 1 + 0.5 · 22·8/28 = 1 + 88/28
    expect_cost(
        "4×2×1 cut at x = 3, all 8 objects below (the empty bonus 0.5): \
         1 + 0.5·22·8/28",
        split_cost(&node(), 0, 3.0, 8, 0, &UNIT),
        1.0 + 88.0 / 28.0,
    );
}

/// A node of area 0 (a segment) gives no ratio: both children count.
#[test]
fn a_node_without_area() {
    let line = Aabb::new(DVec3::ZERO, DVec3::new(4.0, 0.0, 0.0));
    expect_cost(
        "the segment 0..4 on x cut at x = 1, 2 objects below and 3 above \
         (area 0: P = 1 for each child): 1 + 2 + 3",
        split_cost(&line, 0, 1.0, 2, 3, &UNIT),
        1.0 + 5.0,
    );
}

proptest! {
    #![proptest_config(seeded(256))]

    /// Splitting with nobody on one side costs the bonus less than the
    /// same counts split evenly; costs grow with the objects a child
    /// holds, and never fall below one traversal step.
    #[test]
    fn the_bonus_and_monotony(
        x in 0.01f64..3.99,
        n in 1usize..50,
        m in 1usize..50,
    ) {
        let b = node();
        for costs in [UNIT, KdCosts::PBRT_V3, KdCosts::WALD_HAVRAN] {
            let case = format!(
                "4×2×1 cut at x = {x}, costs {}/{}/{}",
                costs.traversal, costs.intersection, costs.empty_bonus
            );
            let c = split_cost(&b, 0, x, n, m, &costs);
            prop_assert!(
                c >= costs.traversal,
                "{}, {} below and {} above: expected at least one \
                 traversal step ({}), got {}",
                case, n, m, costs.traversal, c
            );
            let more_below = split_cost(&b, 0, x, n + 1, m, &costs);
            prop_assert!(
                more_below > c,
                "{}: expected {} below and {} above to cost more than {} \
                 below ({}), got {}",
                case, n + 1, m, n, c, more_below
            );
            let more_above = split_cost(&b, 0, x, n, m + 1, &costs);
            prop_assert!(
                more_above > c,
                "{}: expected {} below and {} above to cost more than {} \
                 above ({}), got {}",
                case, n, m + 1, m, c, more_above
            );
            let empty = split_cost(&b, 0, x, n, 0, &costs);
            let no_bonus = KdCosts { empty_bonus: 0.0, ..costs };
            let full = split_cost(&b, 0, x, n, 0, &no_bonus);
            let expected = costs.traversal
                + (1.0 - costs.empty_bonus) * (full - costs.traversal);
            prop_assert!(
                (empty - expected).abs() <= 1e-9 * expected,
                "{}, {} below and none above: expected the intersection \
                 term times (1 - bonus) = {}, got {}",
                case, n, expected, empty
            );
        }
    }
}
