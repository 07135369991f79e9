//! Chapter 1 — implicit lines and planes: the lecture's figures, drawn
//! from the chapter's public API, and the chapter's entry in the command
//! line ([`CHAPTER`]).
mod diagrams;

use raystep_figure::Chapter;

/// What chapter 1 hands `raystep figures`, `measure`, `render` and `check`.
pub const CHAPTER: Chapter = Chapter {
    id: "ch01",
    title: "Implicit lines and planes",
    package: "ch01-implicit-lines-planes",
    exercises: &["line_through_points", "plane_through_points"],
    figures: diagrams::all,
    charts: &[],
    measurements: &[],
    renderer: None,
};
