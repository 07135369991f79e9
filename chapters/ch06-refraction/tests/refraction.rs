//! Exercise 1: the refracted direction T, by Snell's law.
use ch06::{DVec3, REFRACTIVE_INDICES, critical_angle, refract};
use proptest::prelude::*;
use raystep_check::held_out::Rng;
use raystep_check::{Table, num_places, seeded, unit_vector};

const INCIDENCE_DEGREES: [f64; 7] = [0.0, 15.0, 30.0, 45.0, 60.0, 75.0, 89.0];

/// The incoming direction at angle θ (radians) to the normal N = +y, moving
/// right and down: D = (sin θ, −cos θ, 0).
fn incoming(theta: f64) -> DVec3 {
    DVec3::new(theta.sin(), -theta.cos(), 0.0)
}

/// φ of T, in degrees, measured from −N = −y toward +x (the side D moves
/// to): a correct T has 0 ≤ φ < 90. A T on the near side of the surface
/// shows φ > 90, one bent back across the normal shows φ < 0.
fn phi_degrees(t: DVec3) -> f64 {
    t.x.atan2(-t.y).to_degrees()
}

/// φ of T in degrees (or "none"), right-aligned in 7 characters: any φ
/// from −180° to 180° fits, so a wrong T changes its own cell and not the
/// width of the column (and the first differing line is its row).
fn cell(t: Option<DVec3>) -> String {
    let text = t.map_or("none".to_string(), |t| num_places(phi_degrees(t), 2));
    format!("{text:>7}")
}

/// φ in degrees for each material of the table, entering it from vacuum and
/// leaving it into vacuum, at θ = 0°, 15°, …, 89°. Leaving, past the
/// critical angle, there is no T: total internal reflection ("none").
#[test]
fn refraction_table() {
    let mut header =
        vec!["material".to_string(), "n".to_string(), "way".to_string()];
    header.extend(INCIDENCE_DEGREES.iter().map(|d| format!("φ at θ={d}°")));
    let mut table = Table::new(&header);
    let n = DVec3::Y;
    for (name, ior) in REFRACTIVE_INDICES {
        for (way, n_theta, n_phi) in [("in", 1.0, ior), ("out", ior, 1.0)] {
            let mut row =
                vec![name.to_string(), ior.to_string(), way.to_string()];
            row.extend(INCIDENCE_DEGREES.iter().map(|&degrees| {
                cell(refract(incoming(degrees.to_radians()), n, n_theta, n_phi))
            }));
            table.row(&row);
        }
    }
    insta::assert_snapshot!(table.to_string());
}

/// The critical angle of each material into vacuum, and refract on either
/// side of it: 0.01° below it there is a T, 0.01° above it there is none.
/// (From vacuum into the material there is no critical angle: every
/// angle refracts.)
#[test]
fn critical_angle_table() {
    let mut table = Table::new(&[
        "material",
        "n",
        "θc out (°)",
        "φ at θc − 0.01°",
        "T at θc + 0.01°",
    ]);
    for (name, ior) in REFRACTIVE_INDICES {
        let (out, into) = (critical_angle(ior, 1.0), critical_angle(1.0, ior));
        let (out_deg, below, above) = match out {
            Some(c) => {
                let step = 0.01f64.to_radians();
                (
                    num_places(c.to_degrees(), 2),
                    cell(refract(incoming(c - step), DVec3::Y, ior, 1.0)),
                    cell(refract(incoming(c + step), DVec3::Y, ior, 1.0)),
                )
            }
            None => {
                ("none".into(), format!("{:>7}", "-"), format!("{:>7}", "-"))
            }
        };
        assert_eq!(into, None, "{name}: no critical angle going into it");
        table.row(&[name.to_string(), ior.to_string(), out_deg, below, above]);
    }
    insta::assert_snapshot!(table.to_string());
}

/// A random ray hitting a random surface from its front: (D, N) with
/// N·D < 0, and two indices of refraction in [1, 2.5].
fn crossing() -> impl Strategy<Value = (DVec3, DVec3, f64, f64)> {
    (unit_vector(), unit_vector(), 1.0..2.5f64, 1.0..2.5f64)
        .prop_filter("not tangent", |(d, n, _, _)| d.dot(*n).abs() > 1e-9)
        .prop_map(|(d, n, a, b)| (d, if d.dot(n) > 0.0 { -n } else { n }, a, b))
}

/// sin θ for unit D and N: the length of D's part along the surface.
fn sin_between(a: DVec3, n: DVec3) -> f64 {
    a.cross(n).length()
}

