//! Rasterization: for each object, for each pixel in its projection, test
//! the z-value, shade.
use raystep_core::DVec2;

use crate::{
    Buffers, DepthBuffer, Projection, Stage, barycentric, clip_near, covers,
    perspective_depth, shade_pixel,
};

/// What a rasterization did, counted.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct RasterCounts {
    /// Triangles drawn (after clipping at the near plane).
    pub triangles: u64,
    /// Pixel centres tested against a triangle's edges (its bounding box).
    pub tested: u64,
    /// Of those, covered by the triangle.
    pub covered: u64,
    /// Of those, closer than what the pixel showed: shaded.
    pub shaded: u64,
}

// ANCHOR: rasterize
/// Draws every triangle of the stage, one after another, into the three
/// buffers, with the camera of the stage's world. One thread: this is the
/// lecture's loop, not a fast one.
pub fn rasterize(stage: &Stage) -> (Buffers, RasterCounts) {
    let world = &stage.world;
    let (width, height) = (world.width, world.height);
    let projection = Projection {
        camera: world.camera,
        width,
        height,
    };
    let mut buffers = Buffers::new(width, height, world.background);
    let mut depth = DepthBuffer::new(width, height);
    let mut counts = RasterCounts::default();
    // For each object (here: each triangle of each object) …
    for triangle in &stage.triangles {
        // Step 1: to view coordinates, cut at the near plane.
        let view = clip_near(triangle.corners.map(|p| projection.view(p)));
        // (a triangle cut at the near plane may leave a quadrilateral: a fan)
        for k in 1..view.len().saturating_sub(1) {
            let corners = [view[0], view[k], view[k + 1]];
            // Step 2: project the corners onto the screen.
            let screen = corners.map(|v| projection.to_pixels(v));
            let z = corners.map(|v| v.z);
            counts.triangles += 1;
            // Step 3: for each pixel whose centre may be inside (the
            // triangle's bounding box, clipped to the image) …
            let Some((columns, rows)) = pixel_box(&screen, width, height)
            else {
                continue;
            };
            for row in rows {
                for column in columns.clone() {
                    counts.tested += 1;
                    // … is its centre covered (edge functions, fill rule)?
                    let p = Projection::pixel_centre(column, row);
                    if !covers(&screen, p) {
                        continue;
                    }
                    counts.covered += 1;
                    // Step 4: the depth there, and the z test.
                    let Some(lambda) = barycentric(&screen, p) else {
                        continue;
                    };
                    let z = perspective_depth(lambda, z);
                    if !depth.test_and_set(column, row, z) {
                        continue;
                    }
                    // Step 5: shade. The point is found from its depth along
                    // the pixel's view direction, as a deferred renderer does.
                    counts.shaded += 1;
                    let ray =
                        world.camera.pixel_ray(column, row, width, height);
                    let t = z / ray.direction.dot(world.camera.forward);
                    let i = row as usize * width as usize + column as usize;
                    buffers.id[i] = Some(triangle.object);
                    buffers.depth[i] = z;
                    buffers.color.set(
                        column,
                        row,
                        shade_pixel(
                            world,
                            &ray,
                            t,
                            triangle.object,
                            triangle.normal,
                        ),
                    );
                }
            }
        }
    }
    (buffers, counts)
}
// ANCHOR_END: rasterize

/// The columns and rows of the pixels whose centres lie in the bounding
/// box of `screen`, within the image; None if there are none.
fn pixel_box(
    screen: &[DVec2; 3], width: u32, height: u32,
) -> Option<(std::ops::RangeInclusive<u32>, std::ops::RangeInclusive<u32>)> {
    let lo = screen[0].min(screen[1]).min(screen[2]);
    let hi = screen[0].max(screen[1]).max(screen[2]);
    if !(lo.is_finite() && hi.is_finite()) {
        return None;
    }
    // centres c + ½ with lo ≤ c + ½ ≤ hi
    let first = |lo: f64| (lo - 0.5).ceil().max(0.0);
    let last = |hi: f64, n: u32| (hi - 0.5).floor().min(f64::from(n) - 1.0);
    let (c0, c1) = (first(lo.x), last(hi.x, width));
    let (r0, r1) = (first(lo.y), last(hi.y, height));
    if c0 > c1 || r0 > r1 {
        return None;
    }
    Some((c0 as u32..=c1 as u32, r0 as u32..=r1 as u32))
}
