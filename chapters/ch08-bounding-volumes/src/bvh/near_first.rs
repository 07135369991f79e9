//! Exercise 6: the near-first walk of a [`Bvh`] for the closest hit.
//!
//! A box the ray misses rules out everything inside it with one test;
//! visiting the nearer child first finds a close hit early, and every box
//! that begins beyond it is then skipped unopened.
use raystep_core::{Hit, Interval, Ray};
use raystep_world::Object;

use crate::Bvh;
use crate::bvh::enter;

// ANCHOR: near_first
/// The closest hit of `ray` within `interval` among `objects` (the list
/// `bvh` was built over): the object's index and the hit.
///
/// Visit the nodes whose boxes the ray enters, the nearer child first,
/// and skip every box that begins beyond the closest hit found so far.
pub fn near_first_closest_hit(
    bvh: &Bvh, objects: &[Object], ray: &Ray, interval: Interval,
) -> Option<(usize, Hit)> {
    let mut interval = interval;
    let mut closest = None;
    let mut test = |index: u32, interval: &mut Interval| {
        let index = index as usize;
        if let Some(hit) = objects[index].shape.intersect(ray, *interval) {
            *interval = interval.with_max(hit.t); // only closer ones now
            closest = Some((index, hit));
        }
    };
    // Step 1: the objects outside the tree (planes), one by one.
    for &index in &bvh.unbounded {
        test(index, &mut interval);
    }
    // Step 2: the nodes still to visit, each with the t at which the ray
    // enters its box; the root first.
    let mut stack: Vec<(u32, f64)> = Vec::with_capacity(64);
    if let Some(root) = bvh.nodes.first()
        && let Some(t) = enter(root, ray, interval)
    {
        stack.push((0, t));
    }
    while let Some((k, entry)) = stack.pop() {
        // Step 3: skip a box that begins beyond the closest hit (the
        // interval has shrunk since the box was pushed).
        if entry > interval.max {
            continue;
        }
        let node = bvh.nodes[k as usize];
        if node.is_leaf() {
            // Step 4: a leaf: test its objects.
            for &index in bvh.leaf_objects(&node) {
                test(index, &mut interval);
            }
        } else {
            // Step 5: push the farther child first, so that the nearer
            // one is visited first and shrinks the interval for it.
            let (a, b) = (node.first, node.first + 1);
            let ta = enter(&bvh.nodes[a as usize], ray, interval);
            let tb = enter(&bvh.nodes[b as usize], ray, interval);
            match (ta, tb) {
                (Some(ta), Some(tb)) if tb < ta => {
                    stack.extend([(a, ta), (b, tb)])
                }
                (Some(ta), Some(tb)) => stack.extend([(b, tb), (a, ta)]),
                (Some(ta), None) => stack.push((a, ta)),
                (None, Some(tb)) => stack.push((b, tb)),
                (None, None) => {}
            }
        }
    }
    closest
}
// ANCHOR_END: near_first
