//! Exercise 1: does a triangle on screen cover a pixel centre? The edge
//! functions, the fill rule on shared edges, and the barycentric weights.
//!
//! Pixel (c, r) has its centre at (c + ½, r + ½), x to the right, y down.
//! Most corners here lie on pixel centres or on whole numbers, so edges
//! pass *exactly* through pixel centres and every edge function is exact
//! (small multiples of ¼), whatever the order of operations: the fill rule,
//! not rounding, decides those pixels. The rule (chapter 2's
//! `owns_boundary`) gives a triangle the edges whose inside lies to their
//! right (+x), or below them (+y, down on screen) when they are
//! horizontal: on screen, its left and top edges.
use ch07::{DVec2, barycentric, covers};
use proptest::prelude::*;
use raystep_check::{Table, num, seeded};

fn p(x: f64, y: f64) -> DVec2 {
    DVec2::new(x, y)
}

/// The centre of pixel (column, row).
fn centre(column: u32, row: u32) -> DVec2 {
    p(f64::from(column) + 0.5, f64::from(row) + 0.5)
}

/// Twice the signed area of (a, b, q), computed here and not with the
/// code under test: exact for the small half-integer coordinates used.
fn cross(a: DVec2, b: DVec2, q: DVec2) -> f64 {
    (b - a).perp_dot(q - a)
}

/// Is `q` on the closed segment from `a` to `b`? (Exact, as [`cross`].)
fn on_segment(a: DVec2, b: DVec2, q: DVec2) -> bool {
    cross(a, b, q) == 0.0 && (q - a).dot(q - b) <= 0.0
}

/// Is `q` on an edge of the triangle?
fn on_an_edge(t: &[DVec2; 3], q: DVec2) -> bool {
    (0..3).any(|i| on_segment(t[i], t[(i + 1) % 3], q))
}

/// Is `q` strictly inside the triangle, off its edges? (Exact.)
fn strictly_inside(t: &[DVec2; 3], q: DVec2) -> bool {
    let s = [
        cross(t[0], t[1], q),
        cross(t[1], t[2], q),
        cross(t[2], t[0], q),
    ];
    s.iter().all(|&x| x > 0.0) || s.iter().all(|&x| x < 0.0)
}

/// The coverage of one triangle on a `width × height` grid, one character
/// per pixel centre: `#` covered, `+` covered although on an edge (the
/// triangle owns that edge), `o` on an edge but not covered (a neighbour
/// sharing that edge would own it), `.` outside.
fn coverage_table(t: &[DVec2; 3], width: u32, height: u32) -> String {
    let mut text = String::new();
    for row in 0..height {
        for column in 0..width {
            let q = centre(column, row);
            text.push(match (covers(t, q), on_an_edge(t, q)) {
                (true, false) => '#',
                (true, true) => '+',
                (false, true) => 'o',
                (false, false) => '.',
            });
        }
        text.push('\n');
    }
    text
}

/// How many pixel centres of the grid the triangle covers.
fn covered(t: &[DVec2; 3], width: u32, height: u32) -> usize {
    (0..height)
        .flat_map(|row| (0..width).map(move |column| centre(column, row)))
        .filter(|&q| covers(t, q))
        .count()
}

/// The triangle the other way round (clockwise ↔ counter-clockwise).
fn reversed(t: &[DVec2; 3]) -> [DVec2; 3] {
    [t[0], t[2], t[1]]
}

