//! Simple 3D → 2D projections, for drawing 3D scenes with the 2D primitives.

use raystep_core::{DVec2, DVec3};

/// A projection from 3D world space onto the 2D drawing plane (y up).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Projection {
    kind: Kind,
}

#[derive(Clone, Copy, Debug, PartialEq)]
enum Kind {
    /// A pinhole camera: an orthonormal basis looking along `forward`.
    Perspective {
        eye: DVec3,
        right: DVec3,
        up: DVec3,
        forward: DVec3,
        tan_half_fov: f64,
    },
    /// x right, y up, z drawn along `z_axis` (the projected unit z vector).
    Oblique { z_axis: DVec2 },
}

impl Projection {
    /// A pinhole camera at `eye` looking at `target`, with `up` roughly up and a vertical field
    /// of view of `fov_y_degrees`.
    ///
    /// [`Projection::project`] returns coordinates on the image plane one unit in front of the
    /// eye (x right, y up), so the visible part is `[-a·t, a·t] × [-t, t]` with
    /// `t = tan(fov_y / 2)` ([`Projection::tan_half_fov`]) and `a` the aspect ratio: view it with
    /// `page.view(DVec2::new(-a * t, -t), DVec2::new(a * t, t))`. Points must lie in front of
    /// the eye; points behind it come out mirrored.
    ///
    /// # Panics
    /// If `eye == target` or `up` is parallel to the view direction.
    pub fn perspective(
        eye: DVec3, target: DVec3, up: DVec3, fov_y_degrees: f64,
    ) -> Projection {
        let forward = (target - eye).normalize();
        let right = forward.cross(up).normalize();
        assert!(
            forward.is_finite() && right.is_finite(),
            "perspective projection needs eye != target and `up` not along the view direction"
        );
        let up = right.cross(forward);
        Projection {
            kind: Kind::Perspective {
                eye,
                right,
                up,
                forward,
                tan_half_fov: (fov_y_degrees.to_radians() / 2.0).tan(),
            },
        }
    }

    /// A cabinet-style oblique projection: x to the right, y up, and the z axis drawn at
    /// `angle_degrees` counter-clockwise from the x axis, shortened by `depth_scale`:
    /// `(x, y, z) ↦ (x + k·z·cos θ, y + k·z·sin θ)`.
    ///
    /// `oblique(45.0, 0.5)` draws +z receding up and to the right (the classic cabinet view);
    /// `oblique(225.0, 0.5)` draws +z coming towards the viewer, down and to the left, which
    /// looks right-handed.
    pub fn oblique(angle_degrees: f64, depth_scale: f64) -> Projection {
        let a = angle_degrees.to_radians();
        Projection {
            kind: Kind::Oblique {
                z_axis: depth_scale * DVec2::new(a.cos(), a.sin()),
            },
        }
    }

    /// The 2D drawing-plane point (y up) of 3D point `p`.
    pub fn project(&self, p: DVec3) -> DVec2 {
        match self.kind {
            Kind::Perspective {
                eye,
                right,
                up,
                forward,
                ..
            } => {
                let d = p - eye;
                let depth = d.dot(forward);
                DVec2::new(d.dot(right) / depth, d.dot(up) / depth)
            }
            Kind::Oblique { z_axis } => DVec2::new(p.x, p.y) + p.z * z_axis,
        }
    }

    /// For a perspective projection, tan(fov_y / 2): the image plane's half height. 1 for an
    /// oblique projection.
    pub fn tan_half_fov(&self) -> f64 {
        match self.kind {
            Kind::Perspective { tan_half_fov, .. } => tan_half_fov,
            Kind::Oblique { .. } => 1.0,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn perspective_centres_the_target_and_keeps_up_up() {
        let p = Projection::perspective(
            DVec3::new(0.0, 0.0, 5.0),
            DVec3::ZERO,
            DVec3::Y,
            60.0,
        );
        assert!(p.project(DVec3::ZERO).length() < 1e-12);
        let q = p.project(DVec3::new(1.0, 2.0, 0.0));
        assert!((q - DVec2::new(0.2, 0.4)).length() < 1e-12, "{q}");
        assert!((p.tan_half_fov() - 30f64.to_radians().tan()).abs() < 1e-12);
    }

    #[test]
    fn oblique_draws_z_at_the_angle() {
        let p = Projection::oblique(90.0, 0.5);
        let q = p.project(DVec3::new(1.0, 2.0, 2.0));
        assert!((q - DVec2::new(1.0, 3.0)).length() < 1e-12, "{q}");
    }
}
