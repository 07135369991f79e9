//! Exercise 2: the DDA's stepping loop. From the cell the ray is in, the
//! next cell is the neighbour across the plane the ray meets first: the
//! axis with the smallest `t_max`. One comparison and one addition per
//! cell, as a rasterizer steps from pixel to pixel by adding a constant.
use std::ops::ControlFlow;

use raystep_core::{Interval, Ray};

use crate::{Lattice, Visit, dda_setup};

// ANCHOR: walk
/// Calls `visit` for every cell `ray` passes through within `interval`,
/// in order along the ray, until `visit` breaks or the ray leaves the
/// grid.
pub fn walk(
    lattice: &Lattice, ray: &Ray, interval: Interval,
    mut visit: impl FnMut(Visit) -> ControlFlow<()>,
) {
    // Step 1: the setup (exercise 1).
    let Some(mut dda) = dda_setup(lattice, ray, interval) else {
        return;
    };
    let mut t_in = dda.t_enter;
    loop {
        // Step 2: the plane met first: the axis with the smallest t_max
        // (on a tie, x before y before z). The ray leaves the cell there.
        let axis = if dda.t_max.x <= dda.t_max.y {
            if dda.t_max.x <= dda.t_max.z { 0 } else { 2 }
        } else if dda.t_max.y <= dda.t_max.z {
            1
        } else {
            2
        };
        let t_out = dda.t_max[axis].min(dda.t_exit);
        // Step 3: visit the cell; stop if the visitor is done.
        let index = lattice.index(dda.cell);
        let cell = dda.cell;
        if visit(Visit {
            cell,
            index,
            t_in,
            t_out,
        })
        .is_break()
        {
            return;
        }
        // Step 4: stop where the ray leaves the grid or the interval (a
        // +∞ t_max, a ray parallel to every plane, stops too; so does NaN).
        let next_plane = dda.t_max[axis];
        if next_plane >= dda.t_exit || next_plane.is_nan() {
            return;
        }
        // Step 5: step into the neighbour across that plane; stop past
        // the last cell.
        let next = dda.cell[axis] as isize + isize::from(dda.step[axis]);
        if next < 0 || next >= lattice.cells[axis] as isize {
            return;
        }
        dda.cell[axis] = next as usize;
        t_in = dda.t_max[axis];
        dda.t_max[axis] += dda.t_delta[axis];
    }
}
// ANCHOR_END: walk
