//! A side view of 3D space, for diagrams of what happens in the vertical
//! plane of a ray.
use raystep_core::{DVec2, DVec3};

/// A 2D side view of 3D space: the vertical plane through `origin` that
/// contains the horizontal direction `along`, drawn as (distance along it,
/// height). Points off the plane are projected straight onto it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SideView {
    /// A point of the plane: distances are measured from it.
    pub origin: DVec3,
    /// The plane's horizontal unit direction.
    pub along: DVec3,
    /// The plane's unit normal, horizontal.
    pub across: DVec3,
}

impl SideView {
    /// The side view through `origin` containing the horizontal part of
    /// `dir` (which must not be vertical).
    pub fn new(origin: DVec3, dir: DVec3) -> SideView {
        let along = DVec3::new(dir.x, 0.0, dir.z).normalize();
        SideView {
            origin,
            along,
            across: along.cross(DVec3::Y),
        }
    }

    /// The drawing point of `p` (its projection onto the plane): (distance
    /// along from the origin, height).
    pub fn at(&self, p: DVec3) -> DVec2 {
        DVec2::new((p - self.origin).dot(self.along), p.y)
    }

    /// The drawing direction of `d`.
    pub fn dir(&self, d: DVec3) -> DVec2 {
        DVec2::new(d.dot(self.along), d.y)
    }

    /// The 3D point of drawing point `q`, on the plane.
    pub fn point(&self, q: DVec2) -> DVec3 {
        self.origin + q.x * self.along + (q.y - self.origin.y) * DVec3::Y
    }

    /// How far `p` lies off the plane.
    pub fn off(&self, p: DVec3) -> f64 {
        (p - self.origin).dot(self.across)
    }
}

/// Where `camera` puts the point `p` on a `width × height` image: pixel
/// coordinates from the top-left corner (x right, y down), to place labels
/// on a render. (Chapter 7 derives the same projection step by step for
/// its rasterizer.)
pub fn camera_pixel(
    camera: &raystep_core::Camera, p: DVec3, width: u32, height: u32,
) -> DVec2 {
    let d = p - camera.eye;
    let z = d.dot(camera.forward);
    let x = d.dot(camera.right) / z / (camera.half_height * camera.aspect);
    let y = d.dot(camera.up) / z / camera.half_height;
    DVec2::new(
        (x + 1.0) / 2.0 * f64::from(width),
        (1.0 - y) / 2.0 * f64::from(height),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn side_view_round_trips_points_in_its_plane() {
        let view = SideView::new(
            DVec3::new(1.0, 2.0, 3.0),
            DVec3::new(3.0, -5.0, 4.0),
        );
        let p = view.point(DVec2::new(2.5, -1.0));
        assert!((view.at(p) - DVec2::new(2.5, -1.0)).length() < 1e-12);
        assert!(view.off(p).abs() < 1e-12);
        assert!((view.off(p + view.across) - 1.0).abs() < 1e-12);
    }

    #[test]
    fn the_camera_puts_its_target_in_the_image_centre() {
        let camera = raystep_core::Camera::look_at(
            DVec3::new(0.0, 1.0, 5.0),
            DVec3::ZERO,
            DVec3::Y,
            40.0,
            2.0,
        );
        let centre = camera_pixel(&camera, DVec3::ZERO, 200, 100);
        assert!((centre - DVec2::new(100.0, 50.0)).length() < 1e-9);
        // the pixel ray through a pixel's centre meets points that land there
        let ray = camera.pixel_ray(17, 80, 200, 100);
        let at = camera_pixel(&camera, ray.at(3.0), 200, 100);
        assert!((at - DVec2::new(17.5, 80.5)).length() < 1e-9);
    }
}
