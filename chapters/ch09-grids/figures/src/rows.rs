//! The rows of chapter 9's CSV files (written by `raystep measure`, read
//! by the charts): the resolution sweep, the grid beside the hierarchy
//! and brute force, mailboxing, and the stability catalogue.
use raystep_render::csv::{Decimals, Flag, Row, positive};
use serde::{Deserialize, Serialize};

/// One grid resolution on one scene (`grid-resolution.csv`).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct ResolutionRow {
    /// `uniform-10000`, `bunny`, `stadium`.
    pub scene: String,
    /// Its triangles.
    pub triangles: u64,
    /// Cells along the longest axis.
    pub longest: u64,
    /// Is this the rule's choice (3·∛N)?
    #[serde(with = "Flag")]
    pub rule: bool,
    /// Cells in all.
    pub cells: u64,
    /// Milliseconds to build.
    #[serde(with = "Decimals::<3>")]
    pub build_ms: f64,
    /// Bytes of the lists, their starts and the triangles.
    pub bytes: u64,
    /// Nanoseconds per camera ray (closest hit, one thread, median).
    #[serde(with = "Decimals::<1>")]
    pub primary_ns: f64,
    /// Cells visited per camera ray.
    #[serde(with = "Decimals::<2>")]
    pub primary_cells: f64,
    /// Triangle tests per camera ray.
    #[serde(with = "Decimals::<2>")]
    pub primary_tests: f64,
}

impl Row for ResolutionRow {
    fn check(&self) -> Result<(), String> {
        positive(
            &[self.build_ms, self.primary_ns, self.bytes as f64],
            "times and sizes",
        )
    }
}

/// The methods of [`CompareRow`].
pub const BRUTE: &str = "brute force";
/// See [`BRUTE`].
pub const BVH: &str = "BVH";
/// See [`BRUTE`].
pub const GRID: &str = "grid";

/// One method on one scene (`grid-vs-bvh.csv`).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct CompareRow {
    /// The scene.
    pub scene: String,
    /// Its triangles.
    pub triangles: u64,
    /// [`BRUTE`], [`BVH`] or [`GRID`].
    pub method: String,
    /// Milliseconds to build (0 for brute force).
    #[serde(with = "Decimals::<3>")]
    pub build_ms: f64,
    /// Bytes of the structure and the triangles it reads.
    pub bytes: u64,
    /// Nanoseconds per camera ray.
    #[serde(with = "Decimals::<1>")]
    pub primary_ns: f64,
    /// Nanoseconds per incoherent ray.
    #[serde(with = "Decimals::<1>")]
    pub incoherent_ns: f64,
    /// Node (or cell) visits plus triangle tests per camera ray.
    #[serde(with = "Decimals::<2>")]
    pub primary_work: f64,
    /// The same per incoherent ray.
    #[serde(with = "Decimals::<2>")]
    pub incoherent_work: f64,
}

impl Row for CompareRow {
    fn check(&self) -> Result<(), String> {
        if ![BRUTE, BVH, GRID].contains(&self.method.as_str()) {
            return Err(format!("unknown method `{}`", self.method));
        }
        positive(
            &[self.primary_ns, self.incoherent_ns, self.bytes as f64],
            "times and sizes",
        )
    }
}

/// One fill with and without the mailbox on one scene
/// (`grid-mailbox.csv`).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct MailboxRow {
    /// The scene.
    pub scene: String,
    /// `boxes` or `exact`.
    pub fill: String,
    /// Entries in all cell lists.
    pub entries: u64,
    /// Triangle tests per incoherent ray, mailbox off.
    #[serde(with = "Decimals::<3>")]
    pub tests_off: f64,
    /// Of them, tests of a triangle the ray had already tested.
    #[serde(with = "Decimals::<3>")]
    pub repeats_off: f64,
    /// Triangle tests per incoherent ray, mailbox on.
    #[serde(with = "Decimals::<3>")]
    pub tests_on: f64,
    /// Of them, repeats (the hashed mailbox forgets a few).
    #[serde(with = "Decimals::<3>")]
    pub repeats_on: f64,
    /// Nanoseconds per incoherent ray, mailbox off.
    #[serde(with = "Decimals::<1>")]
    pub ns_off: f64,
    /// Nanoseconds per incoherent ray, mailbox on.
    #[serde(with = "Decimals::<1>")]
    pub ns_on: f64,
}

impl Row for MailboxRow {
    fn check(&self) -> Result<(), String> {
        positive(&[self.ns_off, self.ns_on], "times and sizes")
    }
}

/// One scene × one kind of dangerous ray (`grid-stability.csv`): counted,
/// not timed.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct StabilityRow {
    /// The scene.
    pub scene: String,
    /// The kind of ray.
    pub case: String,
    /// Rays asked (each: closest hit, two any-hit questions).
    pub rays: u64,
    /// Answers that differ from brute force, mailbox on.
    #[serde(rename = "disagreements_mailbox")]
    pub wrong_mailbox: u64,
    /// The same, mailbox off.
    #[serde(rename = "disagreements_no_mailbox")]
    pub wrong_plain: u64,
}

impl Row for StabilityRow {}

#[cfg(test)]
mod tests {
    use super::*;
    use raystep_figure::writes_back;

    /// The committed files read and write back byte for byte: a new
    /// measurement writes their format.
    #[test]
    fn the_committed_csv_files_write_back_unchanged() {
        writes_back::<ResolutionRow>("ch09", "grid-resolution.csv").unwrap();
        writes_back::<CompareRow>("ch09", "grid-vs-bvh.csv").unwrap();
        writes_back::<MailboxRow>("ch09", "grid-mailbox.csv").unwrap();
        writes_back::<StabilityRow>("ch09", "grid-stability.csv").unwrap();
    }
}
