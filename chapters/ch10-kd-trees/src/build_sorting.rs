//! The simple SAH build: at every node, list every object's candidate
//! planes, sort them, sweep. Sorting at every level costs O(N log N) per
//! level: O(N log² N) in all.
use raystep_core::Aabb;

use crate::events::{
    Side, children, push_events, side, sweep, worth_splitting,
};
use crate::kdtree::{Input, Output};
use crate::{Event, event_order};

/// Builds the subtree over `objects` in box `node` at depth 0.
pub(crate) fn build(
    input: &Input,
    objects: &[u32],
    node: Aabb,
    out: &mut Output,
) {
    subtree(input, objects, node, 0, out);
}

fn subtree(
    input: &Input,
    objects: &[u32],
    node: Aabb,
    depth: usize,
    out: &mut Output,
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
    let (mut below, mut above) = (Vec::new(), Vec::new());
    for (&i, b) in objects.iter().zip(&boxes) {
        match side(b, &plane) {
            Side::Below => below.push(i),
            Side::Above => above.push(i),
            Side::Both => {
                below.push(i);
                above.push(i);
            }
        }
    }
    let (below_box, above_box) = children(&node, plane.axis, plane.position);
    let me = out.split(plane.axis, plane.position);
    subtree(input, &below, below_box, depth + 1, out);
    out.above(me);
    subtree(input, &above, above_box, depth + 1, out);
}
