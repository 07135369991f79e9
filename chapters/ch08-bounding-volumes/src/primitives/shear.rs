//! The watertight test's view of a ray (exercise 2 fills in its steps):
//! the axes it renames and the shear that turns the ray into the z axis.
use raystep_core::DVec3;

/// Steps 1 and 2 of [`watertight`](crate::watertight) for one direction:
/// kept per ray by the walks, which shear every triangle they test with
/// it ([`Shear::of`], [`Shear::vertex`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Shear {
    /// kx, ky, kz: kz the axis the ray goes along most.
    pub axes: [usize; 3],
    /// (D[kx]/D[kz], D[ky]/D[kz], 1/D[kz]): the shear that takes the
    /// direction to (0, 0, 1).
    pub shear: DVec3,
}
