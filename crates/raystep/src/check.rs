//! `raystep check chNN`: run a chapter's tests in student mode and say, for
//! each exercise, whether it passes, fails (and where first), or is still the
//! untouched stub.
//!
//! Cargo's output is read, not its exit code alone: cargo names each test
//! binary on stderr (`Running tests/line_through_points.rs (…)`) in the same
//! order as the binaries print their `running N tests` blocks on stdout, so
//! pairing the two tells which results belong to which exercise. The parsing
//! is a pure function over the captured text ([`parse`], [`report`]).

use std::collections::HashMap;
use std::fmt;
use std::io::{BufRead, BufReader, Read};
use std::path::{Path, PathBuf};
use std::process::{Command, ExitCode, Stdio};

use crate::{Error, workspace};

/// What `raystep check` was asked to do.
#[derive(Debug)]
pub struct Options {
    /// `ch01`, `01` or `1`.
    pub chapter: String,
    /// Test the reference solution (no `exercise` feature).
    pub reference: bool,
    /// Build in this target directory instead of cargo's default.
    pub target_dir: Option<PathBuf>,
    /// Do not echo cargo's build progress.
    pub quiet: bool,
}

/// The panic message of `todo!()`: a test that stops here has not been attempted.
const TODO: &str = "not yet implemented";

/// Runs `raystep check`.
pub fn run(options: &Options) -> Result<ExitCode, Error> {
    let root = workspace::root();
    let chapters = workspace::chapters(&root)?;
    let chapter = workspace::resolve(&options.chapter, &chapters, |c| &c.id)?;
    let exercises = chapter.exercises()?;
    let sources: HashMap<String, String> = exercises
        .iter()
        .filter_map(|e| {
            let path = chapter.dir.join("tests").join(format!("{e}.rs"));
            Some((e.clone(), std::fs::read_to_string(path).ok()?))
        })
        .collect();

    let mode = if options.reference {
        "reference solution"
    } else {
        "student mode, exercise/*.rs"
    };
    if !options.quiet {
        eprintln!(
            "building and running the tests of {} ({mode})…",
            chapter.package
        );
    }
    let output = run_cargo(&root, &chapter.package, options)?;

    println!("{} ({mode})", chapter.package);
    let binaries = match parse(&output.stdout, &output.stderr) {
        Ok(binaries) => binaries,
        Err(failure) => {
            println!("  {failure}");
            return Ok(ExitCode::FAILURE);
        }
    };
    let report = report(&exercises, &binaries, &sources);
    print!("{report}");
    Ok(if report.all_passed() {
        ExitCode::SUCCESS
    } else {
        ExitCode::FAILURE
    })
}

/// Cargo's captured output.
struct Captured {
    stdout: String,
    stderr: String,
}

/// `cargo test -p <package> [--features exercise] --no-fail-fast` in the workspace root.
fn run_cargo(root: &Path, package: &str, options: &Options) -> Result<Captured, Error> {
    let program = std::env::var("CARGO").unwrap_or_else(|_| "cargo".to_string());
    let mut command = Command::new(&program);
    command
        .current_dir(root)
        .args(["test", "--color", "never", "-p", package]);
    if !options.reference {
        command.args(["--features", "exercise"]);
    }
    command
        .arg("--no-fail-fast")
        // Short panic reports; no snapshot files written while checking.
        .env("RUST_BACKTRACE", "0")
        .env_remove("INSTA_FORCE_PASS")
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped());
    if std::env::var_os("INSTA_UPDATE").is_none() {
        command.env("INSTA_UPDATE", "no");
    }
    if let Some(dir) = &options.target_dir {
        command.env("CARGO_TARGET_DIR", dir);
    }
    let spawn_error = |source| Error::Spawn {
        program: program.clone(),
        source,
    };
    let mut child = command.spawn().map_err(spawn_error)?;

    // Echo the build progress (not the test runs) while collecting stderr.
    let stderr = child.stderr.take().expect("stderr is piped");
    let quiet = options.quiet;
    let echo = std::thread::spawn(move || {
        let mut text = String::new();
        let mut building = true;
        for line in BufReader::new(stderr).lines().map_while(Result::ok) {
            building &= !is_test_run_line(&line);
            if building && !quiet {
                eprintln!("{line}");
            }
            text.push_str(&line);
            text.push('\n');
        }
        text
    });
    let mut stdout = String::new();
    let mut pipe = child.stdout.take().expect("stdout is piped");
    let read = pipe.read_to_string(&mut stdout);
    let stderr = echo.join().unwrap_or_default();
    child.wait().map_err(spawn_error)?;
    read.map_err(spawn_error)?;
    Ok(Captured { stdout, stderr })
}

