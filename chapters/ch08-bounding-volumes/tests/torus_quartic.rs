//! Exercise 3: the torus quartic's coefficients, checked against the
//! torus's implicit function at the ray's points.
mod common;
use ch08::{DVec3, Ray, horner, torus_quartic};
use common::Rng;
use raystep_check::Table;

/// The implicit function f = (x² + y² + z² + R² − r²)² − 4R²(x² + z²)
/// at p, and the size of its terms (for a relative tolerance).
fn implicit(major: f64, minor: f64, p: DVec3) -> (f64, f64) {
    let (rr, across) = (major * major, p.x * p.x + p.z * p.z);
    let e = p.length_squared() + rr - minor * minor;
    let size = (p.length_squared() + rr + minor * minor).powi(2);
    (e * e - 4.0 * rr * across, size)
}

/// On 500 seeded tori and rays (directions of any length, origins inside
/// and outside the torus), the polynomial with the returned coefficients
/// (lowest degree first) equals f at ray.at(t) for t from −2 to 10,
/// within 1e-12 of the size of f's terms.
#[test]
fn the_quartic_is_f_along_the_ray() {
    let mut rng = Rng::new(8);
    for case in 0..500 {
        let major = rng.uniform(0.5, 3.0);
        let minor = major * rng.uniform(0.05, 0.95);
        let origin = DVec3::new(
            rng.uniform(-5.0, 5.0),
            rng.uniform(-5.0, 5.0),
            rng.uniform(-5.0, 5.0),
        );
        let direction = DVec3::new(
            rng.uniform(-1.0, 1.0),
            rng.uniform(-1.0, 1.0),
            rng.unit(),
        ) * rng.uniform(0.2, 3.0);
        let ray = Ray::new(origin, direction);
        let c = torus_quartic(major, minor, &ray);
        for t in [-2.0, 0.0, 0.37, 1.0, 2.5, 10.0] {
            let (want, size) = implicit(major, minor, ray.at(t));
            let got = horner(&c, t);
            let tolerance = 1e-12
                * size.max(
                    (origin.length() + t.abs() * direction.length())
                        .powi(2)
                        .powi(2),
                );
            assert!(
                (got - want).abs() <= tolerance,
                "case {case}: torus R = {major}, r = {minor}, ray {ray:?}: \
                 the quartic {c:?} (lowest degree first) at t = {t} is {got}, \
                 but f at ray.at(t) is {want}"
            );
        }
    }
}

/// The coefficients to 6 significant digits (0 when below 1e-12 of the
/// largest), so that any correct order of operations gives the same text.
fn coefficient(x: f64, largest: f64) -> String {
    if x.abs() <= 1e-12 * largest {
        "0".to_string()
    } else {
        format!("{x:.5e}")
    }
}

/// c₀ … c₃ for a few rays with unit directions (c₄ = |D|⁴ = 1), against
/// two tori. c₀ is f at the origin: 63.59 for the first ray, from
/// (−3, 0.1, 0.2), and the torus R = 1, r = 0.25. From the centre the
/// quartic is even in t (c₁ = c₃ = 0) and c₀ = (R² − r²)².
#[test]
fn coefficient_table() {
    let rays = [
        (DVec3::new(-3.0, 0.1, 0.2), DVec3::new(1.0, 0.03, -0.02)),
        (DVec3::new(0.2, 2.0, -0.1), DVec3::new(0.1, -1.0, 0.07)),
        (DVec3::new(0.0, 0.0, 0.0), DVec3::new(0.8, 0.1, 0.6)),
        (DVec3::new(5.0, 1.0, -4.0), DVec3::new(-0.7, -0.2, 0.6)),
        (DVec3::new(120.0, 35.0, -80.0), DVec3::new(-1.2, -0.33, 0.8)),
    ];
    let mut table = Table::new(&[
        "R",
        "r",
        "origin",
        "direction (normalised)",
        "c0",
        "c1",
        "c2",
        "c3",
    ]);
    for (major, minor) in [(1.0, 0.25), (2.0, 1.5)] {
        for (origin, direction) in rays {
            let ray = Ray::new(origin, direction.normalize());
            let c = torus_quartic(major, minor, &ray);
            assert!(
                (c[4] - 1.0).abs() < 1e-12,
                "c4 = |D|⁴ = 1 for a unit direction, got {c:?} (lowest degree \
                 first?)"
            );
            let largest = c.iter().fold(0.0f64, |m, x| m.max(x.abs()));
            let mut row = vec![
                major.to_string(),
                minor.to_string(),
                format!("{origin}"),
                format!("{direction}"),
            ];
            row.extend(c[..4].iter().map(|&x| coefficient(x, largest)));
            table.row(&row);
        }
    }
    insta::assert_snapshot!(table.to_string());
}
