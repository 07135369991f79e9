//! A chapter's report: each exercise judged by the results of its test
//! binary, the chapter's other tests counted, and the snapshot files that
//! are not the reference named.

use std::collections::{BTreeMap, HashMap};
use std::fmt;
use std::path::PathBuf;

use super::build_failure::BuildFailure;
use super::libtest_output::{Failure, Outcome, TestResult};
use super::snapshot_changes::{self, ChangedSnapshot};
use super::test_binary::{Target, TestBinary};
use super::verdict::Verdict;

/// The verdict on every exercise, the count of the chapter's other tests,
/// and the snapshot files that are not the reference.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct Report {
    /// Each exercise and its verdict, in the order given: the code
    /// exercises, then the paper questions.
    pub exercises: Vec<(String, Verdict)>,
    /// What the table says of each exercise besides its verdict (its
    /// difficulty, whether it is worked on paper), by name; none is shown
    /// for an exercise missing here.
    pub labels: BTreeMap<String, Label>,
    /// Other tests (unit tests, tests of no exercise) that passed.
    pub other_passed: usize,
    /// Other tests that stopped at a `todo!()`: they wait for the exercises.
    pub other_waiting: usize,
    /// Other tests that failed, each as `name (file:line): why`, in source
    /// order (else by name), and other binaries that crashed or timed out.
    pub other_failed: Vec<String>,
    /// Set when nothing was built to run.
    pub build_failure: Option<BuildFailure>,
    /// Snapshot files that are not the reference.
    pub changed_snapshots: Vec<ChangedSnapshot>,
    /// The package folder, as the user would type it (for the advice on
    /// changed snapshots).
    pub package_dir: PathBuf,
    /// The chapter's held-out program as built with the code checked
    /// (`examples/chNN_held_out.rs`, see [`crate::held_out`]), if it has
    /// one.
    pub held_out_runner: Option<PathBuf>,
}

/// What the table says of an exercise besides its verdict.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct Label {
    /// The difficulty: `★`, `★★` or `★★★`.
    pub stars: String,
    /// A question worked on paper (answered in `exercise/answers.toml`),
    /// not code.
    pub paper: bool,
}

impl Label {
    /// The exercise's name as the table shows it: `q1 (paper)`.
    pub fn name(&self, exercise: &str) -> String {
        if self.paper {
            format!("{exercise} (paper)")
        } else {
            exercise.to_string()
        }
    }
}

impl Report {
    /// The name of `exercise` as the table shows it.
    pub fn shown_name(&self, exercise: &str) -> String {
        self.labels
            .get(exercise)
            .map_or_else(|| exercise.to_string(), |l| l.name(exercise))
    }

    /// The report when nothing could be built: every exercise says why.
    pub fn not_built(exercises: &[String], failure: BuildFailure) -> Report {
        Report {
            exercises: exercises
                .iter()
                .map(|e| {
                    (e.clone(), Verdict::NotBuilt(failure.failure.clone()))
                })
                .collect(),
            build_failure: Some(failure),
            ..Report::default()
        }
    }

    /// Every exercise passed, no other test failed or waits, and every
    /// snapshot is the reference.
    pub fn all_passed(&self) -> bool {
        self.build_failure.is_none()
            && self.other_failed.is_empty()
            && self.other_waiting == 0
            && self.changed_snapshots.is_empty()
            && self.exercises.iter().all(|(_, v)| *v == Verdict::Passed)
    }

    /// The other tests in one line: `20 passed, 6 wait for your exercises
    /// (todo!()), 1 failed (first: …)`.
    pub fn other_tests(&self) -> String {
        let mut line = format!("{} passed", self.other_passed);
        if self.other_waiting > 0 {
            line.push_str(&format!(
                ", {} wait for your exercises (todo!())",
                self.other_waiting
            ));
        }
        if let Some(first) = self.other_failed.first() {
            line.push_str(&format!(
                ", {} failed (first: {first})",
                self.other_failed.len()
            ));
        }
        line
    }
}

impl fmt::Display for Report {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        const OTHER: &str = "other tests";
        if let Some(build) = &self.build_failure {
            writeln!(f, "  {}", build.failure)?;
            // The paper questions are judged without a build.
            for (exercise, verdict) in &self.exercises {
                if self.labels.get(exercise).is_some_and(|l| l.paper) {
                    let name = self.shown_name(exercise);
                    writeln!(f, "  {name}  {verdict}")?;
                }
            }
        } else {
            let width = self
                .exercises
                .iter()
                .map(|(e, _)| self.shown_name(e).chars().count())
                .chain([OTHER.len()])
                .max()
                .unwrap_or(0);
            // The difficulty column, when the exercises have one.
            let stars = self
                .labels
                .values()
                .map(|l| l.stars.chars().count())
                .max()
                .unwrap_or(0);
            // `name  ★★   verdict`: the stars left-aligned in their column.
            let column = if stars > 0 { stars + 2 } else { 0 };
            for (exercise, verdict) in &self.exercises {
                let name = self.shown_name(exercise);
                let level = self.labels.get(exercise).map_or("", |l| &l.stars);
                let pad = width - name.chars().count() + 2;
                let after = column - level.chars().count();
                writeln!(
                    f,
                    "  {name}{:pad$}{level}{:after$}{verdict}",
                    "", ""
                )?;
            }
            let pad = width - OTHER.len() + 2 + column;
            writeln!(f, "  {OTHER}{:pad$}{}", "", self.other_tests())?;
        }
        for line in
            snapshot_changes::advice(&self.changed_snapshots, &self.package_dir)
        {
            writeln!(f, "{line}")?;
        }
        if self.build_failure.is_some() {
            return Ok(());
        }
        let count = |paper: bool| {
            let of_kind: Vec<&Verdict> = self
                .exercises
                .iter()
                .filter(|(e, _)| {
                    self.labels.get(e).is_some_and(|l| l.paper) == paper
                })
                .map(|(_, v)| v)
                .collect();
            let passed = of_kind.iter().filter(|v| ***v == Verdict::Passed);
            (passed.count(), of_kind.len())
        };
        let (code, code_of) = count(false);
        let (paper, paper_of) = count(true);
        match (code_of, paper_of) {
            (0, 0) => writeln!(f, "this chapter has no exercises"),
            (_, 0) => writeln!(f, "{code} of {code_of} exercises passed"),
            _ => writeln!(
                f,
                "{code} of {code_of} exercises and {paper} of {paper_of} \
                 paper questions passed"
            ),
        }
    }
}

