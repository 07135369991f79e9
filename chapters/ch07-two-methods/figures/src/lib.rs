//! Chapter 7 — two rendering methods: the lecture's figures, charts and measurements, drawn
//! from the chapter's public API, and the chapter's entry in the command
//! line ([`CHAPTER`]).
mod charts;
mod diagrams;
pub mod measurements;

use raystep_figure::{Chapter, Measurement};
use raystep_render::csv::to_csv;
use raystep_render::{Image, RenderOptions};
use raystep_scene::Scene;
use raystep_world::Accelerate;

/// What chapter 7 hands `raystep figures`, `measure`, `render` and `check`.
pub const CHAPTER: Chapter = Chapter {
    id: "ch07",
    title: "Two rendering methods",
    package: "ch07-two-methods",
    exercises: &["coverage", "depth_test"],
    figures: diagrams::all,
    charts: &[charts::scaling_chart],
    measurements: &[Measurement {
        what: "ch07 scaling",
        file: "scaling.csv",
        steps: measurements::steps,
        run: |repeats, step| {
            Ok(to_csv(&measurements::measure_scaling(repeats, step)?))
        },
    }],
    renderer: Some(render),
};

/// `raystep render` with chapter 7's rasterizer and z-buffer (polygons
/// only, one thread).
fn render(
    scene: &Scene,
    file: &str,
    _options: &RenderOptions,
    _accelerate: Accelerate,
) -> Result<Image, String> {
    let stage =
        ch07::Stage::from_scene(scene, file).map_err(|e| e.to_string())?;
    let (buffers, _) = ch07::rasterize(&stage);
    Ok(buffers.color)
}
