//! How `raystep check` judges a chapter's exercises, without running
//! anything: why a build built nothing ([`BuildFailure`]), what each test
//! binary printed (libtest's output, insta's snapshot reports read back),
//! how it ended ([`TestBinary`]), and from these one [`Verdict`] per
//! exercise in the chapter's [`Report`]. The command line builds and runs
//! the tests; this module reads and judges what they said.
//!
//! Its files import one way, from the report down: `report` →
//! `verdict` → `test_binary` → `libtest_output` → `snapshot_diff` →
//! `snapshot_table`, beside `build_failure`, `run_context` and
//! `snapshot_changes`, which import none of the others.

mod build_failure;
mod libtest_output;
mod report;
mod run_context;
mod snapshot_changes;
mod snapshot_diff;
mod snapshot_table;
mod test_binary;
mod verdict;

#[cfg(test)]
mod tests;

pub use build_failure::{
    BuildFailure, CargoFailure, CompileError, cargo_failure, compile_errors,
};
pub use libtest_output::{
    Failure, Outcome, Output, TestResult, parse_list, parse_output_in,
};
pub use report::{Label, Report, report};
pub use run_context::{Context, lexically_normal};
pub use snapshot_changes::{
    Change, ChangedSnapshot, advice, changed_snapshots,
};
pub use test_binary::{
    Ended, Target, TestBinary, TimedOut, still_running, test_binary_in,
};
pub use verdict::Verdict;
