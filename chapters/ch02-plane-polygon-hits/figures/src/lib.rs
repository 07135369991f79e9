//! Chapter 2 — plane and polygon hits: the lecture's figures, drawn
//! from the chapter's public API, and the chapter's entry in the command
//! line ([`CHAPTER`]).
mod diagrams;
mod questions;

use raystep_figure::Chapter;

/// What chapter 2 hands `raystep figures`, `measure`, `render` and `check`.
pub const CHAPTER: Chapter = Chapter::new(
    "ch02-plane-polygon-hits",
    "Plane and polygon hits",
    &["ray_plane", "inside_polygon"],
)
.stars(&[1, 2])
.questions(questions::all)
.figures(diagrams::all);
