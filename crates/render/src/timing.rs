//! Timing renders for the charts: the one place that decides how a render
//! time is measured, so that every chapter's chart means the same thing.
//!
//! A render of a small image takes a few milliseconds, about as long as the
//! machine's own hiccups, and a machine that warms up or gets busy during a
//! run would make whichever job ran first look slower. So each sample runs
//! its job several times in a row, and the jobs take turns: job 0, job 1,
//! …, job n−1, then job 0 again, so that any drift shifts every job alike.
//! The median of each job's samples is kept.
use std::time::Instant;

/// How each job is timed: `rounds` samples of `batch` runs each.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Timing {
    /// Samples per job (the median is kept); at least 1.
    pub rounds: usize,
    /// Runs per sample, timed together.
    pub batch: usize,
}

impl Timing {
    /// The same timing with `rounds` samples per job.
    pub const fn with_rounds(self, rounds: usize) -> Timing {
        Timing { rounds, ..self }
    }

    /// Times every job, taking turns, after one untimed run of each to warm
    /// the caches; returns each job's median time per run in milliseconds.
    /// `step` is called once per round.
    pub fn median_ms(
        self, jobs: &mut [&mut dyn FnMut()], mut step: impl FnMut(),
    ) -> Vec<f64> {
        for job in jobs.iter_mut() {
            job();
        }
        let batch = self.batch.max(1);
        let mut samples = vec![Vec::new(); jobs.len()];
        let mut order: Vec<usize> = (0..jobs.len()).collect();
        let mut seed: u64 = 0x9E37_79B9_7F4A_7C15;
        for _ in 0..self.rounds.max(1) {
            // a new order every round (Fisher–Yates with a fixed seed), so
            // that a disturbance that comes back every round does not keep
            // hitting the same job
            for i in (1..order.len()).rev() {
                seed = seed
                    .wrapping_mul(6_364_136_223_846_793_005)
                    .wrapping_add(1_442_695_040_888_963_407);
                order.swap(i, (seed >> 33) as usize % (i + 1));
            }
            for &k in &order {
                let start = Instant::now();
                for _ in 0..batch {
                    jobs[k]();
                }
                samples[k]
                    .push(start.elapsed().as_secs_f64() * 1e3 / batch as f64);
            }
            step();
        }
        samples.into_iter().map(median).collect()
    }
}

/// The middle value (the upper one of an even count).
fn median(mut times: Vec<f64>) -> f64 {
    times.sort_by(f64::total_cmp);
    times[times.len() / 2]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_job_runs_warm_up_plus_rounds_times_batch() {
        let (mut a, mut b) = (0, 0);
        let mut steps = 0;
        let timing = Timing {
            rounds: 3,
            batch: 4,
        };
        let times = timing
            .median_ms(&mut [&mut || a += 1, &mut || b += 1], || steps += 1);
        assert_eq!((a, b, steps), (13, 13, 3));
        assert_eq!(times.len(), 2);
        assert!(times.iter().all(|t| t.is_finite() && *t >= 0.0));
    }

    #[test]
    fn the_median_ignores_one_outlier() {
        assert_eq!(median(vec![1.0, 100.0, 2.0]), 2.0);
        assert_eq!(median(vec![5.0]), 5.0);
    }
}
