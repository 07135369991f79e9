//! Exercise 2 (★★★): the DDA's stepping loop. From the cell the ray is in, the
//! next cell is the neighbour across the plane the ray meets first: the
//! axis with the smallest `t_max`. One comparison and one addition per
//! cell, as a rasterizer steps from pixel to pixel by adding a constant.
//!
//! Fill in `walk`; `cargo run --release -- check ch09` judges it.
use std::ops::ControlFlow;

use raystep_core::{Interval, Ray};

#[allow(unused_imports, reason = "the setup the loop starts from")]
use crate::dda_setup;
use crate::{Lattice, Visit};

// ANCHOR: walk
/// Calls `visit` for every cell `ray` passes through within `interval`,
/// in order along the ray, until `visit` breaks or the ray leaves the
/// grid.
pub fn walk(
    lattice: &Lattice, ray: &Ray, interval: Interval,
    mut visit: impl FnMut(Visit) -> ControlFlow<()>,
) {
    // TODO:
    // 1. `dda_setup(lattice, ray, interval)` (exercise 1); None: return.
    //    The first cell is entered at `t_enter`.
    // 2. Loop:
    //    a. The axis with the smallest `t_max` (on a tie, x before y
    //       before z): the ray leaves the cell through that axis's plane,
    //       at t_out = min(t_max[axis], t_exit).
    //    b. Call `visit(Visit { cell, index: lattice.index(cell), t_in,
    //       t_out })`; if it returns `ControlFlow::Break(())`, return.
    //    c. If t_max[axis] ≥ t_exit, the ray leaves the grid (or its
    //       interval) in this cell: return. (+∞ ≥ +∞ is true, so a ray
    //       parallel to every plane stops; stop on a NaN t_max too.)
    //    d. Step: cell[axis] += step[axis]; if that leaves the grid
    //       (below 0 or at `lattice.cells[axis]`), return.
    //    e. The new cell is entered at the old t_max[axis]; then
    //       t_max[axis] += t_delta[axis].
    let _ = (lattice, ray, interval, &mut visit);
    todo!("ch09 exercise 2: walk")
}
// ANCHOR_END: walk
