//! Exercise 5 (★★): the SAH cost of one split.
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
    // TODO:
    // 1. The parent's surface area A(parent) (`Aabb::surface_area`).
    // 2. If it is above 0: one visit of the parent (`costs.traversal`),
    //    plus each child's chance of being hit, A(child) / A(parent),
    //    times its objects' tests, N(child) · `costs.intersection`.
    // 3. If it is 0 (a flat or point-like parent), the chances are 1:
    //    costs.traversal + (N(left) + N(right)) · costs.intersection.
    let _ = (parent, left, n_left, right, n_right, costs);
    todo!("ch08 exercise 5: sah_split")
}
// ANCHOR_END: split_cost
