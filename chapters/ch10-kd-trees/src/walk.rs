//! The front-to-back walk: down the tree, nearest child first, the far
//! one pushed on a stack with the stretch of the ray inside it.
use raystep_core::{Interval, Ray};

use ch09::hit_in_cell;

use crate::{KdNode, KdTree, MAX_DEPTH, Split, Step, traversal_step};

/// A node as the walk reaches it, with the stretch `[t_min, t_max]` of
/// the ray inside it; a leaf comes with its objects.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct KdVisit<'a> {
    /// The node's index.
    pub node: u32,
    /// Where the ray enters it.
    pub t_min: f64,
    /// Where the ray leaves it.
    pub t_max: f64,
    /// A leaf's objects (`None` for an interior node).
    pub objects: Option<&'a [u32]>,
}

// ANCHOR: walk
/// Walks the nodes along `ray` within `interval`, front to back, telling
/// `visit` each node it reaches. `visit` answers how far along the ray
/// anything still matters (the closest hit so far; −∞ to stop): a node
/// taken from the stack that the ray enters only after that is skipped.
///
/// Front to back, every node on the stack starts where the last leaf
/// ends, so a hit inside that leaf empties the stack. Not so for a ray
/// lying in a plane: it is in both children over the same stretch, and
/// the second must still be looked at.
///
/// A ray with a NaN or zero direction meets no node.
pub fn kd_walk<'a>(
    tree: &'a KdTree, ray: &Ray, interval: Interval,
    mut visit: impl FnMut(KdVisit<'a>) -> f64,
) {
    let d = ray.direction;
    if d.is_nan() || d == d * 0.0 || tree.nodes.is_empty() {
        return;
    }
    // Step 1: the stretch of the ray inside the root's box.
    let Some(inside) = ch08::slab_test(&tree.bounds, ray, interval) else {
        return;
    };
    let inverse = 1.0 / d;
    let mut stack = [(0u32, 0.0, 0.0); MAX_DEPTH + 1];
    let mut top = 0;
    let (mut node, mut t_min, mut t_max) = (0u32, inside.min, inside.max);
    let mut bound;
    loop {
        match tree.nodes[node as usize] {
            // Step 2: an interior node: near child now, far one later.
            KdNode::Split { axis, plane, above } => {
                let _ = visit(KdVisit {
                    node,
                    t_min,
                    t_max,
                    objects: None,
                });
                let axis = axis as usize;
                let split = Split {
                    plane,
                    below: node + 1,
                    above,
                };
                match traversal_step(
                    split,
                    ray.origin[axis],
                    inverse[axis],
                    t_min,
                    t_max,
                ) {
                    Step::One(child) => node = child,
                    Step::Both {
                        near,
                        far,
                        near_until,
                        far_from,
                    } => {
                        stack[top] = (far, far_from, t_max);
                        top += 1;
                        (node, t_max) = (near, near_until);
                    }
                }
                continue;
            }
            // Step 3: a leaf: its objects, and how far the ray still matters.
            KdNode::Leaf { first, count } => {
                let objects = Some(tree.leaf_objects(first, count));
                bound = visit(KdVisit {
                    node,
                    t_min,
                    t_max,
                    objects,
                });
            }
        }
        // Step 4: the next far child the ray enters before `bound`.
        loop {
            if top == 0 {
                return;
            }
            top -= 1;
            (node, t_min, t_max) = stack[top];
            if !hit_in_cell(bound, t_min) {
                break;
            }
        }
    }
}
// ANCHOR_END: walk
