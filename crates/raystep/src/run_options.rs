//! How to build and run one chapter's tests: the options `raystep check`
//! and `raystep grade` share, and the limits a student's code runs under.

use std::path::PathBuf;
use std::time::Duration;

use std::process::{Command, ExitStatus};

use crate::limited_process::{
    Limits, describe_sandboxed_status, describe_status,
};
use crate::sandbox::Sandbox;

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
    /// How much memory the build and each test binary may ask for
    /// (`--memory`), in bytes.
    pub memory: u64,
    /// How much one test binary may print (`--output`), in bytes.
    pub output: u64,
    /// Where the build and the tests run: inside bubblewrap, or as they are.
    pub sandbox: Option<Sandbox>,
    /// Which copy of the workspace this is, when several build into one
    /// target folder at once (`raystep grade --jobs`): 0 for the first.
    pub copy: u32,
    /// Where the examples a build makes (the held-out program) are copied
    /// as soon as it ends, for the run to use (`raystep grade`); else they
    /// are used where cargo put them.
    pub keep_examples: Option<PathBuf>,
}

impl Run {
    /// The limits of one test binary (or held-out program) of the student.
    pub fn limits(&self) -> Limits {
        Limits {
            time: self.timeout,
            memory: Some(self.memory),
            output: Some(self.output),
        }
    }

    /// `command` inside the sandbox, if there is one.
    pub fn contained(&self, command: Command) -> Command {
        match &self.sandbox {
            Some(sandbox) => sandbox.wrap(command),
            None => command,
        }
    }

    /// How a process of this run ended, as cargo says it.
    pub fn described(&self, status: ExitStatus) -> String {
        match self.sandbox {
            Some(_) => describe_sandboxed_status(status),
            None => describe_status(status),
        }
    }
}

/// The limits `raystep check` and `raystep grade` take on the command
/// line.
#[derive(Debug, Clone, clap::Args)]
pub struct LimitArgs {
    /// Kill a test binary still running after this many seconds; its
    /// exercise is `timed out`.
    #[arg(long, value_name = "SECS", value_parser = seconds,
          default_value_t = DEFAULT_TIMEOUT_SECS as f64)]
    pub timeout: f64,
    /// Stop the build or a test binary that asks for more memory than
    /// this (each process: the compiler, a test binary, what it starts);
    /// its exercise fails, `out of memory (limit 2 GiB, --memory)`.
    #[arg(long, value_name = "SIZE", value_parser = parse_size,
          default_value = DEFAULT_MEMORY)]
    pub memory: u64,
    /// Stop a test binary that prints more than this (stdout and stderr
    /// together); its exercise fails, `printed more than 8 MiB`.
    #[arg(long, value_name = "SIZE", value_parser = parse_size,
          default_value = DEFAULT_OUTPUT)]
    pub output: u64,
}

impl LimitArgs {
    /// `--timeout` as a duration.
    pub fn timeout(&self) -> Duration {
        Duration::from_secs_f64(self.timeout)
    }
}

/// Parses `--timeout`: a positive number of seconds, `60` or `2.5`.
fn seconds(arg: &str) -> Result<f64, String> {
    match arg.trim().parse::<f64>() {
        Ok(s) if s > 0.0 && Duration::try_from_secs_f64(s).is_ok() => Ok(s),
        _ => Err("expected a positive number of seconds".to_string()),
    }
}

/// The default of `--timeout`, in seconds. The slowest test binaries of the
/// reference solutions (chapter 7's unit tests and `tests/agreement.rs`, a
/// debug build) take under a second on two cores; a minute leaves a wide
/// margin for a slow machine and a slow but correct student solution, and
/// still ends an endless loop in reasonable time.
pub const DEFAULT_TIMEOUT_SECS: u64 = 60;

/// The default of `--memory`. The reference's test binaries use under
/// 100 MiB, and the compiler under 300 MiB for the largest chapter; 2 GiB
/// leaves room for a wasteful but correct solution, and stops a loop that
/// collects without end long before the machine (24 GiB here) swaps.
pub const DEFAULT_MEMORY: &str = "2GiB";

/// The default of `--output`: libtest prints each failing test's captured
/// output, a few KiB for the chapters' tests; 8 MiB is a flood.
pub const DEFAULT_OUTPUT: &str = "8MiB";

/// A size as `--memory` and `--output` take it: a whole number of bytes
/// with `KiB`, `MiB` or `GiB` (or `K`, `M`, `G`) after it, or none.
pub fn parse_size(arg: &str) -> Result<u64, String> {
    let arg = arg.trim();
    let split = arg.find(|c: char| !c.is_ascii_digit()).unwrap_or(arg.len());
    let (number, unit) = arg.split_at(split);
    let shift = match unit.trim() {
        "" | "B" => 0,
        "K" | "KiB" => 10,
        "M" | "MiB" => 20,
        "G" | "GiB" => 30,
        _ => {
            return Err(format!(
                "`{arg}` is not a size: write it as 2GiB, 512MiB or 64KiB"
            ));
        }
    };
    let number: u64 = number.parse().map_err(|_| {
        format!("`{arg}` is not a size: write it as 2GiB, 512MiB or 64KiB")
    })?;
    match number.checked_mul(1 << shift) {
        Some(0) => Err("a size of 0 leaves no room at all".to_string()),
        Some(bytes) => Ok(bytes),
        None => Err(format!("`{arg}` is too large")),
    }
}

/// A size as the verdicts say it: `2 GiB`, `512 MiB`, `100000 bytes`.
pub fn shown_size(bytes: u64) -> String {
    for (shift, unit) in [(30, "GiB"), (20, "MiB"), (10, "KiB")] {
        if bytes >= 1 << shift && bytes.is_multiple_of(1 << shift) {
            return format!("{} {unit}", bytes >> shift);
        }
    }
    format!("{bytes} bytes")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sizes_are_read_and_said_in_binary_units() {
        assert_eq!(parse_size("2GiB"), Ok(2 << 30));
        assert_eq!(parse_size("512M"), Ok(512 << 20));
        assert_eq!(parse_size("64 KiB"), Ok(64 << 10));
        assert_eq!(parse_size("1000"), Ok(1000));
        assert!(parse_size("2GB").unwrap_err().contains("2GiB"));
        assert!(parse_size("lots").is_err());
        assert!(parse_size("0").is_err());
        assert!(parse_size("99999999999G").is_err());
        assert_eq!(shown_size(2 << 30), "2 GiB");
        assert_eq!(shown_size(8 << 20), "8 MiB");
        assert_eq!(shown_size(3 << 10), "3 KiB");
        assert_eq!(shown_size(100_000), "100000 bytes");
        let defaults = [DEFAULT_MEMORY, DEFAULT_OUTPUT].map(parse_size);
        assert_eq!(defaults, [Ok(2 << 30), Ok(8 << 20)]);
    }
}
