//! Ray casting: for each pixel, shoot a ray; for each object, test it;
//! keep the closest; shade.
use raystep_core::Interval;

use crate::{Buffers, Stage, shade_pixel};

// ANCHOR: raycast
/// Chapter 3's brute-force loop on the stage's world: every pixel's ray
/// is tested against every polygon. One thread, like [`crate::rasterize`],
/// so that the two loops compare.
pub fn raycast(stage: &Stage) -> Buffers {
    let world = &stage.world;
    let (width, height) = (world.width, world.height);
    let mut buffers = Buffers::new(width, height, world.background);
    // For each pixel …
    for row in 0..height {
        for column in 0..width {
            // Step 1: shoot the ray through its centre.
            let ray = world.camera.pixel_ray(column, row, width, height);
            // Step 2: for each object, test it; keep the closest.
            let Some((index, hit)) = world.closest_hit(&ray, Interval::FORWARD)
            else {
                continue;
            };
            // Step 3: shade; note the depth along the view direction.
            let i = row as usize * width as usize + column as usize;
            buffers.id[i] = Some(index);
            buffers.depth[i] = hit.t * ray.direction.dot(world.camera.forward);
            buffers.color.set(
                column,
                row,
                shade_pixel(world, &ray, hit.t, index, hit.normal),
            );
        }
    }
    buffers
}
// ANCHOR_END: raycast
