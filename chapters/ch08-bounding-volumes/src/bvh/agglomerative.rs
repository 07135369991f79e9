//! Exact agglomerative clustering (Walter et al. 2008): start with one
//! cluster per object and merge, again and again, the two clusters whose
//! union has the smallest area. Each cluster remembers its nearest
//! neighbour; a merge only makes unions larger, so only the clusters
//! whose neighbour was merged look again: O(n²) on most inputs.
use raystep_core::Aabb;

use super::builder::AGGLOMERATIVE_LIMIT;
use super::flatten::flatten;
use super::ploc::ploc_merges;
use super::tree::{Bvh, bounded_objects};

/// The agglomerative hierarchy over `boxes` (PLOC with radius 8 above
/// [`AGGLOMERATIVE_LIMIT`] objects).
pub(crate) fn agglomerative(boxes: &[Aabb]) -> Bvh {
    let (objects, unbounded) = bounded_objects(boxes);
    let merges = if objects.len() > AGGLOMERATIVE_LIMIT {
        ploc_merges(boxes, &objects, 8)
    } else {
        exact_merges(boxes, &objects)
    };
    flatten(boxes, objects, &merges, unbounded)
}

// ANCHOR: agglomerative
/// The merges, closest pair first (see [`flatten`] for the numbering).
fn exact_merges(boxes: &[Aabb], objects: &[u32]) -> Vec<[u32; 2]> {
    let m = objects.len();
    // Step 1: one cluster per object, in slots; a merge reuses the first
    // slot and frees the second.
    let mut id: Vec<u32> = (0..m as u32).collect();
    let mut bounds: Vec<Aabb> =
        objects.iter().map(|&i| boxes[i as usize]).collect();
    let mut alive = vec![true; m];
    let mut nearest: Vec<(f64, usize)> =
        (0..m).map(|s| nearest_to(s, &bounds, &alive)).collect();
    let mut merges = Vec::with_capacity(m.saturating_sub(1));
    for _ in 1..m {
        // Step 2: the closest pair of all (the first, on a tie).
        let a = (0..m)
            .filter(|&s| alive[s])
            .min_by(|&s, &t| nearest[s].0.total_cmp(&nearest[t].0))
            .expect("two clusters or more");
        let b = nearest[a].1;
        // Step 3: merge them into slot a.
        merges.push([id[a], id[b]]);
        id[a] = (m + merges.len() - 1) as u32;
        bounds[a] = bounds[a].union(bounds[b]);
        alive[b] = false;
        // Step 4: the merged cluster and those whose neighbour was a or
        // b look again; every other neighbour is still the nearest.
        for s in 0..m {
            if alive[s] && (s == a || nearest[s].1 == a || nearest[s].1 == b) {
                nearest[s] = nearest_to(s, &bounds, &alive);
            }
        }
    }
    merges
}

/// The live cluster whose union with cluster `s` has the smallest area
/// (the first, on a tie), and that area.
fn nearest_to(s: usize, bounds: &[Aabb], alive: &[bool]) -> (f64, usize) {
    let mut best = (f64::INFINITY, s);
    for t in 0..bounds.len() {
        if t != s && alive[t] {
            let d = bounds[s].union(bounds[t]).surface_area();
            if best.1 == s || d.total_cmp(&best.0).is_lt() {
                best = (d, t);
            }
        }
    }
    best
}
// ANCHOR_END: agglomerative
