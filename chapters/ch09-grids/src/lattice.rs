//! The cells of a uniform grid: one box cut into equal cells, and the
//! arithmetic that finds a point's cell and a cell's box.
use raystep_core::{Aabb, DVec3};

/// A box cut into `cells[0] × cells[1] × cells[2]` equal cells.
///
/// Cell `[i, j, k]` is the box from `bounds.min + [i, j, k]·size` to one
/// `size` further. A point exactly on the plane between two cells belongs
/// to the cell above it (the half-open rule `[i·size, (i+1)·size)`): the
/// same tie rule as chapter 2's `owns_boundary` for a point exactly on
/// an edge ("nudged right and up"), so every point has exactly one cell.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Lattice {
    /// The box the cells fill.
    pub bounds: Aabb,
    /// How many cells along x, y and z (each at least 1).
    pub cells: [usize; 3],
    /// One cell's extent along each axis.
    pub size: DVec3,
}

impl Lattice {
    /// `bounds` cut into `cells` (each at least 1) along the three axes.
    pub fn new(bounds: Aabb, cells: [usize; 3]) -> Lattice {
        let cells = cells.map(|n| n.max(1));
        let n = DVec3::new(cells[0] as f64, cells[1] as f64, cells[2] as f64);
        Lattice {
            bounds,
            cells,
            size: (bounds.max - bounds.min) / n,
        }
    }

    /// How many cells in all.
    pub fn count(&self) -> usize {
        self.cells.iter().product()
    }

    /// The cell's number in a flat array: x fastest, then y, then z.
    pub fn index(&self, cell: [usize; 3]) -> usize {
        cell[0] + self.cells[0] * (cell[1] + self.cells[1] * cell[2])
    }

    /// The coordinate of the `i`-th plane between cells along `axis`
    /// (plane 0 is the box's min face, plane `cells[axis]` its max face,
    /// exactly).
    pub fn plane(&self, axis: usize, i: usize) -> f64 {
        if i >= self.cells[axis] {
            self.bounds.max[axis]
        } else {
            self.bounds.min[axis] + i as f64 * self.size[axis]
        }
    }

    /// The cell along `axis` that holds the coordinate `x`: the tie rule
    /// sends a point on a plane to the cell above it; a point outside the
    /// box goes to the nearest cell.
    pub fn slot(&self, axis: usize, x: f64) -> usize {
        let n = self.cells[axis];
        let s = ((x - self.bounds.min[axis]) / self.size[axis]).floor();
        // `as` saturates (NaN → 0); the clamp keeps the box's max face
        // and anything beyond it in the last cell.
        (s.max(0.0) as usize).min(n - 1)
    }

    /// The cell holding `p` (the nearest cell for a point outside).
    pub fn cell_of(&self, p: DVec3) -> [usize; 3] {
        [0, 1, 2].map(|axis| self.slot(axis, p[axis]))
    }

    /// The box of one cell.
    pub fn cell_box(&self, cell: [usize; 3]) -> Aabb {
        let corner = |offset: usize| {
            DVec3::from_array(
                [0, 1, 2].map(|axis| self.plane(axis, cell[axis] + offset)),
            )
        };
        Aabb {
            min: corner(0),
            max: corner(1),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn lattice() -> Lattice {
        Lattice::new(
            Aabb::new(DVec3::ZERO, DVec3::new(4.0, 2.0, 1.0)),
            [4, 2, 1],
        )
    }

    #[test]
    fn a_point_on_a_plane_belongs_to_the_cell_above() {
        let l = lattice();
        assert_eq!(l.cell_of(DVec3::new(1.0, 1.0, 0.5)), [1, 1, 0]);
        assert_eq!(l.cell_of(DVec3::new(0.999, 0.999, 0.5)), [0, 0, 0]);
        // the max faces and beyond: the last cell; below: the first
        assert_eq!(l.cell_of(DVec3::new(4.0, 2.0, 1.0)), [3, 1, 0]);
        assert_eq!(l.cell_of(DVec3::new(-5.0, 9.0, f64::NAN)), [0, 1, 0]);
    }

    #[test]
    fn cells_tile_the_box() {
        let l = lattice();
        assert_eq!(l.count(), 8);
        assert_eq!(l.index([3, 1, 0]), 7);
        let b = l.cell_box([3, 1, 0]);
        assert_eq!((b.min, b.max), (DVec3::new(3.0, 1.0, 0.0), l.bounds.max));
    }
}
