use crate::Ray;
use glam::DVec3;

/// A pinhole camera: the lecture's "for each pixel on screen, shoot a ray".
///
/// The eye sits at `look_from`; the image plane is one unit in front of it,
/// facing `look_at`, with `up` pointing up in the picture.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Camera {
    /// The eye: every primary ray starts here.
    pub eye: DVec3,
    /// Unit vector from the eye to the centre of the image plane.
    pub forward: DVec3,
    /// Unit vector to the right in the picture.
    pub right: DVec3,
    /// Unit vector up in the picture.
    pub up: DVec3,
    /// Half the image plane's height at distance 1: `tan(fov_y / 2)`.
    pub half_height: f64,
    /// Image width divided by height.
    pub aspect: f64,
}

impl Camera {
    /// A camera at `look_from` looking at `look_at`, `vfov_degrees` the
    /// vertical field of view and `aspect` the width/height ratio.
    ///
    /// `up` need not be perpendicular to the view direction, only not
    /// parallel to it.
    pub fn look_at(
        look_from: DVec3, look_at: DVec3, up: DVec3, vfov_degrees: f64,
        aspect: f64,
    ) -> Camera {
        let forward = (look_at - look_from).normalize();
        let right = forward.cross(up).normalize();
        let up = right.cross(forward);
        Camera {
            eye: look_from,
            forward,
            right,
            up,
            half_height: (vfov_degrees.to_radians() / 2.0).tan(),
            aspect,
        }
    }

    /// The ray through image-plane coordinates `(u, v)`, both in `[0, 1]`:
    /// `(0, 0)` is the top-left corner of the picture, `(1, 1)` the
    /// bottom-right. The direction is a unit vector, so `t` is a distance.
    pub fn ray(&self, u: f64, v: f64) -> Ray {
        let x = (2.0 * u - 1.0) * self.half_height * self.aspect;
        let y = (1.0 - 2.0 * v) * self.half_height;
        let direction =
            (self.forward + x * self.right + y * self.up).normalize();
        Ray::new(self.eye, direction)
    }

    /// The ray through the centre of pixel `(column, row)` of a
    /// `width × height` image, rows counted from the top.
    pub fn pixel_ray(
        &self, column: u32, row: u32, width: u32, height: u32,
    ) -> Ray {
        let u = (f64::from(column) + 0.5) / f64::from(width);
        let v = (f64::from(row) + 0.5) / f64::from(height);
        self.ray(u, v)
    }

    /// [`pixel_ray`](Camera::pixel_ray) of every pixel of a `width ×
    /// height` image, row by row from the top: `(column, row, ray)`.
    pub fn pixel_rays(
        &self, width: u32, height: u32,
    ) -> impl Iterator<Item = (u32, u32, Ray)> {
        let camera = *self;
        (0..height).flat_map(move |row| {
            (0..width).map(move |column| {
                (column, row, camera.pixel_ray(column, row, width, height))
            })
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn centre_ray_looks_at_the_target_and_corners_span_the_fov() {
        let cam = Camera::look_at(
            DVec3::new(0.0, 0.0, 5.0),
            DVec3::ZERO,
            DVec3::Y,
            90.0,
            2.0,
        );
        let centre = cam.ray(0.5, 0.5);
        assert!((centre.direction - DVec3::NEG_Z).length() < 1e-12);
        // 90° vertical fov: the top edge is 45° up; the aspect makes x twice y.
        let top_left = cam.ray(0.0, 0.0).direction;
        assert!((top_left.y / -top_left.z - 1.0).abs() < 1e-12);
        assert!((top_left.x / -top_left.z + 2.0).abs() < 1e-12);
        // rows count from the top
        assert!(cam.pixel_ray(0, 0, 4, 4).direction.y > 0.0);
        assert!(cam.pixel_ray(0, 3, 4, 4).direction.y < 0.0);
        // every pixel once, row by row
        let all: Vec<_> = cam.pixel_rays(4, 3).collect();
        assert_eq!(all.len(), 12);
        assert_eq!(all[6], (2, 1, cam.pixel_ray(2, 1, 4, 3)));
    }
}
