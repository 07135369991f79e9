//! Building a [`Bvh`] top-down: split the objects in two, again and
//! again, until the surface area heuristic says a leaf is cheaper.
//!
//! The choices are made on `f32` copies of the boxes, kept side by side
//! with their indices (`Item`), and the final boxes are the exact `f64`
//! unions of the objects' boxes (step 4), so a rounded copy never makes a
//! node too small. On the 235 136-triangle bunny, the tree and its
//! [`MeshBvh`](crate::MeshBvh) (binned SAH, 16 bins, one thread) took
//! 350–450 ms before these steps and about 230 ms after (measured on a
//! busy two-core machine); see `Bins` for the steps.
use raystep_core::Aabb;
use raystep_core::glam::Vec3A;

use super::builder::Builder;
use super::items::{Box32, Item, items, measure};
use super::sah_split::split_cost;
use super::sweep::sweep_sah;
use super::tree::{
    Bvh, BvhNode, INTERSECTION, MAX_LEAF, SahCosts, bounded_objects,
};

/// A node still to be split: its box and its centroids' box (twice the
/// centroids, as `Item::centroid2`).
struct Task {
    node: usize,
    bounds: Box32,
    centroids: Box32,
}

/// A split chosen: the objects are reordered so that the first `left` go
/// to the left child; each side's box and centroids' box.
struct Split {
    left: usize,
    sides: [(Box32, Box32); 2],
}

/// The tree over `boxes`, split by `builder`; a node of at most `leaf`
/// objects is a leaf without asking (1: every node is split while the
/// SAH says a split is cheaper).
pub(crate) fn top_down(boxes: &[Aabb], builder: Builder, leaf: usize) -> Bvh {
    // Step 1: objects with a finite box go into the tree, the rest
    // (planes, empty boxes) are asked by every ray.
    let (order, unbounded) = bounded_objects(boxes);
    if order.is_empty() {
        return Bvh {
            nodes: Vec::new(),
            order,
            unbounded,
        };
    }
    // Step 2: the builder's copies of the boxes.
    let mut items = items(boxes, &order);
    let (bounds, centroids) = measure(&items);
    // Step 3: the root holds them all; split nodes until none is left.
    let mut nodes = Vec::with_capacity(2 * items.len() / 3);
    nodes.push(BvhNode {
        bounds: Aabb::EMPTY,
        first: 0,
        count: items.len() as u32,
    });
    let mut bins = Bins::default();
    let mut stack = vec![Task {
        node: 0,
        bounds,
        centroids,
    }];
    // ANCHOR: leaf_stop
    while let Some(task) = stack.pop() {
        let node = nodes[task.node];
        let (first, count) = (node.first as usize, node.count as usize);
        if count <= leaf {
            continue; // small enough to stay a leaf
        }
        // ANCHOR_END: leaf_stop
        let objects = &mut items[first..first + count];
        let Some(split) = choose(builder, objects, &task, &mut bins) else {
            continue; // one object
        };
        // The heuristic: is the split cheaper than the leaf?
        let [(l, lc), (r, rc)] = split.sides;
        // Exercise 5 (in student mode, the student's own).
        let cost = split_cost(
            &task.bounds.to_aabb(),
            &l.to_aabb(),
            split.left,
            &r.to_aabb(),
            count - split.left,
            &SahCosts::CHOSEN,
        );
        if count <= MAX_LEAF && count as f64 * INTERSECTION <= cost {
            continue; // a leaf is cheaper: keep it
        }
        // Two children, side by side; the left one is split first.
        let children = nodes.len();
        nodes.push(BvhNode {
            bounds: Aabb::EMPTY,
            first: first as u32,
            count: split.left as u32,
        });
        nodes.push(BvhNode {
            bounds: Aabb::EMPTY,
            first: (first + split.left) as u32,
            count: (count - split.left) as u32,
        });
        nodes[task.node].first = children as u32;
        nodes[task.node].count = 0;
        let task = |node, (bounds, centroids)| Task {
            node,
            bounds,
            centroids,
        };
        stack.push(task(children + 1, (r, rc)));
        stack.push(task(children, (l, lc)));
    }
    // Step 4: the exact boxes: a leaf's is the union of its objects'
    // boxes, an interior node's the union of its children's (which come
    // after it, hence the reverse order).
    let order: Vec<u32> = items.iter().map(|item| item.index).collect();
    refit(&mut nodes, &order, boxes);
    Bvh {
        nodes,
        order,
        unbounded,
    }
}

