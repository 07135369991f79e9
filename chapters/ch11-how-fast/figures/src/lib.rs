//! The appendix "how fast can it go": its chart and measurement, and its
//! entry in the command line ([`CHAPTER`]).
mod charts;
pub mod measurements;
pub mod rows;

use raystep_figure::{Chapter, Measurement};
use raystep_render::csv::to_csv;

/// What the appendix hands `raystep figures`, `measure` and `check`.
pub const CHAPTER: Chapter = Chapter {
    id: "ch11",
    title: "Appendix: how fast can it go",
    package: "ch11-how-fast",
    exercises: &[],
    figures: Vec::new,
    charts: &[charts::steps_chart],
    measurements: &[Measurement {
        what: "ch11 fast steps and peers",
        file: "fast-steps.csv",
        steps: measurements::steps,
        run: |repeats, step| {
            Ok(to_csv(&measurements::measure_steps(repeats, step)?))
        },
    }],
    renderer: None,
};
