//! A bottom-up builder's binary tree, one object per leaf, laid out as
//! every [`Bvh`] is: the root at 0, children side by side, each leaf a
//! range of `order`; and cut back where the surface area heuristic says
//! a leaf is cheaper than the subtree below it.
use raystep_core::Aabb;

use super::tree::{Bvh, BvhNode, INTERSECTION, MAX_LEAF, TRAVERSAL};

/// The tree of `merges` over `objects` laid out as a [`Bvh`].
///
/// Cluster `c < objects.len()` is the object `objects[c]`; merge `k`
/// makes cluster `objects.len() + k` from its two clusters (made before
/// it). The last cluster is the root; `unbounded` is kept as it is.
pub(crate) fn flatten(
    boxes: &[Aabb], objects: Vec<u32>, merges: &[[u32; 2]], unbounded: Vec<u32>,
) -> Bvh {
    let m = objects.len();
    if m == 0 {
        return Bvh {
            nodes: Vec::new(),
            order: objects,
            unbounded,
        };
    }
    // Step 1: each cluster's exact box, size and cost (the tests a ray
    // that enters its box expects), children before their parents.
    let total = m + merges.len();
    let mut bounds: Vec<Aabb> = Vec::with_capacity(total);
    bounds.extend(objects.iter().map(|&i| boxes[i as usize]));
    let mut counts = vec![1usize; m];
    let mut costs = vec![INTERSECTION; m];
    let mut leaf = vec![true; m];
    for &[a, b] in merges {
        let (a, b) = (a as usize, b as usize);
        let whole = bounds[a].union(bounds[b]);
        let count = counts[a] + counts[b];
        // Step 2: the cheaper of a leaf and a split, each child as cheap
        // as its own subtree was made (with two leaves below, this is
        // exercise 5's split_cost).
        let area = whole.surface_area();
        let split = if area > 0.0 {
            TRAVERSAL
                + (bounds[a].surface_area() * costs[a]
                    + bounds[b].surface_area() * costs[b])
                    / area
        } else {
            TRAVERSAL + costs[a] + costs[b]
        };
        let as_leaf = count as f64 * INTERSECTION;
        let is_leaf = count <= MAX_LEAF && as_leaf <= split;
        bounds.push(whole);
        counts.push(count);
        costs.push(if is_leaf { as_leaf } else { split });
        leaf.push(is_leaf);
    }
    // Step 3: lay the kept nodes out from the root down: an interior
    // node's two children take the next two places, a leaf's objects the
    // next places of `order`.
    let root = total - 1;
    let mut nodes = vec![placeholder()];
    let mut order = Vec::with_capacity(m);
    let mut stack = vec![(root, 0usize)];
    let mut below = Vec::new();
    while let Some((c, k)) = stack.pop() {
        if leaf[c] {
            let first = order.len();
            below.push(c);
            while let Some(d) = below.pop() {
                if d < m {
                    order.push(objects[d]);
                } else {
                    let [a, b] = merges[d - m];
                    below.push(b as usize);
                    below.push(a as usize);
                }
            }
            nodes[k] = BvhNode {
                bounds: bounds[c],
                first: first as u32,
                count: (order.len() - first) as u32,
            };
        } else {
            let [a, b] = merges[c - m];
            let children = nodes.len();
            nodes.extend([placeholder(), placeholder()]);
            nodes[k] = BvhNode {
                bounds: bounds[c],
                first: children as u32,
                count: 0,
            };
            stack.push((b as usize, children + 1));
            stack.push((a as usize, children));
        }
    }
    Bvh {
        nodes,
        order,
        unbounded,
    }
}

fn placeholder() -> BvhNode {
    BvhNode {
        bounds: Aabb::EMPTY,
        first: 0,
        count: 0,
    }
}