/// Corners (in pixel units) worked by hand on the smallest cases first.
#[test]
fn hand_worked_pixels() {
    // the square of pixel (2, 2) cut along its diagonal x + y = 5, which
    // passes through its centre (2.5, 2.5): that centre is on the
    // hypotenuse of both halves. The upper-left half's hypotenuse has its
    // inside up-left: not its edge; the lower-right half's has its inside
    // down-right: its edge. One of the two covers the centre.
    let upper_left = [p(2.0, 2.0), p(3.0, 2.0), p(2.0, 3.0)];
    let lower_right = [p(3.0, 2.0), p(3.0, 3.0), p(2.0, 3.0)];
    // a triangle with its corners on pixel centres: its left and top
    // edges are its own, its right and bottom edges are not
    let t = [p(0.5, 0.5), p(4.5, 0.5), p(0.5, 4.5)];
    // a right edge going straight down, inside to its left: not owned
    let right = [p(4.5, 0.5), p(4.5, 4.5), p(0.5, 2.5)];
    // a bottom edge, inside above it: not owned
    let bottom = [p(0.5, 4.5), p(4.5, 4.5), p(2.5, 0.5)];
    #[rustfmt::skip]
    let cases = [
        (upper_left, (2.5, 2.5), false,
            "on the hypotenuse of the upper-left half (inside up-left: not its edge)"),
        (lower_right, (2.5, 2.5), true,
            "on the hypotenuse of the lower-right half (inside down-right: its edge)"),
        (t, (1.5, 1.5), true, "inside"),
        (t, (2.5, 0.5), true, "on the top edge (its own)"),
        (t, (0.5, 2.5), true, "on the left edge (its own)"),
        (t, (0.5, 0.5), true, "the top-left corner (on two edges of its own)"),
        (t, (2.5, 2.5), false, "on the hypotenuse (inside up-left: not its edge)"),
        (t, (4.5, 0.5), false, "the top-right corner (on the hypotenuse)"),
        (t, (0.5, 4.5), false, "the bottom-left corner (on the hypotenuse)"),
        (t, (3.5, 1.5), false, "on the hypotenuse again"),
        (t, (3.5, 3.5), false, "outside"),
        (right, (4.5, 2.5), false, "on a right edge (inside to its left: not its edge)"),
        (right, (3.5, 2.5), true, "just left of the right edge, inside"),
        (bottom, (2.5, 4.5), false, "on a bottom edge (inside above it: not its edge)"),
        (bottom, (2.5, 3.5), true, "just above the bottom edge, inside"),
    ];
    for (triangle, (x, y), expected, where_) in cases {
        let got = covers(&triangle, p(x, y));
        assert!(
            got == expected,
            "covers({:?}, ({x}, {y})), {where_}: expected {expected}, got \
             {got}",
            triangle.map(|c| (c.x, c.y))
        );
    }
}

/// Small triangles on an 8×8 pixel grid, each in both windings (the
/// table must not change). The counts are worked by hand: the right
/// triangle with legs of 6 pixels covers the centres with c + r < 6 (its
/// hypotenuse x + y = 7 is not its own): 6 + 5 + … + 1 = 21; its mirror
/// half of the square covers the other 36 − 21 = 15 (its right and
/// bottom edges are not its own, its hypotenuse is).
#[test]
fn coverage_tables() {
    #[rustfmt::skip]
    let triangles = [
        ("right triangle, corners and legs on pixel centres",
            [p(0.5, 0.5), p(6.5, 0.5), p(0.5, 6.5)]),
        ("the other half of the square, sharing the hypotenuse",
            [p(6.5, 0.5), p(6.5, 6.5), p(0.5, 6.5)]),
        ("slanted edges through pixel centres",
            [p(0.5, 0.5), p(6.5, 3.5), p(2.5, 7.5)]),
        ("corners on pixel corners",
            [p(1.0, 1.0), p(7.0, 2.0), p(3.0, 7.0)]),
        ("a sliver one pixel high",
            [p(0.5, 2.5), p(7.5, 3.5), p(0.5, 3.5)]),
        ("half a pixel, the half without the centre",
            [p(2.0, 2.0), p(3.0, 2.0), p(2.0, 3.0)]),
        ("half a pixel, the half with the centre on its edge",
            [p(3.0, 2.0), p(3.0, 3.0), p(2.0, 3.0)]),
    ];
    let mut text = String::from(
        "# covered, + covered on an edge, o on an edge but not covered, . outside\n",
    );
    for (name, t) in triangles {
        let table = coverage_table(&t, 8, 8);
        let other = coverage_table(&reversed(&t), 8, 8);
        if let Some((row, (a, b))) = table
            .lines()
            .zip(other.lines())
            .enumerate()
            .find(|(_, (a, b))| a != b)
        {
            panic!(
                "{name}: expected the same pixels covered in the other \
                 winding, got row {row} `{b}` instead of `{a}`"
            );
        }
        text.push_str(&format!(
            "\n{name}: {:?}, {} covered\n{table}",
            t.map(|c| (c.x, c.y)),
            covered(&t, 8, 8)
        ));
    }
    for (i, expected, why) in [
        (0, 21, "the centres with c + r < 6: 6 + 5 + … + 1"),
        (1, 15, "the other 36 − 21 of the square's centres"),
        (5, 0, "no pixel centre inside, one on an edge not its own"),
        (6, 1, "one pixel centre, on an edge of its own"),
    ] {
        let (name, t) = &triangles[i];
        let got = covered(t, 8, 8);
        assert!(
            got == expected,
            "{name}: pixel centres covered: expected {expected} ({why}), got \
             {got}"
        );
    }
    insta::assert_snapshot!(text);
}

