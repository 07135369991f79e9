//! Where a ray is in its tree, and the two rules that stop the recursion.
use raystep_core::DVec3;

// ANCHOR: path
/// Where a ray sits in the ray tree of its pixel.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Path {
    /// How many bounces made it: 0 for the primary ray, 1 for the ray
    /// reflected where the primary ray hit, and so on.
    pub depth: u32,
    /// Its contribution to the pixel: the product of the k's along the
    /// path (kr at each reflection, kt at each transmission), per channel.
    /// What the ray brings back is multiplied by this before it reaches
    /// the pixel.
    pub weight: DVec3,
}

impl Path {
    /// The primary ray: depth 0, weight 1.
    pub const PRIMARY: Path = Path {
        depth: 0,
        weight: DVec3::ONE,
    };

    /// The path of a ray spawned here whose light is scaled by `k`: one
    /// bounce deeper, weight times `k`.
    pub fn then(self, k: DVec3) -> Path {
        Path {
            depth: self.depth + 1,
            weight: self.weight * k,
        }
    }

    /// The weight as one number: its largest channel.
    pub fn contribution(&self) -> f64 {
        self.weight.max_element()
    }
}
// ANCHOR_END: path

/// Which rule cut a ray.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Cut {
    /// Rule 1: it would go deeper than the maximum depth.
    Depth,
    /// Rule 2: its contribution is below the threshold.
    Contribution,
}

// ANCHOR: stop
/// The lecture's two rules for when to stop spawning rays.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Stop {
    /// Rule 1: no ray deeper than this (0: primary rays only, the local
    /// model of chapter 4).
    pub max_depth: u32,
    /// Rule 2: no ray whose contribution (largest channel of its weight)
    /// is below this. 0 turns the rule off.
    pub min_contribution: f64,
}

/// The depth cap of [`Stop::contribution`]: rule 2 alone never ends
/// between two perfect mirrors (kr = 1, the weight stays 1), so it keeps
/// rule 1 as a safety net this deep.
pub const SAFETY_DEPTH: u32 = 64;

/// What `raystep render` uses for chapters 5–6: rule 2 at 1/1000, a
/// ray below what an 8-bit pixel can show after the tone curve.
pub const DEFAULT_STOP: Stop = Stop::contribution(1e-3);

impl Stop {
    /// Rule 1 alone: stop at `max_depth` bounces, whatever the ray is
    /// worth.
    pub const fn depth(max_depth: u32) -> Stop {
        Stop {
            max_depth,
            min_contribution: 0.0,
        }
    }

    /// Rule 2: stop when a ray would contribute less than `threshold`
    /// (with [`SAFETY_DEPTH`] as the last resort).
    pub const fn contribution(threshold: f64) -> Stop {
        Stop {
            max_depth: SAFETY_DEPTH,
            min_contribution: threshold,
        }
    }

    /// Should the ray with this `path` be cut, and by which rule? The
    /// depth rule is asked first.
    pub fn cut(&self, path: Path) -> Option<Cut> {
        if path.depth > self.max_depth {
            Some(Cut::Depth)
        } else if path.contribution() < self.min_contribution {
            Some(Cut::Contribution)
        } else {
            None
        }
    }
}
// ANCHOR_END: stop