/// Cargo's "the build is done, tests start" lines.
fn is_test_run_line(line: &str) -> bool {
    let line = line.trim_start();
    line.starts_with("Finished ") || line.starts_with("Running ") || line.starts_with("Doc-tests ")
}

/// Which target a test binary was built from.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Target {
    /// `unittests src/lib.rs` or a binary's unit tests.
    Unit(String),
    /// An integration test, by file stem: `tests/line_through_points.rs` → `line_through_points`.
    Test(String),
    /// The doc tests.
    Doc,
}

/// How one test ended.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Outcome {
    /// `ok`.
    Passed,
    /// `ignored`.
    Ignored,
    /// `FAILED`, with the first line of the panic message if one was printed.
    Failed(Option<String>),
}

/// One test and how it ended.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct TestResult {
    /// As libtest prints it: `tests::offsets_are_signed`.
    pub name: String,
    /// How it ended.
    pub outcome: Outcome,
}

/// The results of one test binary.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct TestBinary {
    /// Which target it was built from.
    pub target: Target,
    /// Every test that reported, in the order they reported.
    pub results: Vec<TestResult>,
    /// `None` if the binary printed its `test result:` line; otherwise why it
    /// stopped early (cargo's "process didn't exit successfully" line).
    pub crashed: Option<String>,
}

/// Cargo ran no tests at all.
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
            CargoFailure::DoesNotCompile(error) => write!(f, "the tests do not compile: {error}"),
            CargoFailure::Cargo(error) => write!(f, "cargo failed: {error}"),
        }
    }
}

/// Reads `cargo test --no-fail-fast` output: its stdout (what the test
/// binaries print) and its stderr (cargo's progress, naming each binary).
pub fn parse(stdout: &str, stderr: &str) -> Result<Vec<TestBinary>, CargoFailure> {
    let targets = targets(stderr);
    if targets.is_empty() {
        return Err(cargo_failure(stderr));
    }
    let blocks = blocks(stdout);
    Ok(targets
        .into_iter()
        .zip(blocks)
        .map(|((target, crash), block)| {
            let (results, finished) = parse_block(block);
            TestBinary {
                target,
                results,
                crashed: (!finished)
                    .then(|| crash.unwrap_or_else(|| "the test binary stopped early".to_string())),
            }
        })
        .collect())
}

/// The test binaries cargo ran, in order, each with the reason it crashed if cargo gave one.
fn targets(stderr: &str) -> Vec<(Target, Option<String>)> {
    let mut targets: Vec<(Target, Option<String>)> = Vec::new();
    for line in stderr.lines().map(str::trim) {
        if let Some(rest) = line.strip_prefix("Running ") {
            let source = rest.split(" (").next().unwrap_or(rest);
            let target = match source.strip_prefix("unittests ") {
                Some(path) => Target::Unit(path.to_string()),
                None => Target::Test(test_stem(source)),
            };
            targets.push((target, None));
        } else if line.starts_with("Doc-tests ") {
            targets.push((Target::Doc, None));
        } else if let Some(why) = exit_reason(line) {
            if let Some((_, crash @ None)) = targets.last_mut() {
                *crash = Some(format!("the test binary crashed ({why})"));
            }
        }
    }
    targets
}

/// `tests/line.rs` → `line`; `tests/line/main.rs` → `line`.
fn test_stem(source: &str) -> String {
    let path = Path::new(source);
    let stem = path.file_stem().and_then(|s| s.to_str()).unwrap_or(source);
    if stem == "main" {
        if let Some(dir) = path
            .parent()
            .and_then(|p| p.file_name())
            .and_then(|s| s.to_str())
        {
            return dir.to_string();
        }
    }
    stem.to_string()
}

