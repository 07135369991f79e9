//! Chapter 3 — illumination: the lecture's figures, drawn
//! from the chapter's public API, and the chapter's entry in the command
//! line ([`CHAPTER`]).
mod diagrams;
mod questions;

use raystep_figure::{Chapter, render_world};

/// What chapter 3 hands `raystep figures`, `measure`, `render` and `check`.
pub const CHAPTER: Chapter = Chapter::new(
    "ch03-illumination",
    "Illumination",
    &["sphere_hit", "reflect", "local_shading"],
)
.stars(&[2, 1, 2])
.questions(questions::all)
.figures(diagrams::all)
// `raystep render` with chapter 3's tracer: the local model, every light
// visible
.renderer(|scene, file, options, accelerate| {
    render_world(ch03::world(scene, file), accelerate, options, |world| {
        ch03::render(world, ch03::Terms::All, options)
    })
});