/// Every node's exact box, from the objects' `f64` boxes.
pub(crate) fn refit(nodes: &mut [BvhNode], order: &[u32], boxes: &[Aabb]) {
    for k in (0..nodes.len()).rev() {
        let node = nodes[k];
        let (first, count) = (node.first as usize, node.count as usize);
        nodes[k].bounds = if node.is_leaf() {
            order[first..first + count]
                .iter()
                .map(|&i| boxes[i as usize])
                .fold(Aabb::EMPTY, Aabb::union)
        } else {
            nodes[first].bounds.union(nodes[first + 1].bounds)
        };
    }
}

/// Reorders `objects` by the builder's rule and says how many go left
/// (between 1 and `objects.len() − 1`); None for a single object.
fn choose(
    builder: Builder, objects: &mut [Item], task: &Task, bins: &mut Bins,
) -> Option<Split> {
    if objects.len() <= 1 {
        return None;
    }
    let c = task.centroids;
    let extent = c.max - c.min;
    let axis = extent.max_position();
    let half = objects.len() / 2;
    let by_axis = |a: &Item, b: &Item| {
        a.centroid2()[axis].total_cmp(&b.centroid2()[axis])
    };
    let left = if extent[axis] <= 0.0 {
        half // all centroids equal: split by count
    } else {
        match builder {
            Builder::BinnedSah { bins: count } => {
                if let Some(split) = bins.split(objects, &c, count) {
                    return Some(split);
                }
                half
            }
            Builder::SweepSah => sweep_sah(objects).unwrap_or(half),
            Builder::Midpoint => {
                let middle = 0.5 * (c.min[axis] + c.max[axis]);
                let middle = Cut {
                    min: 0.0,
                    scale: 1.0,
                    below: middle,
                };
                let (left, ..) = partition_on(objects, axis, middle);
                if left == 0 || left == objects.len() {
                    objects.select_nth_unstable_by(half, by_axis);
                    half
                } else {
                    left
                }
            }
            // the median; the bottom-up builders never come here
            _ => {
                objects.select_nth_unstable_by(half, by_axis);
                half
            }
        }
    };
    let (l, r) = objects.split_at(left);
    Some(Split {
        left,
        sides: [measure(l), measure(r)],
    })
}

/// One slice of the centroids' box on one axis: how many centroids fall
/// in it, and the box around their objects.
#[derive(Clone, Copy, Debug)]
struct Bin {
    bounds: Box32,
    count: u32,
}

/// The binned SAH's scratch space, reused from node to node.
///
/// The steps that made the split faster (together with the `f32` items,
/// ~400 → ~230 ms on the 235 136-triangle bunny with its MeshBvh, one
/// thread):
/// * step 1 bins all three axes in one pass over the objects, which lie
///   side by side with their boxes (was: three passes through an index
///   array);
/// * step 3 takes the children's boxes from the bins, and step 4 their
///   centroids' boxes from the partition pass (was: two more passes, then
///   two more for the children's leaves).
///
/// And later, for the appendix's step 12 (its build of the big bunny,
/// four bench runs each, taking turns: 97–111 → 81–83 ms): step 4
/// compares one coordinate with the cut instead of computing three bins,
/// swaps only the pairs found on the wrong sides from both ends (was:
/// every object bound right, with the last unexamined one), and runs in
/// a function of its own for each axis (the axis a constant; inlined,
/// its two boxes lived on the stack).
#[derive(Default)]
struct Bins {
    bins: [Vec<Bin>; 3],
    right: Vec<Box32>,
}

