//! A grid made for one thing only: many triangles, and the benchmark's
//! single-precision rays, tested with chapter 8's watertight test (the
//! very same numbers as every other method of `raystep bench`).
use std::ops::ControlFlow;

use ch08::{MeshHit, PreparedRay, Ray32, TraceCounts};
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
        triangles: &[[DVec3; 3]],
        resolution: Resolution,
        fill: Fill,
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

    /// The closest hit within `interval`; `counts` gets the cells visited
    /// (as `nodes`) and the triangle tests.
    pub fn closest_hit(
        &self,
        ray: &Ray32,
        interval: Interval,
        counts: &mut TraceCounts,
    ) -> Option<MeshHit> {
        self.closest_recorded(ray, interval, counts, |_| {})
    }

    /// [`MeshGrid::closest_hit`], telling `tested` each triangle it
    /// tests, in order (to count the tests of a triangle already tested).
    /// Generic, so that the benchmark's no-op recorder costs nothing.
    pub fn closest_recorded(
        &self,
        ray: &Ray32,
        interval: Interval,
        counts: &mut TraceCounts,
        mut tested: impl FnMut(u32),
    ) -> Option<MeshHit> {
        if !ray.is_valid() {
            return None;
        }
        let prepared = PreparedRay::new(ray);
        let mut interval = interval;
        let mut closest = None;
        let mut test = |k: u32, interval: &mut Interval| {
            counts.triangles += 1;
            tested(k);
            if let Some(t) =
                prepared.triangle(&self.triangles[k as usize], *interval)
            {
                *interval = interval.with_max(t);
                closest = Some(MeshHit { triangle: k, t });
            }
        };
        for &k in &self.grid.unbounded {
            test(k, &mut interval);
        }
        let mut mailbox = Mailbox::new();
        let mut cells = 0;
        walk(&self.grid.lattice, &ray.to_ray(), interval, |cell| {
            cells += 1;
            for &k in self.grid.cell_objects(cell.index) {
                if self.grid.mailboxing && mailbox.seen(k) {
                    continue;
                }
                test(k, &mut interval);
            }
            if hit_in_cell(interval.max, cell.t_out) {
                ControlFlow::Break(())
            } else {
                ControlFlow::Continue(())
            }
        });
        counts.nodes += cells;
        closest
    }

    /// Is anything hit within `interval`? Stops at the first hit.
    pub fn any_hit(
        &self,
        ray: &Ray32,
        interval: Interval,
        counts: &mut TraceCounts,
    ) -> bool {
        if !ray.is_valid() {
            return false;
        }
        let prepared = PreparedRay::new(ray);
        let mut test = |k: u32| {
            counts.triangles += 1;
            prepared
                .triangle(&self.triangles[k as usize], interval)
                .is_some()
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
