//! How to build and run one chapter's tests: the options `raystep check`
//! and `raystep grade` share.

use std::path::PathBuf;
use std::time::Duration;

/// How to build and run one chapter's tests (`raystep check` and `raystep
/// grade` alike).
#[derive(Debug, Clone)]
pub struct Run {
    /// Test the reference solution (no `exercise` feature).
    pub reference: bool,
    /// Build in this target directory instead of cargo's default.
    pub target_dir: Option<PathBuf>,
    /// Do not echo cargo's build progress or the binaries run.
    pub quiet: bool,
    /// How long one test binary may run before it is killed.
    pub timeout: Duration,
}

/// The default of `--timeout`, in seconds. The slowest test binaries of the
/// reference solutions (chapter 7's unit tests and `tests/agreement.rs`, a
/// debug build) take under a second on two cores; a minute leaves a wide
/// margin for a slow machine and a slow but correct student solution, and
/// still ends an endless loop in reasonable time.
pub const DEFAULT_TIMEOUT_SECS: u64 = 60;
