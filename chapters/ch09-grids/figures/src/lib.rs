//! Chapter 9 — grids: the lecture's figures, charts and measurements,
//! drawn from the chapter's public API, and the chapter's entry in the
//! command line ([`CHAPTER`]).
mod charts;
mod diagrams;
pub mod measurements;
mod questions;
pub mod rows;
mod scene_files;

use raystep_figure::{Chapter, measurement};

pub use scene_files::{
    STEM_SPHERES, STEM_STADIUM, stadium_toml, uniform_spheres_toml,
};

/// What chapter 9 hands `raystep figures`, `measure`, `render` and `check`.
pub const CHAPTER: Chapter =
    Chapter::new("ch09-grids", "Grids", &["dda_setup", "walk"])
        .stars(&[2, 3])
        .questions(questions::all)
        .figures(diagrams::all)
        .charts(&[
            charts::resolution_chart,
            charts::compare_chart,
            charts::mailbox_chart,
        ])
        .measurements(&[
            measurement!(
                "ch09 grid resolution",
                "grid-resolution.csv",
                measurements::resolution_steps,
                measurements::measure_resolution
            ),
            measurement!(
                "ch09 grid, BVH, brute force",
                "grid-vs-bvh.csv",
                measurements::compare_steps,
                measurements::measure_compare
            ),
            measurement!(
                "ch09 mailboxing",
                "grid-mailbox.csv",
                measurements::mailbox_steps,
                measurements::measure_mailbox
            ),
            measurement!(
                "ch09 stability",
                "grid-stability.csv",
                measurements::stability_steps,
                measurements::measure_stability
            ),
        ])
        // chapter 8's shapes traced by chapter 6's tracer, as for chapter
        // 8's scenes; `--accel grid` hands it this chapter's grid
        .renderer(ch08_figures::render);
