//! Asking a [`Bvh`] the tracer's two questions: a box that the ray
//! misses rules out everything inside it with one test.
use raystep_core::{Hit, Interval, Ray};
use raystep_world::{Accelerator, Object};

use crate::bvh::enter;
use crate::{Bvh, BvhNode};

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
        // Step 2: the nodes still to visit, each with the t at which the
        // ray enters its box; the root first.
        let mut stack: Vec<(u32, f64)> = Vec::with_capacity(64);
        if let Some(root) = self.nodes.first()
            && let Some(t) = enter(root, ray, interval)
        {
            stack.push((0, t));
        }
        while let Some((k, entry)) = stack.pop() {
            // Step 3: skip a box that begins beyond the closest hit (the
            // interval has shrunk since the box was pushed).
            if entry > interval.max {
                continue;
            }
            let node = self.nodes[k as usize];
            if node.is_leaf() {
                // Step 4: a leaf: test its objects.
                for &index in self.leaf_objects(&node) {
                    test(index, &mut interval);
                }
            } else {
                // Step 5: push the farther child first, so that the nearer
                // one is visited first and shrinks the interval for it.
                let (a, b) = (node.first, node.first + 1);
                let ta = enter(&self.nodes[a as usize], ray, interval);
                let tb = enter(&self.nodes[b as usize], ray, interval);
                match (ta, tb) {
                    (Some(ta), Some(tb)) if tb < ta => {
                        stack.extend([(a, ta), (b, tb)])
                    }
                    (Some(ta), Some(tb)) => stack.extend([(b, tb), (a, ta)]),
                    (Some(ta), None) => stack.push((a, ta)),
                    (None, Some(tb)) => stack.push((b, tb)),
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
                if self.leaf_objects(&node).iter().any(|&index| hits(index)) {
                    return true; // one blocker is enough
                }
            } else {
                stack.extend([node.first, node.first + 1]);
            }
        }
        false
    }
}

impl Bvh {
    /// The objects of a leaf: its range of [`Bvh::order`].
    fn leaf_objects(&self, node: &BvhNode) -> &[u32] {
        &self.order[node.first as usize..(node.first + node.count) as usize]
    }
}
