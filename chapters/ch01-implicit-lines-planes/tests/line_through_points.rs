//! Exercise 1: the implicit line through two points.
use ch01::{DVec2, Degenerate, Line2, rotate90};
use proptest::prelude::*;
use raystep_check::{Table, num, seeded, vec2};

fn line(p0: (f64, f64), p1: (f64, f64)) -> Result<Line2, Degenerate> {
    Line2::through(DVec2::new(p0.0, p0.1), DVec2::new(p1.0, p1.1))
}

/// The line through two distinct points, or a panic that says which.
fn proper_line(p0: (f64, f64), p1: (f64, f64)) -> Line2 {
    line(p0, p1).unwrap_or_else(|e| {
        panic!(
            "Line2::through({p0:?}, {p1:?}): expected a line (the points \
             differ), got the error \"{e}\""
        )
    })
}

#[test]
fn rotate90_turns_counter_clockwise() {
    let x = DVec2::X;
    let y = DVec2::Y;
    #[rustfmt::skip]
    let cases = [
        ("+x", x, y, "a quarter turn left takes +x to +y"),
        ("+y", y, -x, "a quarter turn left takes +y to -x"),
        ("(3, -2)", DVec2::new(3.0, -2.0), DVec2::new(2.0, 3.0),
            "the same turn, on a vector of another length"),
    ];
    for (name, v, expected, why) in cases {
        let got = rotate90(v);
        assert!(
            got == expected,
            "rotate90 of {name}: expected {expected} ({why}), got {got}"
        );
    }
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
        let l = proper_line(p0, p1);
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
    let l = proper_line((0.0, 0.0), (2.0, 0.0));
    #[rustfmt::skip]
    let cases = [
        ((5.0, 3.0), 3.0, "3 to the left of the line y = 0, where N points"),
        ((-1.0, -0.5), -0.5, "0.5 to the right of it, against N"),
        ((7.0, 0.0), 0.0, "on the line, beyond P1"),
    ];
    for ((x, y), expected, why) in cases {
        let got = l.eval(DVec2::new(x, y));
        assert!(
            got == expected,
            "f({x}, {y}) on the line from (0, 0) to (2, 0): expected \
             {expected} ({why}), got {got}"
        );
    }
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
    // the verdicts first (a wrong one fails on its row), then the normals
    let mut normals = Vec::new();
    for (p0, p1) in cases {
        let result = match line(p0, p1) {
            Ok(l) => {
                normals.push((p0, p1, l.normal));
                format!("ok, N = {}", vec2(l.normal))
            }
            Err(e) => format!("error: {e}"),
        };
        table.row(&[format!("{p0:?}"), format!("{p1:?}"), result]);
    }
    insta::assert_snapshot!(table.to_string());
    for (p0, p1, n) in normals {
        assert!(
            (n.length() - 1.0).abs() < 1e-12,
            "Line2::through({p0:?}, {p1:?}): expected a unit normal, got N = \
             {n} of length {}",
            n.length()
        );
    }
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
        let l = Line2::through(p0, p1);
        prop_assert!(l.is_ok(), "Line2::through({p0}, {p1}): expected a line, got {l:?}");
        let l = l.unwrap();
        let scale = p0.abs().max(p1.abs()).max_element().max(1.0);
        let (n, v) = (l.normal, l.direction);
        let [f0, f1] = [l.eval(p0), l.eval(p1)];
        prop_assert!(f0.abs() <= 1e-13 * scale, "line through {p0} and {p1}: expected f(P0) = 0 (the line passes through P0), got {f0}");
        prop_assert!(f1.abs() <= 1e-13 * scale, "line through {p0} and {p1}: expected f(P1) = 0 (the line passes through P1), got {f1}");
        prop_assert!((n.length() - 1.0).abs() <= 1e-14, "line through {p0} and {p1}: expected a unit normal, got N = {n} of length {}", n.length());
        prop_assert!(n.dot(v).abs() <= 1e-15, "line through {p0} and {p1}: expected N at right angles to V, got N·V = {} (N = {n}, V = {v})", n.dot(v));
        let walked = l.eval(p0 + 2.5 * n);
        prop_assert!((walked - 2.5).abs() <= 1e-13 * scale, "line through {p0} and {p1}: expected f = 2.5 at P0 + 2.5·N (f is the distance along N), got {walked}");
        // V points from P0 toward P1
        prop_assert!(v.dot(p1 - p0) > 0.0, "line through {p0} and {p1}: expected V to point from P0 toward P1, got V = {v}");
    }
}

/// The same unit triangle of lines, scaled from 1e-6 to 1e6: f(P0) and f(P1)
/// stay zero within rounding relative to the coordinates, and N stays a
/// unit vector. Counts the failures over every scale and edge: 0.
#[test]
fn stable_from_1e_minus_6_to_1e6() {
    let mut failures = 0;
    let mut checked = 0;
    let mut first_failure = None;
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
            let l = Line2::through(p0, p1).unwrap_or_else(|e| {
                panic!(
                    "Line2::through({p0}, {p1}): expected a line (scale \
                     1e{exponent}), got the error \"{e}\""
                )
            });
            let scale = p0.abs().max(p1.abs()).max_element();
            checked += 1;
            let ok = (l.normal.length() - 1.0).abs() <= 1e-14
                && l.eval(p0).abs() <= 1e-14 * scale
                && l.eval(p1).abs() <= 1e-14 * scale;
            if !ok {
                failures += 1;
                first_failure.get_or_insert(format!(
                    "P0 = {p0}, P1 = {p1}: |N| = {}, f(P0) = {}, f(P1) = {}",
                    l.normal.length(),
                    l.eval(p0),
                    l.eval(p1)
                ));
            }
        }
    }
    assert_eq!(checked, 39, "lines checked: 3 edges at 13 scales");
    assert!(
        failures == 0,
        "lines with N not unit or f(P0), f(P1) not 0 (within 1e-14 of the \
         coordinates): expected 0 of {checked}, got {failures}; the first: \
         {}",
        first_failure.unwrap_or_default()
    );
}
