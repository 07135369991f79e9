//! # Chapter 9 — grids
//!
//! A uniform spatial partition: the scene's box cut into equal cells,
//! every cell with the list of objects in it. A ray walks the cells it
//! passes through, in order, with an algorithm much like rasterization
//! (the 3D DDA of Amanatides and Woo), and tests only the objects listed
//! there; the first cell that holds a hit ends the walk. Good for lots of
//! similarly sized small objects; bad for a small detailed object in a
//! big empty scene (the "teapot in a stadium"; both scenes are generated
//! in `raystep_bench`, their scene files in the chapter's figures crate).
//!
//! Student mode: with the feature `exercise` the modules marked below are
//! replaced by the stubs in `exercise/`.

// ---------------------------------------------------------------------
// The grid: cells, how many, and the objects in each.
// ---------------------------------------------------------------------

mod grid;
mod lattice;
mod resolution;
mod triangle_box;

pub use grid::{Fill, Grid, GridStats};
pub use lattice::Lattice;
pub use resolution::{
    MAX_CELLS, RULE_FACTOR, Resolution, cells_for, rule_cells,
};
pub use triangle_box::triangle_overlaps_box;

// ---------------------------------------------------------------------
// The walk: the 3D DDA, and the tracer's two questions.
// ---------------------------------------------------------------------

mod dda;
mod grid_trace;
mod mailbox;
mod mesh_grid;

// Exercise 1: the DDA's setup.
#[cfg_attr(feature = "exercise", path = "../exercise/dda_setup.rs")]
mod dda_setup;
// Exercise 2: the DDA's stepping loop.
#[cfg_attr(feature = "exercise", path = "../exercise/walk.rs")]
mod walk;

pub use dda::{Dda, Visit};
pub use dda_setup::dda_setup;
pub use grid_trace::{EXIT_SLACK, hit_in_cell};
pub use mailbox::{Mailbox, SLOTS};
pub use mesh_grid::MeshGrid;
pub use walk::walk;

pub use raystep_core::{Aabb, DVec3, Hit, Interval, Ray};
pub use raystep_world::{Accelerator, Object};
