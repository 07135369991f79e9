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

/// The rule: which structure the scene with these boxes needs.
pub fn choose(boxes: &[Aabb]) -> Structure {
    let bounded = boxes
        .iter()
        .filter(|b| !b.is_empty() && b.min.is_finite() && b.max.is_finite())
        .count();
    if bounded < FEW {
        Structure::Brute
    } else {
        Structure::Bvh
    }
}

/// `--accel auto`: the rule's structure, built over `objects`.
pub fn auto(objects: &[Object]) -> Arc<dyn Accelerator> {
    let boxes: Vec<Aabb> = objects.iter().map(|o| o.shape.bounds()).collect();
    choose(&boxes).build(objects)
}
