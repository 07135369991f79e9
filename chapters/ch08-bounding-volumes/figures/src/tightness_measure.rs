//! How tight a bounding volume is, measured: random lines through the
//! object's sampling sphere (`raystep_bench::sampling_sphere`), each
//! asked of the bound and of the object, counted into the lecture's
//! [`Tightness`].
use ch08::{Bound, BoundKind, Primitive, RandomLines, Tightness};
use raystep_bench::sampling_sphere;
use raystep_core::{Interval, Shape};

/// [`measure_tightness`] for this kind of bound around a primitive.
pub fn tightness(
    object: &dyn Primitive, kind: BoundKind, rays: u64, seed: u64,
) -> Tightness {
    measure_tightness(object, &kind.around(object), rays, seed)
}

/// Shoots `rays` random rays along lines that meet the object's
/// [`sampling_sphere`] ([`RandomLines`] with `seed`) and counts what they
/// hit. The same seed gives the same counts on every machine.
pub fn measure_tightness(
    object: &dyn Shape, bound: &Bound, rays: u64, seed: u64,
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
