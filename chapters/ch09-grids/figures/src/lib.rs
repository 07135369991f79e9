//! Chapter 9 — grids: the lecture's figures, charts and measurements,
//! drawn from the chapter's public API, and the chapter's entry in the
//! command line ([`CHAPTER`]).
mod charts;
mod diagrams;
pub mod measurements;
pub mod rows;

use raystep_figure::{Chapter, Measurement};
use raystep_render::csv::to_csv;
use raystep_render::{Image, RenderOptions};
use raystep_scene::Scene;
use raystep_world::Accelerate;

/// What chapter 9 hands `raystep figures`, `measure`, `render` and `check`.
pub const CHAPTER: Chapter = Chapter {
    id: "ch09",
    title: "Grids",
    package: "ch09-grids",
    exercises: &["dda_setup", "walk"],
    figures: diagrams::all,
    charts: &[
        charts::resolution_chart,
        charts::compare_chart,
        charts::mailbox_chart,
    ],
    measurements: &[
        Measurement {
            what: "ch09 grid resolution",
            file: "grid-resolution.csv",
            steps: measurements::resolution_steps,
            run: |repeats, step| {
                Ok(to_csv(&measurements::measure_resolution(repeats, step)?))
            },
        },
        Measurement {
            what: "ch09 grid, BVH, brute force",
            file: "grid-vs-bvh.csv",
            steps: measurements::compare_steps,
            run: |repeats, step| {
                Ok(to_csv(&measurements::measure_compare(repeats, step)?))
            },
        },
        Measurement {
            what: "ch09 mailboxing",
            file: "grid-mailbox.csv",
            steps: measurements::mailbox_steps,
            run: |repeats, step| {
                Ok(to_csv(&measurements::measure_mailbox(repeats, step)?))
            },
        },
        Measurement {
            what: "ch09 stability",
            file: "grid-stability.csv",
            steps: measurements::stability_steps,
            run: |repeats, step| {
                Ok(to_csv(&measurements::measure_stability(repeats, step)?))
            },
        },
    ],
    renderer: Some(render),
};

/// `raystep render` with chapter 8's primitives, traced by chapter 6's
/// tracer (reflection, refraction, exact Fresnel), the objects searched by
/// what `--accel` asks for.
fn render(
    scene: &Scene,
    file: &str,
    options: &RenderOptions,
    accelerate: Accelerate,
) -> Result<Image, String> {
    let world = ch08::world(scene, file)
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
