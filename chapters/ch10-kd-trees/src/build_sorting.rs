//! The simple SAH build: at every node, list every object's candidate
//! planes, sort them, sweep. Sorting at every level costs O(N log N) per
//! level: O(N log² N) in all.
use raystep_core::Aabb;

use crate::builder_io::{Input, Output};
use crate::events::{children, push_events, sides, sweep, worth_splitting};
use crate::{Event, event_order};

/// Builds the subtree over `objects` in box `node` at `depth` (the
/// whole tree: all the objects in the root's box at depth 0).
pub(crate) fn subtree(
    input: &Input, objects: &[u32], node: Aabb, depth: usize, out: &mut Output,
) {
    // Step 1: every object's box in this node.
    let boxes: Vec<Aabb> =
        objects.iter().map(|&i| input.bounds_in(i, &node)).collect();
    // Step 2: the cheapest plane on each axis, from freshly sorted events.
    let mut best = None;
    if !objects.is_empty() && depth < input.max_depth {
        for axis in 0..3 {
            let mut events: Vec<Event> = Vec::with_capacity(2 * objects.len());
            for (&i, b) in objects.iter().zip(&boxes) {
                push_events(&mut events, i, b, axis);
            }
            events.sort_unstable_by(event_order);
            sweep(&events, axis, objects.len(), &node, &input.costs, &mut best);
        }
    }
    // Step 3: a leaf, unless the plane pays.
    let Some(plane) =
        best.filter(|p| worth_splitting(p, objects.len(), &input.costs))
    else {
        out.leaf(objects.iter().copied());
        return;
    };
    // Step 4: each object to its side (or both), then the two children.
    let (below, above) = sides(objects, boxes, &plane);
    let (below_box, above_box) = children(&node, plane.axis, plane.position);
    let me = out.split(plane.axis, plane.position);
    subtree(input, &below, below_box, depth + 1, out);
    out.above(me);
    subtree(input, &above, above_box, depth + 1, out);
}
