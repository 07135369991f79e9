//! Asking a [`Bvh`] the tracer's two questions: a box that the ray
//! misses rules out everything inside it with one test.
use raystep_core::{Hit, Interval, Ray};
use raystep_world::{Accelerator, Object};

use crate::Bvh;
use crate::bvh::enter;

impl Accelerator for Bvh {
    // ANCHOR: bvh_closest_hit
    /// The closest hit: visit the nodes whose boxes the ray enters, the
    /// nearer child first, and skip every box that begins beyond the
    /// closest hit found so far.
    fn closest_hit(
        &self,
        objects: &[Object],
        ray: &Ray,
        interval: Interval,
    ) -> Option<(usize, Hit)> {
        let mut interval = interval;
        let mut closest = None;
        let mut test = |index: u32, interval: &mut Interval| {
            let index = index as usize;
            if let Some(hit) = objects[index].shape.intersect(ray, *interval) {
                *interval = interval.with_max(hit.t); // only closer ones now
                closest = Some((index, hit));
            }
        };
        // Step 1: the objects outside the tree (planes), one by one.
        for &index in &self.unbounded {
            test(index, &mut interval);
        }
        // Step 2: the nodes still to visit, the root first.
        let mut stack: Vec<u32> = Vec::with_capacity(64);
        if !self.nodes.is_empty() {
            stack.push(0);
        }
        while let Some(k) = stack.pop() {
            let node = self.nodes[k as usize];
            // Step 3: skip a box the ray misses, or enters beyond the
            // closest hit (the interval has shrunk since it was pushed).
            if enter(&node, ray, interval).is_none() {
                continue;
            }
            if node.is_leaf() {
                // Step 4: a leaf: test its objects.
                let range =
                    node.first as usize..(node.first + node.count) as usize;
                for &index in &self.order[range] {
                    test(index, &mut interval);
                }
            } else {
                // Step 5: push the farther child first, so that the nearer
                // one is visited first and shrinks the interval for it.
                let (a, b) = (node.first, node.first + 1);
                let ta = enter(&self.nodes[a as usize], ray, interval);
                let tb = enter(&self.nodes[b as usize], ray, interval);
                match (ta, tb) {
                    (Some(ta), Some(tb)) if tb < ta => stack.extend([a, b]),
                    (Some(_), Some(_)) => stack.extend([b, a]),
                    (Some(_), None) => stack.push(a),
                    (None, Some(_)) => stack.push(b),
                    (None, None) => {}
                }
            }
        }
        closest
    }
    // ANCHOR_END: bvh_closest_hit

    /// Does anything meet the ray? The same walk, stopped at the first
    /// object hit, in any order.
    fn any_hit(
        &self,
        objects: &[Object],
        ray: &Ray,
        interval: Interval,
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
        let mut stack: Vec<u32> = Vec::with_capacity(64);
        if !self.nodes.is_empty() {
            stack.push(0);
        }
        while let Some(k) = stack.pop() {
            let node = self.nodes[k as usize];
            if enter(&node, ray, interval).is_none() {
                continue;
            }
            if node.is_leaf() {
                let range =
                    node.first as usize..(node.first + node.count) as usize;
                if self.order[range].iter().any(|&index| hits(index)) {
                    return true; // one blocker is enough
                }
            } else {
                stack.extend([node.first, node.first + 1]);
            }
        }
        false
    }
}
