//! Exercise 3: the local illumination model.
use ch03::{DVec3, LightSample, Material, shading_terms};
use proptest::prelude::*;
use raystep_check::{Table, seeded, unit_vector, vec3};

fn v(x: f64, y: f64, z: f64) -> DVec3 {
    DVec3::new(x, y, z)
}

fn material(kd: f64, ks: f64, p: f64) -> Material {
    Material {
        name: "test".to_string(),
        ka: v(0.2, 0.1, 0.1),
        kd: v(kd, kd * 0.5, kd * 0.25),
        ks: DVec3::splat(ks),
        p,
        ..Material::default()
    }
}

fn light(direction: DVec3, intensity: f64) -> LightSample {
    LightSample {
        direction: direction.normalize(),
        intensity: DVec3::splat(intensity),
        visibility: 1.0,
    }
}

/// Each term on its own, for lights overhead, at 60°, behind the surface,
/// in shadow, and a highlight seen straight on and off to the side.
#[test]
fn shading_table() {
    let n = v(0.0, 1.0, 0.0);
    let eye_above = v(0.0, 1.0, 0.0);
    let eye_side = v(1.0, 1.0, 0.0).normalize();
    let ambient = DVec3::splat(0.5);
    let m = material(0.8, 0.4, 10.0);
    #[rustfmt::skip]
    let cases = [
        ("no lights", eye_above, vec![]),
        ("overhead", eye_above, vec![light(v(0.0, 1.0, 0.0), 1.0)]),
        ("60° incidence", eye_above, vec![light(v(3f64.sqrt(), 1.0, 0.0), 1.0)]),
        ("behind surface", eye_above, vec![light(v(0.0, -1.0, 0.0), 1.0)]),
        ("in shadow (S=0)", eye_above, vec![LightSample { visibility: 0.0, ..light(v(0.0, 1.0, 0.0), 1.0) }]),
        ("highlight off-axis", eye_side, vec![light(v(-1.0, 1.0, 0.0), 1.0)]),
        ("two lights", eye_above, vec![light(v(0.0, 1.0, 0.0), 0.5), light(v(1.0, 1.0, 0.0), 2.0)]),
    ];
    let mut table =
        Table::new(&["case", "ambient", "diffuse", "specular", "L"]);
    for (name, eye, lights) in cases {
        let t = shading_terms(&m, n, eye, ambient, &lights);
        table.row(&[
            name.to_string(),
            vec3(t.ambient),
            vec3(t.diffuse),
            vec3(t.specular),
            vec3(t.sum()),
        ]);
    }
    insta::assert_snapshot!(table.to_string());
}

/// A light behind the surface (N·L < 0) or exactly along it (N·L = 0)
/// adds nothing: no diffuse light, and no highlight either, although its
/// mirrored direction R points toward this eye (R·V > 0).
#[test]
fn lights_behind_or_along_the_surface_add_nothing() {
    let n = v(0.0, 1.0, 0.0);
    let m = material(0.8, 0.4, 10.0);
    #[rustfmt::skip]
    let cases = [
        ("a light just behind the surface, seen from a grazing eye",
            v(1.0, -0.1, 0.0), v(-1.0, 0.1, 0.0)),
        ("a light exactly along the surface (N·L = 0)",
            v(1.0, 0.0, 0.0), v(-1.0, 1.0, 0.0)),
    ];
    for (name, l, eye) in cases {
        let (l, eye) = (l.normalize(), eye.normalize());
        let t = shading_terms(&m, n, eye, DVec3::ZERO, &[light(l, 1.0)]);
        assert!(
            t.diffuse == DVec3::ZERO && t.specular == DVec3::ZERO,
            "{name}: N = {n}, L = {l}, V = {eye}, N·L = {:.4}: expected no \
             diffuse and no specular light (skip a light with N·L ≤ 0 \
             entirely), got diffuse {} and specular {}",
            n.dot(l),
            vec3(t.diffuse),
            vec3(t.specular)
        );
    }
}

/// The exponent p of the highlight need not be a whole number: with
/// R·V = 1/√2 and p = 2.5 the highlight is ks·(1/√2)^2.5 = 0.4·0.42045.
#[test]
fn a_highlight_with_a_fractional_exponent() {
    let n = v(0.0, 1.0, 0.0);
    let m = material(0.0, 0.4, 2.5);
    // L at 45° from the left: R at 45° to the right, 45° from V = N
    let l = v(-1.0, 1.0, 0.0).normalize();
    let t = shading_terms(&m, n, n, DVec3::ZERO, &[light(l, 1.0)]);
    let expected = 0.4 * 0.5f64.sqrt().powf(2.5);
    assert!(
        (t.specular - DVec3::splat(expected)).abs().max_element() <= 1e-12,
        "ks = 0.4, p = 2.5, R·V = 1/√2: expected a specular term of \
         ks·(R·V)^p = {expected:.6} in every channel (p is not rounded to a \
         whole number), got {}",
        vec3(t.specular)
    );
}

proptest! {
    #![proptest_config(seeded(256))]

    /// Light is never negative, and the diffuse term grows with kd·(N·L):
    /// turning the light toward the normal, or raising kd, never darkens.
    #[test]
    fn non_negative_and_monotone_in_kd_n_dot_l(
        n in unit_vector(), l in unit_vector(), eye in unit_vector(), kd in 0.0..1.0f64, ks in 0.0..1.0f64, p in 1.0..100.0f64
    ) {
        let m = material(kd, ks, p);
        let t = shading_terms(&m, n, eye, DVec3::splat(0.2), &[light(l, 1.0)]);
        let what = format!("N = {n}, L = {l}, V = {eye}, kd = {kd}, ks = {ks}, p = {p}");
        for (term, value) in [("ambient", t.ambient), ("diffuse", t.diffuse), ("specular", t.specular)] {
            prop_assert!(value.min_element() >= 0.0, "{what}: expected a {term} term ≥ 0 in every channel (light is never negative), got {value}");
        }
        // a light halfway toward the normal: N·L at least as large
        let closer = (l + n).normalize();
        let t_closer = shading_terms(&m, n, eye, DVec3::ZERO, &[light(closer, 1.0)]);
        prop_assert!(t_closer.diffuse.x >= t.diffuse.x - 1e-12, "{what}: the light turned halfway toward N (L = {closer}): expected at least as much diffuse light as {}, got {}", t.diffuse.x, t_closer.diffuse.x);
        // more kd, more diffuse
        let brighter = shading_terms(&material((kd + 0.1).min(1.0), ks, p), n, eye, DVec3::ZERO, &[light(l, 1.0)]);
        prop_assert!(brighter.diffuse.x >= t.diffuse.x, "{what}: kd raised by 0.1: expected at least as much diffuse light as {}, got {}", t.diffuse.x, brighter.diffuse.x);
    }
}
