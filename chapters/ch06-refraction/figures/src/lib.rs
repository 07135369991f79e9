//! Chapter 6 — refraction: the lecture's figures, charts and measurements, drawn
//! from the chapter's public API, and the chapter's entry in the command
//! line ([`CHAPTER`]).
mod charts;
mod diagrams;
pub mod measurements;
mod questions;

use raystep_figure::{Chapter, measurement, render_world};
use raystep_render::{Image, RenderError, RenderOptions};
use raystep_world::World;

/// What chapter 6 hands `raystep figures`, `measure`, `render` and `check`.
pub const CHAPTER: Chapter =
    Chapter::new("ch06-refraction", "Refraction", &["refraction", "schlick"])
        .stars(&[2, 1])
        .questions(questions::all)
        .figures(diagrams::all)
        .charts(&[diagrams::reflectance_chart, charts::fresnel_chart])
        .measurements(&[measurement!(
            "ch06 fresnel",
            "fresnel.csv",
            |_| ch06::REFRACTIVE_INDICES.len() as u64,
            measurements::measure_fresnel
        )])
        .renderer(|scene, file, options, accelerate| {
            render_world(
                ch03::world(scene, file),
                accelerate,
                options,
                |world| render_exact(world, options),
            )
        });

/// Chapter 6's tracer as `raystep render` runs it: reflection and
/// refraction, split by the exact Fresnel equations. Chapter 8 renders
/// its own shapes with it.
pub fn render_exact(
    world: &World, options: &RenderOptions,
) -> Result<Image, RenderError> {
    let (stop, fresnel) = (&ch06::DEFAULT_STOP, ch06::Fresnel::Exact);
    ch06::render(world, stop, fresnel, options).map(|(image, _)| image)
}
