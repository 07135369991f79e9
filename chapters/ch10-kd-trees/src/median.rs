//! The median tree: every node cut in the middle of its longest side,
//! the objects not looked at (beside the SAH, what a plane costs when
//! nobody weighs it).
use raystep_core::Aabb;

use crate::MEDIAN_LEAF;
use crate::builder_io::{Input, Output};
use crate::events::{Plane, children, sides};

/// Builds the subtree over `objects` in box `node` at `depth` (the
/// whole tree: all the objects in the root's box at depth 0).
pub(crate) fn subtree(
    input: &Input, objects: &[u32], node: Aabb, depth: usize, out: &mut Output,
) {
    // Step 1: the middle of the longest side.
    let axis = (node.max - node.min).max_position();
    let position = 0.5 * (node.min[axis] + node.max[axis]);
    let inside = node.min[axis] < position && position < node.max[axis];
    // Step 2: a leaf when few objects are left, or the tree is deep.
    if objects.len() <= MEDIAN_LEAF || depth >= input.max_depth || !inside {
        out.leaf(objects.iter().copied());
        return;
    }
    // Step 3: each object to its side (flat ones in the plane below).
    let plane = Plane {
        axis,
        position,
        planar_below: true,
        cost: 0.0,
        counts: (0, 0),
    };
    let boxes = objects.iter().map(|&i| input.bounds_in(i, &node));
    let (below, above) = sides(objects, boxes, &plane);
    // Step 4: a cut that separates nothing (every object on both
    // sides) makes no progress: a leaf. Without this, tiny cells under
    // larger triangles would split on down to the depth limit.
    if below.len() == objects.len() && above.len() == objects.len() {
        out.leaf(objects.iter().copied());
        return;
    }
    let (below_box, above_box) = children(&node, axis, position);
    let me = out.split(axis, position);
    subtree(input, &below, below_box, depth + 1, out);
    out.above(me);
    subtree(input, &above, above_box, depth + 1, out);
}
