//! Exercise 2: the reflection Rᵢ of the light direction.
use ch03::{DVec3, reflect_light};
use proptest::prelude::*;
use raystep_check::{Table, seeded, unit_vector, vec3};

fn v(x: f64, y: f64, z: f64) -> DVec3 {
    DVec3::new(x, y, z)
}

#[test]
fn reflect_table() {
    let up = v(0.0, 1.0, 0.0);
    #[rustfmt::skip]
    let cases = [
        ("light overhead", v(0.0, 1.0, 0.0), up),
        ("45° from the left", v(-1.0, 1.0, 0.0).normalize(), up),
        ("grazing", v(1.0, 1e-3, 0.0).normalize(), up),
        ("tilted normal", v(0.0, 0.0, 1.0), v(0.0, 0.6, 0.8)),
        ("light below", v(0.6, -0.8, 0.0), up),
    ];
    let mut table = Table::new(&["case", "L", "N", "R"]);
    for (name, l, n) in cases {
        table.row(&[
            name.to_string(),
            vec3(l),
            vec3(n),
            vec3(reflect_light(l, n)),
        ]);
    }
    insta::assert_snapshot!(table.to_string());
}

proptest! {
    #![proptest_config(seeded(256))]

    /// |R| = |L|; the angle to N is the same (R·N = L·N); R + L lies along
    /// N (the mirror keeps the normal part and flips the rest).
    #[test]
    fn mirror_properties(l in unit_vector(), n in unit_vector()) {
        let r = reflect_light(l, n);
        let what = format!("reflect_light(L = {l}, N = {n}) = {r}");
        prop_assert!((r.length() - 1.0).abs() <= 1e-12, "{what}: expected a unit vector (|L| = 1), got |R| = {}", r.length());
        prop_assert!((r.dot(n) - l.dot(n)).abs() <= 1e-12, "{what}: expected R·N = L·N = {} (the same angle to N), got {}", l.dot(n), r.dot(n));
        prop_assert!((r + l).cross(n).length() <= 1e-12, "{what}: expected R + L along N (the part across N flips sign), got R + L = {}", r + l);
    }
}
