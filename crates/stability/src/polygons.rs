//! Chapter 2's inside tests in 2D where they are fragile: points on the
//! edge two polygons share and at a fan's shared vertex (each must have
//! exactly one owner, the tie rule), on horizontal edges, level with a
//! vertex, a hair from an edge, and on a shared chain bent by rounding.
use ch02::{DVec2, inside_convex, inside_crossing};
use ch08::SplitMix64;

use crate::trials::{below, count_failures, per_method, uniform};
use crate::{Budget, Case, Count, Expect};

const POLYGONS: &str = "polygon tests";

/// This group's cases.
pub fn cases() -> Vec<Case> {
    vec![
        Case {
            group: POLYGONS,
            name: "point on a shared edge",
            what: "a point on the edge two convex polygons share has exactly \
                   one owner (the tie rule)",
            run: on_a_shared_edge,
        },
        Case {
            group: POLYGONS,
            name: "point at a shared vertex",
            what: "a fan's shared vertex has exactly one owner (the tie rule)",
            run: at_a_shared_vertex,
        },
        Case {
            group: POLYGONS,
            name: "point on a horizontal edge",
            what: "points on a 2 × 2 grid's shared edges and centre: one \
                   owner each (half-open in y)",
            run: on_a_horizontal_edge,
        },
        Case {
            group: POLYGONS,
            name: "point level with a vertex",
            what: "the crossing ray passes exactly through a vertex: counted \
                   once, so inside stays right",
            run: level_with_a_vertex,
        },
        Case {
            group: POLYGONS,
            name: "point 1e-9 from an edge",
            what: "a point 1e-9 inside or outside an edge is on its side for \
                   both tests",
            run: near_an_edge,
        },
        Case {
            group: POLYGONS,
            name: "almost straight shared chain",
            what: "a shared chain bent by rounding: the edge test leaks \
                   there, the crossing number never",
            run: almost_straight_chain,
        },
    ]
}

/// The edge test, for convex counter-clockwise outlines.
const EDGE_TEST: &str = "edge test (inside_convex)";
/// The crossing number, for any simple outline.
const CROSSING: &str = "crossing number (inside_crossing)";

/// One count per inside test, edge test first.
fn per_inside_test(
    failures: [u64; 2], trials: u64, expect: [Expect; 2],
) -> Vec<(Count, Expect)> {
    per_method([EDGE_TEST, CROSSING], failures, trials, expect)
}

/// Both inside tests, in the order of [`per_inside_test`].
const INSIDE_TESTS: [fn(&[DVec2], DVec2) -> bool; 2] =
    [inside_convex, inside_crossing];

/// How many of `polygons` `inside` says hold `p`.
fn owners(
    inside: fn(&[DVec2], DVec2) -> bool, polygons: &[&[DVec2]], p: DVec2,
) -> usize {
    polygons.iter().filter(|outline| inside(outline, p)).count()
}

/// A strictly convex counter-clockwise polygon of 4…8 corners on an
/// ellipse around a point of [−10, 10]²; with `lattice`, its corners
/// are on a 1/64 lattice (and it is checked still strictly convex).
fn convex_polygon(rng: &mut SplitMix64, lattice: bool) -> Vec<DVec2> {
    loop {
        let n = 4 + below(rng, 5);
        let mut gaps: Vec<f64> =
            (0..n).map(|_| uniform(rng, 0.2, 1.0)).collect();
        let total: f64 = gaps.iter().sum();
        gaps.iter_mut()
            .for_each(|g| *g *= std::f64::consts::TAU / total);
        if gaps.iter().any(|&g| g > 2.8) {
            continue;
        }
        let centre =
            DVec2::new(uniform(rng, -10.0, 10.0), uniform(rng, -10.0, 10.0));
        let radii = DVec2::new(uniform(rng, 1.0, 3.0), uniform(rng, 1.0, 3.0));
        let (mut angle, turn) =
            (uniform(rng, 0.0, 6.3), uniform(rng, 0.0, 6.3));
        let rotate = DVec2::from_angle(turn);
        let corners: Vec<DVec2> = gaps
            .iter()
            .map(|g| {
                angle += g;
                let p =
                    centre + rotate.rotate(radii * DVec2::from_angle(angle));
                if lattice {
                    (p * 64.0).round() / 64.0
                } else {
                    p
                }
            })
            .collect();
        let convex = (0..n).all(|i| {
            let (a, b, c) =
                (corners[i], corners[(i + 1) % n], corners[(i + 2) % n]);
            (b - a).perp_dot(c - b) > 1e-6
        });
        if convex {
            return corners;
        }
    }
}

