//! What one test binary printed on stdout (libtest's pretty format), read
//! back: each test's outcome and, for a failed one, why and where: an insta
//! snapshot's first differing row, or the panic's message and values.

use std::collections::HashMap;

use super::run_context::Context;
use super::snapshot_diff::{InstaFailure, snapshot_contents};

/// The panic message of `todo!()`: a test that stops here has not been attempted.
const TODO: &str = "not yet implemented";

/// How one test ended.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Outcome {
    /// `ok`.
    Passed,
    /// `ignored`.
    Ignored,
    /// `FAILED`, with its panic if one was printed.
    Failed(Option<Failure>),
}

/// Why a test failed: the first line of its panic, or for a snapshot the
/// first row or line that differs; and where.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Failure {
    /// What went wrong, in one line.
    pub message: String,
    /// `file:line` of the panic (of the snapshot assertion for a snapshot),
    /// relative to the package when it is in it: `tests/recursion.rs:212`.
    /// `None` when the panic is in a library outside the workspace.
    pub at: Option<String>,
}

impl Failure {
    /// The test stopped at a `todo!()`.
    pub fn is_todo(&self) -> bool {
        self.message.contains(TODO)
    }
}

/// One test and how it ended.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct TestResult {
    /// As libtest prints it: `tests::offsets_are_signed`.
    pub name: String,
    /// How it ended.
    pub outcome: Outcome,
}

/// What one test binary printed on stdout (libtest's pretty format).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Output {
    /// Every test that reported, in the order they reported.
    pub results: Vec<TestResult>,
    /// It reached its `test result:` line.
    pub finished: bool,
    /// Tests libtest said were slow: `test x has been running for over 60 seconds`.
    pub slow: Vec<String>,
}

/// Reads what one test binary printed on stdout, reading the snapshot
/// files failures name and saying locations as `context` tells.
pub fn parse_output_in(stdout: &str, context: &Context) -> Output {
    let mut results = Vec::new();
    let mut slow = Vec::new();
    let mut failures: HashMap<&str, Failure> = HashMap::new();
    let mut finished = false;
    let mut section: Option<(&str, Vec<&str>)> = None;
    // The failure section of one test ends: read its panic.
    fn close<'a>(
        section: &mut Option<(&'a str, Vec<&'a str>)>,
        failures: &mut HashMap<&'a str, Failure>, context: &Context,
    ) {
        if let Some((name, text)) = section.take() {
            failures.extend(failure(&text, context).map(|m| (name, m)));
        }
    }
    for line in stdout.lines() {
        if let Some(name) = line
            .strip_prefix("---- ")
            .and_then(|l| l.strip_suffix(" stdout ----"))
        {
            close(&mut section, &mut failures, context);
            section = Some((name, Vec::new()));
            continue;
        }
        if line == "failures:" || line.starts_with("test result: ") {
            close(&mut section, &mut failures, context);
            finished |= line.starts_with("test result: ");
            continue;
        }
        if let Some((_, text)) = section.as_mut() {
            text.push(line);
            continue;
        }
        if let Some(name) = line
            .strip_prefix("test ")
            .and_then(|l| l.split_once(" has been running for over "))
            .map(|(name, _)| name)
        {
            slow.push(name.to_string());
            continue;
        }
        if let Some((name, status)) = line
            .strip_prefix("test ")
            .and_then(|l| l.rsplit_once(" ... "))
        {
            let outcome = match status {
                "ok" => Outcome::Passed,
                "FAILED" => Outcome::Failed(None),
                s if s.starts_with("ignored") => Outcome::Ignored,
                _ => continue,
            };
            results.push(TestResult {
                name: name.to_string(),
                outcome,
            });
        }
    }
    close(&mut section, &mut failures, context);
    for result in &mut results {
        if let Outcome::Failed(failure) = &mut result.outcome {
            *failure = failures.get(result.name.as_str()).cloned();
        }
    }
    Output {
        results,
        finished,
        slow,
    }
}

/// The tests of `binary --list --format terse` (`name: test` lines), in order.
pub fn parse_list(stdout: &str) -> Vec<String> {
    stdout
        .lines()
        .filter_map(|line| line.strip_suffix(": test"))
        .map(str::to_string)
        .collect()
}

