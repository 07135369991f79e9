//! PLOC, parallel locally-ordered clustering (Meister and Bittner 2018),
//! run on one thread: a bottom-up build. The objects are sorted along a
//! Morton curve, so that neighbours in space are mostly neighbours in
//! the list; each cluster looks `radius` places either way for the one
//! whose union with it has the smallest area, and every pair that chose
//! each other merges. Round after round, until one cluster is left.
use raystep_core::Aabb;
use raystep_core::glam::{UVec3, Vec3A};

use super::flatten::flatten;
use super::items::{Box32, items, measure};
use super::tree::{Bvh, bounded_objects};

/// The PLOC hierarchy over `boxes`.
pub(crate) fn ploc(boxes: &[Aabb], radius: usize) -> Bvh {
    let (objects, unbounded) = bounded_objects(boxes);
    let merges = ploc_merges(boxes, &objects, radius);
    flatten(boxes, objects, &merges, unbounded)
}

// ANCHOR: ploc
/// The merges PLOC makes over `objects` (cluster `c` is `objects[c]`;
/// see [`flatten`]).
pub(crate) fn ploc_merges(
    boxes: &[Aabb], objects: &[u32], radius: usize,
) -> Vec<[u32; 2]> {
    let radius = radius.max(1);
    // Step 1: the boxes in f32 (only the choices read them) and their
    // centroids' Morton codes; sorted along the curve.
    let items = items(boxes, objects);
    let (_, c) = measure(&items);
    let extent = c.max - c.min;
    let scale = Vec3A::select(
        extent.cmpgt(Vec3A::ZERO),
        ((1u32 << 21) - 1) as f32 / extent,
        Vec3A::ZERO,
    );
    let mut keyed: Vec<(u64, u32)> = items
        .iter()
        .enumerate()
        .map(|(k, item)| {
            let cell = ((item.centroid2() - c.min) * scale).as_uvec3();
            (morton(cell), k as u32)
        })
        .collect();
    keyed.sort_unstable();
    let mut clusters: Vec<u32> = keyed.iter().map(|&(_, k)| k).collect();
    let mut bounds: Vec<Box32> = keyed
        .iter()
        .map(|&(_, k)| items[k as usize].bounds())
        .collect();
    drop(keyed);
    let mut merges = Vec::with_capacity(objects.len().saturating_sub(1));
    let mut nearest: Vec<(f32, u32)> = Vec::new();
    while clusters.len() > 1 {
        let n = clusters.len();
        // Step 2: each cluster's nearest neighbour within `radius`: each
        // pair's distance (the area of their union) is computed once and
        // offered to both. A cluster's candidates come in the order of
        // the pair (lower place, higher place), and only a strictly
        // smaller distance replaces the first: every tie is broken the
        // same way from both sides, so the closest pair of all always
        // chooses each other and every round merges.
        nearest.clear();
        nearest.resize(n, (f32::INFINITY, u32::MAX));
        for i in 0..n {
            let a = bounds[i];
            for j in i + 1..(i + 1 + radius).min(n) {
                let d = a.union(bounds[j]).area();
                let d = if d.is_nan() { f32::INFINITY } else { d };
                if d < nearest[i].0 || nearest[i].1 == u32::MAX {
                    nearest[i] = (d, j as u32);
                }
                if d < nearest[j].0 || nearest[j].1 == u32::MAX {
                    nearest[j] = (d, i as u32);
                }
            }
        }
        // Step 3: mutual nearest neighbours merge; the new cluster takes
        // the place of the first of the two, and the list closes up.
        let mut next = 0;
        for i in 0..n {
            let j = nearest[i].1 as usize;
            let mutual = nearest[j].1 as usize == i;
            if mutual && j < i {
                continue; // merged at j
            }
            if mutual {
                merges.push([clusters[i], clusters[j]]);
                clusters[next] = (objects.len() + merges.len() - 1) as u32;
                bounds[next] = bounds[i].union(bounds[j]);
            } else {
                clusters[next] = clusters[i];
                bounds[next] = bounds[i];
            }
            next += 1;
        }
        clusters.truncate(next);
        bounds.truncate(next);
    }
    merges
}
// ANCHOR_END: ploc

/// The Morton code of a cell (21 bits per axis): the bits of x, y and z
/// interleaved, so that sorting by it follows a Z-shaped curve.
fn morton(cell: UVec3) -> u64 {
    fn spread(v: u32) -> u64 {
        let mut x = u64::from(v) & 0x1f_ffff;
        x = (x | x << 32) & 0x1f_0000_0000_ffff;
        x = (x | x << 16) & 0x1f_0000_ff00_00ff;
        x = (x | x << 8) & 0x100f_00f0_0f00_f00f;
        x = (x | x << 4) & 0x10c3_0c30_c30c_30c3;
        (x | x << 2) & 0x1249_2492_4924_9249
    }
    spread(cell.x) << 2 | spread(cell.y) << 1 | spread(cell.z)
}