/// A convex polygon cut along a chord between two corners that are not
/// neighbours into two convex polygons sharing that edge; points on
/// the chord (5%…95% along it): exactly on it when the corners lie on a
/// 1/64 lattice and the fraction is k/64 (half the trials), else as
/// rounded. Each point must have exactly one owner.
fn on_a_shared_edge(budget: &Budget) -> Vec<(Count, Expect)> {
    let failures = count_failures(budget.rays, 0x17_0011, |rng| {
        let exact = rng.next_f64() < 0.5;
        let outline = convex_polygon(rng, exact);
        let n = outline.len();
        let i = below(rng, n);
        let j = (i + 2 + below(rng, n - 3)) % n;
        let (lo, hi) = (i.min(j), i.max(j));
        let first: Vec<DVec2> = outline[lo..=hi].to_vec();
        let second: Vec<DVec2> = outline[hi..]
            .iter()
            .chain(&outline[..=lo])
            .copied()
            .collect();
        let (a, b) = (outline[lo], outline[hi]);
        let s = if exact {
            (3 + below(rng, 59)) as f64 / 64.0
        } else {
            uniform(rng, 0.05, 0.95)
        };
        let p = a + (b - a) * s;
        INSIDE_TESTS.map(|inside| owners(inside, &[&first, &second], p) != 1)
    });
    per_inside_test(failures, budget.rays as u64, [Expect::Never; 2])
}

/// A fan of 3…8 triangles around a random vertex c (each gap between
/// rim corners under π): c must have exactly one owner.
fn at_a_shared_vertex(budget: &Budget) -> Vec<(Count, Expect)> {
    let failures = count_failures(budget.rays, 0x17_0012, |rng| {
        let c =
            DVec2::new(uniform(rng, -10.0, 10.0), uniform(rng, -10.0, 10.0));
        let n = 3 + below(rng, 6);
        // Step 1: gaps between the rim corners, each under π.
        let gaps = loop {
            let gaps: Vec<f64> =
                (0..n).map(|_| uniform(rng, 0.1, 1.0)).collect();
            let scale = std::f64::consts::TAU / gaps.iter().sum::<f64>();
            if gaps.iter().all(|g| g * scale < 3.0) {
                break gaps.into_iter().map(|g| g * scale).collect::<Vec<_>>();
            }
        };
        // Step 2: the rim, counter-clockwise around c.
        let mut angle = uniform(rng, 0.0, 6.3);
        let rim: Vec<DVec2> = gaps
            .iter()
            .map(|g| {
                angle += g;
                c + uniform(rng, 0.5, 2.0) * DVec2::from_angle(angle)
            })
            .collect();
        let fan: Vec<[DVec2; 3]> =
            (0..n).map(|i| [c, rim[i], rim[(i + 1) % n]]).collect();
        let outlines: Vec<&[DVec2]> = fan.iter().map(|t| &t[..]).collect();
        INSIDE_TESTS.map(|inside| owners(inside, &outlines, c) != 1)
    });
    per_inside_test(failures, budget.rays as u64, [Expect::Never; 2])
}

/// A 2 × 2 grid of rectangles (random float corners): points on its
/// shared horizontal edge, its shared vertical edge, and its centre.
/// Each must have exactly one owner.
fn on_a_horizontal_edge(budget: &Budget) -> Vec<(Count, Expect)> {
    let failures = count_failures(budget.rays, 0x17_0013, |rng| {
        let x0 = uniform(rng, -10.0, 10.0);
        let y0 = uniform(rng, -10.0, 10.0);
        let x = [x0, x0 + uniform(rng, 0.1, 3.0)];
        let x = [x[0], x[1], x[1] + uniform(rng, 0.1, 3.0)];
        let y = [y0, y0 + uniform(rng, 0.1, 3.0)];
        let y = [y[0], y[1], y[1] + uniform(rng, 0.1, 3.0)];
        let cell = |i: usize, j: usize| {
            [
                DVec2::new(x[i], y[j]),
                DVec2::new(x[i + 1], y[j]),
                DVec2::new(x[i + 1], y[j + 1]),
                DVec2::new(x[i], y[j + 1]),
            ]
        };
        let cells = [cell(0, 0), cell(1, 0), cell(0, 1), cell(1, 1)];
        let outlines: Vec<&[DVec2]> = cells.iter().map(|c| &c[..]).collect();
        let p = match below(rng, 3) {
            0 => DVec2::new(uniform(rng, x[0], x[2]), y[1]),
            1 => DVec2::new(x[1], uniform(rng, y[0], y[2])),
            _ => DVec2::new(x[1], y[1]),
        };
        INSIDE_TESTS.map(|inside| owners(inside, &outlines, p) != 1)
    });
    per_inside_test(failures, budget.rays as u64, [Expect::Never; 2])
}