/// Why cargo ran nothing: the first compiler error (with its location), or cargo's first error.
fn cargo_failure(stderr: &str) -> CargoFailure {
    let lines: Vec<&str> = stderr.lines().collect();
    let first_error = lines.iter().position(|l| l.starts_with("error"));
    let compile_failed = lines
        .iter()
        .any(|l| l.starts_with("error: could not compile"));
    match first_error {
        Some(i) if compile_failed => {
            let mut error = lines[i].to_string();
            if let Some(at) = lines.get(i + 1).and_then(|l| l.trim().strip_prefix("--> ")) {
                error.push_str(&format!(" (at {})", at.replace("src/../", "")));
            } else if let Some(why) = lines[i..].iter().find_map(|l| exit_reason(l)) {
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

/// How a process that cargo ran (a test binary, the compiler) ended, from
/// cargo's "process didn't exit successfully: `…` (signal: 7, SIGBUS: …)":
/// the text in the last brackets.
fn exit_reason(line: &str) -> Option<&str> {
    let why = line
        .trim()
        .strip_prefix("process didn't exit successfully: ")?;
    Some(
        why.rsplit_once("` (")
            .map_or(why, |(_, w)| w.trim_end_matches(')')),
    )
}

/// Splits the binaries' stdout at each `running N tests` line.
fn blocks(stdout: &str) -> Vec<Vec<&str>> {
    let mut blocks: Vec<Vec<&str>> = Vec::new();
    for line in stdout.lines() {
        if is_running_line(line) {
            blocks.push(Vec::new());
        } else if let Some(block) = blocks.last_mut() {
            block.push(line);
        }
    }
    blocks
}

/// `running 1 test`, `running 12 tests`.
fn is_running_line(line: &str) -> bool {
    line.strip_prefix("running ")
        .and_then(|rest| {
            rest.strip_suffix(" tests")
                .or_else(|| rest.strip_suffix(" test"))
        })
        .is_some_and(|n| !n.is_empty() && n.bytes().all(|b| b.is_ascii_digit()))
}

/// One binary's results, and whether it reached its `test result:` line.
fn parse_block(block: Vec<&str>) -> (Vec<TestResult>, bool) {
    let mut results = Vec::new();
    let mut failures: HashMap<&str, String> = HashMap::new();
    let mut finished = false;
    let mut section: Option<(&str, Vec<&str>)> = None;
    for line in block {
        if let Some(name) = line
            .strip_prefix("---- ")
            .and_then(|l| l.strip_suffix(" stdout ----"))
        {
            if let Some((name, text)) = section.take() {
                failures.extend(failure_message(&text).map(|m| (name, m)));
            }
            section = Some((name, Vec::new()));
            continue;
        }
        if line == "failures:" || line.starts_with("test result: ") {
            if let Some((name, text)) = section.take() {
                failures.extend(failure_message(&text).map(|m| (name, m)));
            }
            finished |= line.starts_with("test result: ");
            continue;
        }
        if let Some((_, text)) = section.as_mut() {
            text.push(line);
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
    if let Some((name, text)) = section.take() {
        failures.extend(failure_message(&text).map(|m| (name, m)));
    }
    for result in &mut results {
        if let Outcome::Failed(message) = &mut result.outcome {
            *message = failures.get(result.name.as_str()).cloned();
        }
    }
    (results, finished)
}

/// The first line of the first panic in a failed test's captured output; for
/// an insta snapshot, also the first differing lines of its diff, and for
/// `assert_eq!`, the two values when they are short.
fn failure_message(text: &[&str]) -> Option<String> {
    let panic = text
        .iter()
        .position(|l| l.starts_with("thread '") && l.contains(" panicked at "))?;
    let mut message = text.get(panic + 1)?.trim().to_string();
    if let Some(diff) = snapshot_difference(&text[..panic]) {
        message.push_str(&format!(" ({diff})"));
    } else if message.starts_with("assertion `left") {
        // assert_eq!/assert_ne!: the two values follow on their own lines.
        let value = |i: usize, label: &str| {
            let line = text.get(panic + i)?.trim_start().strip_prefix(label)?;
            (line.len() <= 80).then(|| line.trim().to_string())
        };
        if let (Some(left), Some(right)) = (value(2, "left:"), value(3, "right:")) {
            message.push_str(&format!(" (left: {left}, right: {right})"));
        }
    }
    Some(message)
}

/// The first removed and added line of an insta snapshot diff, runs of
/// spaces squeezed: ``snapshot line 1: expected `3`, got `4` ``.
fn snapshot_difference(text: &[&str]) -> Option<String> {
    if !text.iter().any(|l| l.contains("Snapshot Summary")) {
        return None;
    }
    // Diff rows are `  old  new │±text`; the first row with this sign.
    let changed = |sign: &str| {
        text.iter().find_map(|l| {
            let (numbers, rest) = l.split_once(&format!("│{sign}"))?;
            let number = numbers.split_whitespace().next().unwrap_or("?").to_string();
            Some((
                number,
                rest.split_whitespace().collect::<Vec<_>>().join(" "),
            ))
        })
    };
    match (changed("-"), changed("+")) {
        (Some((line, old)), Some((_, new))) => Some(format!(
            "snapshot line {line}: expected `{old}`, got `{new}`"
        )),
        (Some((line, old)), None) => Some(format!("snapshot line {line}: missing `{old}`")),
        (None, Some((line, new))) => Some(format!("new line {line}: unexpected `{new}`")),
        (None, None) => None,
    }
}

/// What happened to one exercise.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Verdict {
    /// Every test of the exercise passed.
    Passed,
    /// A test failed for a reason other than `todo!()`: the first such test and why.
    Failed(String),
    /// Every failing test stopped at a `todo!()`.
    NotAttempted,
}

impl fmt::Display for Verdict {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Verdict::Passed => write!(f, "passed"),
            Verdict::Failed(why) => write!(f, "failed: {why}"),
            Verdict::NotAttempted => write!(f, "not attempted"),
        }
    }
}

/// The verdict on every exercise, and the count of the chapter's other tests.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Report {
    /// Each exercise and its verdict, in the order given.
    pub exercises: Vec<(String, Verdict)>,
    /// Other tests (unit tests, doc tests, tests of no exercise) that passed.
    pub other_passed: usize,
    /// Other tests that failed, each as `name: why`.
    pub other_failed: Vec<String>,
}

impl Report {
    /// Every exercise passed and no other test failed.
    pub fn all_passed(&self) -> bool {
        self.other_failed.is_empty() && self.exercises.iter().all(|(_, v)| *v == Verdict::Passed)
    }
}

impl fmt::Display for Report {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        const OTHER: &str = "other tests";
        let width = self
            .exercises
            .iter()
            .map(|(e, _)| e.len())
            .chain([OTHER.len()])
            .max()
            .unwrap_or(0);
        for (exercise, verdict) in &self.exercises {
            writeln!(f, "  {exercise:width$}  {verdict}")?;
        }
        write!(
            f,
            "  {OTHER:width$}  {} passed, {} failed",
            self.other_passed,
            self.other_failed.len()
        )?;
        match self.other_failed.first() {
            Some(first) => writeln!(f, " (first: {first})")?,
            None => writeln!(f)?,
        }
        let passed = self
            .exercises
            .iter()
            .filter(|(_, v)| *v == Verdict::Passed)
            .count();
        if self.exercises.is_empty() {
            writeln!(f, "this chapter has no exercises")
        } else {
            writeln!(f, "{passed} of {} exercises passed", self.exercises.len())
        }
    }
}

/// Judges each exercise by the results of its test binary `tests/<exercise>.rs`.
/// `sources` holds the text of those files, to name failing tests in source
/// order (otherwise alphabetically).
pub fn report(
    exercises: &[String],
    binaries: &[TestBinary],
    sources: &HashMap<String, String>,
) -> Report {
    let is_exercise =
        |b: &TestBinary| matches!(&b.target, Target::Test(stem) if exercises.contains(stem));
    let exercises = exercises
        .iter()
        .map(|exercise| {
            let own: Vec<&TestBinary> = binaries
                .iter()
                .filter(|b| b.target == Target::Test(exercise.clone()))
                .collect();
            let verdict = verdict(exercise, &own, sources.get(exercise).map(String::as_str));
            (exercise.clone(), verdict)
        })
        .collect();
    let mut other_passed = 0;
    let mut other_failed = Vec::new();
    for binary in binaries.iter().filter(|b| !is_exercise(b)) {
        for result in &binary.results {
            match &result.outcome {
                Outcome::Passed => other_passed += 1,
                Outcome::Ignored => {}
                Outcome::Failed(why) => other_failed.push(describe(&result.name, why.as_deref())),
            }
        }
        if let Some(crash) = &binary.crashed {
            other_failed.push(crash.clone());
        }
    }
    Report {
        exercises,
        other_passed,
        other_failed,
    }
}

/// One exercise's verdict from its binaries' results.
fn verdict(exercise: &str, binaries: &[&TestBinary], source: Option<&str>) -> Verdict {
    if binaries.is_empty() {
        return Verdict::Failed(format!("no tests ran (expected tests/{exercise}.rs)"));
    }
    let position = |name: &str| {
        let short = name.rsplit("::").next().unwrap_or(name);
        source
            .and_then(|s| s.find(&format!("fn {short}(")))
            .unwrap_or(usize::MAX)
    };
    let mut failed: Vec<(&str, Option<&str>)> = binaries
        .iter()
        .flat_map(|b| &b.results)
        .filter_map(|r| match &r.outcome {
            Outcome::Failed(why) => Some((r.name.as_str(), why.as_deref())),
            _ => None,
        })
        .collect();
    failed.sort_by_key(|(name, _)| (position(name), *name));
    let not_todo = failed
        .iter()
        .find(|(_, why)| !why.is_some_and(|w| w.contains(TODO)));
    if let Some((name, why)) = not_todo {
        return Verdict::Failed(describe(name, *why));
    }
    if let Some(crash) = binaries.iter().find_map(|b| b.crashed.as_ref()) {
        return Verdict::Failed(crash.clone());
    }
    if failed.is_empty() {
        Verdict::Passed
    } else {
        Verdict::NotAttempted
    }
}

/// `name: first line of the panic`.
fn describe(name: &str, why: Option<&str>) -> String {
    format!("{name}: {}", why.unwrap_or("failed (no panic message)"))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn exercises(names: &[&str]) -> Vec<String> {
        names.iter().map(|s| s.to_string()).collect()
    }

    /// A chapter with exercises `add` (both tests hit `todo!()`) and `triple`
    /// (a wrong answer: an insta snapshot and an `assert_eq!` fail), other
    /// tests in `src/lib.rs` and `tests/other.rs`.
    fn student() -> Vec<TestBinary> {
        parse(
            include_str!("../testdata/student.stdout"),
            include_str!("../testdata/student.stderr"),
        )
        .unwrap()
    }

    #[test]
    fn binaries_are_paired_with_their_targets() {
        let binaries = student();
        let targets: Vec<Target> = binaries.iter().map(|b| b.target.clone()).collect();
        assert_eq!(
            targets,
            [
                Target::Unit("src/lib.rs".into()),
                Target::Test("add".into()),
                Target::Test("other".into()),
                Target::Test("triple".into()),
                Target::Doc,
            ]
        );
        assert!(binaries.iter().all(|b| b.crashed.is_none()));
        assert_eq!(binaries[0].results.len(), 1);
        assert_eq!(binaries[4].results.len(), 0);
    }

    #[test]
    fn panic_messages_are_found() {
        let binaries = student();
        let outcome = |binary: usize, name: &str| {
            binaries[binary]
                .results
                .iter()
                .find(|r| r.name == name)
                .map(|r| r.outcome.clone())
                .unwrap()
        };
        assert_eq!(
            outcome(1, "adds_small"),
            Outcome::Failed(Some("not yet implemented".into()))
        );
        assert_eq!(
            outcome(3, "triple_eq"),
            Outcome::Failed(Some(
                "assertion `left == right` failed: triple of two (left: 8, right: 6)".into()
            ))
        );
        assert_eq!(
            outcome(3, "triple_snapshot"),
            Outcome::Failed(Some(
                "snapshot assertion for 'triples' failed in line 2 (snapshot line 1: expected `3`, got `4`)".into()
            ))
        );
        assert_eq!(outcome(3, "triple_zero"), Outcome::Passed);
    }

    #[test]
    fn student_verdicts() {
        let sources = HashMap::from([(
            "triple".to_string(),
            "#[test]\nfn triple_snapshot() {}\n#[test]\nfn triple_eq() {}\n".to_string(),
        )]);
        let report = report(&exercises(&["add", "triple"]), &student(), &sources);
        assert_eq!(
            report.exercises,
            [
                ("add".to_string(), Verdict::NotAttempted),
                (
                    "triple".to_string(),
                    Verdict::Failed(
                        "triple_snapshot: snapshot assertion for 'triples' failed in line 2 \
                         (snapshot line 1: expected `3`, got `4`)"
                            .into()
                    )
                ),
            ]
        );
        assert_eq!(report.other_passed, 2);
        assert!(report.other_failed.is_empty());
        assert!(!report.all_passed());
        assert_eq!(
            report.to_string(),
            "  add          not attempted\n\
             \x20 triple       failed: triple_snapshot: snapshot assertion for 'triples' failed \
             in line 2 (snapshot line 1: expected `3`, got `4`)\n\
             \x20 other tests  2 passed, 0 failed\n\
             0 of 2 exercises passed\n"
        );
    }

    #[test]
    fn without_sources_the_first_failure_is_alphabetical() {
        let report = report(&exercises(&["triple"]), &student(), &HashMap::new());
        assert_eq!(
            report.exercises[0].1,
            Verdict::Failed(
                "triple_eq: assertion `left == right` failed: triple of two (left: 8, right: 6)"
                    .into()
            )
        );
    }

    #[test]
    fn reference_verdicts() {
        let binaries = parse(
            include_str!("../testdata/reference.stdout"),
            include_str!("../testdata/reference.stderr"),
        )
        .unwrap();
        let report = report(&exercises(&["add", "triple"]), &binaries, &HashMap::new());
        assert_eq!(
            report.exercises,
            [
                ("add".to_string(), Verdict::Passed),
                ("triple".to_string(), Verdict::Passed)
            ]
        );
        assert!(report.all_passed());
        assert!(report.to_string().ends_with("2 of 2 exercises passed\n"));
    }

    #[test]
    fn an_exercise_without_tests_fails() {
        let report = report(&exercises(&["missing"]), &student(), &HashMap::new());
        assert_eq!(
            report.exercises[0].1,
            Verdict::Failed("no tests ran (expected tests/missing.rs)".into())
        );
    }

    #[test]
    fn compile_errors_are_reported_with_their_location() {
        let failure = parse("", include_str!("../testdata/compile-error.stderr")).unwrap_err();
        assert_eq!(
            failure.to_string(),
            "the tests do not compile: error[E0308]: mismatched types (at exercise/ex.rs:3:26)"
        );
    }

    #[test]
    fn a_killed_compiler_is_reported_with_how_it_stopped() {
        let failure = parse("", include_str!("../testdata/compiler-killed.stderr")).unwrap_err();
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
            parse("", stderr).unwrap_err(),
            CargoFailure::Cargo(stderr.trim().to_string())
        );
    }

    #[test]
    fn a_crashing_binary_fails_its_exercise() {
        let binaries = parse(
            include_str!("../testdata/crash.stdout"),
            include_str!("../testdata/crash.stderr"),
        )
        .unwrap();
        assert_eq!(
            binaries[0].crashed.as_deref(),
            Some("the test binary crashed (signal: 6, SIGABRT: process abort signal)")
        );
        assert_eq!(binaries[1].crashed, None);
        let report = report(&exercises(&["crash"]), &binaries, &HashMap::new());
        assert_eq!(
            report.exercises[0].1,
            Verdict::Failed(
                "the test binary crashed (signal: 6, SIGABRT: process abort signal)".into()
            )
        );
        assert_eq!(report.other_passed, 1);
    }

    #[test]
    fn doc_tests_ignored_tests_and_module_paths() {
        let stdout = "\nrunning 3 tests\n\
            test tests::fits ... ok\n\
            test tests::slow ... ignored, takes a minute\n\
            test tests::rounds - should panic ... ok\n\n\
            test result: ok. 2 passed; 0 failed; 1 ignored; 0 measured; 0 filtered out; finished in 0.00s\n\n\
            running 1 test\n\
            test chapters/ch01/src/lib.rs - Line2 (line 7) ... FAILED\n\n\
            failures:\n\n\
            ---- chapters/ch01/src/lib.rs - Line2 (line 7) stdout ----\n\
            Test executable failed (exit status: 101).\n\n\
            stderr:\n\n\
            thread 'main' (42) panicked at chapters/ch01/src/lib.rs:5:1:\n\
            not yet implemented\n\n\n\
            failures:\n    chapters/ch01/src/lib.rs - Line2 (line 7)\n\n\
            test result: FAILED. 0 passed; 1 failed; 0 ignored; 0 measured; 0 filtered out; finished in 0.10s\n";
        let stderr =
            "     Running unittests src/lib.rs (target/debug/deps/ch01-1)\n   Doc-tests ch01\n";
        let binaries = parse(stdout, stderr).unwrap();
        assert_eq!(binaries.len(), 2);
        let report = report(&[], &binaries, &HashMap::new());
        assert_eq!(report.other_passed, 2);
        assert_eq!(
            report.other_failed,
            ["chapters/ch01/src/lib.rs - Line2 (line 7): not yet implemented"]
        );
        assert!(!report.all_passed());
        assert!(
            report
                .to_string()
                .ends_with("this chapter has no exercises\n")
        );
    }

    #[test]
    fn running_lines() {
        assert!(is_running_line("running 1 test"));
        assert!(is_running_line("running 12 tests"));
        assert!(!is_running_line("running tests"));
        assert!(!is_running_line("  running 1 test"));
    }

    #[test]
    fn nested_test_folders_are_named_by_folder() {
        assert_eq!(test_stem("tests/line.rs"), "line");
        assert_eq!(test_stem("tests/line/main.rs"), "line");
    }
}
