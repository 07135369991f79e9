//! Exercise 2: the edge test for a convex polygon.
use ch02::{DVec2, edge_function, inside_convex, inside_crossing};
use proptest::prelude::*;
use raystep_check::{Table, num, seeded};

fn p(x: f64, y: f64) -> DVec2 {
    DVec2::new(x, y)
}

/// A counter-clockwise pentagon (a house), probe points inside, outside,
/// on edges and on vertices: each edge's f and the verdict of the edge
/// test. The coordinates are small integers, so every f is exact whatever
/// the order of operations, and the boundary verdicts follow the tie rule:
/// an edge belongs to the polygon on its right (+x), or above it when the
/// edge is horizontal.
///
/// The columns are f of each edge in turn: the bottom (0, 0) → (4, 0),
/// the right wall (4, 0) → (4, 3), the right roof (4, 3) → (2, 5), the
/// left roof (2, 5) → (0, 3) and the left wall (0, 3) → (0, 0).
#[test]
fn inside_table() {
    let house = [
        p(0.0, 0.0),
        p(4.0, 0.0),
        p(4.0, 3.0),
        p(2.0, 5.0),
        p(0.0, 3.0),
    ];
    let probes = [
        ("centre", p(2.0, 2.0)),
        ("outside right", p(5.0, 1.0)),
        ("outside below", p(2.0, -1.0)),
        ("on bottom edge", p(2.0, 0.0)),
        ("on left edge", p(0.0, 1.5)),
        ("on right edge", p(4.0, 1.5)),
        ("on roof edge", p(3.0, 4.0)),
        ("vertex (0,0)", p(0.0, 0.0)),
        ("vertex (4,0)", p(4.0, 0.0)),
        ("vertex (2,5)", p(2.0, 5.0)),
        ("under the roof", p(3.0, 3.75)),
        ("over the roof", p(3.0, 4.25)),
    ];
    let mut table = Table::new(&[
        "point",
        "f(bottom)",
        "f(right wall)",
        "f(right roof)",
        "f(left roof)",
        "f(left wall)",
        "inside",
    ]);
    for (name, q) in probes {
        let mut row = vec![name.to_string()];
        for i in 0..5 {
            row.push(num(edge_function(house[i], house[(i + 1) % 5], q)));
        }
        row.push(inside_convex(&house, q).to_string());
        table.row(&row);
    }
    insta::assert_snapshot!(table.to_string());
}

#[test]
fn edge_function_is_exact_at_endpoints_and_antisymmetric_to_the_bit() {
    // |b − a| times the signed distance: positive on the left
    #[rustfmt::skip]
    let cases = [
        ((0.0, 0.0), (2.0, 0.0), (1.0, 3.0), 6.0,
            "3 to the left of an edge of length 2"),
        ((0.0, 0.0), (0.0, 2.0), (1.0, 1.0), -2.0,
            "1 to the right of an edge of length 2"),
        ((1.0, 1.0), (1.0, 1.0), (5.0, 5.0), 0.0,
            "an edge of length 0 has N = 0"),
    ];
    for ((ax, ay), (bx, by), (x, y), expected, why) in cases {
        let got = edge_function(p(ax, ay), p(bx, by), p(x, y));
        assert!(
            got == expected,
            "edge_function(a = ({ax}, {ay}), b = ({bx}, {by}), p = ({x}, \
             {y})): expected {expected} ({why}), got {got}"
        );
    }
    let (a, b) = (p(0.1, 0.7), p(2.3, -1.9));
    for q in [p(0.3, 0.3), p(1.7, -0.2), p(-4.0, 9.0)] {
        let (forward, backward) =
            (edge_function(a, b, q), edge_function(b, a, q));
        assert!(
            forward == -backward,
            "the edge {a} → {b} and the same edge {b} → {a}, at {q}: \
             expected exactly opposite values (the endpoints taken in one \
             fixed order), got {forward:e} and {backward:e}"
        );
    }
    // exactly zero at both endpoints, whichever way the edge runs
    for (from, to) in [(a, b), (b, a)] {
        for (name, q) in [("a", a), ("b", b)] {
            let got = edge_function(from, to, q);
            assert!(
                got == 0.0,
                "the edge {from} → {to} at its endpoint {name} = {q}: \
                 expected exactly 0, got {got:e}"
            );
        }
    }
}