impl Bins {
    // ANCHOR: binned_sah
    /// The binned SAH split: on each axis, `count` equal slices of the
    /// centroids' box `c`; the cut between two slices with the lowest
    /// A(left)·N(left) + A(right)·N(right). None if no cut leaves objects
    /// on both sides.
    fn split(
        &mut self, objects: &mut [Item], c: &Box32, count: usize,
    ) -> Option<Split> {
        // (no more bins than objects: a small node sweeps few bins)
        let count = count.min(objects.len()).max(2);
        let extent = c.max - c.min;
        let scale = Vec3A::select(
            extent.cmpgt(Vec3A::ZERO),
            count as f32 / extent,
            Vec3A::ZERO,
        );
        // (clamped in f32 and converted in one SIMD step: 20 % faster
        // than as_uvec3's three conversions)
        let last = Vec3A::splat((count - 1) as f32);
        let bin_of = |item: &Item| {
            ((item.centroid2() - c.min) * scale)
                .clamp(Vec3A::ZERO, last)
                .as_ivec3()
        };
        // Step 1: each bin's count and box, on the three axes at once.
        let empty = Bin {
            bounds: Box32::EMPTY,
            count: 0,
        };
        for bins in &mut self.bins {
            bins.clear();
            bins.resize(count, empty);
        }
        for item in objects.iter() {
            let b = bin_of(item);
            let bounds = item.bounds();
            for axis in 0..3 {
                let bin = &mut self.bins[axis][b[axis] as usize];
                bin.bounds = bin.bounds.union(bounds);
                bin.count += 1;
            }
        }
        // Step 2: on each axis, sweep from the right, then from the left:
        // the cost of cutting after each bin.
        let n = objects.len() as u32;
        let mut best: Option<(f32, usize, usize, Box32, Box32)> = None;
        self.right.resize(count, Box32::EMPTY);
        for axis in 0..3 {
            if extent[axis] <= 0.0 {
                continue;
            }
            let bins = &self.bins[axis];
            let mut b = Box32::EMPTY;
            for k in (1..count).rev() {
                b = b.union(bins[k].bounds);
                self.right[k - 1] = b;
            }
            let (mut left, mut b) = (0, Box32::EMPTY);
            for (cut, (bin, &right)) in bins.iter().zip(&self.right).enumerate()
            {
                if cut == count - 1 {
                    break; // no cut after the last bin
                }
                left += bin.count;
                b = b.union(bin.bounds);
                if left == 0 || left == n {
                    continue;
                }
                let cost =
                    b.area() * left as f32 + right.area() * (n - left) as f32;
                if best.is_none_or(|(c, ..)| cost < c) {
                    best = Some((cost, axis, cut, b, right));
                }
            }
        }
        // Step 3: the children's boxes come from the bins.
        let (_, axis, cut, l, r) = best?;
        // Step 4: the partition, which measures the centroids on the way.
        // An object goes left when its bin is at most `cut`, that is
        // unless its scaled centroid is at least `cut + 1` (the same
        // operations as `bin_of`'s, on the one axis, so the same sides as
        // the bins').
        let cut = Cut {
            min: c.min[axis],
            scale: scale[axis],
            below: (cut + 1) as f32,
        };
        let (i, lc, rc) = partition_on(objects, axis, cut);
        Some(Split {
            left: i,
            sides: [(l, lc), (r, rc)],
        })
    }
    // ANCHOR_END: binned_sah
}

// ANCHOR: partition
/// A cut on one axis (a binned SAH's, or the midpoint): an object goes
/// left when `(2·centroid − min) · scale < below`, or is NaN.
#[derive(Clone, Copy)]
struct Cut {
    min: f32,
    scale: f32,
    below: f32,
}

/// [`partition_measured`] on `axis`, the axis a constant in each copy.
fn partition_on(
    objects: &mut [Item], axis: usize, cut: Cut,
) -> (usize, Box32, Box32) {
    match axis {
        0 => partition_measured::<0>(objects, cut),
        1 => partition_measured::<1>(objects, cut),
        _ => partition_measured::<2>(objects, cut),
    }
}

/// Moves the objects left of `cut` on axis `AXIS` to the front, from both
/// ends, swapping only the pairs on the wrong sides; how many, and the
/// two sides' centroids' boxes.
#[inline(never)] // (the boxes kept in registers)
fn partition_measured<const AXIS: usize>(
    objects: &mut [Item], cut: Cut,
) -> (usize, Box32, Box32) {
    // (a NaN goes left too: where the scale is infinite, a centroid on
    // the box's side gives 0·∞, which `bin_of` puts in bin 0; sent right,
    // it could leave a side empty)
    let left = |item: &Item| {
        let x = (item.centroid2()[AXIS] - cut.min) * cut.scale;
        x < cut.below || x.is_nan()
    };
    let (mut lc, mut rc) = (Box32::EMPTY, Box32::EMPTY);
    let (mut i, mut j) = (0, objects.len());
    loop {
        // from the front, the first that goes right
        while i < j && left(&objects[i]) {
            lc = lc.grow(objects[i].centroid2());
            i += 1;
        }
        // from the back, the last that goes left
        while i < j && !left(&objects[j - 1]) {
            rc = rc.grow(objects[j - 1].centroid2());
            j -= 1;
        }
        if i == j {
            return (i, lc, rc);
        }
        objects.swap(i, j - 1);
    }
}
// ANCHOR_END: partition