/// How many of `triangles` cover each pixel centre of the grid, row by row.
fn counts(
    triangles: &[[DVec2; 3]], width: u32, height: u32,
) -> Vec<Vec<usize>> {
    (0..height)
        .map(|row| {
            (0..width)
                .map(|column| {
                    let q = centre(column, row);
                    triangles.iter().filter(|t| covers(t, q)).count()
                })
                .collect()
        })
        .collect()
}

/// The counts as text, one digit per pixel.
fn count_text(counts: &[Vec<usize>]) -> String {
    counts
        .iter()
        .map(|row| row.iter().map(|n| n.to_string()).collect::<String>() + "\n")
        .collect()
}

/// Which triangle covers each pixel centre, as a letter (`a`, `b`, …,
/// `A`, … in the order given; `*` if more than one, `.` none).
fn owner_text(triangles: &[[DVec2; 3]], width: u32, height: u32) -> String {
    const NAMES: &[u8] =
        b"abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ";
    let mut text = String::new();
    for row in 0..height {
        for column in 0..width {
            let q = centre(column, row);
            let mut which =
                triangles.iter().enumerate().filter(|(_, t)| covers(t, q));
            text.push(match (which.next(), which.next()) {
                (None, _) => '.',
                (Some((i, _)), None) => char::from(NAMES[i]),
                (Some(_), Some(_)) => '*',
            });
        }
        text.push('\n');
    }
    text
}

/// Triangles tiling the square [lo, hi]² (corners on pixel centres) must
/// cover the pixels the square itself covers under the same rule, each
/// exactly once: its top and left sides are its own, its right and bottom
/// sides are not, so the centres with lo ≤ x < hi and lo ≤ y < hi: no
/// gap inside, no double hit anywhere, no hit outside.
fn assert_tiles_the_square(
    name: &str, triangles: &[[DVec2; 3]], lo: f64, hi: f64, size: u32,
) {
    let counts = counts(triangles, size, size);
    let (mut gaps, mut doubles, mut outside) = (0, 0, 0);
    for (row, line) in counts.iter().enumerate() {
        for (column, &n) in line.iter().enumerate() {
            let q = centre(column as u32, row as u32);
            let in_square = (lo..hi).contains(&q.x) && (lo..hi).contains(&q.y);
            match (in_square, n) {
                (true, 0) => gaps += 1,
                (_, 2..) => doubles += 1,
                (false, 1) => outside += 1,
                _ => {}
            }
        }
    }
    assert!(
        (gaps, doubles, outside) == (0, 0, 0),
        "{name}: expected every pixel of the square covered once and none \
         outside it, got {gaps} gaps, {doubles} double hits and {outside} \
         hits outside; counts:\n{}",
        count_text(&counts)
    );
}

