//! The rays of chapter 8's tightness measurements: the lecture's random
//! lines (`ch08::RandomLines`) through a sphere around the object, drawn
//! with one seed, so that the tests, the figures and the charts all show
//! the same rays.
use ch08::BoundingSphere;
use raystep_core::Shape;

/// The seed of the tightness measurements.
pub const TIGHTNESS_SEED: u64 = 0x0B0D_2026;

/// The sphere the tightness rays are drawn through: around the object's
/// box's centre, with twice the radius of the box's circumsphere. Every
/// bound of the object fits inside it, and 3 rays in 4 pass the box's
/// circumsphere by, as most rays of a scene miss most of its objects.
pub fn sampling_sphere(object: &dyn Shape) -> BoundingSphere {
    let around = BoundingSphere::around_box(&object.bounds());
    BoundingSphere {
        radius: 2.0 * around.radius,
        ..around
    }
}
