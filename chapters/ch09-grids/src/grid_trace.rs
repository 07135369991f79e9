//! Asking a [`Grid`] the tracer's two questions: walk the cells along the
//! ray, test the objects listed in each, and stop at the first cell that
//! holds a hit.
use std::ops::ControlFlow;

use raystep_core::{Hit, Interval, Ray};
use raystep_world::{Accelerator, Object};

use crate::{Grid, Mailbox, Visit, walk};

/// How far past a cell's exit a hit may be measured and still count as
/// inside it: rounding moves a cell's computed exit `t` by far less than
/// this fraction of it. A hit that close to the exit makes the walk look
/// at the next cell too, which costs a little and is always safe.
pub const EXIT_SLACK: f64 = 1e-9;

/// Is the closest hit so far, at `t`, inside the cell the ray leaves at
/// `t_out`? Then no cell further on can hold a closer one.
pub fn hit_in_cell(t: f64, t_out: f64) -> bool {
    t <= t_out - EXIT_SLACK * t_out.abs()
}

impl Grid {
    // ANCHOR: closest_hit
    /// The closest hit: the cells in order along the ray. An object can
    /// stretch over several cells, so a hit found in one cell may lie in
    /// a later one: it is kept (the interval now ends there), and the
    /// walk goes on until it reaches the cell that holds it: a closer
    /// hit may still wait in the cells between.
    ///
    /// `observe` is told each cell as the walk enters it (`None`), and
    /// each object as it is tested there (`Some(index)`): the figures draw
    /// the walk from it.
    pub fn closest_hit_observed(
        &self, objects: &[Object], ray: &Ray, interval: Interval,
        observe: &mut dyn FnMut(Visit, Option<u32>),
    ) -> Option<(usize, Hit)> {
        let mut interval = interval;
        let mut closest = None;
        let mut test = |index: u32, interval: &mut Interval| {
            let object = &objects[index as usize];
            if let Some(hit) = object.shape.intersect(ray, *interval) {
                *interval = interval.with_max(hit.t);
                closest = Some((index as usize, hit));
            }
        };
        // Step 1: the objects outside the grid.
        for &index in &self.unbounded {
            test(index, &mut interval);
        }
        // Step 2: the cells, near to far.
        let mut mailbox = Mailbox::new();
        walk(&self.lattice, ray, interval, |cell| {
            observe(cell, None);
            for &index in self.cell_objects(cell.index) {
                // Step 3: an object met in an earlier cell is not tested
                // again (its answer cannot change: the interval only
                // shrinks).
                if self.mailboxing && mailbox.seen(index) {
                    continue;
                }
                observe(cell, Some(index));
                test(index, &mut interval);
            }
            // Step 4: stop once the closest hit lies in this cell.
            if hit_in_cell(interval.max, cell.t_out) {
                ControlFlow::Break(())
            } else {
                ControlFlow::Continue(())
            }
        });
        closest
    }
    // ANCHOR_END: closest_hit
}

impl Accelerator for Grid {
    /// The closest hit ([`Grid::closest_hit_observed`], unobserved).
    fn closest_hit(
        &self, objects: &[Object], ray: &Ray, interval: Interval,
    ) -> Option<(usize, Hit)> {
        self.closest_hit_observed(objects, ray, interval, &mut |_, _| {})
    }

    /// Does anything meet the ray? Any hit at all ends the walk: a shadow
    /// ray needs no order.
    fn any_hit(
        &self, objects: &[Object], ray: &Ray, interval: Interval,
    ) -> bool {
        let hits = |index: u32| {
            objects[index as usize]
                .shape
                .intersect(ray, interval)
                .is_some()
        };
        if self.unbounded.iter().any(|&index| hits(index)) {
            return true;
        }
        let mut mailbox = Mailbox::new();
        let mut blocked = false;
        walk(&self.lattice, ray, interval, |cell| {
            blocked = self.cell_objects(cell.index).iter().any(|&index| {
                !(self.mailboxing && mailbox.seen(index)) && hits(index)
            });
            if blocked {
                ControlFlow::Break(())
            } else {
                ControlFlow::Continue(())
            }
        });
        blocked
    }
}
