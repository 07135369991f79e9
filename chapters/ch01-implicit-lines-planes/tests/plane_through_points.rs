//! Exercise 2: the implicit plane through three points.
use ch01::{DVec3, Degenerate, Plane};
use proptest::prelude::*;
use raystep_check::{Table, num, seeded, vec3};

fn v(x: f64, y: f64, z: f64) -> DVec3 {
    DVec3::new(x, y, z)
}

/// The plane through three points that fix one, or a panic that says which.
fn proper_plane(p0: DVec3, p1: DVec3, p2: DVec3) -> Plane {
    Plane::through(p0, p1, p2).unwrap_or_else(|e| {
        panic!(
            "Plane::through({p0}, {p1}, {p2}): expected a plane (the points \
             are not collinear), got the error \"{e}\""
        )
    })
}

/// N, d and f at a probe point for planes the lecture draws.
#[test]
fn plane_table() {
    let cases = [
        (v(0.0, 0.0, 0.0), v(1.0, 0.0, 0.0), v(0.0, 1.0, 0.0)),
        (v(0.0, 0.0, 0.0), v(0.0, 1.0, 0.0), v(1.0, 0.0, 0.0)),
        (v(1.0, 0.0, 0.0), v(0.0, 1.0, 0.0), v(0.0, 0.0, 1.0)),
        (v(0.0, 2.0, 0.0), v(3.0, 2.0, 1.0), v(-1.0, 2.0, 4.0)),
        (v(1.0, 2.0, 3.0), v(4.0, 0.0, -1.0), v(-2.0, 5.0, 2.0)),
    ];
    let probe = v(1.0, 1.0, 1.0);
    let mut table = Table::new(&["P0", "P1", "P2", "N", "d", "f(1,1,1)"]);
    for (p0, p1, p2) in cases {
        let plane = proper_plane(p0, p1, p2);
        table.row(&[
            vec3(p0),
            vec3(p1),
            vec3(p2),
            vec3(plane.normal),
            num(plane.d),
            num(plane.eval(probe)),
        ]);
    }
    insta::assert_snapshot!(table.to_string());
}

#[test]
fn degenerate_input_is_an_error_never_a_nan_normal() {
    let nan = f64::NAN;
    #[rustfmt::skip]
    let cases = [
        ("P0 = P1", v(1.0, 2.0, 3.0), v(1.0, 2.0, 3.0), v(0.0, 0.0, 1.0)),
        ("P1 = P2", v(0.0, 0.0, 0.0), v(1.0, 1.0, 0.0), v(1.0, 1.0, 0.0)),
        ("collinear", v(0.0, 0.0, 0.0), v(1.0, 1.0, 1.0), v(3.0, 3.0, 3.0)),
        ("collinear, rounded", v(0.1, 0.2, 0.3), v(0.3, 0.6, 0.9), v(0.7, 1.4, 2.1)),
        ("NaN", v(0.0, 0.0, 0.0), v(1.0, nan, 0.0), v(0.0, 1.0, 0.0)),
        ("infinite", v(0.0, 0.0, f64::INFINITY), v(1.0, 0.0, 0.0), v(0.0, 1.0, 0.0)),
        ("overflow", v(-1e308, 0.0, 0.0), v(1e308, 0.0, 0.0), v(0.0, 1.0, 0.0)),
        ("tiny, 1e-200", v(0.0, 0.0, 0.0), v(1e-200, 0.0, 0.0), v(0.0, 1e-200, 0.0)),
        ("huge, 1e200", v(1e200, 0.0, 0.0), v(2e200, 0.0, 0.0), v(1e200, 1e200, 0.0)),
    ];
    let mut table = Table::new(&["case", "result"]);
    // the verdicts first (a wrong one fails on its row), then the normals
    let mut normals = Vec::new();
    for (name, p0, p1, p2) in cases {
        let result = match Plane::through(p0, p1, p2) {
            Ok(plane) => {
                normals.push((name, plane.normal));
                format!("ok, N = {}", vec3(plane.normal))
            }
            Err(e) => format!("error: {e}"),
        };
        table.row(&[name.to_string(), result]);
    }
    insta::assert_snapshot!(table.to_string());
    for (name, n) in normals {
        assert!(
            (n.length() - 1.0).abs() < 1e-12,
            "{name}: expected a unit normal, got N = {n} of length {}",
            n.length()
        );
    }
}

#[test]
fn specific_errors() {
    let o = DVec3::ZERO;
    #[rustfmt::skip]
    let cases = [
        ("P0 = P1 = (0, 0, 0), P2 = (1, 0, 0)", [o, o, DVec3::X],
            Degenerate::CoincidentPoints),
        ("(0, 0, 0), (1, 0, 0), (2, 0, 0)", [o, DVec3::X, 2.0 * DVec3::X],
            Degenerate::Collinear),
    ];
    for (name, [p0, p1, p2], expected) in cases {
        let got = Plane::through(p0, p1, p2);
        assert!(
            got == Err(expected),
            "Plane::through({name}): expected Err({expected:?}), got {got:?}"
        );
    }
}

