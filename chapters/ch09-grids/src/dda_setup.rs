//! Exercise 1: the 3D DDA's setup (Amanatides and Woo, "A fast voxel
//! traversal algorithm for ray tracing", 1987): the first cell, and per
//! axis how far along the ray the next plane between cells is (`t_max`)
//! and how far apart those planes are (`t_delta`).
use ch08::slab_test;
use raystep_core::{DVec3, Interval, Ray};

use crate::{Dda, Lattice};

// ANCHOR: dda_setup
/// The DDA's start for `ray` within `interval`, or None if the ray
/// misses the grid's box there.
pub fn dda_setup(
    lattice: &Lattice, ray: &Ray, interval: Interval,
) -> Option<Dda> {
    // Step 1: clip the ray to the grid's box (chapter 8's slab test).
    let inside = slab_test(&lattice.bounds, ray, interval)?;
    // Step 2: the first cell: the one holding the entry point.
    let cell = lattice.cell_of(ray.at(inside.min));
    // Step 3: per axis, the next plane in the ray's direction, and the
    // distance in t between two planes.
    let (mut step, mut t_max, mut t_delta) = ([0; 3], [0.0; 3], [0.0; 3]);
    for axis in 0..3 {
        let d = ray.direction[axis];
        if d > 0.0 {
            step[axis] = 1;
            let plane = lattice.plane(axis, cell[axis] + 1);
            t_max[axis] = (plane - ray.origin[axis]) / d;
            t_delta[axis] = lattice.size[axis] / d;
        } else if d < 0.0 {
            step[axis] = -1;
            let plane = lattice.plane(axis, cell[axis]);
            t_max[axis] = (plane - ray.origin[axis]) / d;
            t_delta[axis] = -lattice.size[axis] / d;
        } else {
            // Parallel to the planes (d = 0 or −0): never crosses one.
            step[axis] = 0;
            t_max[axis] = f64::INFINITY;
            t_delta[axis] = f64::INFINITY;
        }
    }
    Some(Dda {
        cell,
        step,
        t_max: DVec3::from_array(t_max),
        t_delta: DVec3::from_array(t_delta),
        t_enter: inside.min,
        t_exit: inside.max,
    })
}
// ANCHOR_END: dda_setup
