//! Chapter 7 — two rendering methods: the lecture's figures, charts and measurements, drawn
//! from the chapter's public API, and the chapter's entry in the command
//! line ([`CHAPTER`]).
mod charts;
mod diagrams;
pub mod measurements;
mod questions;

use raystep_figure::{Chapter, measurement};

/// What chapter 7 hands `raystep figures`, `measure`, `render` and `check`.
pub const CHAPTER: Chapter = Chapter::new(
    "ch07-two-methods",
    "Two rendering methods",
    &["coverage", "depth_test"],
)
.stars(&[2, 1])
.questions(questions::all)
.figures(diagrams::all)
.charts(&[charts::scaling_chart])
.measurements(&[measurement!(
    "ch07 scaling",
    "scaling.csv",
    measurements::steps,
    measurements::measure_scaling
)])
// `raystep render` with chapter 7's rasterizer and z-buffer (polygons
// only, one thread)
.renderer(|scene, file, _options, _accelerate| {
    let stage =
        ch07::Stage::from_scene(scene, file).map_err(|e| e.to_string())?;
    let (buffers, _) = ch07::rasterize(&stage);
    Ok(buffers.color)
});
