//! Chapter 6 — refraction: the lecture's figures, charts and measurements, drawn
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

/// What chapter 6 hands `raystep figures`, `measure`, `render` and `check`.
pub const CHAPTER: Chapter = Chapter {
    id: "ch06",
    title: "Refraction",
    package: "ch06-refraction",
    exercises: &["refraction", "schlick"],
    figures: diagrams::all,
    charts: &[diagrams::reflectance_chart, charts::fresnel_chart],
    measurements: &[Measurement {
        what: "ch06 fresnel",
        file: "fresnel.csv",
        steps: |_| ch06::REFRACTIVE_INDICES.len() as u64,
        run: |repeats, step| {
            Ok(to_csv(&measurements::measure_fresnel(repeats, step)))
        },
    }],
    renderer: Some(render),
};

/// `raystep render` with chapter 6's tracer: reflection and refraction,
/// split by the exact Fresnel equations.
fn render(
    scene: &Scene,
    file: &str,
    options: &RenderOptions,
    accelerate: Accelerate,
) -> Result<Image, String> {
    let world = ch03::world(scene, file)
        .map_err(|e| e.to_string())?
        .accelerated(accelerate);
    let (image, _) = ch06::render(
        &world,
        &ch06::DEFAULT_STOP,
        ch06::Fresnel::Exact,
        options,
    )
    .map_err(|e| e.to_string())?;
    Ok(image)
}
