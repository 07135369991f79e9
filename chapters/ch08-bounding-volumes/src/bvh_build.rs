//! Building a [`Bvh`] top-down: split the objects in two, again and
//! again, until the surface area heuristic says a leaf is cheaper.
use raystep_core::{Aabb, DVec3};

use crate::bvh::{INTERSECTION, TRAVERSAL};
use crate::{Bvh, BvhNode, Split};

/// The most objects a leaf may hold when the heuristic would rather not
/// split (all centroids equal, say): more are split by count anyway.
pub const MAX_LEAF: usize = 8;

/// What the builder works on: each object's box and centroid.
struct Input<'a> {
    boxes: &'a [Aabb],
    centroids: Vec<DVec3>,
    split: Split,
}

pub(crate) fn build(boxes: &[Aabb], split: Split) -> Bvh {
    // Step 1: objects with a finite box go into the tree, the rest
    // (planes, and empty boxes, which a wrong shape might still hit) are
    // asked by every ray.
    let (mut order, mut unbounded) = (Vec::new(), Vec::new());
    for (i, b) in boxes.iter().enumerate() {
        let finite = b.min.is_finite() && b.max.is_finite();
        if finite && !b.is_empty() {
            order.push(i as u32);
        } else {
            unbounded.push(i as u32);
        }
    }
    let input = Input {
        boxes,
        centroids: boxes.iter().map(|b| 0.5 * (b.min + b.max)).collect(),
        split,
    };
    // Step 2: the root holds them all; split it recursively.
    let mut nodes = Vec::with_capacity(2 * order.len());
    if !order.is_empty() {
        nodes.push(leaf(&input, &order, 0));
        subdivide(&input, &mut order, 0, &mut nodes);
    }
    Bvh {
        nodes,
        order,
        unbounded,
    }
}

/// A leaf over `order[first ..]` (the whole slice given).
fn leaf(input: &Input, objects: &[u32], first: usize) -> BvhNode {
    BvhNode {
        bounds: union_of(objects.iter().map(|&i| input.boxes[i as usize])),
        first: first as u32,
        count: objects.len() as u32,
    }
}

/// Splits node `k` (a leaf over its range of `order`) if that pays, and its
/// children after it.
fn subdivide(
    input: &Input,
    order: &mut [u32],
    k: usize,
    nodes: &mut Vec<BvhNode>,
) {
    let node = nodes[k];
    let (first, count) = (node.first as usize, node.count as usize);
    if count <= 1 {
        return;
    }
    let objects = &mut order[first..first + count];
    // Step 1: the split the rule chooses: how many go left.
    let left = choose(input, objects);
    // Step 2: the heuristic: is the split cheaper than the leaf?
    let (l, r) = objects.split_at(left);
    let boxes =
        |part: &[u32]| union_of(part.iter().map(|&i| input.boxes[i as usize]));
    let parent = node.bounds.surface_area();
    let split_cost = if parent > 0.0 {
        TRAVERSAL
            + (boxes(l).surface_area() * l.len() as f64
                + boxes(r).surface_area() * r.len() as f64)
                / parent
                * INTERSECTION
    } else {
        TRAVERSAL + count as f64 * INTERSECTION
    };
    let leaf_cost = count as f64 * INTERSECTION;
    if leaf_cost <= split_cost && count <= MAX_LEAF {
        return; // a leaf is cheaper: keep it
    }
    // Step 3: two children, then split each of them.
    let children = nodes.len();
    nodes.push(leaf(input, l, first));
    nodes.push(leaf(input, r, first + left));
    nodes[k].first = children as u32;
    nodes[k].count = 0;
    subdivide(input, order, children, nodes);
    subdivide(input, order, children + 1, nodes);
}

/// Reorders `objects` and returns how many of them go to the left child
/// (between 1 and `objects.len() − 1`).
fn choose(input: &Input, objects: &mut [u32]) -> usize {
    let centroid = |i: u32| input.centroids[i as usize];
    let c = Aabb::around(objects.iter().map(|&i| centroid(i)));
    let extent = c.max - c.min;
    let axis = extent.max_position();
    let half = objects.len() / 2;
    if extent[axis] <= 0.0 {
        return half; // all centroids equal: split by count
    }
    let by_axis =
        |a: &u32, b: &u32| centroid(*a)[axis].total_cmp(&centroid(*b)[axis]);
    match input.split {
        Split::Median => {
            objects.select_nth_unstable_by(half, by_axis);
            half
        }
        Split::Midpoint => {
            let middle = 0.5 * (c.min[axis] + c.max[axis]);
            let left = partition(objects, |i| centroid(i)[axis] < middle);
            if left == 0 || left == objects.len() {
                objects.select_nth_unstable_by(half, by_axis);
                half
            } else {
                left
            }
        }
        Split::BinnedSah { bins } => binned_sah(input, objects, &c, bins),
    }
}

/// The binned SAH split: on each axis, `bins` equal slices of the
/// centroids' box; the cut between two slices with the lowest
/// A(left)·N(left) + A(right)·N(right).
fn binned_sah(
    input: &Input,
    objects: &mut [u32],
    c: &Aabb,
    bins: usize,
) -> usize {
    let bins = bins.max(2);
    let extent = c.max - c.min;
    let bin_of = |i: u32, axis: usize| {
        let x =
            (input.centroids[i as usize][axis] - c.min[axis]) / extent[axis];
        ((x * bins as f64) as usize).min(bins - 1)
    };
    let mut best: Option<(f64, usize, usize)> = None; // (cost, axis, cut)
    for axis in 0..3 {
        if extent[axis] <= 0.0 {
            continue;
        }
        // Step 1: each bin's count and box.
        let mut counts = vec![0usize; bins];
        let mut boxes = vec![Aabb::EMPTY; bins];
        for &i in objects.iter() {
            let b = bin_of(i, axis);
            counts[b] += 1;
            boxes[b] = boxes[b].union(input.boxes[i as usize]);
        }
        // Step 2: sweep from the right, then from the left: the cost of
        // cutting after bin `cut`.
        let mut right_cost = vec![0.0; bins];
        let (mut n, mut b) = (0usize, Aabb::EMPTY);
        for k in (1..bins).rev() {
            n += counts[k];
            b = b.union(boxes[k]);
            right_cost[k - 1] = b.surface_area() * n as f64;
        }
        let (mut n, mut b) = (0usize, Aabb::EMPTY);
        for cut in 0..bins - 1 {
            n += counts[cut];
            b = b.union(boxes[cut]);
            if n == 0 || n == objects.len() {
                continue;
            }
            let cost = b.surface_area() * n as f64 + right_cost[cut];
            if best.is_none_or(|(c, _, _)| cost < c) {
                best = Some((cost, axis, cut));
            }
        }
    }
    match best {
        Some((_, axis, cut)) => partition(objects, |i| bin_of(i, axis) <= cut),
        None => objects.len() / 2,
    }
}

/// Moves the objects for which `left` holds to the front; how many.
fn partition(objects: &mut [u32], left: impl Fn(u32) -> bool) -> usize {
    let mut next = 0;
    for k in 0..objects.len() {
        if left(objects[k]) {
            objects.swap(k, next);
            next += 1;
        }
    }
    next
}

/// The smallest box around all of `boxes`.
fn union_of(boxes: impl Iterator<Item = Aabb>) -> Aabb {
    boxes.fold(Aabb::EMPTY, Aabb::union)
}
