use proptest::test_runner::{Config, RngSeed};

/// A proptest configuration with a fixed seed and no failure files, so a
/// property test checks the same `cases` inputs on every machine and run.
pub fn seeded(cases: u32) -> Config {
    Config {
        cases,
        rng_seed: RngSeed::Fixed(0x5EED_2026),
        failure_persistence: None,
        ..Config::default()
    }
}

/// Unit vectors in every direction (from the cube [−1, 1]³, too-short
/// vectors skipped, normalised): for directions, normals and lights in
/// property tests.
pub fn unit_vector()
-> impl proptest::strategy::Strategy<Value = raystep_core::DVec3> {
    use proptest::strategy::Strategy;
    (-1.0..1.0f64, -1.0..1.0f64, -1.0..1.0f64)
        .prop_filter("not too short", |(x, y, z)| x * x + y * y + z * z > 0.01)
        .prop_map(|(x, y, z)| raystep_core::DVec3::new(x, y, z).normalize())
}
