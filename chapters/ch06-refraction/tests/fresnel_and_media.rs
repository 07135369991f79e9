//! The reference-only pieces of the chapter: the exact Fresnel equations,
//! the split of a ray's weight between reflection and transmission, and
//! the stack of media a ray is in.
use ch06::{DVec3, MAX_NESTING, Media, critical_angle, fresnel, split};
use proptest::prelude::*;
use raystep_check::seeded;

/// The transmittance T by another route than `fresnel`'s: from the
/// transmission amplitudes tₛ = 2n₁cos θ/(n₁cos θ + n₂cos φ) and
/// tₚ = 2n₁cos θ/(n₂cos θ + n₁cos φ), and the flux through the surface,
/// T = (n₂cos φ)/(n₁cos θ)·t². φ comes from the angle, asin(n₁sin θ/n₂).
fn transmittance(theta: f64, n1: f64, n2: f64) -> f64 {
    let phi = (n1 * theta.sin() / n2).asin();
    let (ct, cp) = (theta.cos(), phi.cos());
    // (n₂cos φ)/(n₁cos θ)·(2n₁cos θ)²/den² = 4n₁n₂cos θ cos φ/den²
    let flux = |den: f64| 4.0 * n1 * n2 * ct * cp / (den * den);
    0.5 * (flux(n1 * ct + n2 * cp) + flux(n2 * ct + n1 * cp))
}

proptest! {
    #![proptest_config(seeded(512))]

    /// What is not reflected is transmitted: R from the reflection
    /// amplitudes plus T from the transmission amplitudes is 1 (energy is
    /// conserved at the surface). Below the critical angle, both ways.
    #[test]
    fn reflectance_plus_transmittance_is_one(
        n1 in 1.0..2.5f64, n2 in 1.0..2.5f64, s in 0.0..1.0f64,
    ) {
        // θ anywhere up to 90° or up to the critical angle
        let top = critical_angle(n1, n2).unwrap_or(std::f64::consts::FRAC_PI_2);
        let theta = s * top;
        let r = fresnel(theta.cos(), n1, n2);
        let t = transmittance(theta, n1, n2);
        prop_assert!((r + t - 1.0).abs() <= 1e-12, "R = {r}, T = {t}");
        prop_assert!((0.0..=1.0).contains(&r));
    }

    /// Light is reversible: the ray coming back along T sees the same
    /// reflectance, R(θ; n₁ → n₂) = R(φ; n₂ → n₁).
    #[test]
    fn the_way_back_reflects_the_same(
        n1 in 1.0..2.5f64, n2 in 1.0..2.5f64, s in 0.0..1.0f64,
    ) {
        let top = critical_angle(n1, n2).unwrap_or(std::f64::consts::FRAC_PI_2);
        let theta = s * top;
        let phi = (n1 * theta.sin() / n2).asin();
        let (there, back) = (fresnel(theta.cos(), n1, n2), fresnel(phi.cos(), n2, n1));
        prop_assert!((there - back).abs() <= 1e-9, "{there} vs {back}");
    }

    /// Past the critical angle everything is reflected: R = 1 exactly.
    #[test]
    fn all_reflected_past_the_critical_angle(
        a in 1.0..2.5f64, b in 1.0..2.5f64, s in 1e-9..1.0f64,
    ) {
        let (n1, n2) = (a.max(b), a.min(b));
        prop_assume!(n1 > n2);
        let critical = critical_angle(n1, n2).unwrap();
        let theta = critical + s * (std::f64::consts::FRAC_PI_2 - critical);
        prop_assume!((n1 / n2 * theta.sin()) > 1.0);
        prop_assert_eq!(fresnel(theta.cos(), n1, n2), 1.0);
    }

    /// Splitting a ray creates no light and takes none away:
    /// wr + wt = kr + kt in every channel, neither weight negative, for
    /// any reflectance R and with or without a transmitted ray.
    #[test]
    fn split_conserves_energy(
        kr in (0.0..1.0f64, 0.0..1.0f64, 0.0..1.0f64),
        share in (0.0..1.0f64, 0.0..1.0f64, 0.0..1.0f64),
        r in 0.0..=1.0f64,
        transmits: bool,
    ) {
        let kr = DVec3::new(kr.0, kr.1, kr.2);
        // kt ≤ 1 − kr per channel
        let kt = DVec3::new(share.0, share.1, share.2) * (DVec3::ONE - kr);
        let (wr, wt) = split(kr, kt, r, transmits);
        prop_assert!(((wr + wt) - (kr + kt)).abs().max_element() <= 1e-15, "{wr} + {wt} vs {kr} + {kt}");
        prop_assert!(wr.min_element() >= 0.0 && wt.min_element() >= 0.0);
        prop_assert!((wr + wt).max_element() <= 1.0 + 1e-15);
        if !transmits {
            prop_assert_eq!(wt, DVec3::ZERO);
        }
    }
}

/// R at normal incidence is ((n₁ − n₂)/(n₁ + n₂))², the same both ways:
/// 4 % for glass, 2 % for water, 17 % for diamond.
#[test]
fn normal_incidence() {
    for (n, r) in [(1.5, 0.04), (1.33, 0.02006), (2.417, 0.17197)] {
        assert!((fresnel(1.0, 1.0, n) - r).abs() < 1e-5, "{n}");
        assert!((fresnel(1.0, n, 1.0) - r).abs() < 1e-5, "{n}");
    }
    // no step in index, no reflection
    assert_eq!(fresnel(0.3, 1.33, 1.33), 0.0);
}

