//! Chapter 1 — implicit lines and planes: the lecture's figures, drawn
//! from the chapter's public API, and the chapter's entry in the command
//! line ([`CHAPTER`]).
mod diagrams;
mod questions;

use raystep_figure::Chapter;

/// What chapter 1 hands `raystep figures`, `measure`, `render` and `check`.
pub const CHAPTER: Chapter = Chapter::new(
    "ch01-implicit-lines-planes",
    "Implicit lines and planes",
    &["line_through_points", "plane_through_points"],
)
.stars(&[1, 1])
.questions(questions::all)
.figures(diagrams::all);
