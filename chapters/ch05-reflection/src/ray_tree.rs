//! What a trace spends, noted as it goes: rays counted, and (for the
//! figures and tests) each ray with where it ended.
use crate::{Cut, Path};
use raystep_core::{DVec3, Ray};
use std::ops::AddAssign;

/// The rays of a trace, counted.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct RayCounts {
    /// Primary rays, from the eye through a pixel.
    pub primary: u64,
    /// Secondary rays, spawned at a hit (here every one is a reflected
    /// ray, R = D − 2(D·N)N).
    pub secondary: u64,
    /// Shadow rays, from a hit toward a light (chapter 4).
    pub shadow: u64,
    /// Rays not shot because of rule 1 (the maximum depth).
    pub cut_by_depth: u64,
    /// Rays not shot because of rule 2 (contribution below threshold).
    pub cut_by_contribution: u64,
}

impl RayCounts {
    /// Every ray shot, of every kind.
    pub fn total(&self) -> u64 {
        self.primary + self.secondary + self.shadow
    }
}

impl AddAssign for RayCounts {
    fn add_assign(&mut self, other: RayCounts) {
        self.primary += other.primary;
        self.secondary += other.secondary;
        self.shadow += other.shadow;
        self.cut_by_depth += other.cut_by_depth;
        self.cut_by_contribution += other.cut_by_contribution;
    }
}

/// One ray of a pixel's ray tree, as a figure draws it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LoggedRay {
    /// Its place in the tree: the primary ray is at depth 0; a shadow ray
    /// has the path of the hit it starts from.
    pub path: Path,
    /// Where it starts.
    pub origin: DVec3,
    /// Its direction.
    pub direction: DVec3,
    /// Where it ended: its hit's t (for a shadow ray, the light's), or
    /// None for a miss, or for a ray that was cut.
    pub t: Option<f64>,
    /// Is it a shadow ray?
    pub shadow: bool,
    /// Shadow rays: was the light blocked?
    pub blocked: bool,
    /// Rays that were not shot: the rule that cut them.
    pub cut: Option<Cut>,
}

impl LoggedRay {
    /// Is it the primary ray, from the eye?
    pub fn is_primary(&self) -> bool {
        self.path.depth == 0 && !self.shadow
    }
}

// ANCHOR: ray_log
/// A tracer's notebook: it counts every ray, and if asked to, keeps each
/// one for a figure of the ray tree.
#[derive(Clone, Debug, Default)]
pub struct RayLog {
    /// The counts so far.
    pub counts: RayCounts,
    /// Every ray in the order traced, if recording (see [`RayLog::recording`]).
    pub rays: Option<Vec<LoggedRay>>,
}

impl RayLog {
    /// A log that only counts.
    pub fn new() -> RayLog {
        RayLog::default()
    }

    /// A log that counts and keeps every ray.
    pub fn recording() -> RayLog {
        RayLog {
            rays: Some(Vec::new()),
            ..RayLog::default()
        }
    }

    /// Notes a ray traced at `path` and the t of its closest hit (None for
    /// a miss): a primary ray at depth 0, a secondary one deeper.
    pub fn traced(&mut self, path: Path, ray: &Ray, t: Option<f64>) {
        if path.depth == 0 {
            self.counts.primary += 1;
        } else {
            self.counts.secondary += 1;
        }
        self.keep(path, ray, t, false, false, None);
    }

    /// Notes a shadow ray from a hit at `path`, and whether it was blocked.
    pub fn shadow(
        &mut self, path: Path, ray: &Ray, t_light: f64, blocked: bool,
    ) {
        self.counts.shadow += 1;
        self.keep(path, ray, Some(t_light), true, blocked, None);
    }

    /// Notes a ray at `path` that `cut` stopped before it was shot.
    pub fn cut(&mut self, path: Path, ray: &Ray, cut: Cut) {
        match cut {
            Cut::Depth => self.counts.cut_by_depth += 1,
            Cut::Contribution => self.counts.cut_by_contribution += 1,
        }
        self.keep(path, ray, None, false, false, Some(cut));
    }

    fn keep(
        &mut self, path: Path, ray: &Ray, t: Option<f64>, shadow: bool,
        blocked: bool, cut: Option<Cut>,
    ) {
        if let Some(rays) = &mut self.rays {
            rays.push(LoggedRay {
                path,
                origin: ray.origin,
                direction: ray.direction,
                t,
                shadow,
                blocked,
                cut,
            });
        }
    }
}
// ANCHOR_END: ray_log
