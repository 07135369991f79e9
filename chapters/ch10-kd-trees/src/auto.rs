//! Which structure a scene needs: a rule read off the chapter's measured
//! table, applied before building anything.
use std::sync::Arc;

use raystep_core::Aabb;
use raystep_world::{Accelerator, Object};

use crate::{KdBuilder, KdCosts, KdTree};

/// The structures a tracer can search its objects with.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Structure {
    /// Every ray against every object (chapter 3).
    Brute,
    /// Chapter 8's BVH, binned SAH with 16 bins.
    Bvh,
    /// Chapter 9's uniform grid at the resolution rule.
    Grid,
    /// This chapter's kd-tree: SAH, events, [`KdCosts::CHOSEN`].
    KdTree,
}

impl Structure {
    /// `brute`, `bvh`, `grid`, `kdtree`.
    pub fn name(self) -> &'static str {
        match self {
            Structure::Brute => "brute",
            Structure::Bvh => "bvh",
            Structure::Grid => "grid",
            Structure::KdTree => "kdtree",
        }
    }

    /// Builds it over `objects`.
    pub fn build(self, objects: &[Object]) -> Arc<dyn Accelerator> {
        match self {
            Structure::Brute => Arc::new(ch03::BruteForce),
            Structure::Bvh => Arc::new(ch08::Bvh::for_objects(
                objects,
                ch08::Builder::BinnedSah { bins: 16 },
            )),
            Structure::Grid => Arc::new(ch09::Grid::for_objects(
                objects,
                ch09::Resolution::Rule,
            )),
            Structure::KdTree => Arc::new(KdTree::for_objects(
                objects,
                KdBuilder::SahEvents,
                KdCosts::CHOSEN,
            )),
        }
    }
}

/// Fewer bounded objects than this: brute force (building anything costs
/// more than it saves).
pub const FEW: usize = 8;

/// At least this many objects before a grid is considered (fewer, and
/// a coarse count says little about how they are spread).
pub const MANY: usize = 256;

/// The spread test's cells along the longest side of the scene's box.
pub const SPREAD_CELLS: usize = 4;

/// The spread test passes when no cell is empty and the fullest holds at
/// most this many times the mean.
pub const FULLEST_OVER_MEAN: f64 = 2.0;

/// How evenly a scene's objects fill its box: their centres counted in a
/// coarse lattice (4 cells along the longest side).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Spread {
    /// Bounded objects (planes and the like left out).
    pub objects: usize,
    /// Cells of the coarse lattice.
    pub cells: usize,
    /// Cells holding no object's centre.
    pub empty: usize,
    /// The fullest cell's count over the mean count.
    pub fullest_over_mean: f64,
}

impl Spread {
    /// Small objects everywhere, about as many in every part of the box?
    pub fn is_even(&self) -> bool {
        self.empty == 0 && self.fullest_over_mean <= FULLEST_OVER_MEAN
    }
}

/// Counts the bounded objects' centres in a coarse lattice over their box.
pub fn spread(boxes: &[Aabb]) -> Spread {
    let bounded: Vec<&Aabb> = boxes
        .iter()
        .filter(|b| !b.is_empty() && b.min.is_finite() && b.max.is_finite())
        .collect();
    let bounds = bounded.iter().fold(Aabb::EMPTY, |a, b| a.union(**b));
    let lattice =
        ch09::Lattice::new(bounds, ch09::cells_for(&bounds, SPREAD_CELLS));
    let mut counts = vec![0usize; lattice.count()];
    for b in &bounded {
        counts[lattice.index(lattice.cell_of(0.5 * (b.min + b.max)))] += 1;
    }
    let mean = bounded.len() as f64 / counts.len() as f64;
    let fullest = counts.iter().copied().max().unwrap_or(0) as f64;
    Spread {
        objects: bounded.len(),
        cells: counts.len(),
        empty: counts.iter().filter(|&&n| n == 0).count(),
        fullest_over_mean: if mean > 0.0 { fullest / mean } else { 0.0 },
    }
}

// ANCHOR: choose
/// The rule, read off the chapter's measurements (`which-structure.csv`):
///
/// 1. fewer than [`FEW`] objects: brute force — nothing pays its build;
/// 2. at least [`MANY`] objects spread evenly through their box (the
///    spread test): chapter 9's grid — the cheapest walk there;
/// 3. otherwise chapter 8's BVH — never far from the best, and the only
///    one that copes with a small detailed object in a big empty scene.
///
/// The kd-tree is never chosen: it is the fastest on one measured family
/// of seven (the bunny, by 13 % for a million rays), 2.5 times slower
/// than the BVH in the stadium, and builds 12–26 times slower.
pub fn choose(boxes: &[Aabb]) -> Structure {
    let spread = spread(boxes);
    if spread.objects < FEW {
        Structure::Brute
    } else if spread.objects >= MANY && spread.is_even() {
        Structure::Grid
    } else {
        Structure::Bvh
    }
}
// ANCHOR_END: choose

/// `--accel auto`: the rule's structure, built over `objects`.
pub fn auto(objects: &[Object]) -> Arc<dyn Accelerator> {
    let boxes: Vec<Aabb> = objects.iter().map(|o| o.shape.bounds()).collect();
    choose(&boxes).build(objects)
}