/// A fan of 32 triangles around the vertex (4.5, 4.5), a pixel centre,
/// reaching out to every whole step along the outline of the square
/// [0.5, 8.5]² (so its 32 spokes run in many directions, and those with a
/// direction like (4, −2) or (4, 4) pass through pixel centres on the
/// way). Every other triangle is given clockwise. The vertex itself, the
/// centres on spokes and the centres on the outline are each covered by
/// exactly one triangle.
fn fan() -> Vec<[DVec2; 3]> {
    let hub = p(4.5, 4.5);
    // the outline, clockwise on screen from the top-left corner
    let mut ring = Vec::new();
    for k in 0..8 {
        ring.push(p(0.5 + f64::from(k), 0.5)); // top, rightwards
    }
    for k in 0..8 {
        ring.push(p(8.5, 0.5 + f64::from(k))); // right, downwards
    }
    for k in 0..8 {
        ring.push(p(8.5 - f64::from(k), 8.5)); // bottom, leftwards
    }
    for k in 0..8 {
        ring.push(p(0.5, 8.5 - f64::from(k))); // left, upwards
    }
    (0..ring.len())
        .map(|i| {
            let (a, b) = (ring[i], ring[(i + 1) % ring.len()]);
            if i % 2 == 0 { [hub, a, b] } else { [hub, b, a] }
        })
        .collect()
}

/// The fan's coverage: which triangle covers each pixel (letters in the
/// fan's order, clockwise from the top-left corner) and how many do.
#[test]
fn a_fan_around_a_pixel_centre_covers_each_pixel_once() {
    let fan = fan();
    assert_tiles_the_square("fan", &fan, 0.5, 8.5, 10);
    // the hub (4.5, 4.5) lies on all 32 triangles; exactly one has it
    let hub_owners = fan.iter().filter(|t| covers(t, p(4.5, 4.5))).count();
    assert!(
        hub_owners == 1,
        "triangles covering the fan's hub (4.5, 4.5), a corner of all 32: \
         expected 1, got {hub_owners}"
    );
    insta::assert_snapshot!(format!(
        "which triangle (a = hub, (0.5, 0.5), (1.5, 0.5); then clockwise):\n{}\ncount:\n{}",
        owner_text(&fan, 10, 10),
        count_text(&counts(&fan, 10, 10))
    ));
}