#[test]
fn degenerate_and_nan_input_is_outside() {
    let tri = [p(0.0, 0.0), p(1.0, 0.0), p(0.0, 1.0)];
    assert!(
        !inside_convex(&tri, p(f64::NAN, 0.2)),
        "the point (NaN, 0.2) in the triangle (0, 0), (1, 0), (0, 1): \
         expected outside (f is NaN, so no edge has it on its inner side), \
         got inside"
    );
    for (vertices, q, name) in [
        (&tri[..2], p(0.1, 0.0), "(0, 0), (1, 0), two vertices"),
        (&tri[..1], p(0.0, 0.0), "(0, 0), one vertex"),
        (&tri[..0], p(0.2, 0.2), "no vertex at all"),
    ] {
        assert!(
            !inside_convex(vertices, q),
            "the point {q} in the \"polygon\" of {name}: expected outside \
             (fewer than 3 vertices hold nothing), got inside"
        );
    }
    // a repeated vertex is not an edge
    let with_repeat = [p(0.0, 0.0), p(1.0, 0.0), p(1.0, 0.0), p(0.0, 1.0)];
    assert!(
        inside_convex(&with_repeat, p(0.2, 0.2)),
        "the point (0.2, 0.2) in the triangle (0, 0), (1, 0), (1, 0), \
         (0, 1), whose vertex (1, 0) is repeated: expected inside (a \
         repeated vertex is no edge: skip it), got outside"
    );
}

#[test]
fn crossing_test_on_a_concave_l_either_way_round() {
    let l = [
        (0.0, 0.0),
        (2.0, 0.0),
        (2.0, 1.0),
        (1.0, 1.0),
        (1.0, 2.0),
        (0.0, 2.0),
    ]
    .map(|(x, y)| p(x, y));
    let mut cw = l;
    cw.reverse();
    for (way, polygon) in [("counter-clockwise", l), ("clockwise", cw)] {
        for (q, expected, where_) in [
            (p(0.5, 1.5), true, "in the upper arm"),
            (p(1.5, 0.5), true, "in the right arm"),
            (p(1.5, 1.5), false, "in the notch"),
        ] {
            let got = inside_crossing(&polygon, q);
            assert!(
                got == expected,
                "crossing test on the L-shape ({way}) at {q}, {where_}: \
                 expected inside = {expected}, got {got}"
            );
        }
    }
}

fn convex_polygon() -> impl Strategy<Value = Vec<DVec2>> {
    // points on a circle at sorted angles: convex and counter-clockwise
    (3usize..8, 0.5..4.0f64, -3.0..3.0f64, -3.0..3.0f64).prop_flat_map(
        |(n, r, cx, cy)| {
            proptest::collection::vec(0.0..std::f64::consts::TAU, n).prop_map(
                move |mut angles| {
                    angles.sort_by(f64::total_cmp);
                    angles.dedup_by(|a, b| (*a - *b).abs() < 1e-3);
                    angles
                        .into_iter()
                        .map(|a| p(cx + r * a.cos(), cy + r * a.sin()))
                        .collect()
                },
            )
        },
    )
}

proptest! {
    #![proptest_config(seeded(256))]

    /// On convex polygons the edge test and the crossing test agree, and a
    /// point inside is inside the same polygon walked the other way round
    /// by the crossing test.
    #[test]
    fn edge_test_agrees_with_crossing_test(poly in convex_polygon(), x in -8.0..8.0f64, y in -8.0..8.0f64) {
        prop_assume!(poly.len() >= 3);
        let q = p(x, y);
        let (edge_test, crossing_test) = (inside_convex(&poly, q), inside_crossing(&poly, q));
        prop_assert!(edge_test == crossing_test, "the point {q} and the convex polygon {poly:?}: expected inside_convex = {crossing_test} (as the crossing test says), got {edge_test}");
    }
}
