//! Exercise 5: the SAH cost of one split.
use raystep_core::Aabb;

#[allow(unused_imports)]
use crate::{INTERSECTION, TRAVERSAL};

// ANCHOR: split_cost
/// The surface area heuristic's cost of splitting a node with box
/// `parent` into a left child (box `left`, `n_left` objects) and a right
/// one, each child a leaf:
///
/// C = C_trav + (A(left)·N(left) + A(right)·N(right)) / A(parent) · C_isect
///
/// A ray that hits the parent hits a child with probability (for rays
/// from every direction) the ratio of their surface areas; it then tests
/// the child's objects. A flat or point-like parent (area 0) gives no
/// ratio: both children count as certainly hit, probability 1.
pub fn split_cost(
    parent: &Aabb,
    left: &Aabb,
    n_left: usize,
    right: &Aabb,
    n_right: usize,
) -> f64 {
    // TODO:
    // 1. The parent's surface area A(parent) (`Aabb::surface_area`).
    // 2. If it is above 0: one visit of the parent (`TRAVERSAL`), plus
    //    each child's chance of being hit, A(child) / A(parent), times
    //    its objects' tests, N(child) · `INTERSECTION`.
    // 3. If it is 0 (a flat or point-like parent), the chances are 1:
    //    TRAVERSAL + (N(left) + N(right)) · INTERSECTION.
    let _ = (parent, left, n_left, right, n_right);
    todo!("ch08 exercise 5: sah_split")
}
// ANCHOR_END: split_cost
