//! Why a build built nothing to run, from cargo's stderr: the first
//! compiler error (with its location), every compiler error, or cargo's
//! own error.

use std::fmt;

/// Cargo built nothing to run.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum CargoFailure {
    /// The chapter (or its tests) do not compile: the first compiler error.
    DoesNotCompile(String),
    /// Cargo stopped for another reason: its first error line.
    Cargo(String),
}

impl fmt::Display for CargoFailure {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            CargoFailure::DoesNotCompile(error) => {
                write!(f, "the tests do not compile: {error}")
            }
            CargoFailure::Cargo(error) => write!(f, "cargo failed: {error}"),
        }
    }
}

/// Why a failed build built nothing, from cargo's stderr: the first compiler
/// error (with its location), or cargo's first error.
pub fn cargo_failure(stderr: &str) -> CargoFailure {
    let lines: Vec<&str> = stderr.lines().collect();
    let first_error = lines.iter().position(|l| l.starts_with("error"));
    let compile_failed = lines
        .iter()
        .any(|l| l.starts_with("error: could not compile"));
    match first_error {
        Some(i) if compile_failed => {
            let mut error = lines[i].to_string();
            if let Some(at) =
                lines.get(i + 1).and_then(|l| l.trim().strip_prefix("--> "))
            {
                error.push_str(&format!(" (at {})", at.replace("src/../", "")));
            } else if let Some(why) =
                lines[i..].iter().find_map(|l| exit_reason(l))
            {
                // No diagnostic: the compiler itself was killed (out of memory,
                // a full disk). Cargo says how under "Caused by".
                error.push_str(&format!("; the compiler stopped ({why})"));
            }
            CargoFailure::DoesNotCompile(error)
        }
        Some(i) => CargoFailure::Cargo(lines[i].to_string()),
        None => CargoFailure::Cargo(
            lines
                .iter()
                .rev()
                .find(|l| !l.trim().is_empty())
                .map_or("no tests ran".to_string(), |l| l.trim().to_string()),
        ),
    }
}

/// A build that built nothing to run: why, and every compiler error.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct BuildFailure {
    /// Why, in one line.
    pub failure: CargoFailure,
    /// Every compiler error, in the order the compiler gave them.
    pub errors: Vec<CompileError>,
}

/// One compiler error.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct CompileError {
    /// Its first line: `error[E0308]: mismatched types`.
    pub message: String,
    /// Where, as the compiler said it without `src/../`:
    /// `chapters/ch02-plane-polygon-hits/exercise/ray_plane.rs:3:26`.
    pub at: Option<String>,
}

/// Every compiler error in cargo's stderr (not cargo's own `could not
/// compile` lines), with its location.
pub fn compile_errors(stderr: &str) -> Vec<CompileError> {
    let lines: Vec<&str> = stderr.lines().collect();
    lines
        .iter()
        .enumerate()
        .filter(|(_, l)| {
            (l.starts_with("error[") || l.starts_with("error: "))
                && !l.starts_with("error: could not compile")
                && !l.starts_with("error: aborting")
        })
        .map(|(i, l)| CompileError {
            message: l.to_string(),
            at: lines
                .get(i + 1)
                .and_then(|n| n.trim().strip_prefix("--> "))
                .map(|at| at.replace("src/../", "")),
        })
        .collect()
}

/// How a process that cargo ran (the compiler) ended, from cargo's "process
/// didn't exit successfully: `…` (signal: 7, SIGBUS: …)": the text in the
/// last brackets.
fn exit_reason(line: &str) -> Option<&str> {
    let why = line
        .trim()
        .strip_prefix("process didn't exit successfully: ")?;
    Some(
        why.rsplit_once("` (")
            .map_or(why, |(_, w)| w.trim_end_matches(')')),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn compile_errors_are_reported_with_their_location() {
        let failure =
            cargo_failure(include_str!("../../testdata/compile-error.stderr"));
        assert_eq!(
            failure.to_string(),
            "the tests do not compile: error[E0308]: mismatched types (at exercise/ex.rs:3:26)"
        );
        // Every error, not cargo's own lines.
        assert_eq!(
            compile_errors(include_str!("../../testdata/compile-error.stderr")),
            [CompileError {
                message: "error[E0308]: mismatched types".into(),
                at: Some("exercise/ex.rs:3:26".into()),
            }]
        );
    }

    #[test]
    fn a_killed_compiler_is_reported_with_how_it_stopped() {
        let failure = cargo_failure(include_str!(
            "../../testdata/compiler-killed.stderr"
        ));
        assert_eq!(
            failure.to_string(),
            "the tests do not compile: error: could not compile `ch07-two-methods` (test \"render\"); \
             the compiler stopped (signal: 7, SIGBUS: access to undefined memory)"
        );
    }

    #[test]
    fn other_cargo_errors_are_reported() {
        let stderr = "error: none of the selected packages contains this feature: exercise\n";
        assert_eq!(
            cargo_failure(stderr),
            CargoFailure::Cargo(stderr.trim().to_string())
        );
    }
}
