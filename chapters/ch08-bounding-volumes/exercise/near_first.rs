//! Exercise 6 (★★★): the near-first walk of a [`Bvh`] for the closest hit.
//!
//! Fill in `near_first_closest_hit`; `cargo run --release -- check ch08`
//! judges it.
use raystep_core::{Hit, Interval, Ray};
use raystep_world::Object;

use crate::Bvh;
#[allow(unused_imports, reason = "the box test the walk needs")]
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
    // TODO:
    // 1. Test the objects outside the tree, `bvh.unbounded` (planes),
    //    with `objects[i].shape.intersect(ray, interval)`; after each
    //    hit, shrink the interval to end at its t
    //    (`interval.with_max(hit.t)`) and remember (i, hit).
    // 2. A stack of (node index, entry t): push the root, node 0, if the
    //    ray enters its box: `enter(&bvh.nodes[0], ray, interval)` gives
    //    the entry t, or None for a miss (no nodes: no tree).
    // 3. Pop a node; skip it if its entry t is beyond `interval.max` (a
    //    closer hit was found since it was pushed).
    // 4. A leaf (`node.is_leaf()`): test its objects,
    //    `bvh.leaf_objects(&node)`, as in step 1.
    // 5. An interior node: its children are nodes `node.first` and
    //    `node.first + 1`. Test both boxes; push the one entered farther
    //    first and the nearer last, so that the nearer is popped first.
    // 6. The stack empty: the closest hit remembered, if any.
    let _ = (bvh, objects, ray, interval);
    todo!("ch08 exercise 6: near_first_closest_hit")
}
// ANCHOR_END: near_first
