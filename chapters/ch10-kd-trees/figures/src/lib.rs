//! Chapter 10 — kd-trees: the lecture's figures, charts and measurements,
//! drawn from the chapter's public API, and the chapter's entry in the
//! command line ([`CHAPTER`]).
mod diagrams;

use raystep_figure::Chapter;

/// What chapter 10 hands `raystep figures`, `measure`, `render` and `check`.
pub const CHAPTER: Chapter = Chapter {
    id: "ch10",
    title: "kd-trees",
    package: "ch10-kd-trees",
    exercises: &["split_cost", "traversal_step"],
    figures: diagrams::all,
    charts: &[],
    measurements: &[],
    // chapter 8's shapes traced by chapter 6's tracer, as for chapters 8
    // and 9; `--accel kdtree` hands it this chapter's tree
    renderer: ch08_figures::CHAPTER.renderer,
};
