//! Exercise 1: the reflected direction R = D − 2(D·N)N.
use ch05::{DVec3, reflect_ray};
use proptest::prelude::*;
use raystep_check::{Table, num_places, seeded, unit_vector, vec3};

fn v(x: f64, y: f64, z: f64) -> DVec3 {
    DVec3::new(x, y, z)
}

/// The angle between two vectors in degrees, 0..=180.
fn degrees_between(a: DVec3, b: DVec3) -> f64 {
    (a.dot(b) / (a.length() * b.length()))
        .clamp(-1.0, 1.0)
        .acos()
        .to_degrees()
}

/// Four cases worked by hand (checked first: a wrong formula fails here
/// with the numbers to compare).
#[test]
fn hand_worked_cases() {
    #[rustfmt::skip]
    let cases = [
        // straight down onto the floor: straight back up
        ("straight down onto a floor", v(0.0, -1.0, 0.0), DVec3::Y, v(0.0, 1.0, 0.0)),
        // 45° onto the floor: the part along it is kept, the part along N flips
        ("45° onto a floor", v(1.0, -1.0, 0.0), DVec3::Y, v(1.0, 1.0, 0.0)),
        // grazing, along the surface: nothing to flip
        ("along a floor", v(0.0, 0.0, -3.0), DVec3::Y, v(0.0, 0.0, -3.0)),
        // onto a wall x = 0 from the right, N = +x: the x part flips
        ("onto a wall", v(-2.0, 1.0, -0.5), DVec3::X, v(2.0, 1.0, -0.5)),
    ];
    for (name, d, n, expected) in cases {
        let r = reflect_ray(d, n);
        assert!(
            (r - expected).length() <= 1e-15,
            "{name}: D = {d}, N = {n}: R should be {expected}, got {r}"
        );
    }
}

/// Incoming rays at angles of incidence θ from the normal (0°: straight
/// down onto the surface, 90°: grazing, along it), on a level floor and on
/// a tilted surface, both sides of its normal. R should leave at the same
/// angle θ on the other side of N, in the plane of D and N, as long as D.
#[test]
fn reflected_directions_table() {
    // (surface, N, T, side): the unit normal and a unit tangent along the
    // surface, in the plane the rays come in; the ray comes from the side
    // of N·side, and N is passed as it is ("N flipped": the same rays, the
    // normal given from the other side).
    let tilted = v(0.0, 0.6, 0.8);
    let surfaces = [
        ("floor", DVec3::Y, DVec3::X, 1.0),
        ("tilted", tilted, DVec3::X, 1.0),
        ("tilted, N flipped", -tilted, DVec3::X, -1.0),
        ("wall", DVec3::Z, v(0.6, 0.8, 0.0), 1.0),
    ];
    let angles = [0.0, 30.0, 45.0, 60.0, 89.0, 90.0];
    let mut table =
        Table::new(&["surface", "N", "θ in", "D", "R", "θ out", "|R|"]);
    for (name, n, tangent, side) in surfaces {
        for theta in angles {
            let (sin, cos) = f64::to_radians(theta).sin_cos();
            // toward the surface, against N·side; the wall's ray is twice
            // as long
            let length = if name == "wall" { 2.0 } else { 1.0 };
            let d = length * (sin * tangent - cos * side * n);
            let r = reflect_ray(d, n);
            // θ out: the angle between R and the side of N it leaves on
            // (the side D came from)
            let out_side = if d.dot(n) <= 0.0 { n } else { -n };
            table.row(&[
                name.to_string(),
                vec3(n),
                format!("{theta}°"),
                vec3(d),
                vec3(r),
                format!("{}°", num_places(degrees_between(r, out_side), 2)),
                num_places(r.length(), 4),
            ]);
        }
    }
    insta::assert_snapshot!(table.to_string());
}

proptest! {
    #![proptest_config(seeded(256))]

    /// For any D (any length) and unit N: |R| = |D|; the angle in equals
    /// the angle out (R·N = −D·N); R − D lies along N (only D's normal part
    /// changes); N or −N give the same R; and reflecting R again gives D
    /// back.
    #[test]
    fn mirror_properties(
        direction in unit_vector(),
        length in 0.1..10.0f64,
        n in unit_vector(),
    ) {
        let d = length * direction;
        let r = reflect_ray(d, n);
        let tolerance = 1e-12 * length;
        let what = format!("reflect_ray(D = {d}, N = {n}) = R = {r}");
        prop_assert!((r.length() - d.length()).abs() <= tolerance, "{what}: expected |R| = |D| = {}, got |R| = {}", d.length(), r.length());
        prop_assert!((r.dot(n) + d.dot(n)).abs() <= tolerance, "{what}: expected R·N = −D·N = {}, got R·N = {}", -d.dot(n), r.dot(n));
        prop_assert!((r - d).cross(n).length() <= tolerance, "{what}: expected R − D along N, got R − D = {}", r - d);
        let flipped = reflect_ray(d, -n);
        prop_assert!((flipped - r).length() <= tolerance, "{what}: expected the same R for −N, got {flipped}");
        let back = reflect_ray(r, n);
        prop_assert!((back - d).length() <= tolerance, "{what}: expected R reflected again to be D, got {back}");
    }
}
