//! Chapter 8 — bounding volumes: the lecture's figures, charts and
//! measurements, drawn from the chapter's public API, and the chapter's
//! entry in the command line ([`CHAPTER`]).
mod bvh_charts;
pub mod bvh_measurements;
mod bvh_rows;
mod charts;
mod diagrams;
mod instance_charts;
mod instance_figure;
pub mod instance_measurements;
mod instance_rows;
pub mod measurements;
mod mesh_figures;
mod questions;
mod rows;
mod scene_files;
mod sketch;
mod tightness_measure;
mod torus_figure;

use raystep_figure::{Chapter, measurement, render_world};
use raystep_render::{Image, RenderOptions};
use raystep_scene::Scene;
use raystep_world::Accelerate;
pub use scene_files::{STEM_BUNNIES, bunnies_toml};

pub use tightness_measure::{measure_tightness, tightness};

/// What chapter 8 hands `raystep figures`, `measure`, `render` and `check`.
pub const CHAPTER: Chapter = Chapter::new(
    "ch08-bounding-volumes",
    "Bounding volumes",
    &[
        "slab",
        "watertight",
        "torus_quartic",
        "sphere_of_points",
        "sah_split",
        "near_first",
    ],
)
.stars(&[2, 3, 3, 2, 2, 3])
.questions(questions::all)
.figures(diagrams::all)
.charts(&[
    charts::costs_chart,
    charts::bounding_chart,
    bvh_charts::builders_chart,
    bvh_charts::sah_chart,
    bvh_charts::scaling_chart,
    bvh_charts::precision_chart,
    bvh_charts::zbuffer_chart,
    instance_charts::instances_chart,
])
.measurements(&[
    measurement!(
        "ch08 costs",
        "costs.csv",
        measurements::cost_steps,
        measurements::measure_costs
    ),
    measurement!(
        "ch08 bounding",
        "bounding.csv",
        measurements::bounding_steps,
        measurements::measure_bounding
    ),
    measurement!(
        "ch08 BVH builders",
        "bvh-builders.csv",
        bvh_measurements::builder_steps,
        bvh_measurements::measure_builders
    ),
    measurement!(
        "ch08 BVH scaling",
        "bvh-scaling.csv",
        bvh_measurements::scaling_steps,
        bvh_measurements::measure_scaling
    ),
    measurement!(
        "ch08 BVH node precision",
        "bvh-precision.csv",
        bvh_measurements::precision_steps,
        bvh_measurements::measure_precision
    ),
    measurement!(
        "ch08 BVH against the z-buffer",
        "bvh-zbuffer.csv",
        bvh_measurements::zbuffer_steps,
        bvh_measurements::measure_zbuffer
    ),
    measurement!(
        "ch08 instances",
        "instances.csv",
        instance_measurements::instance_steps,
        instance_measurements::measure_instances
    ),
])
.renderer(render);

/// `raystep render` with chapter 8's primitives and meshes, traced by
/// chapter 6's tracer (reflection, refraction, exact Fresnel) over what
/// `accelerate` builds (`--accel`: the brute-force loop by default);
/// chapters 9 and 10 render with it too (`--accel grid`, `--accel kdtree`
/// hand it their structures). In a scene with instances it builds both
/// levels: each mesh's own structure, and the world's over the objects
/// and instances.
pub fn render(
    scene: &Scene, file: &str, options: &RenderOptions, accelerate: Accelerate,
) -> Result<Image, String> {
    // Each mesh's own structure, built once, as a stage of its own.
    let meshes = scene.meshes.len()
        + scene
            .objects
            .iter()
            .filter(|o| o.shape.kind() == "mesh")
            .count();
    let world = if meshes == 0 {
        ch08::world_with(scene, file, accelerate)
    } else {
        let what = format!("building the structures of {meshes} meshes");
        raystep_render::stage(options.progress, &what, || {
            ch08::world_with(scene, file, accelerate)
        })
    };
    render_world(world, accelerate, options, |world| {
        ch06_figures::render_exact(world, options)
    })
}
