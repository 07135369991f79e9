//! A kd-tree made for one thing only: many triangles, and the benchmark's
//! single-precision rays, tested with chapter 8's watertight test (the
//! very same numbers as every other method of `raystep bench`).
use ch08::{MeshHit, PreparedRay, Ray32, TraceCounts};
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
        triangles: &[[DVec3; 3]],
        builder: KdBuilder,
        costs: KdCosts,
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

    /// The closest hit within `interval`; `counts` gets the nodes
    /// reached and the triangle tests.
    pub fn closest_hit(
        &self,
        ray: &Ray32,
        interval: Interval,
        counts: &mut TraceCounts,
    ) -> Option<MeshHit> {
        if !ray.is_valid() {
            return None;
        }
        let prepared = PreparedRay::new(ray);
        let mut interval = interval;
        let mut closest = None;
        let mut test =
            |k: u32, interval: &mut Interval, counts: &mut TraceCounts| {
                counts.triangles += 1;
                if let Some(t) =
                    prepared.triangle(&self.triangles[k as usize], *interval)
                {
                    *interval = interval.with_max(t);
                    closest = Some(MeshHit { triangle: k, t });
                }
            };
        for &k in &self.tree.unbounded {
            test(k, &mut interval, counts);
        }
        let mut mailbox = Mailbox::new();
        kd_walk(&self.tree, &ray.to_ray(), interval, |visit| {
            counts.nodes += 1;
            let Some(list) = visit.objects else {
                return interval.max;
            };
            for &k in list {
                if self.tree.mailboxing && mailbox.seen(k) {
                    continue;
                }
                test(k, &mut interval, counts);
            }
            interval.max
        });
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
        let test = |k: u32, counts: &mut TraceCounts| {
            counts.triangles += 1;
            prepared
                .triangle(&self.triangles[k as usize], interval)
                .is_some()
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
