//! Any hit: is the shadow ray blocked?
use ch03::World;
use raystep_core::{Interval, Ray};

// ANCHOR: occluded
/// Does anything in `world` meet `ray` with `t` inside `interval`?
///
/// Chapter 03's closest-hit loop, cut short: a shadow ray only asks
/// whether the light is blocked, not by what, so the first blocker found
/// answers it. Nothing is sorted, no closest t is kept, and in a scene
/// where most shadow rays are blocked most of the loop is skipped.
pub fn occluded(world: &World, ray: &Ray, interval: Interval) -> bool {
    for object in &world.objects {
        if object.shape.intersect(ray, interval).is_some() {
            return true; // one blocker is enough
        }
    }
    false
}
// ANCHOR_END: occluded