/// Judges each exercise by the results of its test binary `tests/<exercise>.rs`.
/// `sources` holds the text of the `tests/*.rs` files by stem, to put
/// failing tests in source order (otherwise, and for unit tests, by name).
pub fn report(
    exercises: &[String], binaries: &[TestBinary],
    sources: &HashMap<String, String>,
) -> Report {
    let is_exercise = |b: &TestBinary| matches!(&b.target, Target::Test(stem) if exercises.contains(stem));
    let exercises = exercises
        .iter()
        .map(|exercise| {
            let own: Vec<&TestBinary> = binaries
                .iter()
                .filter(|b| b.target == Target::Test(exercise.clone()))
                .collect();
            let verdict = verdict(
                exercise,
                &own,
                sources.get(exercise).map(String::as_str),
            );
            (exercise.clone(), verdict)
        })
        .collect();
    let mut report = Report {
        exercises,
        ..Report::default()
    };
    for binary in binaries.iter().filter(|b| !is_exercise(b)) {
        let source = match &binary.target {
            Target::Test(stem) => sources.get(stem).map(String::as_str),
            Target::Unit(_) => None,
        };
        let mut results: Vec<&TestResult> = binary.results.iter().collect();
        results.sort_by_key(|r| (source_position(source, &r.name), &r.name));
        for result in results {
            match &result.outcome {
                Outcome::Passed => report.other_passed += 1,
                Outcome::Ignored => {}
                Outcome::Failed(Some(why)) if why.is_todo() => {
                    report.other_waiting += 1;
                }
                Outcome::Failed(why) => report
                    .other_failed
                    .push(describe(&result.name, why.as_ref())),
            }
        }
        if let Some(crash) = &binary.crashed {
            report
                .other_failed
                .push(format!("{}: {crash}", binary.target));
        }
        if let Some(timed_out) = &binary.timed_out {
            report
                .other_failed
                .push(format!("{}: {timed_out}", binary.target));
        }
        if let Some(stopped) = &binary.stopped {
            report
                .other_failed
                .push(format!("{}: {stopped}", binary.target));
        }
    }
    report
}

/// Where the test `name` (`tests::x` or `x`) is defined in `source`;
/// `usize::MAX` if unknown, so that those come last, by name.
fn source_position(source: Option<&str>, name: &str) -> usize {
    let short = name.rsplit("::").next().unwrap_or(name);
    source
        .and_then(|s| s.find(&format!("fn {short}(")))
        .unwrap_or(usize::MAX)
}

/// One exercise's verdict from its binaries' results.
fn verdict(
    exercise: &str, binaries: &[&TestBinary], source: Option<&str>,
) -> Verdict {
    if binaries.is_empty() {
        return Verdict::Failed(format!(
            "no tests ran (expected tests/{exercise}.rs)"
        ));
    }
    // Killed before it could finish: what did report says too little.
    if let Some(timed_out) = binaries.iter().find_map(|b| b.timed_out.as_ref())
    {
        return Verdict::TimedOut(timed_out.clone());
    }
    // Stopped at the memory or output limit: the same.
    if let Some(stopped) = binaries.iter().find_map(|b| b.stopped.as_ref()) {
        return Verdict::Failed(stopped.clone());
    }
    let mut failed: Vec<(&str, Option<&Failure>)> = binaries
        .iter()
        .flat_map(|b| &b.results)
        .filter_map(|r| match &r.outcome {
            Outcome::Failed(why) => Some((r.name.as_str(), why.as_ref())),
            _ => None,
        })
        .collect();
    failed.sort_by_key(|(name, _)| (source_position(source, name), *name));
    let not_todo = failed
        .iter()
        .find(|(_, why)| !why.is_some_and(Failure::is_todo));
    let crash = binaries.iter().find_map(|b| b.crashed.as_ref());
    if let Some((name, why)) = not_todo {
        // A binary that crashes never prints why its tests failed.
        if let (None, Some(crash)) = (why, crash) {
            return Verdict::Failed(format!(
                "{name}: failed, and {crash} before it could say why"
            ));
        }
        return Verdict::Failed(describe(name, *why));
    }
    if let Some(crash) = crash {
        return Verdict::Failed(crash.clone());
    }
    if failed.is_empty() {
        Verdict::Passed
    } else {
        Verdict::NotAttempted
    }
}

/// `name (file:line): what went wrong`.
fn describe(name: &str, why: Option<&Failure>) -> String {
    match why {
        Some(Failure {
            message,
            at: Some(at),
        }) => format!("{name} ({at}): {message}"),
        Some(Failure { message, at: None }) => format!("{name}: {message}"),
        None => format!("{name}: failed (no panic message)"),
    }
}
