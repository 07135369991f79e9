//! How tight a bounding volume is, measured: of the rays that hit the
//! bound, how many miss the object (the wasted object tests), and what
//! the bound saves on average.
use raystep_core::{Interval, Shape};

use crate::{Bound, BoundKind, BoundingSphere, Primitive, RandomLines};

/// The seed of the tightness measurements (tests, figures and charts all
/// use it, so they show the same rays).
pub const TIGHTNESS_SEED: u64 = 0x0B0D_2026;

/// What `rays` random rays did with an object and its bound.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Tightness {
    /// The rays shot.
    pub rays: u64,
    /// Rays that hit the bound.
    pub bound_hits: u64,
    /// Rays that hit the object.
    pub object_hits: u64,
    /// Rays that hit the bound but missed the object: object tests spent
    /// for nothing.
    pub wasted: u64,
    /// Rays that hit the object but missed the bound: hits a bounded object
    /// would lose. 0 for a correct bound.
    pub lost: u64,
}

impl Tightness {
    /// P(bound hit): the fraction of rays that hit the bound, so that pay
    /// for the object's test too.
    pub fn p_bound(&self) -> f64 {
        self.bound_hits as f64 / self.rays as f64
    }

    /// P(object hit): the fraction of rays that hit the object.
    pub fn p_object(&self) -> f64 {
        self.object_hits as f64 / self.rays as f64
    }

    /// P(object hit | bound hit): how tight the bound is (1 is a perfect
    /// fit). NaN if no ray hit the bound.
    pub fn p_object_given_bound(&self) -> f64 {
        (self.bound_hits - self.wasted) as f64 / self.bound_hits as f64
    }

    /// The fraction of bound hits that miss the object, 1 − P(object |
    /// bound). NaN if no ray hit the bound.
    pub fn wasted_fraction(&self) -> f64 {
        self.wasted as f64 / self.bound_hits as f64
    }

    // ANCHOR: expected_cost
    /// The average cost of a ray behind the bound, C_bound + P(bound hit)
    /// · C_object, in the units of the two costs. Without the bound every
    /// ray costs C_object.
    pub fn expected_cost(&self, c_bound: f64, c_object: f64) -> f64 {
        c_bound + self.p_bound() * c_object
    }

    /// C_object over the expected cost: above 1 the bound pays, below 1
    /// it costs more than it saves.
    pub fn speed_up(&self, c_bound: f64, c_object: f64) -> f64 {
        c_object / self.expected_cost(c_bound, c_object)
    }
    // ANCHOR_END: expected_cost
}

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

/// [`measure_tightness`] for this kind of bound around a primitive.
pub fn tightness(
    object: &dyn Primitive,
    kind: BoundKind,
    rays: u64,
    seed: u64,
) -> Tightness {
    measure_tightness(object, &kind.around(object), rays, seed)
}

// ANCHOR: measure_tightness
/// Shoots `rays` random rays along lines that meet the object's
/// [`sampling_sphere`] ([`RandomLines`] with `seed`) and counts what they
/// hit. The same seed gives the same counts on every machine.
pub fn measure_tightness(
    object: &dyn Shape,
    bound: &Bound,
    rays: u64,
    seed: u64,
) -> Tightness {
    let mut counts = Tightness {
        rays,
        ..Tightness::default()
    };
    let lines = RandomLines::new(sampling_sphere(object), seed);
    for ray in lines.take(rays as usize) {
        // Step 1: both tests, on every ray.
        let on_bound = bound.hit(&ray, Interval::FORWARD).is_some();
        let on_object = object.intersect(&ray, Interval::FORWARD).is_some();
        // Step 2: count what they said.
        counts.bound_hits += u64::from(on_bound);
        counts.object_hits += u64::from(on_object);
        counts.wasted += u64::from(on_bound && !on_object);
        counts.lost += u64::from(on_object && !on_bound);
    }
    counts
}
// ANCHOR_END: measure_tightness
