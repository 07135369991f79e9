//! What the 3D DDA works with: where a ray's walk stands (the exercises
//! fill it in and step it), and one cell of the walk.
use raystep_core::DVec3;

/// Where a ray's walk through a grid stands: the cell it is in and, per
/// axis, the `t` of the next plane between cells.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Dda {
    /// The cell the ray is in.
    pub cell: [usize; 3],
    /// Per axis, the step to the next cell: +1, −1, or 0 for a ray
    /// parallel to that axis's planes.
    pub step: [i8; 3],
    /// Per axis, the `t` at which the ray crosses into the next cell
    /// along that axis (+∞ if it never does).
    pub t_max: DVec3,
    /// Per axis, the `t` it takes to cross one whole cell (+∞ if
    /// parallel): `t_max` grows by this much at each step along the axis.
    pub t_delta: DVec3,
    /// Where the ray enters the grid (at least the interval's start).
    pub t_enter: f64,
    /// Where it leaves the grid, or the interval ends, if sooner.
    pub t_exit: f64,
}

/// One cell on a ray's walk: which, and the part of the ray inside it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Visit {
    /// The cell, `[x, y, z]`.
    pub cell: [usize; 3],
    /// Its number in the grid's flat arrays
    /// ([`Lattice::index`](crate::Lattice::index)).
    pub index: usize,
    /// Where the ray enters the cell.
    pub t_in: f64,
    /// Where it leaves it (or the walk's interval ends).
    pub t_out: f64,
}
