use raystep_core::{Hit, Interval, Ray};

use crate::Object;

// ANCHOR: accelerator
/// The one seam between a collection of objects and a tracer: the two
/// questions every tracer asks of the objects of a world.
///
/// Chapter 3's brute-force loop (`ch03::BruteForce`: "for each object,
/// does the ray hit it? keep the closest") is the first implementation;
/// chapters 8–10 add a bounding volume hierarchy, a grid and a kd-tree
/// behind the same two methods. A tracer asks [`World::closest_hit`] and
/// [`World::any_hit`](crate::World::any_hit) and never knows which one
/// answers, so every chapter's tracer runs on every accelerator unchanged.
///
/// An accelerator holds only what it built from the objects' bounds (a
/// tree of indices, a grid of cell lists); the objects themselves are
/// handed in with every question, and identified by their index in that
/// slice. One built for a list of objects answers for that list only.
///
/// [`World::closest_hit`]: crate::World::closest_hit
pub trait Accelerator: std::fmt::Debug + Send + Sync {
    /// The closest hit of `ray` among `objects` with `t` in `interval`:
    /// which object (its index), and the hit.
    fn closest_hit(
        &self, objects: &[Object], ray: &Ray, interval: Interval,
    ) -> Option<(usize, Hit)>;

    /// Does any of `objects` meet `ray` with `t` in `interval`? (A shadow
    /// ray asks only this: one blocker is enough.)
    fn any_hit(
        &self, objects: &[Object], ray: &Ray, interval: Interval,
    ) -> bool;
}
// ANCHOR_END: accelerator
