//! The appendix "how fast can it go": its chart and measurement, and its
//! entry in the command line ([`CHAPTER`]).
mod charts;
pub mod measurements;
pub mod rows;

use raystep_figure::{Chapter, measurement};

/// What the appendix hands `raystep figures`, `measure` and `check`.
pub const CHAPTER: Chapter =
    Chapter::new("ch11-how-fast", "Appendix: how fast can it go", &[])
        .charts(&[charts::steps_chart])
        .measurements(&[measurement!(
            "ch11 fast steps and peers",
            "fast-steps.csv",
            measurements::steps,
            measurements::measure_steps
        )]);
