//! Chapter 5 — reflection: the lecture's figures, charts and measurements, drawn
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

/// What chapter 5 hands `raystep figures`, `measure`, `render` and `check`.
pub const CHAPTER: Chapter = Chapter {
    id: "ch05",
    title: "Reflection",
    package: "ch05-reflection",
    exercises: &["reflection", "recursion"],
    figures: diagrams::all,
    charts: &[charts::stopping_chart],
    measurements: &[Measurement {
        what: "ch05 stopping",
        file: "stopping.csv",
        steps: |rounds| (measurements::CHART_SCENES.len() * rounds) as u64,
        run: |repeats, step| {
            Ok(to_csv(&measurements::measure_stopping(repeats, step)))
        },
    }],
    renderer: Some(render),
};

/// `raystep render` with chapter 5's tracer: recursive reflected rays,
/// stopped by contribution.
fn render(
    scene: &Scene,
    file: &str,
    options: &RenderOptions,
    accelerate: Accelerate,
) -> Result<Image, String> {
    let world = ch03::world(scene, file)
        .map_err(|e| e.to_string())?
        .accelerated(accelerate);
    let (image, _) = ch05::render(&world, &ch05::DEFAULT_STOP, options)
        .map_err(|e| e.to_string())?;
    Ok(image)
}