/// Why a failed test failed, from its captured output: for an insta
/// snapshot, the first row or line that differs and where it is asserted;
/// otherwise the first panic's message (every line of it, in one line) and
/// where it panicked (for `assert_eq!`, with the two values).
fn failure(text: &[&str], context: &Context) -> Option<Failure> {
    let panic = text.iter().position(|l| {
        l.starts_with("thread '") && l.contains(" panicked at ")
    })?;
    let panicked_at = text[panic]
        .split_once(" panicked at ")
        .map(|(_, at)| at.trim_end().trim_end_matches(':'))
        .and_then(|at| context.location(at));
    if let Some(insta) = InstaFailure::parse(&text[..panic]) {
        let expected = insta
            .file
            .as_deref()
            .and_then(|file| context.snapshot(file))
            .map(|file| snapshot_contents(&file));
        return Some(Failure {
            message: insta.describe(expected.as_deref()),
            at: insta
                .source
                .as_deref()
                .and_then(|source| context.location(source))
                .or(panicked_at),
        });
    }
    let mut message = text.get(panic + 1)?.trim().to_string();
    let mut at = panicked_at;
    if message.starts_with("assertion `left") {
        // assert_eq!/assert_ne!: the two values follow on their own lines.
        let value = |i: usize, label: &str| {
            let line = text.get(panic + i)?.trim_start().strip_prefix(label)?;
            Some(shortened(line.trim(), VALUE_CHARS))
        };
        if let (Some(left), Some(right)) =
            (value(2, "left:"), value(3, "right:"))
        {
            message.push_str(&format!(" (left: {left}, right: {right})"));
        }
    } else {
        // Every line of the panic's message, not only its first: a
        // property test's says which assertion failed with which values
        // (`prop_assert_eq!`'s left and right), where, and on which input.
        let rest = text[panic + 2..]
            .iter()
            .take_while(|l| {
                !l.starts_with("stack backtrace:")
                    && !l.starts_with("note: ")
                    && !l.starts_with("thread '")
                    && !l.starts_with('\t')
            })
            .map(|l| l.trim())
            .filter(|l| !l.is_empty());
        for line in rest {
            message.push(' ');
            message.push_str(line);
        }
        // proptest panics where its macro starts; its message says where
        // the failing assertion is: `… at tests/walk.rs:168.`
        if message.starts_with("Test failed: ")
            && let Some(place) = proptest_location(&message, context)
        {
            at = Some(place);
        }
        message = shortened(&message, MESSAGE_CHARS);
    }
    Some(Failure { message, at })
}

/// The longest value of an `assert_eq!` kept in a message, in characters.
const VALUE_CHARS: usize = 300;

/// The longest panic message kept, in characters.
const MESSAGE_CHARS: usize = 800;

/// `text` cut to `limit` characters, with `…` where it was cut.
fn shortened(text: &str, limit: usize) -> String {
    if text.chars().count() <= limit {
        return text.to_string();
    }
    let mut cut: String = text.chars().take(limit - 1).collect();
    cut.push('…');
    cut
}

/// The location in a proptest message, `… at tests/walk.rs:168.`, as
/// [`Context::location`] says it.
fn proptest_location(message: &str, context: &Context) -> Option<String> {
    message.match_indices(" at ").find_map(|(i, _)| {
        let rest = &message[i + 4..];
        let end = rest.find(|c: char| c.is_whitespace()).unwrap_or(rest.len());
        let place = rest[..end].trim_end_matches(['.', ',', ';']);
        let (file, line) = place.rsplit_once(':')?;
        (file.ends_with(".rs") && line.bytes().all(|b| b.is_ascii_digit()))
            .then(|| context.location(place))
            .flatten()
    })
}

/// Reads what one test binary printed on stdout (paths as printed).
#[cfg(test)]
pub(crate) fn parse_output(stdout: &str) -> Output {
    parse_output_in(stdout, &Context::default())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A panic of several lines keeps them all (a property test's says
    /// which values failed, where, and on which input); proptest's own
    /// location replaces its macro's; long values are cut, not dropped.
    #[test]
    fn a_panic_of_several_lines_keeps_its_values() {
        let stdout = "\nrunning 2 tests\ntest p ... FAILED\ntest e ... FAILED\n\n\
            failures:\n\n---- p stdout ----\n\n\
            thread 'p' (31207) panicked at tests/t.rs:2:1:\n\
            Test failed: assertion failed: `(left == right)` \n  left: `0`, \n right: `100`: doubling 0 at tests/t.rs:5.\n\
            minimal failing input: x = 0\n\tsuccesses: 0\n\tlocal rejects: 0\n\tglobal rejects: 0\n\n\
            ---- e stdout ----\n\n\
            thread 'e' (31158) panicked at tests/t.rs:10:10:\n\
            assertion `left == right` failed\n  left: [1.0, 1.0, 1.0]\n right: [X]\n\
            note: run with `RUST_BACKTRACE=1` environment variable to display a backtrace\n\n\
            failures:\n    p\n    e\n\n\
            test result: FAILED. 0 passed; 2 failed; 0 ignored; 0 measured; 0 filtered out; finished in 0.00s\n";
        let long = format!("[{}]", "1.0, ".repeat(100));
        let stdout = stdout.replace("[X]", &long);
        let output = parse_output(&stdout);
        let failure = |name: &str| match &output
            .results
            .iter()
            .find(|r| r.name == name)
            .unwrap()
            .outcome
        {
            Outcome::Failed(Some(failure)) => failure.clone(),
            other => panic!("{other:?}"),
        };
        assert_eq!(
            failure("p"),
            Failure {
                message: "Test failed: assertion failed: `(left == right)` \
                          left: `0`, right: `100`: doubling 0 at \
                          tests/t.rs:5. minimal failing input: x = 0"
                    .into(),
                at: Some("tests/t.rs:5".into()),
            }
        );
        let e = failure("e");
        assert!(
            e.message.starts_with(
                "assertion `left == right` failed (left: [1.0, 1.0, 1.0], \
                 right: [1.0, 1.0,"
            ) && e.message.ends_with("…)")
                && e.message.chars().count() < 400,
            "{e:?}"
        );
    }

    #[test]
    fn listed_tests_are_read() {
        assert_eq!(
            parse_list("a::b: test\nc: test\nbench_it: bench\n"),
            ["a::b", "c"]
        );
        assert!(parse_list("").is_empty());
    }
}
