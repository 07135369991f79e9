//! Chapter 10 — kd-trees: the lecture's figures, charts and measurements,
//! drawn from the chapter's public API, and the chapter's entry in the
//! command line ([`CHAPTER`]).
mod charts;
mod diagrams;
pub mod measurements;
mod questions;
pub mod rows;

use raystep_figure::{Chapter, measurement};

/// What chapter 10 hands `raystep figures`, `measure`, `render` and `check`.
pub const CHAPTER: Chapter = Chapter::new(
    "ch10-kd-trees",
    "kd-trees",
    &["split_cost", "traversal_step"],
)
.stars(&[2, 3])
.questions(questions::all)
.figures(diagrams::all)
.charts(&[
    charts::build_chart,
    charts::which_chart,
    charts::costs_chart,
])
.measurements(&[
    measurement!(
        "ch10 kd-tree builds",
        "kd-build.csv",
        measurements::build_steps,
        measurements::measure_build
    ),
    measurement!(
        "ch10 kd-tree variants",
        "kd-variants.csv",
        measurements::variants_steps,
        measurements::measure_variants
    ),
    measurement!(
        "ch10 which structure",
        "which-structure.csv",
        measurements::structures_steps,
        measurements::measure_structures
    ),
    measurement!(
        "ch10 stability",
        "kd-stability.csv",
        measurements::stability_steps,
        measurements::measure_stability
    ),
])
// chapter 8's shapes traced by chapter 6's tracer, as for chapters 8
// and 9; `--accel kdtree` hands it this chapter's tree
.renderer(ch08_figures::render);
