//! Exercise 5: the SAH cost of one split.
use raystep_core::Aabb;

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
    let (n_left, n_right) = (n_left as f64, n_right as f64);
    // Step 1: the parent's area; 0 means every child is hit for certain.
    let area = parent.surface_area();
    if area > 0.0 {
        // Step 2: each child's chance of a hit times its objects' tests,
        // after the one visit of the parent.
        TRAVERSAL
            + (left.surface_area() * n_left + right.surface_area() * n_right)
                / area
                * INTERSECTION
    } else {
        TRAVERSAL + (n_left + n_right) * INTERSECTION
    }
}
// ANCHOR_END: split_cost

#[cfg(test)]
mod tests {
    use raystep_core::{Aabb, DVec3};

    /// The builders' private copy computes the same, bit for bit.
    #[test]
    fn the_builders_copy_agrees() {
        let b = |a: f64, c: f64| Aabb::new(DVec3::splat(a), DVec3::splat(c));
        for (p, l, r) in [
            (b(0.0, 2.0), b(0.0, 1.0), b(1.0, 2.0)),
            (b(0.0, 0.0), b(0.0, 0.0), b(0.0, 0.0)),
            (b(-3.0, 7.0), b(-3.0, 0.1), b(0.5, 7.0)),
        ] {
            for (n, m) in [(0, 3), (1, 1), (5, 2)] {
                assert_eq!(
                    super::split_cost(&p, &l, n, &r, m).to_bits(),
                    crate::bvh::split_cost_reference(&p, &l, n, &r, m)
                        .to_bits()
                );
            }
        }
    }
}
