//! Asking a [`Bvh`] the tracer's two questions: a box that the ray
//! misses rules out everything inside it with one test.
use raystep_core::{Hit, Interval, Ray};
use raystep_world::{Accelerator, Object};

use super::near_first::near_first_closest_hit;
use super::tree::{Bvh, enter};

impl Accelerator for Bvh {
    /// The closest hit: the near-first walk ([`near_first_closest_hit`],
    /// exercise 6).
    fn closest_hit(
        &self, objects: &[Object], ray: &Ray, interval: Interval,
    ) -> Option<(usize, Hit)> {
        near_first_closest_hit(self, objects, ray, interval)
    }

    /// Does anything meet the ray? The same walk, stopped at the first
    /// object hit, in any order.
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
