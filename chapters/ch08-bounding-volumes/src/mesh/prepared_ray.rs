//! Step 1 of every walk through a mesh: everything that depends on the
//! ray alone (the reciprocal direction, the watertight test's shear) is
//! computed once per ray, not once per box or per triangle; and the one
//! loop step every closest-hit walk repeats for each candidate triangle.
use raystep_core::{DVec3, Interval, Ray32};
use raystep_world::{MeshHit, TraceCounts};

use crate::Shear;
use crate::primitives::sheared_hit;

/// A ray prepared for the walk: the watertight test's shear, and the
/// slab test's reciprocal direction in both precisions.
///
/// Public so that every mesh structure (chapters 9–11, the benchmark's
/// peers) is handed the very same triangle test: [`PreparedRay::triangle`].
pub struct PreparedRay {
    /// The origin, and the watertight test's axes and shear.
    origin: DVec3,
    shear: Shear,
    /// The slab test's origin and reciprocal direction, in both
    /// precisions, and per axis whether the ray goes toward −axis (then
    /// it enters the slab through its max plane).
    pub(crate) origin32: [f32; 3],
    pub(crate) inverse32: [f32; 3],
    pub(crate) origin64: [f64; 3],
    pub(crate) inverse64: [f64; 3],
    pub(crate) negative: [usize; 3],
}

impl PreparedRay {
    /// The ray's reciprocal direction and shear.
    pub fn new(ray: &Ray32) -> PreparedRay {
        let d = ray.direction.as_dvec3();
        let inverse32 = ray.direction.to_array().map(|x| 1.0 / x);
        PreparedRay {
            origin: ray.origin.as_dvec3(),
            // The watertight test's steps 1 and 2 (exercise 2).
            shear: Shear::of(d),
            origin32: ray.origin.to_array(),
            inverse32,
            origin64: ray.origin.as_dvec3().to_array(),
            inverse64: d.to_array().map(|x| 1.0 / x),
            negative: inverse32.map(|x| usize::from(x.is_sign_negative())),
        }
    }

    /// The prepared ray, or `None` for a ray with a NaN, an infinity or a
    /// zero direction: every walk answers those "no hit" untraced.
    pub fn traced(ray: &Ray32) -> Option<PreparedRay> {
        ray.is_valid().then(|| PreparedRay::new(ray))
    }

    /// The watertight test's step 3 and the rest: the hit `t` of the
    /// triangle `v` within `interval`. The same numbers as
    /// [`watertight`](crate::watertight) gives, computed in the same
    /// order.
    #[inline]
    pub fn triangle(&self, v: &[DVec3; 3], interval: Interval) -> Option<f64> {
        // Step 3 (exercise 2), then steps 4–7.
        let sheared = v.map(|vertex| self.shear.vertex(self.origin, vertex));
        sheared_hit(sheared, &self.shear, interval)
    }

    /// Does the triangle `v` block the ray within `interval`? One
    /// any-hit test, counted.
    #[inline]
    pub fn blocked_by(
        &self, v: &[DVec3; 3], interval: Interval, counts: &mut TraceCounts,
    ) -> bool {
        counts.triangles += 1;
        self.triangle(v, interval).is_some()
    }
}

/// The closest hit so far, and the interval it leaves: what a
/// closest-hit walk carries from one candidate triangle to the next.
#[derive(Clone, Copy, Debug)]
pub struct Closest {
    /// `t` still wanted: the query's interval, its end pulled in to the
    /// closest hit so far.
    pub interval: Interval,
    /// The closest hit so far.
    pub hit: Option<MeshHit>,
}

impl Closest {
    /// Nothing found yet within `interval`.
    pub fn new(interval: Interval) -> Closest {
        Closest {
            interval,
            hit: None,
        }
    }

    /// Tests the candidate triangle `triangle` (corners `v`), counted; a
    /// hit becomes the closest and ends the interval. Says whether it did.
    #[inline]
    pub fn test(
        &mut self, ray: &PreparedRay, triangle: u32, v: &[DVec3; 3],
        counts: &mut TraceCounts,
    ) -> bool {
        counts.triangles += 1;
        let Some(t) = ray.triangle(v, self.interval) else {
            return false;
        };
        self.interval = self.interval.with_max(t);
        self.hit = Some(MeshHit { triangle, t });
        true
    }
}
