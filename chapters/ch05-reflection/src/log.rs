//! What a trace spends: rays counted by kind, and (for figures) every ray
//! with its end points.
use crate::{Cut, Path};
use raystep_core::{DVec3, Ray};
use std::ops::AddAssign;

/// The kinds of rays a recursive tracer shoots.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum RayKind {
    /// From the eye through a pixel.
    Primary,
    /// From a hit toward a light (chapter 04).
    Shadow,
    /// The mirror ray R = D − 2(D·N)N.
    Reflected,
    /// The refracted ray (chapter 06).
    Transmitted,
}

/// Rays counted by kind, and the rays the two rules did not shoot.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct RayCounts {
    /// Primary rays.
    pub primary: u64,
    /// Shadow rays.
    pub shadow: u64,
    /// Reflected rays.
    pub reflected: u64,
    /// Transmitted rays.
    pub transmitted: u64,
    /// Rays not shot because of rule 1 (the maximum depth).
    pub cut_by_depth: u64,
    /// Rays not shot because of rule 2 (contribution below threshold).
    pub cut_by_contribution: u64,
    /// Refractions that found total internal reflection (chapter 06).
    pub total_internal_reflections: u64,
    /// Surfaces crossed against the medium bookkeeping (chapter 06): a ray
    /// leaving an object it was not inside, or entering one it was.
    pub medium_mismatches: u64,
}

impl RayCounts {
    /// Every ray shot, of every kind.
    pub fn total(&self) -> u64 {
        self.primary + self.shadow + self.reflected + self.transmitted
    }

    /// Rays shot after the primary ones (reflected and transmitted), the
    /// rays the stopping rules decide about.
    pub fn secondary(&self) -> u64 {
        self.reflected + self.transmitted
    }
}

impl AddAssign for RayCounts {
    fn add_assign(&mut self, other: RayCounts) {
        self.primary += other.primary;
        self.shadow += other.shadow;
        self.reflected += other.reflected;
        self.transmitted += other.transmitted;
        self.cut_by_depth += other.cut_by_depth;
        self.cut_by_contribution += other.cut_by_contribution;
        self.total_internal_reflections += other.total_internal_reflections;
        self.medium_mismatches += other.medium_mismatches;
    }
}

/// One ray of a pixel's ray tree, as a figure draws it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LoggedRay {
    /// What kind of ray.
    pub kind: RayKind,
    /// Its place in the tree (shadow rays: the path of the hit they start
    /// from).
    pub path: Path,
    /// Where it starts.
    pub origin: DVec3,
    /// Its direction.
    pub direction: DVec3,
    /// Where it ended: its hit's t, or None for a miss. For a ray that was
    /// cut, None.
    pub t: Option<f64>,
    /// Shadow rays: was the light blocked?
    pub blocked: bool,
    /// Rays that were not shot: the rule that cut them.
    pub cut: Option<Cut>,
}

// ANCHOR: ray_log
/// The tracer's notebook: it counts every ray, and if asked to, keeps
/// each one for a figure of the ray tree.
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

    /// Notes a traced ray of `kind` at `path` and the t of its closest hit
    /// (None for a miss).
    pub fn traced(&mut self, kind: RayKind, path: Path, ray: &Ray, t: Option<f64>) {
        match kind {
            RayKind::Primary => self.counts.primary += 1,
            RayKind::Shadow => self.counts.shadow += 1,
            RayKind::Reflected => self.counts.reflected += 1,
            RayKind::Transmitted => self.counts.transmitted += 1,
        }
        self.keep(kind, path, ray, t, false, None);
    }

    /// Notes a shadow ray from a hit at `path`, and whether it was blocked.
    pub fn shadow(&mut self, path: Path, ray: &Ray, t_light: f64, blocked: bool) {
        self.counts.shadow += 1;
        self.keep(RayKind::Shadow, path, ray, Some(t_light), blocked, None);
    }

    /// Notes a ray of `kind` at `path` that `cut` stopped before it was
    /// shot.
    pub fn cut(&mut self, kind: RayKind, path: Path, ray: &Ray, cut: Cut) {
        match cut {
            Cut::Depth => self.counts.cut_by_depth += 1,
            Cut::Contribution => self.counts.cut_by_contribution += 1,
        }
        self.keep(kind, path, ray, None, false, Some(cut));
    }

    fn keep(
        &mut self,
        kind: RayKind,
        path: Path,
        ray: &Ray,
        t: Option<f64>,
        blocked: bool,
        cut: Option<Cut>,
    ) {
        if let Some(rays) = &mut self.rays {
            rays.push(LoggedRay {
                kind,
                path,
                origin: ray.origin,
                direction: ray.direction,
                t,
                blocked,
                cut,
            });
        }
    }
}
// ANCHOR_END: ray_log
