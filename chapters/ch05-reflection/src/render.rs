//! The recursive tracer over a whole image, its rays counted.
use crate::{Path, RayCounts, RayKind, RayLog, Stop, trace};
use ch03::{World, render_with};
use raystep_core::Ray;
use raystep_render::{Image, RenderError, RenderOptions};
use std::sync::Mutex;

// ANCHOR: render
/// For each pixel on screen: trace the primary ray recursively under
/// `stop`. Returns the image and every ray it took. Rows run in parallel;
/// image and counts are the same for any number of threads.
pub fn render(
    world: &World,
    stop: &Stop,
    options: &RenderOptions,
) -> Result<(Image, RayCounts), RenderError> {
    let total = Mutex::new(RayCounts::default());
    let image = render_with(world, options, |ray| {
        let mut log = RayLog::new();
        let colour = trace(world, ray, RayKind::Primary, Path::PRIMARY, stop, &mut log);
        *total.lock().unwrap_or_else(|e| e.into_inner()) += log.counts;
        colour
    })?;
    Ok((image, total.into_inner().unwrap_or_else(|e| e.into_inner())))
}
// ANCHOR_END: render

/// The ray tree of one pixel: every ray its trace shot or cut, in order.
pub fn pixel_tree(world: &World, column: u32, row: u32, stop: &Stop) -> Vec<crate::LoggedRay> {
    let ray: Ray = world
        .camera
        .pixel_ray(column, row, world.width, world.height);
    let mut log = RayLog::recording();
    trace(world, &ray, RayKind::Primary, Path::PRIMARY, stop, &mut log);
    log.rays.unwrap_or_default()
}
