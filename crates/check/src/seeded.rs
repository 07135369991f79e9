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
