//! Exercise 5: the SAH cost of one split.
use raystep_core::Aabb;

use crate::SahCosts;

// ANCHOR: split_cost
/// The surface area heuristic's cost of splitting a node with box
/// `parent` into a left child (box `left`, `n_left` objects) and a right
/// one, each child a leaf:
///
/// C = C_trav + (A(left)·N(left) + A(right)·N(right)) / A(parent) · C_isect
///
/// with C_trav = `costs.traversal` and C_isect = `costs.intersection`
/// (the builders pass [`SahCosts::CHOSEN`]).
/// A ray that hits the parent hits a child with probability (for rays
/// from every direction) the ratio of their surface areas; it then tests
/// the child's objects. A flat or point-like parent (area 0) gives no
/// ratio: both children count as certainly hit, probability 1.
pub fn split_cost(
    parent: &Aabb, left: &Aabb, n_left: usize, right: &Aabb, n_right: usize,
    costs: &SahCosts,
) -> f64 {
    let (n_left, n_right) = (n_left as f64, n_right as f64);
    // Step 1: the parent's area; 0 means every child is hit for certain.
    let area = parent.surface_area();
    if area > 0.0 {
        // Step 2: each child's chance of a hit times its objects' tests,
        // after the one visit of the parent.
        costs.traversal
            + (left.surface_area() * n_left + right.surface_area() * n_right)
                / area
                * costs.intersection
    } else {
        costs.traversal + (n_left + n_right) * costs.intersection
    }
}
// ANCHOR_END: split_cost
