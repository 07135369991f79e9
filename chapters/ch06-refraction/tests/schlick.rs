//! Exercise 2: Schlick's approximation of the Fresnel reflectance, against
//! the exact equations.
use ch06::{REFRACTIVE_INDICES, critical_angle, fresnel, schlick};
use proptest::prelude::*;
use raystep_check::{Table, num, num_places, seeded};

const ANGLES: [f64; 5] = [0.0, 30.0, 60.0, 80.0, 89.0];

/// R by the exact equations and by Schlick, side by side ("exact /
/// Schlick"), for each material of the table, into it from vacuum and out
/// of it into vacuum, at θ = 0°, 30°, 60°, 80° and 89°.
#[test]
fn reflectance_table() {
    let mut header = vec!["material".to_string(), "way".to_string()];
    header.extend(ANGLES.iter().map(|a| format!("R at {a}°: exact / Schlick")));
    let mut table = Table::new(&header);
    for (name, ior) in REFRACTIVE_INDICES {
        for (way, n_theta, n_phi) in [("in", 1.0, ior), ("out", ior, 1.0)] {
            let mut row = vec![name.to_string(), way.to_string()];
            row.extend(ANGLES.iter().map(|a| {
                let c = a.to_radians().cos();
                format!(
                    "{} / {}",
                    num(fresnel(c, n_theta, n_phi)),
                    num(schlick(c, n_theta, n_phi))
                )
            }));
            table.row(&row);
        }
    }
    insta::assert_snapshot!(table.to_string());
}

/// The largest |Schlick − exact| over θ from 0° to 90° in 0.001° steps,
/// and the θ where it is.
fn largest_error(n_theta: f64, n_phi: f64) -> (f64, f64) {
    (0..=90_000)
        .map(|i| {
            let theta = (f64::from(i) * 0.001).to_radians();
            let c = theta.cos();
            let error =
                (schlick(c, n_theta, n_phi) - fresnel(c, n_theta, n_phi)).abs();
            (error, theta.to_degrees())
        })
        .fold((0.0, 0.0), |best, e| if e.0 > best.0 { e } else { best })
}

/// How far Schlick is from the exact R at worst, for each material, both
/// ways.
///
/// Into and out of a material the largest error is the same: leaving the
/// denser side Schlick takes the angle on the less dense side, and the
/// exact R is the same for a ray and its reverse. So the "out" error peaks
/// just below the critical angle at the same size as the "in" error near
/// grazing.
///
/// For every material denser than air it is at most 0.0754 (diamond);
/// 0.033 for quartz, 0.036 for glass, 0.060 for water, 0.066 for ice. Not
/// monotonic in n: the error is large for the small steps of ice and
/// water, smallest around glass, and large again for diamond. Between
/// (almost) equal indices Schlick fails (see `index_matched_surfaces`).
#[test]
fn largest_error_table() {
    let mut table =
        Table::new(&["material", "way", "largest error", "at θ (°)"]);
    for (name, ior) in REFRACTIVE_INDICES {
        let (in_error, in_at) = largest_error(1.0, ior);
        let (out_error, out_at) = largest_error(ior, 1.0);
        // (the two sweeps sample the curve at different points near the
        // peak, hence the 1e-6)
        assert!(
            (in_error - out_error).abs() < 1e-6,
            "{name} (n = {ior}): expected the same largest error into it and \
             out of it (leaving, Schlick takes the angle on the less dense \
             side), got {in_error} in (at θ = {in_at}°) and {out_error} out \
             (at θ = {out_at}°)"
        );
        if ior > 1.1 {
            assert!(
                in_error <= 0.08 && out_error <= 0.08,
                "{name} (n = {ior}): expected Schlick within 0.08 of the \
                 exact R, got {in_error} off in (at θ = {in_at}°) and \
                 {out_error} out (at θ = {out_at}°)"
            );
        }
        for (way, error, at) in
            [("in", in_error, in_at), ("out", out_error, out_at)]
        {
            table.row(&[
                name.to_string(),
                way.to_string(),
                num(error),
                num_places(at, 1),
            ]);
        }
    }
    insta::assert_snapshot!(table.to_string());
}

