//! Chapter 8 — bounding volumes: the lecture's figures, charts and
//! measurements, drawn from the chapter's public API, and the chapter's
//! entry in the command line ([`CHAPTER`]).
mod bvh_charts;
pub mod bvh_measurements;
mod bvh_rows;
mod charts;
mod diagrams;
pub mod measurements;
mod rows;
mod torus_figure;

use raystep_figure::{Chapter, Measurement};
use raystep_render::csv::to_csv;
use raystep_render::{Image, RenderOptions};
use raystep_scene::Scene;
use raystep_world::Accelerate;

/// What chapter 8 hands `raystep figures`, `measure`, `render` and `check`.
pub const CHAPTER: Chapter = Chapter {
    id: "ch08",
    title: "Bounding volumes",
    package: "ch08-bounding-volumes",
    exercises: &[
        "slab",
        "watertight",
        "torus_quartic",
        "sphere_of_points",
        "sah_split",
        "near_first",
    ],
    figures: diagrams::all,
    charts: &[
        charts::costs_chart,
        charts::bounding_chart,
        bvh_charts::builders_chart,
        bvh_charts::sah_chart,
        bvh_charts::scaling_chart,
        bvh_charts::precision_chart,
        bvh_charts::zbuffer_chart,
    ],
    measurements: &[
        Measurement {
            what: "ch08 costs",
            file: "costs.csv",
            steps: measurements::cost_steps,
            run: |repeats, step| {
                Ok(to_csv(&measurements::measure_costs(repeats, step)))
            },
        },
        Measurement {
            what: "ch08 bounding",
            file: "bounding.csv",
            steps: measurements::bounding_steps,
            run: |repeats, step| {
                Ok(to_csv(&measurements::measure_bounding(repeats, step)?))
            },
        },
        Measurement {
            what: "ch08 BVH builders",
            file: "bvh-builders.csv",
            steps: bvh_measurements::builder_steps,
            run: |repeats, step| {
                Ok(to_csv(&bvh_measurements::measure_builders(repeats, step)?))
            },
        },
        Measurement {
            what: "ch08 BVH scaling",
            file: "bvh-scaling.csv",
            steps: bvh_measurements::scaling_steps,
            run: |repeats, step| {
                Ok(to_csv(&bvh_measurements::measure_scaling(repeats, step)?))
            },
        },
        Measurement {
            what: "ch08 BVH node precision",
            file: "bvh-precision.csv",
            steps: bvh_measurements::precision_steps,
            run: |repeats, step| {
                Ok(to_csv(&bvh_measurements::measure_precision(repeats, step)?))
            },
        },
        Measurement {
            what: "ch08 BVH against the z-buffer",
            file: "bvh-zbuffer.csv",
            steps: bvh_measurements::zbuffer_steps,
            run: |repeats, step| {
                Ok(to_csv(&bvh_measurements::measure_zbuffer(repeats, step)?))
            },
        },
    ],
    renderer: Some(render),
};

/// `raystep render` with chapter 8's primitives, traced by chapter 6's
/// tracer (reflection, refraction, exact Fresnel) over the brute-force
/// loop.
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
