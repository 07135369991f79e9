//! The full tracer over a whole image, its rays counted.
use crate::{CAMERA_MEDIUM, Fresnel, Media, trace};
use ch03::{World, render_with};
use ch05::{LoggedRay, Path, RayCounts, RayKind, RayLog, Stop};
use raystep_render::{Image, RenderError, RenderOptions};
use std::sync::Mutex;

// ANCHOR: render
/// For each pixel on screen: trace the primary ray with reflection and
/// refraction under `stop`, splitting light by `fresnel`. Returns the
/// image and every ray it took; both are the same for any number of
/// threads.
pub fn render(
    world: &World,
    stop: &Stop,
    fresnel: Fresnel,
    options: &RenderOptions,
) -> Result<(Image, RayCounts), RenderError> {
    let total = Mutex::new(RayCounts::default());
    let media = Media::new(CAMERA_MEDIUM);
    let image = render_with(world, options, |ray| {
        let mut log = RayLog::new();
        let colour = trace(
            world,
            ray,
            RayKind::Primary,
            Path::PRIMARY,
            &media,
            stop,
            fresnel,
            &mut log,
        );
        *total.lock().unwrap_or_else(|e| e.into_inner()) += log.counts;
        colour
    })?;
    Ok((image, total.into_inner().unwrap_or_else(|e| e.into_inner())))
}
// ANCHOR_END: render

/// The ray tree of one pixel: every ray its trace shot or cut, in order.
pub fn pixel_tree(
    world: &World,
    column: u32,
    row: u32,
    stop: &Stop,
    fresnel: Fresnel,
) -> Vec<LoggedRay> {
    let ray = world
        .camera
        .pixel_ray(column, row, world.width, world.height);
    let mut log = RayLog::recording();
    let media = Media::new(CAMERA_MEDIUM);
    trace(
        world,
        &ray,
        RayKind::Primary,
        Path::PRIMARY,
        &media,
        stop,
        fresnel,
        &mut log,
    );
    log.rays.unwrap_or_default()
}