/// Between (almost) equal indices Schlick is far off near grazing: the
/// exact R is 0 for n_θ = n_φ (there is no surface) and small for vacuum
/// into air, but (1 − cos θ)⁵ with R₀ ≈ 0 still climbs to 0.92 at 89°.
/// Schlick's curve keeps its shape whatever the step in index; the exact
/// one rises later the smaller the step.
#[test]
fn index_matched_surfaces() {
    let c = 89f64.to_radians().cos();
    assert!(fresnel(c, 1.0, 1.0) < 1e-20, "the exact R for n = 1 into 1");
    assert!(
        fresnel(c, 1.0, 1.0003) < 0.1,
        "the exact R for vacuum into air"
    );
    for n_phi in [1.0, 1.0003] {
        // R₀ is 0 or 2.2e-8 here: Schlick is (1 − cos 89°)⁵ = 0.91573…
        let got = schlick(c, 1.0, n_phi);
        assert!(
            (got - 0.915_731_1).abs() < 1e-6,
            "schlick(cos 89°, 1, {n_phi}): expected 0.9157311 (R₀ is \
             about 0, so R is (1 − cos 89°)⁵), got {got}"
        );
    }
}

/// The indices of two media, one denser than the other, and which is
/// the ray's.
fn indices() -> impl Strategy<Value = (f64, f64)> {
    (1.0..2.5f64, 1.0..2.5f64)
}

proptest! {
    #![proptest_config(seeded(512))]

    /// At normal incidence Schlick is R₀, the exact reflectance there
    /// (`fresnel`, the reference's exact equations, tested on their own in
    /// `tests/fresnel_and_media.rs`).
    #[test]
    fn normal_incidence_is_r0((n_theta, n_phi) in indices()) {
        let (exact, got) = (fresnel(1.0, n_theta, n_phi), schlick(1.0, n_theta, n_phi));
        prop_assert!((got - exact).abs() <= 1e-12, "schlick(cos θ = 1, {n_theta}, {n_phi}): expected R₀ = {exact} (the exact reflectance at normal incidence), got {got}");
    }

    /// R is a fraction, and never drops as θ grows (the light glances off
    /// more and more), whichever side the ray is on.
    #[test]
    fn between_0_and_1_and_rising(
        (n_theta, n_phi) in indices(),
        a in 0.0..90.0f64,
        b in 0.0..90.0f64,
    ) {
        let (low, high) = (a.min(b).to_radians(), a.max(b).to_radians());
        let (r_low, r_high) = (
            schlick(low.cos(), n_theta, n_phi),
            schlick(high.cos(), n_theta, n_phi),
        );
        for (theta, r) in [(low, r_low), (high, r_high)] {
            prop_assert!((0.0..=1.0).contains(&r), "schlick(cos {:.4}°, {n_theta}, {n_phi}): expected R between 0 and 1, got {r}", theta.to_degrees());
        }
        prop_assert!(r_high >= r_low - 1e-15, "n_θ = {n_theta}, n_φ = {n_phi}: expected R to rise with θ, got R({:.4}°) = {r_low} > R({:.4}°) = {r_high}", low.to_degrees(), high.to_degrees());
    }

    /// Past the critical angle all the light is reflected: R = 1. Just
    /// below it R < 1 (the light still gets out).
    #[test]
    fn one_past_the_critical_angle((a, b) in indices(), past in 1e-6..1.0f64) {
        let (n_theta, n_phi) = (a.max(b), a.min(b));
        prop_assume!(n_theta > n_phi * 1.001);
        let critical = critical_angle(n_theta, n_phi).unwrap();
        let theta = critical + past * (std::f64::consts::FRAC_PI_2 - critical);
        let r_past = schlick(theta.cos(), n_theta, n_phi);
        prop_assert!(r_past >= 1.0 - 1e-12, "schlick(cos {:.4}°, {n_theta}, {n_phi}), past the critical angle {:.4}°: expected R = 1 (total internal reflection), got {r_past}", theta.to_degrees(), critical.to_degrees());
        let before = critical * (1.0 - past);
        let r_before = schlick(before.cos(), n_theta, n_phi);
        prop_assert!(r_before < 1.0, "schlick(cos {:.4}°, {n_theta}, {n_phi}), below the critical angle {:.4}°: expected R < 1 (light still gets out), got {r_before}", before.to_degrees(), critical.to_degrees());
    }
}
