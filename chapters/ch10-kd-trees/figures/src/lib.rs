//! Chapter 10 — kd-trees: the lecture's figures, charts and measurements,
//! drawn from the chapter's public API, and the chapter's entry in the
//! command line ([`CHAPTER`]).
mod charts;
mod diagrams;
pub mod measurements;
pub mod rows;

use raystep_figure::{Chapter, Measurement};
use raystep_render::csv::to_csv;

/// What chapter 10 hands `raystep figures`, `measure`, `render` and `check`.
pub const CHAPTER: Chapter = Chapter {
    id: "ch10",
    title: "kd-trees",
    package: "ch10-kd-trees",
    exercises: &["split_cost", "traversal_step"],
    figures: diagrams::all,
    charts: &[
        charts::build_chart,
        charts::which_chart,
        charts::costs_chart,
    ],
    measurements: &[
        Measurement {
            what: "ch10 kd-tree builds",
            file: "kd-build.csv",
            steps: measurements::build_steps,
            run: |repeats, step| {
                Ok(to_csv(&measurements::measure_build(repeats, step)?))
            },
        },
        Measurement {
            what: "ch10 kd-tree variants",
            file: "kd-variants.csv",
            steps: measurements::variants_steps,
            run: |repeats, step| {
                Ok(to_csv(&measurements::measure_variants(repeats, step)?))
            },
        },
        Measurement {
            what: "ch10 which structure",
            file: "which-structure.csv",
            steps: measurements::structures_steps,
            run: |repeats, step| {
                Ok(to_csv(&measurements::measure_structures(repeats, step)?))
            },
        },
        Measurement {
            what: "ch10 stability",
            file: "kd-stability.csv",
            steps: measurements::stability_steps,
            run: |repeats, step| {
                Ok(to_csv(&measurements::measure_stability(repeats, step)?))
            },
        },
    ],
    // chapter 8's shapes traced by chapter 6's tracer, as for chapters 8
    // and 9; `--accel kdtree` hands it this chapter's tree
    renderer: ch08_figures::CHAPTER.renderer,
};
