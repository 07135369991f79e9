//! The full-sweep SAH split (Wald 2007; pbrt's "full sweep"): every cut
//! between two neighbouring centroids on each axis is priced, not only
//! the cuts between bins. Exact, and slower: each node sorts its objects
//! three times.
use super::items::{Box32, Item};

// ANCHOR: sweep_sah
/// Reorders `objects` (sorted along the best axis) and says how many go
/// left: the cut with the lowest A(left)·N(left) + A(right)·N(right).
/// None if there are fewer than two objects.
pub(crate) fn sweep_sah(objects: &mut [Item]) -> Option<usize> {
    let n = objects.len();
    if n < 2 {
        return None;
    }
    let mut right_area = vec![0.0f32; n];
    let mut best: Option<(f32, usize, usize)> = None; // (cost, axis, left)
    for axis in 0..3 {
        // Step 1: sort by centroid along the axis (ties by index, so that
        // sorting again gives the same order).
        sort_along(objects, axis);
        // Step 2: sweep from the right: the area of the last n − k boxes.
        let mut b = Box32::EMPTY;
        for k in (1..n).rev() {
            b = b.union(objects[k].bounds());
            right_area[k] = b.area();
        }
        // Step 3: sweep from the left: the cost of the first k on the left.
        let mut b = Box32::EMPTY;
        for k in 1..n {
            b = b.union(objects[k - 1].bounds());
            let cost = b.area() * k as f32 + right_area[k] * (n - k) as f32;
            if best.is_none_or(|(c, ..)| cost < c) {
                best = Some((cost, axis, k));
            }
        }
    }
    // Step 4: the best cut, in the order of its axis.
    let (_, axis, left) = best?;
    if axis != 2 {
        sort_along(objects, axis);
    }
    Some(left)
}
// ANCHOR_END: sweep_sah

/// Sorts by centroid along `axis`, ties by index.
fn sort_along(objects: &mut [Item], axis: usize) {
    objects.sort_unstable_by(|a, b| {
        a.centroid2()[axis]
            .total_cmp(&b.centroid2()[axis])
            .then(a.index.cmp(&b.index))
    });
}