proptest! {
    #![proptest_config(seeded(512))]

    /// Wherever T exists: it is a unit vector, in the plane of D and N, on
    /// the far side of the surface (T·N < 0), and Snell's law holds,
    /// n_θ sin θ = n_φ sin φ.
    #[test]
    fn snells_law_holds((d, n, n_theta, n_phi) in crossing()) {
        let Some(t) = refract(d, n, n_theta, n_phi) else {
            return Ok(());
        };
        let what = format!("refract(D = {d}, N = {n}, n_θ = {n_theta}, n_φ = {n_phi}) = T = {t}");
        prop_assert!((t.length() - 1.0).abs() <= 1e-12, "{what}: expected a unit T, got |T| = {}", t.length());
        prop_assert!(t.dot(d.cross(n)).abs() <= 1e-12, "{what}: expected T in the plane of D and N, got T·(D×N) = {}", t.dot(d.cross(n)));
        prop_assert!(t.dot(n) < 0.0, "{what}: expected T on the far side of the surface (T·N < 0), got T·N = {}", t.dot(n));
        let (lhs, rhs) = (n_theta * sin_between(d, n), n_phi * sin_between(t, n));
        prop_assert!((lhs - rhs).abs() <= 1e-12, "{what}: expected Snell's law n_θ sin θ = n_φ sin φ, got n_θ sin θ = {lhs}, n_φ sin φ = {rhs}");
        // and T goes on along the surface the way D did (not bent back
        // across the normal)
        prop_assert!(t.dot(d) > 0.0, "{what}: expected T to go on the way D goes (T·D > 0), got T·D = {}: bent back across the normal", t.dot(d));
    }

    /// Total internal reflection exactly when sin θ > n_φ/n_θ (away from a
    /// relative 1e-9 of the boundary, where the rounding of sin θ decides).
    #[test]
    fn none_exactly_past_the_critical_angle((d, n, n_theta, n_phi) in crossing()) {
        let (sin_theta, limit) = (sin_between(d, n), n_phi / n_theta);
        let t = refract(d, n, n_theta, n_phi);
        let what = format!("refract(D = {d}, N = {n}, n_θ = {n_theta}, n_φ = {n_phi})");
        if sin_theta > limit * (1.0 + 1e-9) {
            prop_assert!(t.is_none(), "{what}: sin θ = {sin_theta} > n_φ/n_θ = {limit}: expected None (total internal reflection), got {t:?}");
        } else if sin_theta < limit * (1.0 - 1e-9) {
            prop_assert!(t.is_some(), "{what}: sin θ = {sin_theta} < n_φ/n_θ = {limit}: expected a T, got None");
        }
    }

    /// Between equal indices nothing bends: T = D.
    #[test]
    fn equal_indices_do_not_bend((d, n, ior, _) in crossing()) {
        let t = refract(d, n, ior, ior);
        prop_assert!(t.is_some(), "refract(D = {d}, N = {n}, {ior}, {ior}): expected T = D (equal indices), got None");
        let t = t.unwrap();
        prop_assert!((t - d).length() <= 1e-9, "refract(D = {d}, N = {n}, {ior}, {ior}): expected T = D (equal indices do not bend), got T = {t}");
    }
}

/// A uniformly random unit vector: a point of the cube [−1, 1]³ inside
/// the unit ball (and not at its centre), normalised.
fn direction(rng: &mut Rng) -> DVec3 {
    loop {
        let p = rng.vec3(1.0);
        let l2 = p.length_squared();
        if l2 > 1e-4 && l2 <= 1.0 {
            return p / l2.sqrt();
        }
    }
}

/// `count` random surfaces (N, and a unit tangent U ⟂ N), the same ones on
/// every run.
fn random_frames(count: usize) -> Vec<(DVec3, DVec3)> {
    let mut rng = Rng::new(0x5EED_2026);
    (0..count)
        .map(|_| {
            let n = direction(&mut rng);
            let u = n.cross(direction(&mut rng)).normalize();
            (n, u)
        })
        .collect()
}

/// The ray at angle θ to N in a random frame: D = sin θ·U − cos θ·N.
fn at_angle(n: DVec3, u: DVec3, theta: f64) -> DVec3 {
    (theta.sin() * u - theta.cos() * n).normalize()
}

