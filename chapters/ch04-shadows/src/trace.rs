//! The chapter 3 tracer with shadows: Sᵢ from a shadow ray per light.
use crate::{Offset, shadow};
use ch03::{ShadingTerms, World, render_with, shade_with};
use raystep_core::{DVec3, Ray};
use raystep_render::{Image, RenderError, RenderOptions};

// ANCHOR: shade
/// The local model's terms where `ray` first hits the world (None for a
/// miss), each light's Sᵢ from a shadow ray started as `offset` says.
pub fn shade(world: &World, ray: &Ray, offset: Offset) -> Option<ShadingTerms> {
    shade_with(world, ray, |hit, normal, light| {
        shadow(world, hit, normal, light, offset)
    })
}
// ANCHOR_END: shade

/// The colour seen along `ray`: the local model with shadows, the
/// background for a miss.
pub fn trace(world: &World, ray: &Ray, offset: Offset) -> DVec3 {
    shade(world, ray, offset).map_or(world.background, |terms| terms.sum())
}

// ANCHOR: render
/// For each pixel on screen: shoot a ray, shade what it hits first, with a
/// shadow ray to every light. Rows run in parallel; the image is the same
/// for any number of threads.
pub fn render(
    world: &World, offset: Offset, options: &RenderOptions,
) -> Result<Image, RenderError> {
    render_with(world, options, |ray| trace(world, ray, offset))
}
// ANCHOR_END: render
