//! The rows of chapter 9's CSV files (written by `raystep measure`, read
//! by the charts): the resolution sweep, the grid beside the hierarchy
//! and brute force, mailboxing, and the stability catalogue.
use raystep_render::csv::{CsvRow, Record};

/// Times must be positive (false for NaN too).
fn positive(r: &Record, values: &[f64]) -> Result<(), String> {
    if values.iter().all(|&x| x > 0.0) {
        Ok(())
    } else {
        Err(r.error("times and sizes must be positive"))
    }
}

/// One grid resolution on one scene (`grid-resolution.csv`).
#[derive(Clone, Debug, PartialEq)]
pub struct ResolutionRow {
    /// `uniform-10000`, `bunny`, `stadium`.
    pub scene: String,
    /// Its triangles.
    pub triangles: u64,
    /// Cells along the longest axis.
    pub longest: u64,
    /// Is this the rule's choice (3·∛N)?
    pub rule: bool,
    /// Cells in all.
    pub cells: u64,
    /// Milliseconds to build.
    pub build_ms: f64,
    /// Bytes of the lists, their starts and the triangles.
    pub bytes: u64,
    /// Nanoseconds per camera ray (closest hit, one thread, median).
    pub primary_ns: f64,
    /// Cells visited per camera ray.
    pub primary_cells: f64,
    /// Triangle tests per camera ray.
    pub primary_tests: f64,
}

impl CsvRow for ResolutionRow {
    const HEADER: &'static str = "scene,triangles,longest,rule,cells,\
        build_ms,bytes,primary_ns,primary_cells,primary_tests";

    fn to_line(&self) -> String {
        let r = self;
        format!(
            "{},{},{},{},{},{:.3},{},{:.1},{:.2},{:.2}",
            r.scene,
            r.triangles,
            r.longest,
            u8::from(r.rule),
            r.cells,
            r.build_ms,
            r.bytes,
            r.primary_ns,
            r.primary_cells,
            r.primary_tests
        )
    }

    fn from_record(r: &Record) -> Result<ResolutionRow, String> {
        let row = ResolutionRow {
            scene: r.text(0).to_string(),
            triangles: r.count(1, "triangles")?,
            longest: r.count(2, "longest")?,
            rule: r.count(3, "rule")? == 1,
            cells: r.count(4, "cells")?,
            build_ms: r.number(5, "build_ms")?,
            bytes: r.count(6, "bytes")?,
            primary_ns: r.number(7, "primary_ns")?,
            primary_cells: r.number(8, "primary_cells")?,
            primary_tests: r.number(9, "primary_tests")?,
        };
        positive(r, &[row.build_ms, row.primary_ns, row.bytes as f64])?;
        Ok(row)
    }
}

/// The methods of [`CompareRow`].
pub const BRUTE: &str = "brute force";
/// See [`BRUTE`].
pub const BVH: &str = "BVH";
/// See [`BRUTE`].
pub const GRID: &str = "grid";

/// One method on one scene (`grid-vs-bvh.csv`).
#[derive(Clone, Debug, PartialEq)]
pub struct CompareRow {
    /// The scene.
    pub scene: String,
    /// Its triangles.
    pub triangles: u64,
    /// [`BRUTE`], [`BVH`] or [`GRID`].
    pub method: String,
    /// Milliseconds to build (0 for brute force).
    pub build_ms: f64,
    /// Bytes of the structure and the triangles it reads.
    pub bytes: u64,
    /// Nanoseconds per camera ray.
    pub primary_ns: f64,
    /// Nanoseconds per incoherent ray.
    pub incoherent_ns: f64,
    /// Node (or cell) visits plus triangle tests per camera ray.
    pub primary_work: f64,
    /// The same per incoherent ray.
    pub incoherent_work: f64,
}

impl CsvRow for CompareRow {
    const HEADER: &'static str = "scene,triangles,method,build_ms,bytes,\
        primary_ns,incoherent_ns,primary_work,incoherent_work";

    fn to_line(&self) -> String {
        let r = self;
        format!(
            "{},{},{},{:.3},{},{:.1},{:.1},{:.2},{:.2}",
            r.scene,
            r.triangles,
            r.method,
            r.build_ms,
            r.bytes,
            r.primary_ns,
            r.incoherent_ns,
            r.primary_work,
            r.incoherent_work
        )
    }