#[cfg(test)]
mod tests {
    use super::*;
    use raystep_core::DVec3;

    /// `n` small boxes scattered over a cube by a fixed sequence.
    fn scattered(n: usize) -> Vec<Aabb> {
        let mut state = 12345u64;
        let mut next = || {
            state = state
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (state >> 11) as f64 / (1u64 << 53) as f64
        };
        (0..n)
            .map(|_| {
                let min = DVec3::new(next(), next(), next()) * 10.0;
                let size = DVec3::new(next(), next(), next()) * 0.5;
                Aabb {
                    min,
                    max: min + size,
                }
            })
            .collect()
    }

    #[test]
    fn the_binned_split_puts_each_object_on_its_bins_side() {
        let boxes = scattered(1000);
        let order: Vec<u32> = (0..boxes.len() as u32).collect();
        let mut objects = items(&boxes, &order);
        let (_, centroids) = measure(&objects);
        let split = Bins::default()
            .split(&mut objects, &centroids, 16)
            .expect("a cut");
        assert!(0 < split.left && split.left < objects.len());
        let (left, right) = objects.split_at(split.left);
        for (side, part) in [left, right].into_iter().enumerate() {
            let (bounds, centroids) = split.sides[side];
            // The bins' box holds every box of its side: the partition
            // put each object where its bin is.
            for object in part {
                let b = object.bounds();
                assert!(
                    bounds.min.cmple(b.min).all()
                        && b.max.cmple(bounds.max).all(),
                    "side {side}: {b:?} outside {bounds:?}"
                );
            }
            // The centroids' box measured on the way is the side's own.
            let (_, measured) = measure(part);
            assert_eq!(
                (centroids.min, centroids.max),
                (measured.min, measured.max),
                "side {side}"
            );
        }
        let mut kept: Vec<u32> = objects.iter().map(|o| o.index).collect();
        kept.sort_unstable();
        assert_eq!(kept, order, "every object once");
    }

    #[test]
    fn an_object_on_the_cut_goes_right() {
        let boxes = scattered(200);
        let order: Vec<u32> = (0..boxes.len() as u32).collect();
        let mut objects = items(&boxes, &order);
        // The cut at one object's own centroid: it and all beyond go right.
        let on_cut = objects[17].centroid2().x;
        let cut = Cut {
            min: 0.0,
            scale: 1.0,
            below: on_cut,
        };
        let (left, ..) = partition_measured::<0>(&mut objects, cut);
        let want = objects.iter().filter(|o| o.centroid2().x < on_cut).count();
        assert_eq!(left, want);
        assert!(objects[..left].iter().all(|o| o.centroid2().x < on_cut));
        assert!(objects[left..].iter().all(|o| o.centroid2().x >= on_cut));
    }

    #[test]
    fn a_centroid_the_scale_makes_nan_goes_left_as_its_bin() {
        // An infinite scale (a centroids' box thinner than f32 can divide
        // by): the centroid on the box's side gives 0·∞. `bin_of` clamps
        // the NaN to bin 0, so the partition must keep it left.
        let boxes = scattered(50);
        let order: Vec<u32> = (0..boxes.len() as u32).collect();
        let mut objects = items(&boxes, &order);
        let lowest = objects
            .iter()
            .map(|o| o.centroid2().x)
            .fold(f32::INFINITY, f32::min);
        let cut = Cut {
            min: lowest,
            scale: f32::INFINITY,
            below: 1.0,
        };
        let (left, ..) = partition_measured::<0>(&mut objects, cut);
        assert_eq!(left, 1, "only the lowest centroid is in bin 0");
        assert_eq!(objects[0].centroid2().x, lowest);
    }
}
