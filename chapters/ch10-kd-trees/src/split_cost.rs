//! Exercise 1: the SAH cost of one split plane.
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
    // Step 1: the two children's boxes: the node cut at the plane.
    let (mut below, mut above) = (*node, *node);
    below.max[axis] = plane;
    above.min[axis] = plane;
    // Step 2: the chance of passing through each child.
    let area = node.surface_area();
    let (p_below, p_above) = if area > 0.0 {
        (below.surface_area() / area, above.surface_area() / area)
    } else {
        (1.0, 1.0)
    };
    // Step 3: the bonus when one child is empty.
    let bonus = if n_below == 0 || n_above == 0 {
        costs.empty_bonus
    } else {
        0.0
    };
    // Step 4: one step here, then the objects of the children passed.
    let tests = p_below * n_below as f64 + p_above * n_above as f64;
    costs.traversal + (1.0 - bonus) * costs.intersection * tests
}
// ANCHOR_END: split_cost
