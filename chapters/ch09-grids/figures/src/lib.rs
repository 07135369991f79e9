//! Chapter 9 — grids: the lecture's figures, charts and measurements,
//! drawn from the chapter's public API, and the chapter's entry in the
//! command line ([`CHAPTER`]).
mod charts;
mod diagrams;
pub mod measurements;
pub mod rows;

use raystep_figure::{Chapter, Measurement};
use raystep_render::csv::to_csv;

/// What chapter 9 hands `raystep figures`, `measure`, `render` and `check`.
pub const CHAPTER: Chapter = Chapter {
    id: "ch09",
    title: "Grids",
    package: "ch09-grids",
    exercises: &["dda_setup", "walk"],
    figures: diagrams::all,
    charts: &[
        charts::resolution_chart,
        charts::compare_chart,
        charts::mailbox_chart,
    ],
    measurements: &[
        Measurement {
            what: "ch09 grid resolution",
            file: "grid-resolution.csv",
            steps: measurements::resolution_steps,
            run: |repeats, step| {
                Ok(to_csv(&measurements::measure_resolution(repeats, step)?))
            },
        },
        Measurement {
            what: "ch09 grid, BVH, brute force",
            file: "grid-vs-bvh.csv",
            steps: measurements::compare_steps,
            run: |repeats, step| {
                Ok(to_csv(&measurements::measure_compare(repeats, step)?))
            },
        },
        Measurement {
            what: "ch09 mailboxing",
            file: "grid-mailbox.csv",
            steps: measurements::mailbox_steps,
            run: |repeats, step| {
                Ok(to_csv(&measurements::measure_mailbox(repeats, step)?))
            },
        },
        Measurement {
            what: "ch09 stability",
            file: "grid-stability.csv",
            steps: measurements::stability_steps,
            run: |repeats, step| {
                Ok(to_csv(&measurements::measure_stability(repeats, step)?))
            },
        },
    ],
    // chapter 8's shapes traced by chapter 6's tracer, as for chapter 8's
    // scenes; `--accel grid` hands it this chapter's grid
    renderer: ch08_figures::CHAPTER.renderer,
};
