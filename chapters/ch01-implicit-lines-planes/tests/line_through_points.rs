//! Exercise 1: the implicit line through two points.
use ch01::{DVec2, Degenerate, Line2, rotate90};
use proptest::prelude::*;
use raystep_check::{Table, num, seeded, vec2};

fn line(p0: (f64, f64), p1: (f64, f64)) -> Result<Line2, Degenerate> {
    Line2::through(DVec2::new(p0.0, p0.1), DVec2::new(p1.0, p1.1))
}

#[test]
fn rotate90_turns_counter_clockwise() {
    assert_eq!(rotate90(DVec2::X), DVec2::Y);
    assert_eq!(rotate90(DVec2::Y), -DVec2::X);
    assert_eq!(rotate90(DVec2::new(3.0, -2.0)), DVec2::new(2.0, 3.0));
}

/// V, N, c and f at three probe points for lines the lecture draws.
#[test]
fn line_table() {
    let cases = [
        ((0.0, 0.0), (1.0, 0.0)),
        ((0.0, 0.0), (0.0, 2.0)),
        ((1.0, 1.0), (4.0, 5.0)),
        ((-2.0, 3.0), (2.0, -1.0)),
        ((0.5, -1.5), (0.5, 2.5)),
    ];
    let probes = [DVec2::ZERO, DVec2::new(1.0, 2.0), DVec2::new(-3.0, 1.0)];
    let mut table =
        Table::new(&["P0", "P1", "V", "N", "c", "f(0,0)", "f(1,2)", "f(-3,1)"]);
    for (p0, p1) in cases {
        let l = line(p0, p1).expect("a proper line");
        let f: Vec<String> = probes.iter().map(|&p| num(l.eval(p))).collect();
        table.row(&[
            format!("{p0:?}"),
            format!("{p1:?}"),
            vec2(l.direction),
            vec2(l.normal),
            num(l.c),
            f[0].clone(),
            f[1].clone(),
            f[2].clone(),
        ]);
    }
    insta::assert_snapshot!(table.to_string());
}

/// The sign of f says the side: positive to the left of V (where N points).
#[test]
fn sign_of_f_is_the_side_and_size_the_distance() {
    let l = line((0.0, 0.0), (2.0, 0.0)).unwrap();
    assert_eq!(l.eval(DVec2::new(5.0, 3.0)), 3.0);
    assert_eq!(l.eval(DVec2::new(-1.0, -0.5)), -0.5);
    assert_eq!(l.eval(DVec2::new(7.0, 0.0)), 0.0);
}

#[test]
fn degenerate_input_is_an_error_never_a_nan_normal() {
    let mut table = Table::new(&["P0", "P1", "result"]);
    let cases = [
        ((1.0, 2.0), (1.0, 2.0)),
        ((0.0, 0.0), (f64::NAN, 1.0)),
        ((f64::INFINITY, 0.0), (0.0, 1.0)),
        ((-1e308, 0.0), (1e308, 0.0)),
        ((0.0, 0.0), (1e-300, 0.0)),
        ((1e200, 0.0), (3e200, 1e200)),
    ];
    for (p0, p1) in cases {
        let result = match line(p0, p1) {
            Ok(l) => {
                assert!(
                    (l.normal.length() - 1.0).abs() < 1e-12,
                    "unit normal for {p0:?} {p1:?}"
                );
                format!("ok, N = {}", vec2(l.normal))
            }
            Err(e) => format!("error: {e}"),
        };
        table.row(&[format!("{p0:?}"), format!("{p1:?}"), result]);
    }
    insta::assert_snapshot!(table.to_string());
}

fn point() -> impl Strategy<Value = DVec2> {
    (-100.0..100.0f64, -100.0..100.0f64).prop_map(|(x, y)| DVec2::new(x, y))
}

proptest! {
    #![proptest_config(seeded(256))]

    /// f(P0) = f(P1) = 0; N is a unit vector at right angles to V; f grows by
    /// exactly the distance walked along N.
    #[test]
    fn line_properties(p0 in point(), p1 in point()) {
        prop_assume!((p1 - p0).length() > 1e-3);
        let l = Line2::through(p0, p1).unwrap();
        let scale = p0.abs().max(p1.abs()).max_element().max(1.0);
        prop_assert!(l.eval(p0).abs() <= 1e-13 * scale);
        prop_assert!(l.eval(p1).abs() <= 1e-13 * scale);
        prop_assert!((l.normal.length() - 1.0).abs() <= 1e-14);
        prop_assert!(l.normal.dot(l.direction).abs() <= 1e-15);
        prop_assert!((l.eval(p0 + 2.5 * l.normal) - 2.5).abs() <= 1e-13 * scale);
        // V points from P0 toward P1
        prop_assert!(l.direction.dot(p1 - p0) > 0.0);
    }
}

/// The same unit triangle of lines, scaled from 1e-6 to 1e6: f(P0) and f(P1)
/// stay zero within rounding relative to the coordinates, and N stays a
/// unit vector. Counts the failures over every scale and edge: 0.
#[test]
fn stable_from_1e_minus_6_to_1e6() {
    let mut failures = 0;
    let mut checked = 0;
    let shape = [
        DVec2::new(0.3, 0.1),
        DVec2::new(1.7, 0.4),
        DVec2::new(0.9, 1.3),
    ];
    for exponent in -6..=6 {
        let s = 10f64.powi(exponent);
        let offset = DVec2::new(0.25 * s, -3.0 * s);
        for i in 0..3 {
            let p0 = shape[i] * s + offset;
            let p1 = shape[(i + 1) % 3] * s + offset;
            let l = Line2::through(p0, p1).unwrap();
            let scale = p0.abs().max(p1.abs()).max_element();
            checked += 1;
            let ok = (l.normal.length() - 1.0).abs() <= 1e-14
                && l.eval(p0).abs() <= 1e-14 * scale
                && l.eval(p1).abs() <= 1e-14 * scale;
            if !ok {
                failures += 1;
            }
        }
    }
    assert_eq!(checked, 39);
    assert_eq!(failures, 0);
}