/// A grid of 3×3-pixel squares with corners on pixel centres, each split
/// on a diagonal (alternately the two diagonals, so both directions occur),
/// in alternating windings: the diagonals and the squares' sides run
/// through pixel centres, and 4 or 8 triangles meet at the grid's
/// vertices.
fn grid() -> Vec<[DVec2; 3]> {
    let at =
        |i: u32, j: u32| p(0.5 + 3.0 * f64::from(i), 0.5 + 3.0 * f64::from(j));
    let mut triangles = Vec::new();
    for j in 0..3 {
        for i in 0..3 {
            let (tl, tr, br, bl) =
                (at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
            let halves = if (i + j) % 2 == 0 {
                [[tl, tr, br], [tl, br, bl]] // split on the ↘ diagonal
            } else {
                [[tr, br, bl], [tr, bl, tl]] // split on the ↙ diagonal
            };
            for (k, t) in halves.into_iter().enumerate() {
                triangles.push(if (i + j + k as u32).is_multiple_of(2) {
                    t
                } else {
                    reversed(&t)
                });
            }
        }
    }
    triangles
}

#[test]
fn a_grid_of_split_squares_covers_each_pixel_once() {
    let grid = grid();
    assert_eq!(grid.len(), 18, "the test's grid: 9 squares of 2 triangles");
    assert_tiles_the_square("grid", &grid, 0.5, 9.5, 11);
    insta::assert_snapshot!(format!(
        "which triangle (two per square, squares row by row):\n{}\ncount:\n{}",
        owner_text(&grid, 11, 11),
        count_text(&counts(&grid, 11, 11))
    ));
}

/// Triangles of zero area (collinear corners, a repeated corner, one point
/// three times) cover nothing, not even the pixel centres on their line;
/// they have no barycentric weights.
#[test]
fn degenerate_triangles_cover_nothing() {
    #[rustfmt::skip]
    let degenerate = [
        ("collinear along a row of centres", [p(0.5, 2.5), p(3.5, 2.5), p(7.5, 2.5)]),
        ("collinear on a diagonal of centres", [p(0.5, 0.5), p(7.5, 7.5), p(3.5, 3.5)]),
        ("collinear, slanted", [p(1.0, 0.0), p(3.0, 4.0), p(2.0, 2.0)]),
        ("a repeated corner", [p(1.5, 1.5), p(6.5, 4.5), p(1.5, 1.5)]),
        ("one point three times", [p(4.5, 4.5), p(4.5, 4.5), p(4.5, 4.5)]),
    ];
    for (name, t) in degenerate {
        for t in [t, reversed(&t)] {
            let corners = t.map(|c| (c.x, c.y));
            let n = covered(&t, 8, 8);
            assert!(
                n == 0,
                "{name} {corners:?}, of zero area: pixel centres covered: \
                 expected 0, got {n}"
            );
            for q in [t[0], t[1], t[2], (t[0] + t[1]) / 2.0] {
                assert!(
                    !covers(&t, q),
                    "{name} {corners:?}, of zero area, at {q} on it: expected \
                     not covered, got covered"
                );
            }
            let weights = barycentric(&t, p(2.5, 2.5));
            assert!(
                weights.is_none(),
                "barycentric({corners:?}, (2.5, 2.5)), {name}: expected None \
                 (zero area), got {weights:?}"
            );
        }
    }
}

/// Weights worked by hand on the triangle (0, 0), (4, 0), (0, 2).
#[test]
fn barycentric_table() {
    let t = [p(0.0, 0.0), p(4.0, 0.0), p(0.0, 2.0)];
    let probes = [
        ("corner a", p(0.0, 0.0)),
        ("corner b", p(4.0, 0.0)),
        ("corner c", p(0.0, 2.0)),
        ("middle of a b", p(2.0, 0.0)),
        ("middle of b c", p(2.0, 1.0)),
        ("centroid", p(4.0 / 3.0, 2.0 / 3.0)),
        ("outside, past b c", p(4.0, 2.0)),
        ("outside, left of a c", p(-1.0, 1.0)),
    ];
    let mut table = Table::new(&["point", "λa", "λb", "λc", "sum"]);
    // the weights first (a wrong one fails on its row), then the windings
    let mut windings = Vec::new();
    for (name, q) in probes {
        let weights = |t: &[DVec2; 3]| {
            barycentric(t, q).unwrap_or_else(|| {
                panic!(
                    "barycentric({:?}, {q}): expected weights (the triangle \
                     has an area), got None",
                    t.map(|c| (c.x, c.y))
                )
            })
        };
        let w = weights(&t);
        // the other winding: the same weights, b and c swapped
        windings.push((name, q, w, weights(&reversed(&t))));
        table.row(&[
            name.to_string(),
            num(w[0]),
            num(w[1]),
            num(w[2]),
            num(w[0] + w[1] + w[2]),
        ]);
    }
    insta::assert_snapshot!(table.to_string());
    for (name, q, w, wb) in windings {
        assert!(
            (wb[0] - w[0]).abs() < 1e-15
                && (wb[1] - w[2]).abs() < 1e-15
                && (wb[2] - w[1]).abs() < 1e-15,
            "{name} {q}: the triangle a, c, b (the other winding): expected \
             the weights {:?} (those of a, b, c with b and c swapped), got \
             {wb:?}",
            [w[0], w[2], w[1]]
        );
    }
}

/// A coordinate on the half-pixel lattice of an 8×8 grid: 0, ½, 1, …, 8.
fn half() -> impl Strategy<Value = f64> {
    (0..=16i32).prop_map(|k| f64::from(k) / 2.0)
}

fn lattice_point() -> impl Strategy<Value = DVec2> {
    (half(), half()).prop_map(|(x, y)| p(x, y))
}

/// A triangle with corners anywhere in [−10, 10]², not too thin.
fn real_triangle() -> impl Strategy<Value = [DVec2; 3]> {
    proptest::array::uniform3(
        (-10.0..10.0f64, -10.0..10.0f64).prop_map(|(x, y)| p(x, y)),
    )
    .prop_filter("area of at least ½", |t| {
        cross(t[0], t[1], t[2]).abs() >= 1.0
    })
}

proptest! {
    #![proptest_config(seeded(256))]

    /// A triangle on the half-pixel lattice (its edges often pass exactly
    /// through pixel centres) covers the same pixels in all six orders of
    /// its corners, all centres strictly inside it and none outside.
    #[test]
    fn coverage_depends_on_the_triangle_not_the_order(t in proptest::array::uniform3(lattice_point())) {
        let [a, b, c] = t;
        let orders = [[a, b, c], [b, c, a], [c, a, b], [a, c, b], [c, b, a], [b, a, c]];
        let table = coverage_table(&t, 8, 8);
        for order in orders {
            let other = coverage_table(&order, 8, 8);
            let differ = (0..8u32)
                .flat_map(|row| (0..8u32).map(move |column| (column, row)))
                .find(|&(column, row)| {
                    covers(&order, centre(column, row)) != covers(&t, centre(column, row))
                });
            prop_assert!(other == table, "the triangle {:?} and the same one as {:?}: expected the same pixels covered, got {}", t.map(|c| (c.x, c.y)), order.map(|c| (c.x, c.y)), differ.map_or(String::new(), |(column, row)| format!("pixel ({column}, {row}) covered by one and not the other")));
        }
        for row in 0..8 {
            for column in 0..8 {
                let q = centre(column, row);
                if strictly_inside(&t, q) {
                    prop_assert!(covers(&t, q), "covers({:?}, {q}): expected true (strictly inside), got false", t.map(|c| (c.x, c.y)));
                } else if !on_an_edge(&t, q) {
                    prop_assert!(!covers(&t, q), "covers({:?}, {q}): expected false (outside, off the edges), got true", t.map(|c| (c.x, c.y)));
                }
            }
        }
    }

    /// Two triangles sharing the edge a b, on either side of it, in any
    /// windings: no pixel centre is covered by both, and every centre on
    /// the shared edge between a and b is covered by exactly one of them.
    #[test]
    fn a_shared_edge_is_covered_once(
        a in lattice_point(), b in lattice_point(),
        c in lattice_point(), d in lattice_point(),
        flip_first: bool, flip_second: bool,
    ) {
        prop_assume!(cross(a, b, c) * cross(a, b, d) < 0.0, "c and d on opposite sides");
        let first = if flip_first { [b, a, c] } else { [a, b, c] };
        let second = if flip_second { [b, a, d] } else { [a, b, d] };
        for row in 0..8 {
            for column in 0..8 {
                let q = centre(column, row);
                let hits = usize::from(covers(&first, q)) + usize::from(covers(&second, q));
                let pair = format!("{:?} and {:?}", first.map(|c| (c.x, c.y)), second.map(|c| (c.x, c.y)));
                prop_assert!(hits <= 1, "the triangles {pair}, sharing an edge, at {q}: expected covered at most once, got twice");
                if on_segment(a, b, q) && q != a && q != b {
                    prop_assert!(hits == 1, "the triangles {pair} at {q}, on their shared edge: expected covered by exactly one (the one that owns the edge), got {hits}");
                }
            }
        }
    }

    /// The weights sum to 1 and reproduce the point, inside the triangle
    /// or not, and agree with `covers` away from the edges: all clearly
    /// positive inside, one clearly negative outside.
    #[test]
    fn weights_sum_to_one_and_reproduce_the_point(
        t in real_triangle(),
        x in -20.0..20.0f64, y in -20.0..20.0f64,
    ) {
        let q = p(x, y);
        let corners = t.map(|c| (c.x, c.y));
        let w = barycentric(&t, q);
        prop_assert!(w.is_some(), "barycentric({corners:?}, {q}): expected weights (the triangle has an area), got None");
        let w = w.unwrap();
        let sum = w[0] + w[1] + w[2];
        prop_assert!((sum - 1.0).abs() <= 1e-9, "barycentric({corners:?}, {q}) = {w:?}: expected weights summing to 1, got {sum}");
        let back = w[0] * t[0] + w[1] * t[1] + w[2] * t[2];
        prop_assert!((back - q).length() <= 1e-9, "barycentric({corners:?}, {q}) = {w:?}: expected λa·a + λb·b + λc·c = {q}, got {back}");
        if w.iter().all(|&l| l > 1e-9) {
            prop_assert!(covers(&t, q), "covers({corners:?}, {q}): expected true (all weights {w:?} positive: inside), got false");
        }
        if w.iter().any(|&l| l < -1e-9) {
            prop_assert!(!covers(&t, q), "covers({corners:?}, {q}): expected false (a weight of {w:?} negative: outside), got true");
        }
    }
}
