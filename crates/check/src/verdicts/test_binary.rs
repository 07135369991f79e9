//! One test binary's run, judged from what it printed and how it ended:
//! its tests' results, and whether it crashed or was killed at the time
//! limit (with the tests it was still running).

use std::collections::HashSet;
use std::fmt;
use std::time::Duration;

use super::libtest_output::{Outcome, Output, TestResult, parse_output_in};
use super::run_context::Context;

/// Which target a test binary was built from.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Target {
    /// The unit tests of the library or of a binary, by source path in the
    /// package: `src/lib.rs`, `src/bin/ch01-figures.rs`.
    Unit(String),
    /// An integration test, by file stem: `tests/line_through_points.rs` → `line_through_points`.
    Test(String),
}

impl fmt::Display for Target {
    /// As cargo names it when it runs one: `unittests src/lib.rs`, `tests/line.rs`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Target::Unit(source) => write!(f, "unittests {source}"),
            Target::Test(stem) => write!(f, "tests/{stem}.rs"),
        }
    }
}

/// How a test binary's run ended.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Ended {
    /// It exited by itself: successfully or not, and how, as cargo says it
    /// (`exit status: 101`, `signal: 6, SIGABRT: process abort signal`).
    Exited {
        /// Exit status 0.
        success: bool,
        /// How.
        how: String,
    },
    /// It could not be started: why.
    NotStarted(String),
    /// It was stopped at a limit other than time: out of memory, or
    /// killed for printing too much.
    Stopped {
        /// Which limit, as the verdict says it: `out of memory (limit
        /// 2 GiB, --memory)`.
        why: String,
        /// How it ended, as cargo says it (`signal: 6, SIGABRT: …`).
        how: String,
        /// Its tests in the order libtest starts them (`--list`); empty if unknown.
        listed: Vec<String>,
        /// How many tests it ran at once (`--test-threads`).
        threads: usize,
    },
    /// It was still running at `limit` and was killed.
    TimedOut {
        /// The time limit.
        limit: Duration,
        /// Its tests in the order libtest starts them (`--list`); empty if unknown.
        listed: Vec<String>,
        /// How many tests it ran at once (`--test-threads`).
        threads: usize,
    },
}

/// A test binary that was killed at the time limit.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct TimedOut {
    /// The limit.
    pub limit: Duration,
    /// The tests that were running when it was killed, if that is known.
    pub still_running: Vec<String>,
}

impl fmt::Display for TimedOut {
    /// `timed out after 60 s (still running: recursion::facing_mirrors_terminate)`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "timed out after {} s", self.limit.as_secs_f64())?;
        if !self.still_running.is_empty() {
            write!(f, " (still running: {})", self.still_running.join(", "))?;
        }
        Ok(())
    }
}

/// The results of one test binary.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct TestBinary {
    /// Which target it was built from.
    pub target: Target,
    /// Every test that reported, in the order they reported.
    pub results: Vec<TestResult>,
    /// `None` if the binary printed its `test result:` line (or timed out);
    /// otherwise why it stopped early.
    pub crashed: Option<String>,
    /// `Some` if it was killed at the time limit.
    pub timed_out: Option<TimedOut>,
    /// `Some` if it was stopped at another limit: which, and the tests it
    /// was running (`out of memory (limit 2 GiB, --memory) while running
    /// walk_records_every_cell`).
    pub stopped: Option<String>,
}

/// One binary's results from what it printed and how it ended, reading
/// snapshot files and saying locations as `context` tells.
pub fn test_binary_in(
    target: Target, stdout: &str, ended: &Ended, context: &Context,
) -> TestBinary {
    let output = parse_output_in(stdout, context);
    let stopped = match ended {
        Ended::Stopped {
            why,
            listed,
            threads,
            ..
        } => {
            let running = still_running(&output, listed, *threads);
            Some(if running.is_empty() {
                why.clone()
            } else {
                format!("{why} while running {}", running.join(", "))
            })
        }
        _ => None,
    };
    let (crashed, timed_out) = match ended {
        Ended::Stopped { .. } => (None, None),
        Ended::TimedOut {
            limit,
            listed,
            threads,
        } => (
            None,
            Some(TimedOut {
                limit: *limit,
                still_running: still_running(&output, listed, *threads),
            }),
        ),
        // Killed by a signal after its `test result:` line, or failing
        // with no test failed: libtest itself never does that, so the line
        // may not be libtest's.
        Ended::Exited {
            success: false,
            how,
        } if output.finished
            && (how.contains("signal: ")
                || !output
                    .results
                    .iter()
                    .any(|r| matches!(r.outcome, Outcome::Failed(_)))) =>
        {
            (Some(format!("the test binary crashed ({how})")), None)
        }
        _ if output.finished => (None, None),
        Ended::Exited { success: true, .. } => {
            (Some("the test binary stopped early".to_string()), None)
        }
        Ended::Exited { how, .. } => {
            (Some(format!("the test binary crashed ({how})")), None)
        }
        Ended::NotStarted(why) => (
            Some(format!("the test binary could not be started ({why})")),
            None,
        ),
    };
    TestBinary {
        target,
        results: output.results,
        crashed,
        timed_out,
        stopped,
    }
}

/// The tests a killed binary was still running, in the order it started them.
///
/// libtest starts its tests in `--list` order, up to `threads` at a time,
/// and starts the next whenever one ends. So when `done` tests have
/// reported, the first `done + min(threads, unfinished)` tests of the list
/// have started, and those among them that did not report are the ones
/// running. If a test that reported is not among them the order was another
/// (shuffled): only the tests libtest itself called slow are named then.
pub fn still_running(
    output: &Output, listed: &[String], threads: usize,
) -> Vec<String> {
    let reported: HashSet<&str> =
        output.results.iter().map(|r| r.name.as_str()).collect();
    let done = listed
        .iter()
        .filter(|name| reported.contains(name.as_str()))
        .count();
    let started = &listed[..done + threads.max(1).min(listed.len() - done)];
    let in_order = reported
        .iter()
        .all(|name| started.iter().any(|s| s == name));
    let mut running: Vec<String> = if in_order {
        started
            .iter()
            .filter(|name| !reported.contains(name.as_str()))
            .cloned()
            .collect()
    } else {
        Vec::new()
    };
    for name in &output.slow {
        if !reported.contains(name.as_str()) && !running.contains(name) {
            running.push(name.clone());
        }
    }
    running
}
