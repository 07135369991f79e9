//! Chapter 2 — plane and polygon hits: the lecture's figures, drawn
//! from the chapter's public API, and the chapter's entry in the command
//! line ([`CHAPTER`]).
mod diagrams;

use raystep_figure::Chapter;

/// What chapter 2 hands `raystep figures`, `measure`, `render` and `check`.
pub const CHAPTER: Chapter = Chapter {
    id: "ch02",
    title: "Plane and polygon hits",
    package: "ch02-plane-polygon-hits",
    exercises: &["ray_plane", "inside_polygon"],
    figures: diagrams::all,
    charts: &[],
    measurements: &[],
    renderer: None,
};
