//! Exercise 1 (★★): the 3D DDA's setup (Amanatides and Woo, "A fast voxel
//! traversal algorithm for ray tracing", 1987): the first cell, and per
//! axis how far along the ray the next plane between cells is (`t_max`)
//! and how far apart those planes are (`t_delta`).
//!
//! Fill in `dda_setup`; `cargo run --release -- check ch09` judges it.
#[allow(unused_imports, reason = "step 1 is chapter 8's slab test")]
use ch08::slab_test;
#[allow(unused_imports, reason = "a Dda's t_max and t_delta are DVec3s")]
use raystep_core::DVec3;
use raystep_core::{Interval, Ray};

use crate::{Dda, Lattice};

// ANCHOR: dda_setup
/// The DDA's start for `ray` within `interval`, or None if the ray
/// misses the grid's box there.
pub fn dda_setup(
    lattice: &Lattice, ray: &Ray, interval: Interval,
) -> Option<Dda> {
    // TODO:
    // 1. Clip the ray to the grid's box: chapter 8's
    //    `slab_test(&lattice.bounds, ray, interval)` gives the part of the
    //    interval inside it (its `min` is where the ray enters, its `max`
    //    where it leaves), or None.
    // 2. The first cell: `lattice.cell_of(ray.at(entry t))`.
    // 3. For each axis, with d = ray.direction[axis]:
    //    - d > 0: step +1; the next plane is `lattice.plane(axis,
    //      cell[axis] + 1)`; t_max = (plane − origin[axis]) / d;
    //      t_delta = lattice.size[axis] / d.
    //    - d < 0: step −1; the next plane is `lattice.plane(axis,
    //      cell[axis])` (the cell's own lower plane); the same t_max;
    //      t_delta = −size / d (a distance in t is never negative).
    //    - d == 0 (also −0.0): step 0, t_max and t_delta +∞: the ray never
    //      crosses a plane of this axis (and never divides 0 by 0).
    // 4. Return the Dda with t_enter and t_exit from step 1 (t_max and
    //    t_delta as `DVec3::from_array([x, y, z])`).
    let _ = (lattice, ray, interval);
    todo!("ch09 exercise 1: dda_setup")
}
// ANCHOR_END: dda_setup
