//! The uniform grid: every cell has the list of objects in it.
use raystep_core::{Aabb, DVec3};
use raystep_world::Object;

use crate::{Lattice, Resolution, triangle_overlaps_box};

/// How a grid decides which cells list an object.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Fill {
    /// Every cell the object's bounding box overlaps: simple, and works
    /// for any shape.
    Boxes,
    /// Only the cells a triangle really passes through (the
    /// triangle–box test): fewer entries, fewer tests per ray.
    Exact,
}

impl Fill {
    /// `boxes`, `exact`.
    pub fn name(self) -> &'static str {
        match self {
            Fill::Boxes => "boxes",
            Fill::Exact => "exact",
        }
    }
}

/// A uniform grid over a list of objects: the lattice of cells and, for
/// each cell, the objects in it (stored one after the other: the list of
/// cell `c` is `items[starts[c] .. starts[c + 1]]`).
#[derive(Clone, Debug, PartialEq)]
pub struct Grid {
    /// The cells.
    pub lattice: Lattice,
    /// Where each cell's list begins in `items` (one more entry than
    /// cells: the last is `items.len()`).
    pub starts: Vec<u32>,
    /// The cells' lists, one after the other.
    pub items: Vec<u32>,
    /// Objects with no finite box (a plane): kept outside the grid, in a
    /// list every ray tests (inside, they would fill every cell, and
    /// stretch the grid to infinity).
    pub unbounded: Vec<u32>,
    /// Skip an object already tested by this ray (a hashed mailbox).
    pub mailboxing: bool,
}

/// What a grid is made of, for tables and charts.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GridStats {
    /// Cells along x, y and z.
    pub cells: [usize; 3],
    /// Entries in all cell lists (an object in 5 cells counts 5 times).
    pub entries: usize,
    /// Cells with an empty list.
    pub empty: usize,
    /// The longest list.
    pub longest: usize,
    /// Bytes of the lists and their starts.
    pub bytes: usize,
}

impl Grid {
    /// The grid over `boxes` (object `i` has box `boxes[i]`), each object
    /// listed in every cell its box overlaps.
    pub fn build(boxes: &[Aabb], resolution: Resolution) -> Grid {
        build(boxes, resolution, |_, _| true)
    }

    /// A grid over `boxes` with cells `lattice` chosen by the caller (the
    /// figures want unit cells at whole coordinates), each object listed
    /// in every cell its box overlaps; objects outside the lattice are
    /// listed in the cells at its edge.
    pub fn build_on(boxes: &[Aabb], lattice: Lattice) -> Grid {
        let (inside, unbounded) = split_bounded(boxes);
        fill(boxes, inside, unbounded, lattice, |_, _| true)
    }

    /// The grid over the objects' boxes ([`Shape::bounds`]).
    ///
    /// [`Shape::bounds`]: raystep_core::Shape::bounds
    pub fn for_objects(objects: &[Object], resolution: Resolution) -> Grid {
        let boxes: Vec<Aabb> =
            objects.iter().map(|o| o.shape.bounds()).collect();
        Grid::build(&boxes, resolution)
    }

    /// The grid over triangles, filled by their boxes or exactly.
    pub fn for_triangles(
        triangles: &[[DVec3; 3]], resolution: Resolution, fill: Fill,
    ) -> Grid {
        let boxes: Vec<Aabb> = triangles
            .iter()
            .map(|t| Aabb::around(t.iter().copied()))
            .collect();
        match fill {
            Fill::Boxes => Grid::build(&boxes, resolution),
            Fill::Exact => build(&boxes, resolution, |i, cell| {
                triangle_overlaps_box(&triangles[i as usize], cell)
            }),
        }
    }

    /// The objects listed in cell number `index` ([`Lattice::index`]).
    pub fn cell_objects(&self, index: usize) -> &[u32] {
        let (a, b) = (self.starts[index], self.starts[index + 1]);
        &self.items[a as usize..b as usize]
    }

    /// Its cells, entries and bytes.
    pub fn stats(&self) -> GridStats {
        let lengths = self.starts.windows(2).map(|w| (w[1] - w[0]) as usize);
        GridStats {
            cells: self.lattice.cells,
            entries: self.items.len(),
            empty: lengths.clone().filter(|&n| n == 0).count(),
            longest: lengths.max().unwrap_or(0),
            bytes: (self.starts.len()
                + self.items.len()
                + self.unbounded.len())
                * size_of::<u32>(),
        }
    }
}

