//! Chapter 5 — reflection: the lecture's figures, charts and measurements, drawn
//! from the chapter's public API, and the chapter's entry in the command
//! line ([`CHAPTER`]).
mod charts;
mod diagrams;
pub mod measurements;
mod questions;

use raystep_figure::{Chapter, measurement, render_world};

/// What chapter 5 hands `raystep figures`, `measure`, `render` and `check`.
pub const CHAPTER: Chapter = Chapter::new(
    "ch05-reflection",
    "Reflection",
    &["reflection", "recursion"],
)
.stars(&[1, 2])
.questions(questions::all)
.figures(diagrams::all)
.charts(&[charts::stopping_chart])
.measurements(&[measurement!(
    "ch05 stopping",
    "stopping.csv",
    |rounds| (measurements::CHART_SCENES.len() * rounds) as u64,
    measurements::measure_stopping
)])
// `raystep render` with chapter 5's tracer: recursive reflected
// rays, stopped by contribution
.renderer(|scene, file, options, accelerate| {
    render_world(ch03::world(scene, file), accelerate, options, |world| {
        let stop = &ch05::DEFAULT_STOP;
        ch05::render(world, stop, options).map(|(image, _)| image)
    })
});
