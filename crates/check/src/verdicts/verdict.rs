//! One exercise's verdict: passed, failed (which test, where, why), not
//! attempted, timed out, not built, or refused.

use std::fmt;

use super::build_failure::CargoFailure;
use super::test_binary::TimedOut;

/// What happened to one exercise.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Verdict {
    /// Every test of the exercise passed.
    Passed,
    /// A test failed for a reason other than `todo!()`: the first such
    /// test, where, and why (`name (tests/x.rs:12): message`).
    Failed(String),
    /// Every failing test stopped at a `todo!()`.
    NotAttempted,
    /// The exercise's test binary was still running at the time limit.
    TimedOut(TimedOut),
    /// Nothing was built to run: the chapter does not compile, or cargo
    /// failed.
    NotBuilt(CargoFailure),
    /// The exercise file names another file, the environment or the
    /// operating system (the rules are `raystep`'s `submission_rules`):
    /// where, and what.
    Refused(String),
}

impl Verdict {
    /// The verdict in a word or two, for tables: `passed`, `failed`, `not
    /// attempted`, `timed out`, `does not compile`, `cargo failed`.
    pub fn kind(&self) -> &'static str {
        match self {
            Verdict::Passed => "passed",
            Verdict::Failed(_) => "failed",
            Verdict::NotAttempted => "not attempted",
            Verdict::TimedOut(_) => "timed out",
            Verdict::NotBuilt(CargoFailure::DoesNotCompile(_)) => {
                "does not compile"
            }
            Verdict::NotBuilt(CargoFailure::Cargo(_)) => "cargo failed",
            Verdict::Refused(_) => "refused",
        }
    }

    /// What there is to say beyond [`Verdict::kind`].
    pub fn message(&self) -> Option<String> {
        match self {
            Verdict::Passed | Verdict::NotAttempted => None,
            Verdict::Failed(why) => Some(why.clone()),
            Verdict::TimedOut(timed_out) => Some(timed_out.to_string()),
            Verdict::NotBuilt(failure) => Some(failure.to_string()),
            Verdict::Refused(why) => Some(why.clone()),
        }
    }
}

impl fmt::Display for Verdict {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Verdict::Passed => write!(f, "passed"),
            Verdict::Failed(why) => write!(f, "failed: {why}"),
            Verdict::NotAttempted => write!(f, "not attempted"),
            Verdict::TimedOut(timed_out) => write!(f, "{timed_out}"),
            Verdict::NotBuilt(failure) => write!(f, "{failure}"),
            Verdict::Refused(why) => write!(f, "refused: {why}"),
        }
    }
}
