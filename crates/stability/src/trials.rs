//! What the cases share to run their trials: numbers drawn from the
//! seeded generator, the loop that counts each method's failed trials,
//! and the counts as the table's rows.
use ch08::{DVec3, SplitMix64};

use crate::{Count, Expect};

/// A number uniformly in `[lo, hi)`.
pub(crate) fn uniform(rng: &mut SplitMix64, lo: f64, hi: f64) -> f64 {
    lo + (hi - lo) * rng.next_f64()
}

/// 10ˣ with x uniform in `[lo, hi)`: a size spread evenly over decades.
pub(crate) fn decades(rng: &mut SplitMix64, lo: f64, hi: f64) -> f64 {
    10f64.powf(uniform(rng, lo, hi))
}

/// A point uniformly in the cube [−1, 1]³.
pub(crate) fn cube_point(rng: &mut SplitMix64) -> DVec3 {
    DVec3::new(
        uniform(rng, -1.0, 1.0),
        uniform(rng, -1.0, 1.0),
        uniform(rng, -1.0, 1.0),
    )
}

/// An index uniformly in `0..n`.
pub(crate) fn below(rng: &mut SplitMix64, n: usize) -> usize {
    (rng.next_u64() % n as u64) as usize
}

/// A random unit vector perpendicular to the unit `normal`.
pub(crate) fn tangent(rng: &mut SplitMix64, normal: DVec3) -> DVec3 {
    let (u, v) = normal.any_orthonormal_pair();
    let angle = std::f64::consts::TAU * rng.next_f64();
    angle.cos() * u + angle.sin() * v
}

/// Runs `trial` `trials` times with a generator seeded `seed`; each
/// trial says, per method, whether it failed.
pub(crate) fn count_failures<const N: usize>(
    trials: usize, seed: u64,
    mut trial: impl FnMut(&mut SplitMix64) -> [bool; N],
) -> [u64; N] {
    let mut rng = SplitMix64::new(seed);
    let mut failures = [0; N];
    for _ in 0..trials {
        for (f, failed) in failures.iter_mut().zip(trial(&mut rng)) {
            *f += u64::from(failed);
        }
    }
    failures
}

/// One count per method: its name, its failures of `trials`, and
/// whether it may fail.
pub(crate) fn per_method<const N: usize>(
    methods: [&str; N], failures: [u64; N], trials: u64, expect: [Expect; N],
) -> Vec<(Count, Expect)> {
    methods
        .into_iter()
        .zip(failures)
        .zip(expect)
        .map(|((method, f), e)| (Count::new(method, f, trials), e))
        .collect()
}
