//! Any hit: is the shadow ray blocked?
use ch03::World;
use raystep_core::{Interval, Ray};

// ANCHOR: occluded
/// Does anything in `world` meet `ray` with `t` inside `interval`?
///
/// A shadow ray asks a weaker question than a primary ray: not "what is
/// the closest hit?" but "is there any hit at all?". The world answers it
/// with [`World::any_hit`]: chapter 3's brute-force loop, cut short at the
/// first blocker (`ch03::BruteForce`), or whatever faster structure a later
/// chapter puts behind the same question.
pub fn occluded(world: &World, ray: &Ray, interval: Interval) -> bool {
    world.any_hit(ray, interval)
}
// ANCHOR_END: occluded