/// Rays leaving water, glass and diamond into vacuum at their critical
/// angle θc and 1e-6 rad either side, over 1000 random orientations each.
///
/// 1e-6 rad below θc, sin²φ = 1 − 2e-6·√(n² − 1) or so: 1.7e-6 to 4.3e-6
/// below 1, a billion times the rounding error. Every ray refracts, at
/// φ ≈ 89.9°. 1e-6 rad above, every ray is reflected totally. At θc
/// itself sin²φ is 1 up to rounding: some rays come out as None, the
/// rest as a T grazing the surface (|T·N| = cos φ below 1e-7, the square
/// root of a few ulps), both right answers; none is a NaN or a T pointing
/// anywhere else. Which rays go which way depends on the last bits of
/// sin²φ, so only the two outcomes are asserted, not how many take each.
#[test]
fn at_and_around_the_critical_angle() {
    let frames = random_frames(1000);
    for (name, ior) in [("water", 1.33), ("glass", 1.5), ("diamond", 2.417)] {
        let critical = critical_angle(ior, 1.0).unwrap();
        let refracted = |theta: f64| {
            frames
                .iter()
                .map(|&(n, u)| (n, refract(at_angle(n, u, theta), n, ior, 1.0)))
                .collect::<Vec<_>>()
        };
        let below = refracted(critical - 1e-6);
        let wrong_below = below.iter().find(|(n, t)| {
            !t.is_some_and(|t| {
                (t.length() - 1.0).abs() < 1e-12 && t.dot(*n) < -1e-4
            })
        });
        assert!(
            wrong_below.is_none(),
            "{name} (n = {ior}) into vacuum, 1e-6 rad below the critical \
             angle {critical}: expected a unit T through the surface (T·N < \
             -1e-4), got {:?} for N = {}",
            wrong_below.unwrap().1,
            wrong_below.unwrap().0
        );
        let above = refracted(critical + 1e-6);
        let wrong_above = above.iter().find(|(_, t)| t.is_some());
        assert!(
            wrong_above.is_none(),
            "{name} (n = {ior}) into vacuum, 1e-6 rad past the critical angle \
             {critical}: expected None (total internal reflection), got \
             {:?} for N = {}",
            wrong_above.unwrap().1,
            wrong_above.unwrap().0
        );
        let at = refracted(critical);
        for (n, t) in &at {
            if let Some(t) = t {
                assert!(
                    (t.length() - 1.0).abs() < 1e-12,
                    "{name} (n = {ior}) at its critical angle: expected None \
                     or a unit T, got {t} of length {}",
                    t.length()
                );
                assert!(
                    t.dot(*n).abs() < 1e-7,
                    "{name} (n = {ior}) at its critical angle: expected None \
                     or a T grazing the surface (|T·N| < 1e-7), got T·N = {}",
                    t.dot(*n)
                );
            }
        }
        // The reference: 826 (water), 864 (glass) and 695 (diamond) of the
        // 1000 rays refract, with cos φ at most 2.8e-8, 3.9e-8 and 6.4e-8.
        let some = at.iter().filter(|(_, t)| t.is_some()).count();
        println!(
            "{name}: at θc, {some} of 1000 refract (grazing), the rest reflect totally"
        );
    }
}

/// Entering a denser medium at grazing incidence, θ → 90°: T stays a finite
/// unit vector that obeys Snell's law, and φ tends to the critical angle
/// of the way back (light is reversible: what grazes in leaves at θc).
#[test]
fn grazing_incidence_from_the_less_dense_side() {
    let frames = random_frames(100);
    for (_, ior) in REFRACTIVE_INDICES {
        let limit =
            critical_angle(ior, 1.0).unwrap_or(std::f64::consts::FRAC_PI_2);
        for k in 1..=12 {
            // θ = 90° − 10⁻ᵏ rad, and exactly 90° (D along the surface)
            for gap in [10f64.powi(-k), 0.0] {
                let theta = std::f64::consts::FRAC_PI_2 - gap;
                for &(n, u) in &frames {
                    let d = at_angle(n, u, theta);
                    let what = format!(
                        "refract(D = {d}, N = {n}, 1, {ior}) at θ = 90° − \
                         {gap:e} rad"
                    );
                    let Some(t) = refract(d, n, 1.0, ior) else {
                        panic!(
                            "{what}: expected a T (entering a denser medium \
                             never reflects totally), got None"
                        );
                    };
                    assert!(
                        t.is_finite(),
                        "{what}: expected a finite T, got {t}"
                    );
                    assert!(
                        (t.length() - 1.0).abs() < 1e-12,
                        "{what}: expected a unit T, got {t} of length {}",
                        t.length()
                    );
                    // (at exactly 90° into vacuum, T = D grazes the surface:
                    // T·N is D·N, a rounding error either side of 0)
                    assert!(
                        t.dot(n) <= 1e-15,
                        "{what}: expected T through the surface (T·N ≤ 0), \
                         got T·N = {}",
                        t.dot(n)
                    );
                    let (lhs, rhs) =
                        (sin_between(d, n), ior * sin_between(t, n));
                    assert!(
                        (lhs - rhs).abs() < 1e-12,
                        "{what}: expected Snell's law sin θ = n sin φ, got \
                         sin θ = {lhs}, n sin φ = {rhs}"
                    );
                    // φ is θc within the gap (dφ/dθ ≤ 1 up here) and a few
                    // ulps of angle (near 90°, where vacuum takes φ = θ, a few ulps
                    // of sin φ are 2e-8 rad of φ)
                    let phi = sin_between(t, n).min(1.0).asin();
                    let tolerance = if ior == 1.0 { 1e-7 } else { 1e-9 };
                    assert!(
                        (phi - limit).abs() <= gap + tolerance,
                        "{what}: expected φ within {gap:e} rad of the \
                         critical angle {limit} (what grazes in leaves at \
                         θc), got φ = {phi}"
                    );
                }
            }
        }
    }
}