/// Collinear means |E1×E2| ≤ COLLINEAR_SINE·|E1|·|E2|: the sine of the
/// angle between the edges at most COLLINEAR_SINE, whatever their lengths
/// and directions. Here the edges run along the diagonal (1, 1, 1), where
/// an edge scaled to a largest component of 1 is √3 long: from (0, 0, 0)
/// to (1, 1, 1) and to (1 + δ, 1 − δ, 1), at sin θ = δ·√6/3.
#[test]
fn collinear_is_the_sine_of_the_angle() {
    let sine_per_delta = 6f64.sqrt() / 3.0;
    for (k, expect_collinear) in [(0.5, true), (2.0, false)] {
        let delta = k * ch01::COLLINEAR_SINE / sine_per_delta;
        let p2 = v(1.0 + delta, 1.0 - delta, 1.0);
        let got = Plane::through(DVec3::ZERO, DVec3::ONE, p2);
        let what = format!(
            "Plane::through((0, 0, 0), (1, 1, 1), (1 + δ, 1 − δ, 1)) with δ = \
             {delta:e}: edges at sin θ = {k}·COLLINEAR_SINE"
        );
        if expect_collinear {
            assert!(
                got == Err(Degenerate::Collinear),
                "{what}: expected Err(Collinear) (sin θ ≤ COLLINEAR_SINE), \
                 got {got:?}"
            );
        } else {
            assert!(
                got.is_ok(),
                "{what}: expected a plane (sin θ > COLLINEAR_SINE), got \
                 {got:?}"
            );
        }
    }
}

fn point() -> impl Strategy<Value = DVec3> {
    (-100.0..100.0f64, -100.0..100.0f64, -100.0..100.0f64)
        .prop_map(|(x, y, z)| v(x, y, z))
}

proptest! {
    #![proptest_config(seeded(256))]

    /// N is a unit vector orthogonal to E1 and E2; f is zero at all three
    /// points; the points run counter-clockwise around N.
    #[test]
    fn plane_properties(p0 in point(), p1 in point(), p2 in point()) {
        let (e1, e2) = (p1 - p0, p2 - p0);
        // well-shaped triangles only: the property is about the formula
        prop_assume!(e1.cross(e2).length() > 1e-2 * e1.length() * e2.length());
        let plane = Plane::through(p0, p1, p2);
        prop_assert!(plane.is_ok(), "Plane::through({p0}, {p1}, {p2}): expected a plane, got {plane:?}");
        let plane = plane.unwrap();
        let n = plane.normal;
        let scale = p0.abs().max(p1.abs()).max(p2.abs()).max_element().max(1.0);
        let points = format!("plane through {p0}, {p1}, {p2}");
        prop_assert!((n.length() - 1.0).abs() <= 1e-14, "{points}: expected a unit normal, got N = {n} of length {}", n.length());
        prop_assert!(n.dot(e1).abs() <= 1e-12 * e1.length(), "{points}: expected N at right angles to E1 = P1 − P0, got N·E1 = {} (N = {n})", n.dot(e1));
        prop_assert!(n.dot(e2).abs() <= 1e-12 * e2.length(), "{points}: expected N at right angles to E2 = P2 − P0, got N·E2 = {} (N = {n})", n.dot(e2));
        for (name, p) in [("P0", p0), ("P1", p1), ("P2", p2)] {
            let f = plane.eval(p);
            prop_assert!(f.abs() <= 1e-12 * scale, "{points}: expected f({name}) = 0 (the plane passes through {name}), got {f}");
        }
        prop_assert!(e1.cross(e2).dot(n) > 0.0, "{points}: expected N on the side of E1×E2 = {} (the points run counter-clockwise around N), got N = {n}", e1.cross(e2));
    }
}

/// One tilted triangle scaled from 1e-6 to 1e6 and moved away from the
/// origin: N stays unit and orthogonal to the edges, f stays zero at the
/// points relative to the coordinates. 0 failures.
#[test]
fn stable_from_1e_minus_6_to_1e6() {
    let shape = [v(0.2, 0.1, 0.7), v(1.9, 0.4, -0.3), v(0.6, 1.5, 0.2)];
    let mut failures = 0;
    let mut checked = 0;
    let mut first_failure = None;
    for exponent in -6..=6 {
        let s = 10f64.powi(exponent);
        let offset = v(3.0, -1.0, 2.0) * s;
        let [p0, p1, p2] = shape.map(|p| p * s + offset);
        let plane = proper_plane(p0, p1, p2);
        let scale = p0.abs().max(p1.abs()).max(p2.abs()).max_element();
        checked += 1;
        let ok = (plane.normal.length() - 1.0).abs() <= 1e-14
            && plane.normal.dot(p1 - p0).abs() <= 1e-13 * s
            && plane.normal.dot(p2 - p0).abs() <= 1e-13 * s
            && [p0, p1, p2]
                .iter()
                .all(|&p| plane.eval(p).abs() <= 1e-14 * scale);
        if !ok {
            failures += 1;
            first_failure.get_or_insert(format!(
                "scale 1e{exponent}: |N| = {}, N·E1 = {}, N·E2 = {}, f at the \
                 points {:?}",
                plane.normal.length(),
                plane.normal.dot(p1 - p0),
                plane.normal.dot(p2 - p0),
                [p0, p1, p2].map(|p| plane.eval(p))
            ));
        }
    }
    assert_eq!(checked, 13, "planes checked: one at each of 13 scales");
    assert!(
        failures == 0,
        "planes with N not unit, not at right angles to the edges, or f not \
         0 at the points (relative to the coordinates): expected 0 of \
         {checked}, got {failures}; the first: {}",
        first_failure.unwrap_or_default()
    );
}
