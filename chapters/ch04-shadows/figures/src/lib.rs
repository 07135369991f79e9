//! Chapter 4 — shadows: the lecture's figures, charts and measurements, drawn
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

/// What chapter 4 hands `raystep figures`, `measure`, `render` and `check`.
pub const CHAPTER: Chapter = Chapter {
    id: "ch04",
    title: "Shadows",
    package: "ch04-shadows",
    exercises: &["shadow", "normal_offset"],
    figures: diagrams::all,
    charts: &[charts::acne_chart],
    measurements: &[Measurement {
        what: "ch04 acne",
        file: "acne.csv",
        steps: |_| {
            (measurements::CHART_STRATEGIES.len()
                * measurements::CHART_SCALES.len()) as u64
        },
        run: |repeats, step| {
            Ok(to_csv(&measurements::measure_acne(repeats, step)))
        },
    }],
    renderer: Some(render),
};

/// `raystep render` with chapter 4's tracer: shadow rays, with the
/// scale-aware offset against acne.
fn render(
    scene: &Scene,
    file: &str,
    options: &RenderOptions,
    accelerate: Accelerate,
) -> Result<Image, String> {
    let world = ch03::world(scene, file)
        .map_err(|e| e.to_string())?
        .accelerated(accelerate);
    ch04::render(&world, ch04::Offset::ScaleAware, options)
        .map_err(|e| e.to_string())
}
