//! Exercise 1: the robust slab test, against a catalogue of the rays that
//! break naive ones.
mod common;

use ch08::{Aabb, DVec3, Interval, Ray, slab_test};
use common::{Rng, plain_slab};
use proptest::prelude::*;
use raystep_check::{Table, seeded};

fn v(x: f64, y: f64, z: f64) -> DVec3 {
    DVec3::new(x, y, z)
}

/// The boxes of the catalogue, every coordinate a short binary fraction
/// so the expected answers below are exact: one near the origin, a thin
/// one around 2²⁰ ≈ 1e6, and a tiny one.
fn boxes() -> [Aabb; 3] {
    let m = 1_048_576.0; // 2²⁰
    let tiny = 2f64.powi(-30);
    [
        Aabb::new(v(-1.0, -2.0, 0.5), v(1.0, 3.0, 4.0)),
        Aabb::new(v(m + 0.25, -m - 3.0, -0.125), v(m + 1.75, -m + 1.0, 0.125)),
        Aabb::new(v(tiny, -4.0 * tiny, tiny), v(3.0 * tiny, tiny, 2.0 * tiny)),
    ]
}

/// What a ray must get.
#[derive(Clone, Copy, Debug)]
enum Expected {
    /// No part of the interval inside the box.
    Miss,
    /// Inside from `t_in` to `t_out` (both exact here): the entry to
    /// 1e-12, the exit pushed out by the factor 1 + 2γ₃ at most (3 ulps),
    /// never pulled in.
    Span(f64, f64),
    /// A hit whose interval contains t = 1 (up to a rounding of the entry
    /// or the exit): the ray passes through a point of the boundary there.
    Touches,
    /// Any answer but NaN: None, or an interval inside the query interval
    /// (a ray with NaN in it has no right answer, only wrong ones).
    NotNan,
}

/// What a right answer is, in words.
fn describe(expected: Expected) -> String {
    match expected {
        Expected::Miss => "a miss (None)".to_string(),
        Expected::Span(t_in, t_out) => format!(
            "inside from t = {t_in} to t = {t_out}, the exit pushed out by \
             the factor 1 + 2γ₃ at most, to {}, never pulled in",
            widened(t_out)
        ),
        Expected::Touches => "a hit whose interval contains t = 1, where \
                              the ray touches the box's boundary"
            .to_string(),
        Expected::NotNan => {
            "None or an interval within [0, ∞) without NaN".to_string()
        }
    }
}

/// γ₃ = 3u / (1 − 3u), u = 2⁻⁵³, as in the lecture.
const GAMMA_3: f64 =
    3.0 * (f64::EPSILON / 2.0) / (1.0 - 3.0 * (f64::EPSILON / 2.0));

/// An exact exit `t` pushed out as the lecture's step 3 does: by the
/// factor 1 + 2γ₃, more than the rounding of a computed exit (and no more:
/// a wider box lets through rays that miss it by more than rounding).
fn widened(t: f64) -> f64 {
    t * (1.0 + 2.0 * GAMMA_3)
}

/// Is `got` a right answer?
fn right(got: Option<Interval>, expected: Expected, query: Interval) -> bool {
    let close = |a: f64, b: f64| {
        a == b || (a - b).abs() <= 1e-12 * a.abs().max(b.abs()).max(1e-300)
    };
    match (expected, got) {
        (Expected::Miss, got) => got.is_none(),
        (Expected::Span(t_in, t_out), Some(i)) => {
            close(i.min, t_in) && t_out <= i.max && i.max <= widened(t_out)
        }
        (Expected::Touches, Some(i)) => {
            i.min <= 1.0 + 1e-12 && i.max >= 1.0 - 1e-12
        }
        (Expected::NotNan, None) => true,
        (Expected::NotNan, Some(i)) => {
            !i.min.is_nan()
                && !i.max.is_nan()
                && query.min <= i.min
                && i.max <= query.max
        }
        (_, None) => false,
    }
}