/// With the same index on both sides there is no surface: R = 0 at every
/// angle, grazing ones too. Computed as 1 − η²(1 − cos²θ), cos²φ would
/// lose cos²θ to rounding below cos θ ≈ 1e-8 (1 − cos²θ rounds to 1) and
/// report total reflection, R = 1; summed as (1 − η²) + η²cos²θ it is
/// cos²θ itself.
#[test]
fn index_matched_reflects_nothing_even_grazing() {
    for n in [1.0, 1.0003, 1.33, 1.5, 2.417] {
        for cos_theta in [1.0, 0.5, 0.1, 1e-4, 1e-8, 1e-9, 1e-12, 1e-15] {
            let r = fresnel(cos_theta, n, n);
            assert!(
                r <= 1e-30,
                "n = {n} on both sides, cos θ = {cos_theta:e}: expected \
                 R = 0 (no surface), got {r}"
            );
        }
    }
    // and beside it, a step in index still reflects: everything at 90°,
    // a little less just before
    assert_eq!(fresnel(0.0, 1.0, 1.5), 1.0);
    let r = fresnel(1e-9, 1.0, 1.5);
    assert!(r < 1.0 && r > 0.999_999, "{r}");
}

const WATER: f64 = 1.33;
const AIR: f64 = 1.0003;

/// A ray straight through the centre of an air bubble in a water ball
/// (object 0 the water, object 1 the bubble) crosses four surfaces. The
/// lecture's rule "leaving: swap the indices" would give air → vacuum at
/// the bubble's far side; the stack knows the ray is back in water.
#[test]
fn air_bubble_in_water() {
    let vacuum = Media::new(1.0);
    let steps = [
        (0, WATER, true, 1.0, WATER, vec![0]),
        (1, AIR, true, WATER, AIR, vec![0, 1]),
        (1, AIR, false, AIR, WATER, vec![0]),
        (0, WATER, false, WATER, 1.0, vec![]),
    ];
    let mut media = vacuum;
    for (object, ior, entering, n_theta, n_phi, inside) in steps {
        let c = media.cross(object, ior, entering);
        assert!(c.consistent, "{object} {entering}");
        assert_eq!((c.n_theta, c.n_phi), (n_theta, n_phi));
        assert_eq!(c.beyond.objects(), inside.as_slice());
        assert_eq!(c.beyond.current(), n_phi);
        media = c.beyond;
    }
    assert_eq!(media, vacuum, "back in the open, the stack is empty again");
}

/// Crossings that contradict the stack: leaving an object the ray is not
/// in, entering one it is already in. Each is reported, leaves the stack
/// as it was, and does not bend the ray (n_φ = n_θ).
#[test]
fn mismatches_are_reported_and_change_nothing() {
    let open = Media::new(1.0);
    let in_water = open.cross(0, WATER, true).beyond;
    for (media, object, ior, entering) in [
        (open, 0, WATER, false),    // leaving water from the open
        (in_water, 1, 1.5, false),  // leaving glass from inside water
        (in_water, 0, WATER, true), // entering the water again
    ] {
        let c = media.cross(object, ior, entering);
        assert!(!c.consistent, "{object} {entering}");
        assert_eq!(c.beyond, media);
        assert_eq!((c.n_theta, c.n_phi), (media.current(), media.current()));
    }
}

/// Up to MAX_NESTING objects inside each other; one more is reported as
/// inconsistent and not pushed, and the ray stays in the innermost.
#[test]
fn nesting_deeper_than_max_nesting_is_inconsistent() {
    let mut media = Media::new(1.0);
    for object in 0..MAX_NESTING {
        let c = media.cross(object, 1.1 + 0.1 * object as f64, true);
        assert!(c.consistent, "object {object}");
        media = c.beyond;
    }
    assert_eq!(media.objects().len(), MAX_NESTING);
    let c = media.cross(MAX_NESTING, 3.0, true);
    assert!(!c.consistent);
    assert_eq!(c.beyond, media);
    assert_eq!(c.n_phi, media.current());
    // leaving the innermost still works
    let c = media.cross(MAX_NESTING - 1, 0.0, false);
    assert!(c.consistent);
    assert_eq!(c.beyond.objects().len(), MAX_NESTING - 1);
}

/// Two overlapping balls, water (0) then glass (1): a ray enters water,
/// then glass, then leaves the water first (the balls overlap, they are
/// not nested). It is then in glass only; leaving the glass, in the open.
#[test]
fn overlapping_objects_are_left_in_any_order() {
    let open = Media::new(1.0);
    let both = open.cross(0, WATER, true).beyond.cross(1, 1.5, true).beyond;
    assert_eq!(both.objects(), &[0, 1]);
    let c = both.cross(0, WATER, false);
    assert!(c.consistent);
    assert_eq!(c.beyond.objects(), &[1], "the water is gone, not the glass");
    // still in glass: the surface separates glass from glass
    assert_eq!((c.n_theta, c.n_phi), (1.5, 1.5));
    let c = c.beyond.cross(1, 1.5, false);
    assert!(c.consistent);
    assert_eq!((c.n_theta, c.n_phi), (1.5, 1.0));
    assert_eq!(c.beyond, open);
}
