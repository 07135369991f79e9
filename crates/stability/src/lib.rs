//! One stability catalogue: every place where a ray-tracing method of
//! the lecture is known to fail — rays parallel to a plane or lying in
//! it, rays through shared edges and vertices, grazing rays, origins on
//! surfaces, huge and tiny coordinates, NaN and ∞, deep and flat trees,
//! the critical angle, malformed input files — run against every method
//! that can fail it, and counted: failures out of trials, per case and
//! method, 0 shown as 0.
//!
//! Each group of cases is one module; each case says in one line what
//! goes wrong and runs its trials with a seeded generator, so that every
//! run asks the same questions. The tests run every case with
//! [`Budget::TEST`]; `raystep stability` runs them with
//! [`Budget::FULL`] (≥ 10⁶ rays per accelerator case, ≥ 10⁴ inputs per
//! input case) and writes the table the book shows.
#![deny(missing_docs)]

pub mod accelerators;
pub mod disagreements;
mod edge_rays;
pub mod grid_rays;
pub mod inputs;
pub mod kd_rays;
pub mod media;
pub mod meshes;
pub mod mutate;
pub mod offsets;
pub mod polygons;
mod ray_cases;
pub mod scenes;
pub mod solvers;
pub mod table;
mod trials;
pub mod triangles;

use serde::{Deserialize, Serialize};

// The dangerous rays and scenes of chapters 9 and 10 (grids, kd-trees),
// and the count of answers unlike brute force's.
pub use disagreements::{
    Answers, answers, disagreements, disagreements_by, kd_disagreements,
};
// Rays at the edges two triangles share, and the surfaces they aim at
// (chapter 8's leak counts).
pub use edge_rays::{
    EDGE_REACH, LeakSurface, leak_surfaces, leaks, shared_edge_rays,
};
pub use grid_rays::{StabilityScene, adversarial_rays, stability_scenes};
pub use kd_rays::{KdScene, kd_rays, kd_scenes};
pub use ray_cases::RayCase;

/// How many trials the cases run.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Budget {
    /// Rays per accelerator case (and per case of the cheap primitive
    /// tests).
    pub rays: usize,
    /// Generated inputs per input case.
    pub inputs: usize,
}

impl Budget {
    /// The test suite's: seconds for the whole catalogue.
    pub const TEST: Budget = Budget {
        rays: 1_000,
        inputs: 200,
    };
    /// `raystep stability`'s: ≥ 10⁶ rays per accelerator case, ≥ 10⁴
    /// inputs per input case.
    pub const FULL: Budget = Budget {
        rays: 1_000_000,
        inputs: 10_000,
    };
}

/// One method's result on one case: how many of its trials failed.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct Count {
    /// The method, as the table names it (`watertight`, `bvh: SAH, 16
    /// bins`, `grid`, …).
    pub method: String,
    /// Trials it failed.
    pub failures: u64,
    /// Trials run.
    pub trials: u64,
}

impl Count {
    /// `failures` of `trials` for `method`.
    pub fn new(method: impl Into<String>, failures: u64, trials: u64) -> Count {
        Count {
            method: method.into(),
            failures,
            trials,
        }
    }
}

/// What a failure of a case means for a method: a known weakness the
/// catalogue shows (`Shown`), or a bug (`Never`: the test suite asserts
/// 0 failures).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum Expect {
    /// The method is built to survive the case: any failure is a bug.
    Never,
    /// The method is known to fail it; the count is what the catalogue
    /// is for.
    Shown,
}

/// One adversarial case.
pub struct Case {
    /// Its group (`triangle tests`, `accelerators`, `inputs`, …).
    pub group: &'static str,
    /// Its name, short: `ray through a shared edge`.
    pub name: &'static str,
    /// One line: what goes wrong, and which method survives it.
    pub what: &'static str,
    /// Runs the trials: one count per method, each with whether it may
    /// fail.
    pub run: fn(&Budget) -> Vec<(Count, Expect)>,
}

/// Every case of the catalogue, group after group.
pub fn catalogue() -> Vec<Case> {
    let mut cases = triangles::cases();
    cases.extend(polygons::cases());
    cases.extend(solvers::cases());
    cases.extend(offsets::cases());
    cases.extend(media::cases());
    cases.extend(accelerators::cases());
    cases.extend(meshes::cases());
    cases.extend(inputs::cases());
    cases
}

/// One line of the table: a method's count on a case.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct Row {
    /// The case's group.
    pub group: String,
    /// The case.
    pub case: String,
    /// What goes wrong in it.
    pub what: String,
    /// The method and its count.
    #[serde(flatten)]
    pub count: Count,
    /// Whether the method may fail the case.
    pub expect: Expect,
}

/// The catalogue's groups, in its order.
pub fn groups() -> Vec<&'static str> {
    let mut groups: Vec<&'static str> =
        catalogue().iter().map(|case| case.group).collect();
    groups.dedup();
    groups
}

/// Runs every case of the catalogue with `budget`, telling `started`
/// each case before it runs; an error (before any case runs) if the
/// bunny the cases need cannot be read.
pub fn run_catalogue(
    budget: &Budget, started: &mut dyn FnMut(&Case),
) -> Result<Vec<Row>, String> {
    run_cases(catalogue(), budget, started)
}

/// Runs the cases of one group of the catalogue (named as the table
/// names it), as [`run_catalogue`] runs them all.
pub fn run_group(
    group: &str, budget: &Budget, started: &mut dyn FnMut(&Case),
) -> Result<Vec<Row>, String> {
    if !groups().contains(&group) {
        return Err(format!(
            "no group {group:?} in the catalogue; its groups: {}",
            groups().join(", ")
        ));
    }
    let cases = catalogue().into_iter().filter(|c| c.group == group);
    run_cases(cases.collect(), budget, started)
}

/// Runs `cases` with `budget`, telling `started` each case before it
/// runs.
fn run_cases(
    cases: Vec<Case>, budget: &Budget, started: &mut dyn FnMut(&Case),
) -> Result<Vec<Row>, String> {
    scenes::load_bunny()?;
    let mut rows = Vec::new();
    for case in cases {
        started(&case);
        for (count, expect) in (case.run)(budget) {
            rows.push(Row {
                group: case.group.to_string(),
                case: case.name.to_string(),
                what: case.what.to_string(),
                count,
                expect,
            });
        }
    }
    Ok(rows)
}
