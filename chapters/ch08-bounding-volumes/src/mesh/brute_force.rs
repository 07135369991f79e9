//! Brute force over a mesh: every triangle, in the mesh's order, tested
//! with the chapter's watertight test. What every mesh structure must
//! agree with, asked through the same seam.
use raystep_core::{DVec3, Interval, Ray32};
use raystep_world::{MeshAccelerator, MeshHit, TraceCounts};

use super::prepared_ray::{Closest, PreparedRay};

/// Every triangle of a mesh, tested in order (no structure at all).
#[derive(Clone, Copy, Debug)]
pub struct MeshBruteForce<'a>(pub &'a [[DVec3; 3]]);

impl MeshAccelerator for MeshBruteForce<'_> {
    fn closest_hit(
        &self, ray: &Ray32, interval: Interval, counts: &mut TraceCounts,
    ) -> Option<MeshHit> {
        let ray = PreparedRay::traced(ray)?;
        let mut closest = Closest::new(interval);
        for (k, v) in self.0.iter().enumerate() {
            closest.test(&ray, k as u32, v, counts);
        }
        closest.hit
    }

    fn any_hit(
        &self, ray: &Ray32, interval: Interval, counts: &mut TraceCounts,
    ) -> bool {
        PreparedRay::traced(ray).is_some_and(|ray| {
            self.0.iter().any(|v| ray.blocked_by(v, interval, counts))
        })
    }
}