    fn from_record(r: &Record) -> Result<CompareRow, String> {
        let method = r.text(2);
        if ![BRUTE, BVH, GRID].contains(&method) {
            return Err(r.error(format!("unknown method `{method}`")));
        }
        let row = CompareRow {
            scene: r.text(0).to_string(),
            triangles: r.count(1, "triangles")?,
            method: method.to_string(),
            build_ms: r.number(3, "build_ms")?,
            bytes: r.count(4, "bytes")?,
            primary_ns: r.number(5, "primary_ns")?,
            incoherent_ns: r.number(6, "incoherent_ns")?,
            primary_work: r.number(7, "primary_work")?,
            incoherent_work: r.number(8, "incoherent_work")?,
        };
        positive(r, &[row.primary_ns, row.incoherent_ns, row.bytes as f64])?;
        Ok(row)
    }
}

/// One fill with and without the mailbox on one scene
/// (`grid-mailbox.csv`).
#[derive(Clone, Debug, PartialEq)]
pub struct MailboxRow {
    /// The scene.
    pub scene: String,
    /// `boxes` or `exact`.
    pub fill: String,
    /// Entries in all cell lists.
    pub entries: u64,
    /// Triangle tests per incoherent ray, mailbox off.
    pub tests_off: f64,
    /// Of them, tests of a triangle the ray had already tested.
    pub repeats_off: f64,
    /// Triangle tests per incoherent ray, mailbox on.
    pub tests_on: f64,
    /// Of them, repeats (the hashed mailbox forgets a few).
    pub repeats_on: f64,
    /// Nanoseconds per incoherent ray, mailbox off.
    pub ns_off: f64,
    /// Nanoseconds per incoherent ray, mailbox on.
    pub ns_on: f64,
}

impl CsvRow for MailboxRow {
    const HEADER: &'static str = "scene,fill,entries,tests_off,repeats_off,\
        tests_on,repeats_on,ns_off,ns_on";

    fn to_line(&self) -> String {
        let r = self;
        format!(
            "{},{},{},{:.3},{:.3},{:.3},{:.3},{:.1},{:.1}",
            r.scene,
            r.fill,
            r.entries,
            r.tests_off,
            r.repeats_off,
            r.tests_on,
            r.repeats_on,
            r.ns_off,
            r.ns_on
        )
    }

    fn from_record(r: &Record) -> Result<MailboxRow, String> {
        let row = MailboxRow {
            scene: r.text(0).to_string(),
            fill: r.text(1).to_string(),
            entries: r.count(2, "entries")?,
            tests_off: r.number(3, "tests_off")?,
            repeats_off: r.number(4, "repeats_off")?,
            tests_on: r.number(5, "tests_on")?,
            repeats_on: r.number(6, "repeats_on")?,
            ns_off: r.number(7, "ns_off")?,
            ns_on: r.number(8, "ns_on")?,
        };
        positive(r, &[row.ns_off, row.ns_on])?;
        Ok(row)
    }
}

/// One scene × one kind of dangerous ray (`grid-stability.csv`): counted,
/// not timed.
#[derive(Clone, Debug, PartialEq)]
pub struct StabilityRow {
    /// The scene.
    pub scene: String,
    /// The kind of ray.
    pub case: String,
    /// Rays asked (each: closest hit, two any-hit questions).
    pub rays: u64,
    /// Answers that differ from brute force, mailbox on.
    pub wrong_mailbox: u64,
    /// The same, mailbox off.
    pub wrong_plain: u64,
}

impl CsvRow for StabilityRow {
    const HEADER: &'static str =
        "scene,case,rays,disagreements_mailbox,disagreements_no_mailbox";

    fn to_line(&self) -> String {
        let r = self;
        format!(
            "{},{},{},{},{}",
            r.scene, r.case, r.rays, r.wrong_mailbox, r.wrong_plain
        )
    }

    fn from_record(r: &Record) -> Result<StabilityRow, String> {
        Ok(StabilityRow {
            scene: r.text(0).to_string(),
            case: r.text(1).to_string(),
            rays: r.count(2, "rays")?,
            wrong_mailbox: r.count(3, "disagreements_mailbox")?,
            wrong_plain: r.count(4, "disagreements_no_mailbox")?,
        })
    }
}
