//! The rasterizer's first step: from the world to the screen, with the
//! same pinhole camera that shoots chapter 3's rays.
use raystep_core::{Camera, DVec2, DVec3};

// ANCHOR: projection
/// Where the camera puts points: view coordinates (x right, y up, z the
/// depth along the view direction) and pixel coordinates (x right, y down;
/// pixel (c, r) covers [c, c + 1) × [r, r + 1), its centre is at
/// (c + ½, r + ½)).
///
/// It is the inverse of [`Camera::pixel_ray`]: the ray through a pixel's
/// centre meets exactly the points that project onto that centre.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Projection {
    /// The camera.
    pub camera: Camera,
    /// Image width in pixels.
    pub width: u32,
    /// Image height in pixels.
    pub height: u32,
}

impl Projection {
    /// Step 1: a point in view coordinates: its offsets from the eye along
    /// the camera's right, up and forward axes.
    pub fn view(&self, p: DVec3) -> DVec3 {
        let d = p - self.camera.eye;
        DVec3::new(
            d.dot(self.camera.right),
            d.dot(self.camera.up),
            d.dot(self.camera.forward),
        )
    }

    /// Step 2: the perspective divide and the viewport: a point in view
    /// coordinates (z > 0, in front of the eye) to pixel coordinates.
    /// On the image plane at distance 1 the picture spans
    /// ±half_height·aspect across and ±half_height up and down.
    pub fn to_pixels(&self, v: DVec3) -> DVec2 {
        let c = &self.camera;
        let x = v.x / v.z / (c.half_height * c.aspect);
        let y = v.y / v.z / c.half_height;
        DVec2::new(
            (x + 1.0) / 2.0 * f64::from(self.width),
            (1.0 - y) / 2.0 * f64::from(self.height),
        )
    }

    /// The centre of pixel (column, row), where both methods sample.
    pub fn pixel_centre(column: u32, row: u32) -> DVec2 {
        DVec2::new(f64::from(column) + 0.5, f64::from(row) + 0.5)
    }
}
// ANCHOR_END: projection

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_point_on_a_pixel_ray_projects_onto_the_pixel_centre() {
        let camera = Camera::look_at(
            DVec3::new(1.0, 2.0, 5.0),
            DVec3::new(0.0, 0.5, 0.0),
            DVec3::Y,
            40.0,
            16.0 / 9.0,
        );
        let projection = Projection {
            camera,
            width: 32,
            height: 18,
        };
        for (column, row) in [(0, 0), (31, 17), (5, 11), (16, 9)] {
            let ray = camera.pixel_ray(column, row, 32, 18);
            let view = projection.view(ray.at(3.7));
            // the view depth of a point on a unit ray is t·(D·forward)
            assert!(
                (view.z - 3.7 * ray.direction.dot(camera.forward)).abs()
                    < 1e-12
            );
            let p = projection.to_pixels(view);
            assert!(
                (p - Projection::pixel_centre(column, row)).length() < 1e-9
            );
        }
    }
}
