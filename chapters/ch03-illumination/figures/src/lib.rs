//! Chapter 3 — illumination: the lecture's figures, drawn
//! from the chapter's public API, and the chapter's entry in the command
//! line ([`CHAPTER`]).
mod diagrams;

use raystep_figure::Chapter;
use raystep_render::{Image, RenderOptions};
use raystep_scene::Scene;
use raystep_world::Accelerate;

/// What chapter 3 hands `raystep figures`, `measure`, `render` and `check`.
pub const CHAPTER: Chapter = Chapter {
    id: "ch03",
    title: "Illumination",
    package: "ch03-illumination",
    exercises: &["sphere_hit", "reflect", "local_shading"],
    figures: diagrams::all,
    charts: &[],
    measurements: &[],
    renderer: Some(render),
};

/// `raystep render` with chapter 3's tracer: the local model, every light
/// visible.
fn render(
    scene: &Scene,
    file: &str,
    options: &RenderOptions,
    accelerate: Accelerate,
) -> Result<Image, String> {
    let world = ch03::world(scene, file)
        .map_err(|e| e.to_string())?
        .accelerated(accelerate);
    ch03::render(&world, ch03::Terms::All, options).map_err(|e| e.to_string())
}
