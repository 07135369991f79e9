//! Asking a [`KdTree`] the tracer's two questions.
use ch09::Mailbox;
use raystep_core::{Hit, Interval, Ray};
use raystep_world::{Accelerator, Object};

use crate::{KdTree, KdVisit, kd_walk};

impl KdTree {
    // ANCHOR: closest_hit
    /// The closest hit: the leaves front to back. An object cut by a
    /// plane is listed on both sides, so a hit found in one leaf may lie
    /// beyond it: it is kept, and the walk goes on until the nodes left
    /// all start after it ([`kd_walk`]).
    ///
    /// `observe` is told every node the walk reaches, and each object
    /// tested (with the leaf's visit): the figures draw the walk from it.
    pub fn closest_hit_observed(
        &self, objects: &[Object], ray: &Ray, interval: Interval,
        mut observe: impl FnMut(&KdVisit, Option<u32>),
    ) -> Option<(usize, Hit)> {
        let mut interval = interval;
        let mut closest = None;
        let mut test = |index: u32, interval: &mut Interval| {
            if let Some(hit) =
                objects[index as usize].shape.intersect(ray, *interval)
            {
                *interval = interval.with_max(hit.t);
                closest = Some((index as usize, hit));
            }
        };
        // Step 1: the objects outside the tree.
        for &index in &self.unbounded {
            test(index, &mut interval);
        }
        // Step 2: the leaves, near to far.
        let mut mailbox = Mailbox::new();
        kd_walk(self, ray, interval, |visit| {
            observe(&visit, None);
            let Some(list) = visit.objects else {
                return interval.max;
            };
            for &index in list {
                // Step 3: an object met in an earlier leaf: not again.
                if self.mailboxing && mailbox.seen(index) {
                    continue;
                }
                observe(&visit, Some(index));
                test(index, &mut interval);
            }
            // Step 4: nothing after the closest hit matters.
            interval.max
        });
        closest
    }
    // ANCHOR_END: closest_hit
}

impl Accelerator for KdTree {
    /// The closest hit ([`KdTree::closest_hit_observed`], unobserved).
    fn closest_hit(
        &self, objects: &[Object], ray: &Ray, interval: Interval,
    ) -> Option<(usize, Hit)> {
        self.closest_hit_observed(objects, ray, interval, |_, _| {})
    }

    /// Does anything meet the ray? The first blocker ends the walk.
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
        kd_walk(self, ray, interval, |visit| {
            blocked = visit.objects.is_some_and(|list| {
                list.iter().any(|&index| {
                    !(self.mailboxing && mailbox.seen(index)) && hits(index)
                })
            });
            if blocked {
                f64::NEG_INFINITY
            } else {
                interval.max
            }
        });
        blocked
    }
}
