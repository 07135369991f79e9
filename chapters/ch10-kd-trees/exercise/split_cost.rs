//! Exercise 1 (★★): the SAH cost of one split plane.
use raystep_core::Aabb;

use crate::KdCosts;

// ANCHOR: split_cost
/// The surface area heuristic's cost of cutting a node with box `node`
/// by the plane `x[axis] = plane` into a child below it (`n_below`
/// objects) and one above it (`n_above`), each child a leaf:
///
/// C = C_trav + (1 − b) · C_isect · (P_below·N_below + P_above·N_above)
///
/// where P_child = A(child) / A(node) is the chance that a ray through
/// the node passes through the child, and b is the empty bonus when one
/// child holds nothing (0 otherwise). A node of area 0 (a point, or a
/// line) gives no ratio: each child counts as certainly passed, P = 1.
pub fn split_cost(
    node: &Aabb, axis: usize, plane: f64, n_below: usize, n_above: usize,
    costs: &KdCosts,
) -> f64 {
    // TODO:
    // 1. The children's boxes: copies of `node`, the one below with
    //    `max[axis] = plane`, the one above with `min[axis] = plane`.
    // 2. P = A(child) / A(node) for each (`Aabb::surface_area`); if the
    //    node's area is 0, both are 1.
    // 3. b = `costs.empty_bonus` if a child has no objects, else 0.
    // 4. C = traversal + (1 − b) · intersection · (P_b·N_b + P_a·N_a).
    let _ = (node, axis, plane, n_below, n_above, costs);
    todo!("ch10 exercise 1: split_cost")
}
// ANCHOR_END: split_cost
