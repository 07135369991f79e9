//! A grid made for one thing only: many triangles, and the benchmark's
//! single-precision rays, tested with chapter 8's watertight test (the
//! very same numbers as every other method of `raystep bench`).
use std::ops::ControlFlow;

use ch08::{
    Closest, MeshAccelerator, MeshHit, PreparedRay, Ray32, TraceCounts,
};
use raystep_core::{DVec3, Interval};

use crate::{Fill, Grid, Mailbox, Resolution, hit_in_cell, walk};

/// A triangle mesh's grid and its corners.
#[derive(Clone, Debug, PartialEq)]
pub struct MeshGrid {
    /// The grid over the triangles.
    pub grid: Grid,
    /// The corners of every triangle, in the mesh's order.
    pub triangles: Vec<[DVec3; 3]>,
}

impl MeshGrid {
    /// The grid over `triangles` at `resolution`, filled by `fill`.
    pub fn new(
        triangles: &[[DVec3; 3]], resolution: Resolution, fill: Fill,
    ) -> MeshGrid {
        MeshGrid {
            grid: Grid::for_triangles(triangles, resolution, fill),
            triangles: triangles.to_vec(),
        }
    }

    /// The bytes the walk reads: the grid's lists, and the corners.
    pub fn bytes(&self) -> usize {
        self.grid.stats().bytes + self.triangles.len() * size_of::<[DVec3; 3]>()
    }

    /// [`MeshGrid::closest_hit`], telling `tested` each triangle it
    /// tests, in order (to count the tests of a triangle already tested).
    /// Generic, so that the benchmark's no-op recorder costs nothing.
    pub fn closest_recorded(
        &self, ray: &Ray32, interval: Interval, counts: &mut TraceCounts,
        mut tested: impl FnMut(u32),
    ) -> Option<MeshHit> {
        let prepared = PreparedRay::traced(ray)?;
        let mut closest = Closest::new(interval);
        let mut test = |k: u32, closest: &mut Closest| {
            tested(k);
            closest.test(&prepared, k, &self.triangles[k as usize], counts);
        };
        for &k in &self.grid.unbounded {
            test(k, &mut closest);
        }
        let mut mailbox = Mailbox::new();
        let mut cells = 0;
        let start = closest.interval;
        walk(&self.grid.lattice, &ray.to_ray(), start, |cell| {
            cells += 1;
            for &k in self.grid.cell_objects(cell.index) {
                if self.grid.mailboxing && mailbox.seen(k) {
                    continue;
                }
                test(k, &mut closest);
            }
            if hit_in_cell(closest.interval.max, cell.t_out) {
                ControlFlow::Break(())
            } else {
                ControlFlow::Continue(())
            }
        });
        counts.nodes += cells;
        closest.hit
    }
}

impl MeshAccelerator for MeshGrid {
    /// The closest hit; `counts` gets the cells visited (as `nodes`) and
    /// the triangle tests.
    fn closest_hit(
        &self, ray: &Ray32, interval: Interval, counts: &mut TraceCounts,
    ) -> Option<MeshHit> {
        self.closest_recorded(ray, interval, counts, |_| {})
    }

    fn any_hit(
        &self, ray: &Ray32, interval: Interval, counts: &mut TraceCounts,
    ) -> bool {
        let Some(prepared) = PreparedRay::traced(ray) else {
            return false;
        };
        let mut test = |k: u32| {
            let v = &self.triangles[k as usize];
            prepared.blocked_by(v, interval, counts)
        };
        if self.grid.unbounded.iter().any(|&k| test(k)) {
            return true;
        }
        let mut mailbox = Mailbox::new();
        let (mut cells, mut blocked) = (0, false);
        walk(&self.grid.lattice, &ray.to_ray(), interval, |cell| {
            cells += 1;
            blocked = self.grid.cell_objects(cell.index).iter().any(|&k| {
                !(self.grid.mailboxing && mailbox.seen(k)) && test(k)
            });
            if blocked {
                ControlFlow::Break(())
            } else {
                ControlFlow::Continue(())
            }
        });
        counts.nodes += cells;
        blocked
    }
}
