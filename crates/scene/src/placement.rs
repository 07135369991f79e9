//! Where a mesh is put in the world: scaled, rotated about x, y and z,
//! then moved.
use raystep_core::glam::DMat3;
use raystep_core::{DAffine3, DVec3};

/// A mesh's placement: `scale`, then `rotate` (degrees about x, then y,
/// then z), then `translate`. A scene's `mesh = { … }` and
/// `[[instances]]` entries hold one.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Placement {
    /// The scale along the mesh's own x, y and z, no component 0 (a
    /// negative one mirrors the mesh).
    pub scale: DVec3,
    /// The rotations about x, y and z, in degrees, right-handed (a
    /// positive angle turns y towards z about x, z towards x about y, x
    /// towards y about z).
    pub rotate: DVec3,
    /// The move that comes last.
    pub translate: DVec3,
}

impl Placement {
    /// Leaves the mesh where it is: scale 1, rotate 0, translate 0.
    pub const IDENTITY: Placement = Placement {
        scale: DVec3::ONE,
        rotate: DVec3::ZERO,
        translate: DVec3::ZERO,
    };

    /// T · Rz · Ry · Rx · S: scale first, then rotate about x, then y,
    /// then z (degrees, right-handed), then translate.
    ///
    /// Multiples of 90° rotate exactly (their sines and cosines are 0 and
    /// ±1, not 6e-17), so an axis-aligned mesh stays axis-aligned. A
    /// normal goes to the world by the inverse transpose of the matrix
    /// (`to_world().matrix3.inverse().transpose()`), not by the matrix.
    pub fn to_world(&self) -> DAffine3 {
        let [x, y, z] = self.rotate.to_array().map(sin_cos_degrees);
        let rx = DMat3::from_cols(
            DVec3::X,
            DVec3::new(0.0, x.1, x.0),
            DVec3::new(0.0, -x.0, x.1),
        );
        let ry = DMat3::from_cols(
            DVec3::new(y.1, 0.0, -y.0),
            DVec3::Y,
            DVec3::new(y.0, 0.0, y.1),
        );
        let rz = DMat3::from_cols(
            DVec3::new(z.1, z.0, 0.0),
            DVec3::new(-z.0, z.1, 0.0),
            DVec3::Z,
        );
        let matrix = rz * ry * rx * DMat3::from_diagonal(self.scale);
        DAffine3::from_mat3_translation(matrix, self.translate)
    }
}

impl Default for Placement {
    /// [`Placement::IDENTITY`].
    fn default() -> Placement {
        Placement::IDENTITY
    }
}

/// `(sin, cos)` of `degrees`, exact at the multiples of 90°.
fn sin_cos_degrees(degrees: f64) -> (f64, f64) {
    let turn = degrees.rem_euclid(360.0);
    if turn % 90.0 == 0.0 {
        // (rem_euclid may round a tiny negative angle up to 360)
        let quarter = (turn / 90.0) as usize % 4;
        [(0.0, 1.0), (1.0, 0.0), (0.0, -1.0), (-1.0, 0.0)][quarter]
    } else {
        turn.to_radians().sin_cos()
    }
}