/// A point of `b`: at fraction `f[i]` of its extent along axis i.
fn point_in(b: &Aabb, f: DVec3) -> DVec3 {
    b.min + f * (b.max - b.min)
}

/// Fractions strictly inside, as short binary fractions.
const INSIDE: [f64; 4] = [0.125, 0.375, 0.625, 0.875];
/// Speeds along an axis: powers of 2, so t = distance / speed is exact.
const SPEEDS: [f64; 3] = [1.0, 2.0, 0.25];

/// The other two axes.
fn others(axis: usize) -> [usize; 2] {
    [(axis + 1) % 3, (axis + 2) % 3]
}

/// A direction along `axis` with speed `speed` (signed), exactly 0 on the
/// other axes.
fn along(axis: usize, speed: f64) -> DVec3 {
    let mut d = DVec3::ZERO;
    d[axis] = speed;
    d
}

/// A case of the catalogue: its name and its rays, each with its answer.
type Case = (&'static str, Vec<(Aabb, Ray, Expected)>);

/// Rays along an axis from outside, through the box (a 5 × 4 × 4 grid of
/// positions across it, both ways, three speeds).
fn axis_parallel_through() -> Case {
    let mut rays = Vec::new();
    for b in boxes() {
        let size = b.max - b.min;
        for axis in 0..3 {
            let [i, j] = others(axis);
            for &fi in &INSIDE {
                for &fj in &INSIDE {
                    for gap in [1.0, 0.5 * size[axis], 1024.0] {
                        for &speed in &SPEEDS {
                            for sign in [1.0, -1.0] {
                                let mut f = DVec3::ZERO;
                                (f[i], f[j]) = (fi, fj);
                                let mut o = point_in(&b, f);
                                o[axis] = if sign > 0.0 {
                                    b.min[axis] - gap
                                } else {
                                    b.max[axis] + gap
                                };
                                let ray =
                                    Ray::new(o, along(axis, sign * speed));
                                let expected = Expected::Span(
                                    gap / speed,
                                    (gap + size[axis]) / speed,
                                );
                                rays.push((b, ray, expected));
                            }
                        }
                    }
                }
            }
        }
    }
    ("axis-parallel, through the box", rays)
}

/// Rays along an axis beside the box: one coordinate across the ray just
/// outside (the next float past a face) or far outside.
fn axis_parallel_beside() -> Case {
    let mut rays = Vec::new();
    for b in boxes() {
        for axis in 0..3 {
            let [i, j] = others(axis);
            for &fj in &INSIDE {
                for side in [0, 1] {
                    for far in [false, true] {
                        for sign in [1.0, -1.0] {
                            let mut f = DVec3::ZERO;
                            f[j] = fj;
                            let mut o = point_in(&b, f);
                            o[i] = match (side, far) {
                                (0, false) => b.min[i].next_down(),
                                (0, true) => b.min[i] - 5.0,
                                (_, false) => b.max[i].next_up(),
                                (_, true) => b.max[i] + 5.0,
                            };
                            o[axis] = b.min[axis] - sign * 7.0;
                            let ray = Ray::new(o, along(axis, sign));
                            rays.push((b, ray, Expected::Miss));
                        }
                    }
                }
            }
        }
    }
    ("axis-parallel, beside the box", rays)
}

/// Rays along an axis from inside the box: the interval starts at 0.
fn axis_parallel_from_inside() -> Case {
    let mut rays = Vec::new();
    for b in boxes() {
        let size = b.max - b.min;
        for axis in 0..3 {
            for &fa in &INSIDE {
                for &fo in &INSIDE {
                    for sign in [1.0, -1.0] {
                        let mut o = point_in(&b, DVec3::splat(fo));
                        o[axis] = b.min[axis] + fa * size[axis];
                        let exit = if sign > 0.0 {
                            b.max[axis] - o[axis]
                        } else {
                            o[axis] - b.min[axis]
                        };
                        let ray = Ray::new(o, along(axis, sign));
                        rays.push((b, ray, Expected::Span(0.0, exit)));
                    }
                }
            }
        }
    }
    ("axis-parallel, from inside", rays)
}

/// Origins exactly on a slab's plane: rays lying in the plane (the
/// 0·∞ = NaN case) through the face, along its edges, or beside it; and
/// rays leaving the plane straight into the box or out of it.
fn origins_on_a_slab_plane(zero: f64) -> Vec<(Aabb, Ray, Expected)> {
    let mut rays = Vec::new();
    for b in boxes() {
        let size = b.max - b.min;
        for axis in 0..3 {
            for on_max in [false, true] {
                let plane = if on_max { b.max[axis] } else { b.min[axis] };
                // in the plane, moving along `across`; the third axis
                // inside the face, on its edges, or outside it
                for across in others(axis) {
                    let third = 3 - axis - across;
                    let positions = [
                        (point_in(&b, DVec3::splat(0.375))[third], true),
                        (b.min[third], true),
                        (b.max[third], true),
                        (b.max[third] + size[third], false),
                    ];
                    for (at, hits) in positions {
                        for &speed in &SPEEDS {
                            for sign in [1.0, -1.0] {
                                let mut o = DVec3::ZERO;
                                o[axis] = plane;
                                o[third] = at;
                                o[across] = if sign > 0.0 {
                                    b.min[across] - 2.0
                                } else {
                                    b.max[across] + 2.0
                                };
                                let mut d = DVec3::splat(zero);
                                d[across] = sign * speed;
                                let expected = if hits {
                                    Expected::Span(
                                        2.0 / speed,
                                        (2.0 + size[across]) / speed,
                                    )
                                } else {
                                    Expected::Miss
                                };
                                rays.push((b, Ray::new(o, d), expected));
                            }
                        }
                    }
                }
                // on the face, moving straight in (through the box) or out
                // (touching it at t = 0 only)
                let mut o = point_in(&b, DVec3::splat(0.625));
                o[axis] = plane;
                for inward in [true, false] {
                    let sign = if inward == on_max { -1.0 } else { 1.0 };
                    let mut d = DVec3::splat(zero);
                    d[axis] = sign;
                    let t_out = if inward { size[axis] } else { 0.0 };
                    rays.push((b, Ray::new(o, d), Expected::Span(0.0, t_out)));
                }
            }
        }
    }
    rays
}

/// An integer in [−n, n] other than 0, as a float.
fn offset(rng: &mut Rng, n: f64) -> f64 {
    loop {
        let k = (rng.unit() * (2.0 * n + 1.0)).floor() - n;
        if k != 0.0 {
            return k;
        }
    }
}

/// Rays through points of the box's edges and corners, aimed from far
/// away (up to 1000 units, integer offsets, so the ray passes exactly
/// through its target at t = 1): half of them only touch the box there.
fn edges_and_corners() -> Case {
    let mut rng = Rng::new(0x51AB);
    let mut rays = Vec::new();
    for b in boxes() {
        for k in 0..6000 {
            // a point on an edge (two coordinates pinned to faces) or a
            // corner (three), the others at a fraction n/1024 of the box
            let mut f = DVec3::new(
                (rng.unit() * 1024.0).floor() / 1024.0,
                (rng.unit() * 1024.0).floor() / 1024.0,
                (rng.unit() * 1024.0).floor() / 1024.0,
            );
            let pinned = if k % 4 == 0 { 3 } else { 2 };
            for n in 0..pinned {
                f[(k + n) % 3] = if rng.unit() < 0.5 { 0.0 } else { 1.0 };
            }
            let target = point_in(&b, f);
            let scale = [1.0, 30.0, 1000.0][k % 3];
            let offset = DVec3::new(
                offset(&mut rng, scale),
                offset(&mut rng, scale),
                offset(&mut rng, scale),
            );
            let from = target + offset;
            assert_eq!(target - from, -offset, "an inexact direction");
            rays.push((b, Ray::new(from, -offset), Expected::Touches));
        }
    }
    ("through edges and corners, from far away", rays)
}

/// Rays with −0 and +0 components: the cases above with every zero of the
/// direction made −0.
fn signed_zeros() -> Case {
    let mut rays = origins_on_a_slab_plane(-0.0);
    for (b, ray, expected) in axis_parallel_through()
        .1
        .into_iter()
        .chain(axis_parallel_beside().1)
        .chain(axis_parallel_from_inside().1)
    {
        let d = ray.direction;
        let d = DVec3::select(d.cmpeq(DVec3::ZERO), DVec3::splat(-0.0), d);
        rays.push((b, Ray::new(ray.origin, d), expected));
    }
    ("direction components of −0", rays)
}

/// Rays with NaN in the origin, the direction or both, in one to three
/// components.
fn nan_components() -> Case {
    let mut rays = Vec::new();
    for b in boxes() {
        let inside = point_in(&b, DVec3::splat(0.5));
        for mask in 1..8u32 {
            let nan = |p: DVec3| {
                let mut p = p;
                for axis in 0..3 {
                    if mask & (1 << axis) != 0 {
                        p[axis] = f64::NAN;
                    }
                }
                p
            };
            let o = b.min - 1.0;
            for d in [v(1.0, 1.0, 1.0), v(0.0, 0.0, 1.0), v(-1.0, 2.0, -0.0)] {
                for ray in [
                    Ray::new(nan(o), d),
                    Ray::new(o, nan(d)),
                    Ray::new(nan(inside), nan(d)),
                    Ray::new(nan(inside), d),
                ] {
                    rays.push((b, ray, Expected::NotNan));
                }
            }
        }
    }
    ("NaN components", rays)
}

/// The stability catalogue, counted: every ray's answer against the one
/// constructed for it, for `slab_test` and for the naive slab test. The
/// robust test is never wrong; the naive one fails on origins on a slab
/// plane (it turns 0·∞ = NaN into ±∞ and misses or answers [∞, ∞]) and
/// on rays that only touch an edge or a corner (rounding puts the entry
/// past the exit).
#[test]
fn stability_catalogue() {
    let cases = [
        axis_parallel_through(),
        axis_parallel_beside(),
        axis_parallel_from_inside(),
        ("origin on a slab plane", origins_on_a_slab_plane(0.0)),
        edges_and_corners(),
        signed_zeros(),
        nan_components(),
    ];
    let mut table =
        Table::new(&["case", "rays", "wrong: slab_test", "wrong: naive"]);
    for (name, rays) in &cases {
        let (mut wrong, mut naive_wrong) = (0, 0);
        let mut first_wrong = None;
        for &(b, ray, expected) in rays {
            let query = Interval::FORWARD;
            let got = slab_test(&b, &ray, query);
            if !right(got, expected, query) {
                wrong += 1;
                first_wrong.get_or_insert((b, ray, expected, got));
            }
            naive_wrong += usize::from(!right(
                plain_slab(&b, &ray, query),
                expected,
                query,
            ));
        }
        table.row(&[
            name.to_string(),
            rays.len().to_string(),
            wrong.to_string(),
            naive_wrong.to_string(),
        ]);
        if let Some((b, ray, expected, got)) = first_wrong {
            panic!(
                "{name}: expected no wrong answer from slab_test, got {wrong} \
                 of {} rays wrong; the first: the box {}–{}, the ray from {} \
                 along {}, interval [0, ∞): expected {}, got {got:?}",
                rays.len(),
                b.min,
                b.max,
                ray.origin,
                ray.direction,
                describe(expected)
            );
        }
    }
    insta::assert_snapshot!(table.to_string());
}

/// An empty box is never hit; the box of everything is hit all along.
#[test]
fn empty_and_unbounded_boxes() {
    let ray = Ray::new(v(0.3, 0.2, 0.1), v(1.0, 2.0, 3.0));
    let got = slab_test(&Aabb::EMPTY, &ray, Interval::UNIVERSE);
    assert_eq!(
        got, None,
        "the empty box (min > max): expected None (never hit, whatever \
         the interval), got {got:?}"
    );
    let got = slab_test(&Aabb::EVERYTHING, &ray, Interval::FORWARD);
    assert_eq!(
        got,
        Some(Interval::FORWARD),
        "the box of everything (±∞ corners): expected the whole interval \
         [0, ∞), got {got:?}"
    );
    let b = boxes()[0];
    let through = Ray::new(v(0.0, 0.0, -1.0), v(0.0, 0.0, 1.0));
    assert_eq!(
        slab_test(&b, &through, Interval::new(0.0, 1.0)),
        None,
        "the box starts at t = 1.5, past the interval's max 1: expected \
         None"
    );
}

/// A ray with components of both signs and awkward sizes.
fn ray_strategy() -> impl Strategy<Value = Ray> {
    let coordinate = || -20.0..20.0f64;
    (
        (coordinate(), coordinate(), coordinate()),
        (coordinate(), coordinate(), coordinate()),
    )
        .prop_map(|((x, y, z), (a, b, c))| Ray::new(v(x, y, z), v(a, b, c)))
}

/// A box with corners in [−10, 10]³.
fn box_strategy() -> impl Strategy<Value = Aabb> {
    let coordinate = || -10.0..10.0f64;
    (
        (coordinate(), coordinate(), coordinate()),
        (coordinate(), coordinate(), coordinate()),
    )
        .prop_map(|((x, y, z), (a, b, c))| Aabb::new(v(x, y, z), v(a, b, c)))
}

proptest! {
    #![proptest_config(seeded(1024))]

    /// A ray aimed at a point inside the box hits it, and the interval it
    /// returns contains the point's t (= 1).
    #[test]
    fn aimed_inside_hits(
        b in box_strategy(),
        f in (0.0..1.0f64, 0.0..1.0f64, 0.0..1.0f64),
        from in ray_strategy(),
    ) {
        let target = point_in(&b, DVec3::new(f.0, f.1, f.2));
        let ray = Ray::new(from.origin * 10.0, target - from.origin * 10.0);
        let got = slab_test(&b, &ray, Interval::FORWARD);
        prop_assert!(
            got.is_some_and(|i| i.min <= 1.0 + 1e-12 && i.max >= 1.0 - 1e-12),
            "box {b:?}, ray {ray:?} aimed at {target} inside it (t = 1): \
             expected an interval containing 1, got {got:?}"
        );
    }

    /// Any box, ray and interval: an answer is a part of the interval
    /// whose middle is in the box, and a miss leaves no point of the
    /// interval well inside it (judged on 1 000 points along the ray).
    #[test]
    fn any_ray_gets_the_part_of_its_interval_in_the_box(
        b in box_strategy(),
        ray in ray_strategy(),
        (t0, t1) in (-5.0..5.0f64, 0.0..20.0f64),
    ) {
        let query = Interval::new(t0, t0 + t1);
        let got = slab_test(&b, &ray, query);
        // Within (or beyond) the box by `margin` in every coordinate.
        let margin = 1e-9 * (40.0 + 25.0 * ray.direction.length());
        let within = |p: DVec3, margin: f64| {
            (p - b.min).min_element() >= -margin
                && (b.max - p).min_element() >= -margin
        };
        match got {
            Some(part) => {
                let middle = ray.at((part.min + part.max) / 2.0);
                prop_assert!(
                    part.min >= query.min
                        && part.max <= query.max
                        && part.min <= part.max
                        && within(middle, margin),
                    "box {b:?}, ray {ray:?}, interval {query:?}: expected \
                     the part of the interval inside the box (or None), got \
                     {part:?}, whose middle {middle} is not in the box"
                );
            }
            None => {
                let inside = (0..=1000)
                    .map(|k| query.min + (query.max - query.min) * f64::from(k) / 1000.0)
                    .find(|&t| within(ray.at(t), -margin));
                prop_assert!(
                    inside.is_none(),
                    "box {b:?}, ray {ray:?}, interval {query:?}: expected a \
                     hit (the ray is well inside the box at t = {}), got None",
                    inside.unwrap_or_default()
                );
            }
        }
    }
}
