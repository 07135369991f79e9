//! A kd-tree made for one thing only: many triangles, and the benchmark's
//! single-precision rays, tested with chapter 8's watertight test (the
//! very same numbers as every other method of `raystep bench`).
use ch08::{
    Closest, MeshAccelerator, MeshHit, PreparedRay, Ray32, TraceCounts,
};
use ch09::Mailbox;
use raystep_core::{DVec3, Interval};

use crate::{Clip, KdBuilder, KdCosts, KdTree, kd_walk};

/// A triangle mesh's kd-tree and its corners.
#[derive(Clone, Debug, PartialEq)]
pub struct MeshKd {
    /// The tree over the triangles.
    pub tree: KdTree,
    /// The corners of every triangle, in the mesh's order.
    pub triangles: Vec<[DVec3; 3]>,
}

impl MeshKd {
    /// The tree over `triangles`.
    pub fn new(
        triangles: &[[DVec3; 3]], builder: KdBuilder, costs: KdCosts,
        clip: Clip,
    ) -> MeshKd {
        MeshKd {
            tree: KdTree::for_triangles(triangles, builder, costs, clip),
            triangles: triangles.to_vec(),
        }
    }

    /// The bytes the walk reads: nodes, lists, and the corners.
    pub fn bytes(&self) -> usize {
        self.tree.bytes() + self.triangles.len() * size_of::<[DVec3; 3]>()
    }
}

impl MeshAccelerator for MeshKd {
    /// The closest hit; `counts` gets the nodes reached and the triangle
    /// tests.
    fn closest_hit(
        &self, ray: &Ray32, interval: Interval, counts: &mut TraceCounts,
    ) -> Option<MeshHit> {
        let prepared = PreparedRay::traced(ray)?;
        let mut closest = Closest::new(interval);
        for &k in &self.tree.unbounded {
            closest.test(&prepared, k, &self.triangles[k as usize], counts);
        }
        let mut mailbox = Mailbox::new();
        let start = closest.interval;
        kd_walk(&self.tree, &ray.to_ray(), start, |visit| {
            counts.nodes += 1;
            for &k in visit.objects.unwrap_or_default() {
                if self.tree.mailboxing && mailbox.seen(k) {
                    continue;
                }
                let v = &self.triangles[k as usize];
                closest.test(&prepared, k, v, counts);
            }
            closest.interval.max
        });
        closest.hit
    }

    /// Is anything hit within `interval`? Stops at the first hit.
    fn any_hit(
        &self, ray: &Ray32, interval: Interval, counts: &mut TraceCounts,
    ) -> bool {
        let Some(prepared) = PreparedRay::traced(ray) else {
            return false;
        };
        let test = |k: u32, counts: &mut TraceCounts| {
            let v = &self.triangles[k as usize];
            prepared.blocked_by(v, interval, counts)
        };
        if self.tree.unbounded.iter().any(|&k| test(k, counts)) {
            return true;
        }
        let mut mailbox = Mailbox::new();
        let mut blocked = false;
        kd_walk(&self.tree, &ray.to_ray(), interval, |visit| {
            counts.nodes += 1;
            blocked = visit.objects.is_some_and(|list| {
                list.iter().any(|&k| {
                    !(self.tree.mailboxing && mailbox.seen(k))
                        && test(k, counts)
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
