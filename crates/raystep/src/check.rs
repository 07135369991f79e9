//! `raystep check chNN`: run a chapter's tests in student mode and say, for
//! each exercise, whether it passes, fails (and where first), times out, or
//! is still the untouched stub.
//!
//! Two steps, so that the verdicts do not depend on the user's cargo settings
//! (`term.quiet`, `term.verbose`, colours) and no test can hang the terminal:
//!
//! 1. **Build** ([`crate::test_build`]) with `cargo test --no-run
//!    --message-format=json-render-diagnostics` and cargo's terminal
//!    settings pinned in its environment. Cargo names every test executable
//!    it built, and the target it belongs to, in the `compiler-artifact`
//!    JSON messages on its stdout ([`crate::cargo_artifacts`]); compiler
//!    errors are rendered on its stderr as usual. When some exercises do not
//!    compile, the others are judged in a copy where those are their stubs
//!    ([`crate::compile_isolation`]).
//! 2. **Run** each test binary ourselves ([`crate::test_run`]), in a fixed
//!    order (the library's unit tests, the binaries' unit tests, then
//!    `tests/*.rs` by name), in the package folder with the environment
//!    cargo would give it, explicit libtest arguments and a time limit. A
//!    binary still running at the limit is killed with every process it
//!    started ([`crate::limited_process`]).
//!
//! Doc tests are not run: the chapters have none.
//!
//! Reading what cargo and the tests printed, and judging each exercise by
//! it, are pure functions over captured text: `raystep_check::verdicts`.

use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::Duration;

use raystep_check::verdicts::{
    BuildFailure, Label, Report, Verdict, changed_snapshots,
};
use raystep_figure::Chapter;

use crate::error::Error;
use crate::run_options::Run;
use crate::shown_path::relative;
use crate::test_build::{Artifacts, build, cargo_program};
use crate::test_run::run_built;
use crate::{
    atomic_file, chapters, compile_isolation, progress_file, questions,
    report_formats, submission_rules, workspace,
};

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
    /// How long one test binary may run before it is killed.
    pub timeout: Duration,
    /// How much memory the build and each test binary may ask for, in bytes.
    pub memory: u64,
    /// How much one test binary may print, in bytes.
    pub output: u64,
    /// Also write the report as JSON to this file.
    pub json: Option<PathBuf>,
    /// Also write the report as JUnit XML to this file.
    pub junit: Option<PathBuf>,
}

/// Runs `raystep check`.
pub fn run(options: &Options) -> Result<ExitCode, Error> {
    let root = workspace::root();
    let chapter = chapters::find(&options.chapter, chapters::CHAPTERS)?;
    for path in options.json.iter().chain(&options.junit) {
        atomic_file::can_write(path)?;
    }
    let mode = if options.reference {
        "reference solution"
    } else {
        "student mode, exercise/*.rs"
    };
    if !options.quiet {
        eprintln!(
            "building the tests of {} ({mode}); the first build takes a few \
             minutes…",
            chapter.package
        );
    }
    let run = Run {
        reference: options.reference,
        target_dir: options.target_dir.clone(),
        quiet: options.quiet,
        timeout: options.timeout,
        memory: options.memory,
        output: options.output,
        // The student's own code on the student's own machine.
        sandbox: None,
        copy: 0,
        keep_examples: None,
    };
    let report = check_chapter(&root, chapter, &run)?;
    println!("{} ({mode})", chapter.package);
    print!("{report}");
    let heading = report_formats::Heading {
        chapter: chapter.id,
        package: chapter.package,
        reference: options.reference,
    };
    // The reports for machines, each written whole or not at all.
    if let Some(path) = &options.json {
        let json = report_formats::json(&heading, &report);
        atomic_file::write(path, json.as_bytes())?;
    }
    if let Some(path) = &options.junit {
        let junit = report_formats::junit(&heading, &report);
        atomic_file::write(path, junit.as_bytes())?;
    }
    // The student's verdicts, for `raystep progress` and `raystep watch`
    // (only here: `grade` checks scratch copies, not the student's work).
    if !options.reference
        && let Err(error) = progress_file::record(&root, chapter.id, &report)
    {
        eprintln!("warning: the progress was not recorded: {error}");
    }
    Ok(if report.all_passed() {
        ExitCode::SUCCESS
    } else {
        ExitCode::FAILURE
    })
}

/// Builds and runs the tests of `chapter` in the workspace at `root`, and
/// judges each exercise. Only cargo failing to start is an error; a build
/// that fails is a report whose exercises do not compile.
pub fn check_chapter(
    root: &Path, chapter: &Chapter, run: &Run,
) -> Result<Report, Error> {
    let dir = root.join("chapters").join(chapter.package);
    let exercises: Vec<String> =
        chapter.exercises.iter().map(|e| e.to_string()).collect();
    let cargo = cargo_program();
    let built =
        build(&cargo, root, chapter.package, run, Artifacts::Workspace)?;
    let mut report = match built {
        Ok(built) => run_built(root, chapter, run, built),
        Err(failure) => {
            // The exercises that compile are still judged, in a copy where
            // the ones that do not are their stubs.
            let others = if run.reference {
                None
            } else {
                compile_isolation::check_others(root, chapter, run, &failure)?
            };
            others.unwrap_or_else(|| Report::not_built(&exercises, failure))
        }
    };
    if !run.reference {
        refuse_exercises(&mut report, &dir);
    }
    // The paper questions, judged from the answers file (no build).
    let paper = questions::judge(root, chapter, run.reference)?;
    for (exercise, _) in &report.exercises {
        let stars = chapter.difficulty(exercise).unwrap_or_default();
        let label = Label {
            stars,
            paper: false,
        };
        report.labels.insert(exercise.clone(), label);
    }
    for (question, verdict) in paper {
        let stars = chapter.difficulty(&question).unwrap_or_default();
        let label = Label { stars, paper: true };
        report.labels.insert(question.clone(), label);
        report.exercises.push((question, verdict));
    }
    report.changed_snapshots = changed_snapshots(&dir);
    report.package_dir = relative(&dir);
    Ok(report)
}

/// Every exercise file in `dir/exercise/` that names another file, the
/// environment or the operating system is refused, whatever its tests
/// said: they ran code that is not judged on its own text.
fn refuse_exercises(report: &mut Report, dir: &Path) {
    for (exercise, verdict) in &mut report.exercises {
        let file = format!("exercise/{exercise}.rs");
        let Ok(text) = std::fs::read_to_string(dir.join(&file)) else {
            continue;
        };
        if let Some(refusal) = submission_rules::first_refusal(&text) {
            *verdict = Verdict::Refused(refusal.describe(&file));
        }
    }
}

/// Only builds the tests of `chapter` (as [`check_chapter`] does): why
/// nothing could be built, or `None` if it built.
pub fn build_failure(
    root: &Path, chapter: &Chapter, run: &Run,
) -> Result<Option<BuildFailure>, Error> {
    Ok(build(
        &cargo_program(),
        root,
        chapter.package,
        run,
        Artifacts::Workspace,
    )?
    .err())
}