/// How far a cell reaches beyond its box when objects are listed: a
/// millionth of its size per axis, and a few units of the coordinates'
/// last place. An object that touches a cell, or misses it by a rounding
/// error, is listed in it: the walk never finds a surface in a cell whose
/// list lacks it.
pub(crate) fn reach(lattice: &Lattice) -> DVec3 {
    let magnitude = lattice.bounds.min.abs().max(lattice.bounds.max.abs());
    1e-6 * lattice.size + 8.0 * f64::EPSILON * magnitude
}

// ANCHOR: build
/// Builds a grid over `boxes`; `overlaps(object, cell box)` decides, for
/// each cell of an object's box, whether the object goes in its list.
fn build(
    boxes: &[Aabb], resolution: Resolution,
    overlaps: impl Fn(u32, &Aabb) -> bool,
) -> Grid {
    // Step 1: objects with a finite box go in the grid, the others
    // (planes, and empty boxes) in a list beside it.
    let (inside, unbounded) = split_bounded(boxes);
    // Step 2: the grid's box: around every object, a little larger so
    // that a flat scene still has cells with some thickness.
    let around = inside
        .iter()
        .fold(Aabb::EMPTY, |b, &i| b.union(boxes[i as usize]));
    let bounds = if inside.is_empty() {
        Aabb::new(DVec3::ZERO, DVec3::ZERO)
    } else {
        around
    };
    let margin = 1e-6
        * (bounds.max - bounds.min)
            .max_element()
            .max(bounds.min.abs().max(bounds.max.abs()).max_element())
            .max(1e-300);
    let bounds = Aabb {
        min: bounds.min - DVec3::splat(margin),
        max: bounds.max + DVec3::splat(margin),
    };
    // Step 3: the resolution.
    let lattice = Lattice::new(bounds, resolution.cells(&bounds, inside.len()));
    fill(boxes, inside, unbounded, lattice, overlaps)
}

/// Objects with a finite, non-empty box, and the others.
fn split_bounded(boxes: &[Aabb]) -> (Vec<u32>, Vec<u32>) {
    let (mut inside, mut unbounded) = (Vec::new(), Vec::new());
    for (i, b) in boxes.iter().enumerate() {
        let finite = b.min.is_finite() && b.max.is_finite();
        if finite && !b.is_empty() {
            inside.push(i as u32);
        } else {
            unbounded.push(i as u32);
        }
    }
    (inside, unbounded)
}

/// The cell lists of `inside` on `lattice`: steps 4 and 5 of the build.
fn fill(
    boxes: &[Aabb], inside: Vec<u32>, unbounded: Vec<u32>, lattice: Lattice,
    overlaps: impl Fn(u32, &Aabb) -> bool,
) -> Grid {
    let pad = reach(&lattice);
    // Step 4: each object's range of cells (its box, a little larger),
    // and the cells in it that `overlaps` accepts: (cell, object) pairs.
    let mut pairs: Vec<(u32, u32)> = Vec::new();
    for &i in &inside {
        let b = boxes[i as usize];
        let lo = lattice.cell_of(b.min - pad);
        let hi = lattice.cell_of(b.max + pad);
        for z in lo[2]..=hi[2] {
            for y in lo[1]..=hi[1] {
                for x in lo[0]..=hi[0] {
                    let cell = lattice.cell_box([x, y, z]);
                    let grown = Aabb {
                        min: cell.min - pad,
                        max: cell.max + pad,
                    };
                    if overlaps(i, &grown) {
                        pairs.push((lattice.index([x, y, z]) as u32, i));
                    }
                }
            }
        }
    }
    // Step 5: count each cell's objects, then place them: one array of
    // lists, each cell's list where the counts before it end (a counting
    // sort of the pairs by cell; each list keeps the objects' order).
    let mut starts = vec![0u32; lattice.count() + 1];
    for &(cell, _) in &pairs {
        starts[cell as usize + 1] += 1;
    }
    for c in 1..starts.len() {
        starts[c] += starts[c - 1];
    }
    let mut next = starts.clone();
    let mut items = vec![0u32; pairs.len()];
    for &(cell, i) in &pairs {
        items[next[cell as usize] as usize] = i;
        next[cell as usize] += 1;
    }
    Grid {
        lattice,
        starts,
        items,
        unbounded,
        mailboxing: true,
    }
}
// ANCHOR_END: build
