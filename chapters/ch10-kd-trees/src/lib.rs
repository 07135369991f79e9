//! # Chapter 10 — kd-trees
//!
//! What the book calls axis-aligned BSP trees: use planes to split space
//! into pieces. Each interior node cuts its piece of space in two by a
//! plane perpendicular to x, y or z; each leaf lists the objects that
//! reach into its piece. The surface area heuristic chooses where to cut;
//! a ray walks the pieces it passes through front to back, and the first
//! piece holding a hit ends the walk. Then the lecture's closing
//! question: which structure does a scene need?
//!
//! Student mode: with the feature `exercise` the modules marked below are
//! replaced by the stubs in `exercise/`.

// ---------------------------------------------------------------------
// The tree: planes chosen by the surface area heuristic.
// ---------------------------------------------------------------------

mod build_events;
mod build_sorting;
mod builder_io;
mod clip;
mod costs;
mod events;
mod kd_build;
mod kdtree;
mod median;

// Exercise 1: the SAH cost of one split plane.
#[cfg_attr(feature = "exercise", path = "../exercise/split_cost.rs")]
mod split_cost;

pub use clip::clipped_bounds;
pub use costs::{DEPTH_FACTOR, KdCosts, MAX_DEPTH};
pub use events::{
    Event, EventKind, Plane, Side, event_order, push_events, side, sweep,
};
pub use kdtree::{Clip, KdBuilder, KdNode, KdStats, KdTree, MEDIAN_LEAF};
pub use split_cost::split_cost;

// ---------------------------------------------------------------------
// The walk: front to back, with a stack.
// ---------------------------------------------------------------------

mod kd_trace;
mod mesh_kd;
mod step;
mod walk;

// Exercise 2: one traversal step: which child first, when to push.
#[cfg_attr(feature = "exercise", path = "../exercise/traversal_step.rs")]
mod traversal_step;

pub use mesh_kd::MeshKd;
pub use step::{Split, Step};
pub use traversal_step::traversal_step;
pub use walk::{KdVisit, kd_walk};

pub use raystep_core::{Aabb, DVec3, Hit, Interval, Ray};
pub use raystep_world::{Accelerator, Object};

// ---------------------------------------------------------------------
// Which structure a scene needs.
// ---------------------------------------------------------------------

mod auto;

pub use auto::{
    FEW, FULLEST_OVER_MEAN, MANY, SPREAD_CELLS, Spread, Structure, auto,
    choose, spread,
};