/// Points at exactly the height of a corner of a convex polygon, inside
/// or outside by at least 1e-6 (the boundary's x at that height found
/// from the edges): the crossing ray passes through the corner.
fn level_with_a_vertex(budget: &Budget) -> Vec<(Count, Expect)> {
    let failures = count_failures(budget.rays, 0x17_0014, |rng| {
        let lattice = rng.next_f64() < 0.5;
        let outline = convex_polygon(rng, lattice);
        let n = outline.len();
        let y = outline[below(rng, n)].y;
        // Step 1: where the boundary crosses the height y.
        let (mut left, mut right) = (f64::INFINITY, f64::NEG_INFINITY);
        for i in 0..n {
            let (a, b) = (outline[i], outline[(i + 1) % n]);
            if (a.y - y) * (b.y - y) <= 0.0 && a.y != b.y {
                let x = a.x + (y - a.y) * (b.x - a.x) / (b.y - a.y);
                (left, right) = (left.min(x), right.max(x));
            }
        }
        // Step 2: a point inside (if there is room: not at the top or
        // bottom, where the boundary may run along y) or outside.
        let (low, high) = outline
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), p| {
                (l.min(p.y), h.max(p.y))
            });
        let margin = 1e-6;
        let inside = low < y
            && y < high
            && right - left > 4.0 * margin
            && rng.next_f64() < 0.5;
        let x = if inside {
            uniform(rng, left + margin, right - margin)
        } else if rng.next_f64() < 0.5 {
            left - margin - uniform(rng, 0.0, 2.0)
        } else {
            right + margin + uniform(rng, 0.0, 2.0)
        };
        let p = DVec2::new(x, y);
        INSIDE_TESTS.map(|test| test(&outline, p) != inside)
    });
    per_inside_test(failures, budget.rays as u64, [Expect::Never; 2])
}

/// A point 5%…95% along an edge of a convex polygon, moved 1e-9 across
/// it, inward or outward: the verdict must follow.
fn near_an_edge(budget: &Budget) -> Vec<(Count, Expect)> {
    let failures = count_failures(budget.rays, 0x17_0015, |rng| {
        let outline = convex_polygon(rng, false);
        let n = outline.len();
        let i = below(rng, n);
        let (a, b) = (outline[i], outline[(i + 1) % n]);
        let inward = (b - a).perp().normalize();
        let inside = rng.next_f64() < 0.5;
        let sign = if inside { 1.0 } else { -1.0 };
        let p = a + uniform(rng, 0.05, 0.95) * (b - a) + sign * 1e-9 * inward;
        INSIDE_TESTS.map(|test| test(&outline, p) != inside)
    });
    per_inside_test(failures, budget.rays as u64, [Expect::Never; 2])
}

/// Chapter 2's chain test: two polygons share a chain a → m → b whose
/// middle corner m is placed by rounding, a hair off the line a–b, so
/// one polygon is concave there and the other convex by a rounding
/// error. The concave one always gets the crossing number; the other
/// gets the method counted. Points along the chain and at m must have
/// exactly one owner.
fn almost_straight_chain(budget: &Budget) -> Vec<(Count, Expect)> {
    let failures = count_failures(budget.rays, 0x17_0016, |rng| {
        let (x0, x1) = (uniform(rng, 0.1, 0.8), uniform(rng, 0.2, 0.9));
        let (a, b) = (DVec2::new(x0, 0.0), DVec2::new(x1, 1.0));
        let m = a + (b - a) * ((1 + below(rng, 6)) as f64 / 7.0);
        // both counter-clockwise: up the chain, or down it
        let left = vec![a, m, b, DVec2::new(-1.0, 1.0), DVec2::new(-1.0, 0.0)];
        let right = vec![a, DVec2::new(2.0, 0.0), DVec2::new(2.0, 1.0), b, m];
        // the polygon that turns left at m (or goes straight) is convex
        let turn = |outline: &[DVec2]| {
            let k = outline.iter().position(|&p| p == m).unwrap_or(0);
            let n = outline.len();
            let (p, q) = (outline[(k + n - 1) % n], outline[(k + 1) % n]);
            (m - p).perp_dot(q - m)
        };
        let (convex, concave) = if turn(&left) >= 0.0 {
            (left, right)
        } else {
            (right, left)
        };
        let target = match below(rng, 3) {
            0 => m,
            1 => a + (m - a) * uniform(rng, 0.02, 1.0),
            _ => m + (b - m) * uniform(rng, 0.0, 0.98),
        };
        INSIDE_TESTS.map(|test| {
            let n = usize::from(test(&convex, target))
                + usize::from(inside_crossing(&concave, target));
            n != 1
        })
    });
    per_inside_test(
        failures,
        budget.rays as u64,
        [Expect::Shown, Expect::Never],
    )
}
