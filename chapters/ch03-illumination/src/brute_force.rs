//! The lecture's way of finding what a ray hits: ask every object.
use raystep_core::{Hit, Interval, Ray};
use raystep_world::{Accelerator, Object};

/// The lecture's loop over the objects, with no speed-up at all: every ray
/// is tested against every object. It is the first [`Accelerator`]; the
/// bounding volumes, grids and kd-trees of chapters 8–10 answer the same
/// two questions faster, and must give the same answers.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct BruteForce;

impl Accelerator for BruteForce {
    // ANCHOR: closest_hit
    /// For each object: does the ray hit it? Keep the closest.
    fn closest_hit(
        &self, objects: &[Object], ray: &Ray, interval: Interval,
    ) -> Option<(usize, Hit)> {
        let mut closest = None;
        let mut interval = interval;
        for (index, object) in objects.iter().enumerate() {
            if let Some(hit) = object.shape.intersect(ray, interval) {
                interval = interval.with_max(hit.t); // only closer hits from now on
                closest = Some((index, hit));
            }
        }
        closest
    }
    // ANCHOR_END: closest_hit

    // ANCHOR: any_hit
    /// The same loop, cut short (chapter 4's shadow rays): a shadow ray
    /// only asks whether the light is blocked, not by what, so the first
    /// blocker found answers it. Nothing is sorted, no closest t is kept,
    /// and in a scene where most shadow rays are blocked most of the loop
    /// is skipped.
    fn any_hit(
        &self, objects: &[Object], ray: &Ray, interval: Interval,
    ) -> bool {
        for object in objects {
            if object.shape.intersect(ray, interval).is_some() {
                return true; // one blocker is enough
            }
        }
        false
    }
    // ANCHOR_END: any_hit
}
