//! `raystep check chNN`: run a chapter's tests in student mode and say, for
//! each exercise, whether it passes, fails (and where first), times out, or
//! is still the untouched stub.
//!
//! Two steps, so that the verdicts do not depend on the user's cargo settings
//! (`term.quiet`, `term.verbose`, colours) and no test can hang the terminal:
//!
//! 1. **Build** with `cargo test --no-run --message-format=json-render-diagnostics`
//!    and cargo's terminal settings pinned in its environment. Cargo names
//!    every test executable it built, and the target it belongs to, in the
//!    `compiler-artifact` JSON messages on its stdout ([`test_executables`]);
//!    compiler errors are rendered on its stderr as usual ([`cargo_failure`]).
//! 2. **Run** each test binary ourselves, in a fixed order (the library's unit
//!    tests, the binaries' unit tests, then `tests/*.rs` by name), in the
//!    package folder with the environment cargo would give it, explicit
//!    libtest arguments and a time limit. A binary still running at the limit
//!    is killed with every process it started.
//!
//! Doc tests are not run: the chapters have none.
//!
//! The parsing is pure functions over captured text ([`test_executables`],
//! [`parse_output`], [`test_binary`], [`report`]).

use std::collections::{HashMap, HashSet};
use std::fmt;
use std::io::{self, BufRead, BufReader, Read};
use std::path::{Path, PathBuf};
use std::process::{Child, Command, ExitCode, ExitStatus, Stdio};
use std::sync::{Arc, Mutex, mpsc};
use std::time::{Duration, Instant};

use raystep_figure::Chapter;
use serde::Deserialize;

use crate::snapshot_changes::{self, ChangedSnapshot};
use crate::snapshot_diff::{InstaFailure, snapshot_contents};
use crate::{Error, report_formats, workspace};

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
    /// Also write the report as JSON to this file.
    pub json: Option<PathBuf>,
    /// Also write the report as JUnit XML to this file.
    pub junit: Option<PathBuf>,
}

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

/// The panic message of `todo!()`: a test that stops here has not been attempted.
const TODO: &str = "not yet implemented";

/// How long `--list` may take after a binary timed out (to name its unfinished tests).
const LIST_LIMIT: Duration = Duration::from_secs(10);

/// Runs `raystep check`.
pub fn run(options: &Options) -> Result<ExitCode, Error> {
    let root = workspace::root();
    let chapter =
        crate::chapters::find(&options.chapter, crate::chapters::CHAPTERS)?;
    for path in options.json.iter().chain(&options.junit) {
        crate::atomic_file::can_write(path)?;
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
    };
    let report = check_chapter(&root, chapter, &run)?;
    println!("{} ({mode})", chapter.package);
    print!("{report}");
    let heading = report_formats::Heading {
        chapter: chapter.id,
        package: chapter.package,
        reference: options.reference,
    };
    if let Some(path) = &options.json {
        report_formats::write_json(path, &heading, &report)?;
    }
    if let Some(path) = &options.junit {
        report_formats::write_junit(path, &heading, &report)?;
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
    root: &Path,
    chapter: &Chapter,
    run: &Run,
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
                crate::compile_isolation::check_others(
                    root, chapter, run, &failure,
                )?
            };
            others.unwrap_or_else(|| Report::not_built(&exercises, failure))
        }
    };
    if !run.reference {
        refuse_exercises(&mut report, &dir);
    }
    report.changed_snapshots = snapshot_changes::changed_snapshots(&dir);
    report.package_dir = crate::relative(&dir);
    Ok(report)
}

/// Runs the test binaries of `chapter` that a build of the workspace at
/// `root` made, and judges each exercise.
pub(crate) fn run_built(
    root: &Path,
    chapter: &Chapter,
    run: &Run,
    built: Built,
) -> Report {
    let dir = root.join("chapters").join(chapter.package);
    let exercises: Vec<String> =
        chapter.exercises.iter().map(|e| e.to_string()).collect();
    let cargo = cargo_program();
    let threads = test_threads();
    let context = Context {
        workspace: Some(root.to_path_buf()),
        package: Some(dir.clone()),
    };
    let binaries: Vec<TestBinary> = built
        .tests
        .iter()
        .map(|executable| {
            if !run.quiet {
                eprintln!("     Running {}", executable.target);
            }
            run_tests(executable, &cargo, run.timeout, threads, &context)
        })
        .collect();
    let mut report = report(&exercises, &binaries, &test_sources(&dir));
    report.held_out_runner = built
        .examples
        .into_iter()
        .find(|(name, _)| *name == held_out_name(chapter))
        .map(|(_, path)| path);
    report
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
        if let Some(refusal) = crate::submission_rules::first_refusal(&text) {
            *verdict = Verdict::Refused(refusal.describe(&file));
        }
    }
}

/// Only builds the tests of `chapter` (as [`check_chapter`] does): why
/// nothing could be built, or `None` if it built.
pub fn build_failure(
    root: &Path,
    chapter: &Chapter,
    run: &Run,
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

/// The name of a chapter's held-out program: `examples/ch01_held_out.rs`
/// (see `raystep_check::held_out`).
pub fn held_out_name(chapter: &Chapter) -> String {
    format!("{}_held_out", chapter.id)
}

/// What a test build built to run: the test binaries, and the examples by
/// name.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(crate) struct Built {
    pub tests: Vec<Executable>,
    pub examples: Vec<(String, PathBuf)>,
}

/// The text of every `tests/*.rs` of the package in `dir`, by file stem: to
/// put failing tests in source order.
fn test_sources(dir: &Path) -> HashMap<String, String> {
    let Ok(entries) = std::fs::read_dir(dir.join("tests")) else {
        return HashMap::new();
    };
    entries
        .flatten()
        .map(|entry| entry.path())
        .filter(|path| path.extension().is_some_and(|x| x == "rs"))
        .filter_map(|path| {
            let stem = path.file_stem()?.to_str()?.to_string();
            Some((stem, std::fs::read_to_string(&path).ok()?))
        })
        .collect()
}

/// The cargo that runs raystep (`cargo run` sets `CARGO`), else `cargo` on the path.
pub(crate) fn cargo_program() -> String {
    std::env::var("CARGO").unwrap_or_else(|_| "cargo".to_string())
}

/// Whose artifacts a build may share in its target folder.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Artifacts<'a> {
    /// A workspace of its own: see [`separate_artifacts`].
    Workspace,
    /// A copy of the workspace at this root in which only `package`
    /// differs (see `crate::compile_isolation`): every other crate shares
    /// the artifacts the original's own build makes (its
    /// [`separate_artifacts`] settings, if any), and `package` gets a
    /// setting of its own, so that neither build ever takes the other's
    /// `package` for fresh.
    OwnPackage(&'a Path),
}

/// `cargo test --no-run -p <package> [--features exercise]` in the workspace
/// root: the test executables it built, or why it built none.
pub(crate) fn build(
    cargo: &str,
    root: &Path,
    package: &str,
    options: &Run,
    artifacts: Artifacts<'_>,
) -> Result<Result<Built, BuildFailure>, Error> {
    let mut command = Command::new(cargo);
    command.current_dir(root).args([
        "test",
        "--no-run",
        "--message-format=json-render-diagnostics",
        "--color",
        "never",
        "-p",
        package,
    ]);
    if !options.reference {
        command.args(["--features", "exercise"]);
    }
    command
        // Environment variables override cargo's config files: whatever the
        // user's `term` settings, cargo prints its usual progress (no
        // `Running `rustc …`` lines), uncoloured, without a progress bar.
        .env("CARGO_TERM_QUIET", "false")
        .env("CARGO_TERM_VERBOSE", "false")
        .env("CARGO_TERM_COLOR", "never")
        .env("CARGO_TERM_PROGRESS_WHEN", "never")
        .env("CARGO_TERM_HYPERLINKS", "false")
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped());
    if let Some(dir) = &options.target_dir {
        command.env("CARGO_TARGET_DIR", dir);
    }
    match artifacts {
        Artifacts::Workspace => command
            .args(separate_artifacts(root, options.target_dir.as_deref())),
        Artifacts::OwnPackage(original) => {
            let own = format!("profile.dev.package.\"{package}\".");
            let shared =
                separate_artifacts(original, options.target_dir.as_deref());
            for pair in shared.chunks(2) {
                if !pair.iter().any(|arg| arg.starts_with(&own)) {
                    command.args(pair);
                }
            }
            command.args([
                "--config".to_string(),
                format!("{own}codegen-units=255"),
            ])
        }
    };
    let spawn_error = |source| Error::Spawn {
        program: cargo.to_string(),
        source,
    };
    let mut child = command.spawn().map_err(spawn_error)?;

    // Echo the build progress and the compiler's messages while collecting them.
    let stderr = child.stderr.take().expect("stderr is piped");
    let quiet = options.quiet;
    let echo = std::thread::spawn(move || {
        let mut text = String::new();
        for line in BufReader::new(stderr).lines().map_while(Result::ok) {
            if !quiet {
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
    let status = child.wait().map_err(spawn_error)?;
    read.map_err(spawn_error)?;
    if !status.success() {
        return Ok(Err(BuildFailure {
            failure: cargo_failure(&stderr),
            errors: compile_errors(&stderr),
        }));
    }
    let executables = test_executables(&stdout);
    if executables.is_empty() {
        return Ok(Err(BuildFailure {
            failure: CargoFailure::Cargo(
                "cargo built no test binaries".to_string(),
            ),
            errors: Vec::new(),
        }));
    }
    Ok(Ok(Built {
        tests: executables,
        examples: examples(&stdout),
    }))
}

/// Cargo's arguments that keep this workspace's own artifacts apart in a
/// target folder that is not its own (`--target-dir`, `CARGO_TARGET_DIR`).
///
/// Cargo names the artifacts of a workspace's crates by their paths
/// *inside* the workspace, so copies of one workspace (`raystep grade`'s
/// scratch copy, a student edition) that build into one target folder
/// share artifacts, and cargo judges them fresh by file times alone: one
/// copy could run another's build of a student's code, or a test binary
/// with another copy's folder baked in (`env!("CARGO_MANIFEST_DIR")`, which
/// insta uses to find the snapshots). Built with a setting of their own
/// (`codegen-units = 256`, which changes how rustc splits the work, not
/// what the code does), the workspace's crates get artifacts of their own;
/// dependencies from crates.io are still shared. Nothing is added when the
/// target folder is the workspace's `target/` (the usual case), or when the
/// members cannot be read.
pub fn separate_artifacts(
    root: &Path,
    target_dir: Option<&Path>,
) -> Vec<String> {
    let target = target_dir
        .map(Path::to_path_buf)
        .or_else(|| std::env::var_os("CARGO_TARGET_DIR").map(PathBuf::from))
        .map(|dir| {
            if dir.is_absolute() {
                dir
            } else {
                root.join(dir)
            }
        });
    let own = root.join("target");
    let same = |a: &Path, b: &Path| match (a.canonicalize(), b.canonicalize()) {
        (Ok(a), Ok(b)) => a == b,
        _ => lexically_normal(a) == lexically_normal(b),
    };
    match target {
        Some(target) if !same(&target, &own) => workspace_members(root)
            .iter()
            .flat_map(|name| {
                [
                    "--config".to_string(),
                    format!("profile.dev.package.\"{name}\".codegen-units=256"),
                ]
            })
            .collect(),
        _ => Vec::new(),
    }
}

/// The package names of the workspace's members (its root `Cargo.toml`
/// lists them by folder); empty if a manifest cannot be read.
fn workspace_members(root: &Path) -> Vec<String> {
    let read = |path: PathBuf| -> Option<toml::Table> {
        std::fs::read_to_string(path).ok()?.parse().ok()
    };
    let Some(manifest) = read(root.join("Cargo.toml")) else {
        return Vec::new();
    };
    let members = manifest
        .get("workspace")
        .and_then(|w| w.get("members"))
        .and_then(|m| m.as_array())
        .cloned()
        .unwrap_or_default();
    members
        .iter()
        .filter_map(|member| {
            let package = read(root.join(member.as_str()?).join("Cargo.toml"))?;
            Some(package.get("package")?.get("name")?.as_str()?.to_string())
        })
        .collect()
}

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

/// A test executable cargo built.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Executable {
    /// Which target it was built from.
    pub target: Target,
    /// The executable.
    pub path: PathBuf,
    /// Its package's `Cargo.toml`.
    pub manifest_path: PathBuf,
}

impl Executable {
    /// The package folder: where cargo runs a test binary, its `CARGO_MANIFEST_DIR`.
    pub fn package_dir(&self) -> &Path {
        self.manifest_path.parent().unwrap_or(Path::new("."))
    }
}

/// The fields of one of cargo's JSON messages that name a built target
/// (`"reason": "compiler-artifact"`); the rest are ignored.
#[derive(Deserialize)]
struct Artifact {
    reason: String,
    profile: Option<ArtifactProfile>,
    executable: Option<PathBuf>,
    manifest_path: Option<PathBuf>,
    target: Option<ArtifactTarget>,
}

/// Was the artifact built with the test profile?
#[derive(Deserialize)]
struct ArtifactProfile {
    test: bool,
}

/// Which target an artifact was built from.
#[derive(Deserialize)]
struct ArtifactTarget {
    kind: Vec<String>,
    name: String,
    src_path: PathBuf,
}

/// The test executables named in the JSON messages of `cargo test --no-run
/// --message-format=json…` (one per line on its stdout), in the order
/// `raystep check` runs them: the library's unit tests, the binaries' unit
/// tests by name, the integration tests by name, anything else last.
///
/// A test executable is a `compiler-artifact` built with the test profile
/// (`"profile": {"test": true}`) that has an `executable`; the other
/// artifacts are the dependencies and the plain library and binaries.
pub fn test_executables(messages: &str) -> Vec<Executable> {
    let mut found: Vec<(u8, String, Executable)> = Vec::new();
    for line in messages.lines() {
        // other messages (build scripts, diagnostics) lack these fields
        let Ok(artifact) = serde_json::from_str::<Artifact>(line) else {
            continue;
        };
        let (Some(path), Some(manifest_path), Some(target)) =
            (artifact.executable, artifact.manifest_path, artifact.target)
        else {
            continue;
        };
        if artifact.reason != "compiler-artifact"
            || !artifact.profile.is_some_and(|p| p.test)
        {
            continue;
        }
        let kinds: Vec<&str> = target.kind.iter().map(String::as_str).collect();
        let name = target.name;
        let source = target.src_path;
        let package_dir = manifest_path.parent().unwrap_or(Path::new(""));
        let relative = source.strip_prefix(package_dir).unwrap_or(&source);
        let relative = relative.to_string_lossy().replace('\\', "/");
        let (rank, target) = if kinds.contains(&"test") {
            (2, Target::Test(test_stem(&relative)))
        } else if kinds.contains(&"bin") {
            (1, Target::Unit(relative))
        } else if kinds.contains(&"bench") || kinds.contains(&"example") {
            (3, Target::Unit(relative))
        } else {
            (0, Target::Unit(relative))
        };
        if found.iter().all(|(_, _, e)| e.path != path) {
            found.push((
                rank,
                name,
                Executable {
                    target,
                    path,
                    manifest_path,
                },
            ));
        }
    }
    found.sort_by(|(rank_a, name_a, _), (rank_b, name_b, _)| {
        (rank_a, name_a).cmp(&(rank_b, name_b))
    });
    found.into_iter().map(|(_, _, e)| e).collect()
}

/// The examples named in cargo's JSON messages (a test build builds
/// them too): (name, executable).
pub fn examples(messages: &str) -> Vec<(String, PathBuf)> {
    messages
        .lines()
        .filter_map(|line| serde_json::from_str::<Artifact>(line).ok())
        .filter(|a| a.reason == "compiler-artifact")
        .filter_map(|a| {
            let target = a.target?;
            target
                .kind
                .iter()
                .any(|k| k == "example")
                .then_some((target.name, a.executable?))
        })
        .collect()
}

/// `tests/line.rs` → `line`; `tests/line/main.rs` → `line`.
fn test_stem(source: &str) -> String {
    let path = Path::new(source);
    let stem = path.file_stem().and_then(|s| s.to_str()).unwrap_or(source);
    if stem == "main"
        && let Some(dir) = path
            .parent()
            .and_then(|p| p.file_name())
            .and_then(|s| s.to_str())
    {
        return dir.to_string();
    }
    stem.to_string()
}

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

/// How many tests a binary runs at once: `RUST_TEST_THREADS` if the user set
/// it, else one per core (libtest's own default). Passed explicitly, so that
/// [`still_running`] knows it.
fn test_threads() -> usize {
    std::env::var("RUST_TEST_THREADS")
        .ok()
        .and_then(|n| n.trim().parse().ok())
        .filter(|&n: &usize| n > 0)
        .or_else(|| std::thread::available_parallelism().ok().map(|n| n.get()))
        .unwrap_or(1)
}

/// The command for one test binary, as cargo would run it: in the package
/// folder, with the variables cargo sets that a test may read, and nothing
/// from the user's environment that changes what libtest or insta print or
/// that makes a failing test pass.
fn test_command(
    executable: &Executable,
    cargo: &str,
    args: &[&str],
    context: &Context,
) -> Command {
    let mut command = Command::new(&executable.path);
    command
        .args(args)
        .current_dir(executable.package_dir())
        .env("CARGO", cargo)
        .env("CARGO_MANIFEST_DIR", executable.package_dir())
        .env("CARGO_MANIFEST_PATH", &executable.manifest_path)
        // Short panic reports.
        .env("RUST_BACKTRACE", "0")
        // Output captured and printed per failing test, tests in libtest's
        // order (the threads are passed as an argument).
        .env_remove("RUST_TEST_NOCAPTURE")
        .env_remove("RUST_TEST_THREADS")
        .env_remove("RUST_TEST_SHUFFLE")
        .env_remove("RUST_TEST_SHUFFLE_SEED")
        .env_remove("CLICOLOR_FORCE")
        .env_remove("RAYSTEP_BLESS");
    // No snapshot is ever written or accepted while checking, whatever the
    // user's environment or an `insta.yaml` says: every `INSTA_*` variable
    // goes, and the ones that decide are set (they override the file).
    for (name, _) in std::env::vars_os() {
        if name.to_string_lossy().starts_with("INSTA_") {
            command.env_remove(name);
        }
    }
    command
        .env("INSTA_UPDATE", "no")
        .env("INSTA_FORCE_PASS", "0")
        .env("INSTA_REQUIRE_FULL_MATCH", "0")
        // Snapshot diffs uncoloured, in insta's usual layout (see
        // `crate::snapshot_diff`).
        .env("INSTA_OUTPUT", "diff");
    if let Some(root) = &context.workspace {
        command.env("INSTA_WORKSPACE_ROOT", root);
    }
    command
}

/// Runs one test binary with a time limit and reads what it printed.
fn run_tests(
    executable: &Executable,
    cargo: &str,
    limit: Duration,
    threads: usize,
    context: &Context,
) -> TestBinary {
    let threads_arg = threads.to_string();
    let args = [
        "--test-threads",
        threads_arg.as_str(),
        "--color",
        "never",
        "--format",
        "pretty",
    ];
    let ran = run_with_limit(
        &mut test_command(executable, cargo, &args, context),
        limit,
    );
    let (stdout, ended) = match ran {
        Err(error) => (String::new(), Ended::NotStarted(error.to_string())),
        Ok(Ran {
            stdout,
            stderr,
            exit: Exit::Status(status),
        }) => {
            let mut how = describe_status(status);
            if let Some(test) = overflowed(&stderr) {
                how = format!(
                    "{test} overflowed its stack: a recursion that never \
                     ends? {how}"
                );
            } else if !status.success() {
                // Which tests were running when it died, and of what.
                let output = parse_output_in(&stdout, context);
                let running = if output.finished {
                    Vec::new()
                } else {
                    let listed = list_tests(executable, cargo, limit, context);
                    still_running(&output, &listed, threads)
                };
                let what = match out_of_memory(&stderr) {
                    Some(allocation) => format!(
                        "out of memory ({allocation}: a loop that never \
                         ends while it collects?)"
                    ),
                    None => "crashed".to_string(),
                };
                if !running.is_empty() {
                    how = format!("{} {what}; {how}", running.join(", "));
                } else if out_of_memory(&stderr).is_some() {
                    how = format!("{what}; {how}");
                }
            }
            (
                stdout,
                Ended::Exited {
                    success: status.success(),
                    how,
                },
            )
        }
        Ok(Ran {
            stdout,
            exit: Exit::TimedOut,
            ..
        }) => {
            let listed = list_tests(executable, cargo, limit, context);
            (
                stdout,
                Ended::TimedOut {
                    limit,
                    listed,
                    threads,
                },
            )
        }
    };
    test_binary_in(executable.target.clone(), &stdout, &ended, context)
}

/// The tests of a binary, in the order libtest starts them (`--list`);
/// empty if that cannot be told.
fn list_tests(
    executable: &Executable,
    cargo: &str,
    limit: Duration,
    context: &Context,
) -> Vec<String> {
    let mut list = test_command(
        executable,
        cargo,
        &["--list", "--format", "terse"],
        context,
    );
    match run_with_limit(&mut list, LIST_LIMIT.min(limit)) {
        Ok(Ran {
            stdout,
            exit: Exit::Status(status),
            ..
        }) if status.success() => parse_list(&stdout),
        _ => Vec::new(),
    }
}

/// The runtime's note when an allocation failed (the process then
/// aborts): `memory allocation of 6442450944 bytes failed`, as `6 GiB`.
pub fn out_of_memory(stderr: &str) -> Option<String> {
    stderr.lines().find_map(|line| {
        let bytes: u64 = line
            .trim()
            .strip_prefix("memory allocation of ")?
            .strip_suffix(" bytes failed")?
            .parse()
            .ok()?;
        let gib = bytes as f64 / (1u64 << 30) as f64;
        Some(if gib >= 0.1 {
            format!("it asked for {gib:.1} GiB at once")
        } else {
            format!("it asked for {bytes} bytes at once")
        })
    })
}

/// How a process run by [`run_with_limit`] ended.
#[derive(Debug)]
pub(crate) enum Exit {
    /// By itself.
    Status(ExitStatus),
    /// It was still running at the limit, and was killed with every process
    /// of its process group.
    TimedOut,
}

/// What [`run_with_limit`] saw.
#[derive(Debug)]
pub(crate) struct Ran {
    /// Everything the process printed on stdout (until it was killed).
    pub stdout: String,
    /// Everything it printed on stderr: where a crash says what it was
    /// (`thread 'x' has overflowed its stack`).
    pub stderr: String,
    /// How it ended.
    pub exit: Exit,
}

/// Runs `command` (stdin empty, stdout and stderr captured) for at
/// most `limit`. On Unix the process leads a process group of its own, and
/// at the limit the whole group is killed: the process and anything it
/// started. Ctrl-C still stops it: raystep's terminal signals are forwarded
/// to the group (see [`process_group`]).
pub(crate) fn run_with_limit(
    command: &mut Command,
    limit: Duration,
) -> io::Result<Ran> {
    command
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped());
    process_group::prepare(command);
    let mut child = command.spawn()?;
    let group = process_group::Group::new(&child);

    let stdout = capture(child.stdout.take().expect("stdout is piped"));
    let stderr = capture(child.stderr.take().expect("stderr is piped"));
    let exit = wait_with_limit(&mut child, &group, Instant::now() + limit);
    drop(group);
    let exit = exit?;
    Ok(Ran {
        stdout: stdout.text(),
        stderr: stderr.text(),
        exit,
    })
}

/// A pipe read to its end on a thread of its own.
struct Captured {
    bytes: Arc<Mutex<Vec<u8>>>,
    finished: mpsc::Receiver<()>,
}

fn capture(mut pipe: impl Read + Send + 'static) -> Captured {
    let bytes = Arc::new(Mutex::new(Vec::new()));
    let (done, finished) = mpsc::channel();
    let sink = Arc::clone(&bytes);
    std::thread::spawn(move || {
        let mut buffer = [0; 8192];
        while let Ok(n @ 1..) = pipe.read(&mut buffer) {
            sink.lock()
                .unwrap_or_else(|e| e.into_inner())
                .extend_from_slice(&buffer[..n]);
        }
        let _ = done.send(());
    });
    Captured { bytes, finished }
}

impl Captured {
    /// What came through. The pipe closes when the last process holding it
    /// has ended: at once after a kill. A process the binary started that
    /// outlives it (in another process group) could hold it open: do not
    /// wait for that.
    fn text(self) -> String {
        let _ = self.finished.recv_timeout(Duration::from_secs(2));
        String::from_utf8_lossy(
            &self.bytes.lock().unwrap_or_else(|e| e.into_inner()),
        )
        .into_owned()
    }
}

/// The test whose thread overflowed its stack, from the runtime's note on
/// stderr: `thread 'depth_one' (123) has overflowed its stack`.
pub fn overflowed(stderr: &str) -> Option<&str> {
    stderr.lines().find_map(|line| {
        let rest = line.strip_prefix("thread '")?;
        let (name, rest) = rest.split_once('\'')?;
        rest.contains("has overflowed its stack").then_some(name)
    })
}

/// Waits for `child` until `deadline`, then kills its process group.
fn wait_with_limit(
    child: &mut Child,
    group: &process_group::Group,
    deadline: Instant,
) -> io::Result<Exit> {
    let mut pause = Duration::from_millis(1);
    loop {
        match child.try_wait() {
            Ok(Some(status)) => return Ok(Exit::Status(status)),
            Ok(None) => {}
            Err(error) => {
                group.kill(child);
                let _ = child.wait();
                return Err(error);
            }
        }
        let now = Instant::now();
        if now >= deadline {
            group.kill(child);
            child.wait()?;
            return Ok(Exit::TimedOut);
        }
        std::thread::sleep(pause.min(deadline - now));
        pause = (pause * 2).min(Duration::from_millis(20));
    }
}

/// How a process ended, as cargo says it: `exit status: 101`,
/// `signal: 6, SIGABRT: process abort signal`.
pub(crate) fn describe_status(status: ExitStatus) -> String {
    #[cfg(unix)]
    {
        use std::os::unix::process::ExitStatusExt;
        if let Some(signal) = status.signal() {
            return describe_signal(signal);
        }
    }
    status.to_string()
}

/// `signal: 6, SIGABRT: process abort signal`, with cargo's names.
#[cfg(unix)]
fn describe_signal(signal: i32) -> String {
    let name = match signal {
        1 => "SIGHUP: hangup",
        2 => "SIGINT: terminal interrupt signal",
        3 => "SIGQUIT: terminal quit signal",
        4 => "SIGILL: illegal instruction",
        5 => "SIGTRAP: trace/breakpoint trap",
        6 => "SIGABRT: process abort signal",
        8 => "SIGFPE: erroneous arithmetic operation",
        9 => "SIGKILL: kill",
        11 => "SIGSEGV: invalid memory reference",
        13 => "SIGPIPE: write on a pipe with no one to read",
        14 => "SIGALRM: alarm clock",
        15 => "SIGTERM: termination signal",
        #[cfg(any(target_os = "linux", target_os = "android"))]
        7 => "SIGBUS: access to undefined memory",
        #[cfg(any(target_os = "linux", target_os = "android"))]
        31 => "SIGSYS: bad system call",
        #[cfg(not(any(target_os = "linux", target_os = "android")))]
        10 => "SIGBUS: access to undefined memory",
        #[cfg(not(any(target_os = "linux", target_os = "android")))]
        12 => "SIGSYS: bad system call",
        _ => return format!("signal: {signal}"),
    };
    format!("signal: {signal}, {name}")
}

/// Process groups: a test binary and everything it starts can be killed
/// together, and raystep's own terminal signals (Ctrl-C) reach them although
/// they are not in the terminal's foreground group.
#[cfg(unix)]
mod process_group {
    use std::os::unix::process::CommandExt;
    use std::process::{Child, Command};
    use std::sync::Once;
    use std::sync::atomic::{AtomicI32, Ordering};

    unsafe extern "C" {
        fn kill(pid: i32, signal: i32) -> i32;
        fn signal(signal: i32, handler: usize) -> usize;
        fn raise(signal: i32) -> i32;
    }
    const SIGHUP: i32 = 1;
    const SIGINT: i32 = 2;
    const SIGKILL: i32 = 9;
    const SIGTERM: i32 = 15;
    const SIG_DFL: usize = 0;

    /// The process group of the test binary running now, 0 if none.
    static RUNNING: AtomicI32 = AtomicI32::new(0);

    /// Kills the running group, then dies of `sig` as if no handler were installed.
    extern "C" fn forward(sig: i32) {
        let group = RUNNING.load(Ordering::SeqCst);
        // SAFETY: kill, signal and raise are async-signal-safe. The group is
        // one this process created; its leader is reaped just before
        // `RUNNING` is cleared.
        unsafe {
            if group > 0 {
                kill(-group, SIGKILL);
            }
            signal(sig, SIG_DFL);
            raise(sig);
        }
    }

    /// Makes the process that `command` starts lead a new process group, and
    /// forwards Ctrl-C, hang-up and termination to such groups from now on.
    pub fn prepare(command: &mut Command) {
        static INSTALL: Once = Once::new();
        INSTALL.call_once(|| {
            for sig in [SIGHUP, SIGINT, SIGTERM] {
                // SAFETY: `forward` is an `extern "C" fn(i32)` that only calls
                // async-signal-safe functions.
                unsafe {
                    signal(sig, forward as extern "C" fn(i32) as usize);
                }
            }
        });
        command.process_group(0);
    }

    /// The process group of a running child; forgotten when dropped.
    pub struct Group(i32);

    impl Group {
        pub fn new(child: &Child) -> Group {
            let id = i32::try_from(child.id()).unwrap_or(0);
            RUNNING.store(id, Ordering::SeqCst);
            Group(id)
        }

        /// Kills every process in the group (the child is not reaped yet, so
        /// the group id is still ours).
        pub fn kill(&self, child: &mut Child) {
            if self.0 > 0 {
                // SAFETY: sending a signal has no memory-safety preconditions.
                unsafe {
                    kill(-self.0, SIGKILL);
                }
            }
            let _ = child.kill();
        }
    }

    impl Drop for Group {
        fn drop(&mut self) {
            RUNNING.store(0, Ordering::SeqCst);
        }
    }
}

/// Without process groups, only the test binary itself is killed.
#[cfg(not(unix))]
mod process_group {
    use std::process::{Child, Command};

    pub fn prepare(_command: &mut Command) {}

    pub struct Group;

    impl Group {
        pub fn new(_child: &Child) -> Group {
            Group
        }

        pub fn kill(&self, child: &mut Child) {
            let _ = child.kill();
        }
    }
}

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

/// Where a test binary ran: to read the snapshot files its failures name,
/// and to say panic locations relative to the package.
#[derive(Debug, Clone, Default)]
pub struct Context {
    /// The workspace root (rustc's and insta's paths are relative to it).
    pub workspace: Option<PathBuf>,
    /// The package folder.
    pub package: Option<PathBuf>,
}

impl Context {
    /// The text of a snapshot file insta named (relative to the workspace
    /// root, or to the package).
    fn snapshot(&self, file: &str) -> Option<String> {
        [&self.workspace, &self.package]
            .into_iter()
            .flatten()
            .find_map(|dir| std::fs::read_to_string(dir.join(file)).ok())
    }

    /// `path:line[:column]` as `path:line`, the path relative to the
    /// package when it is inside it, without `src/../`; `None` for a path
    /// outside the workspace (a library, the standard library).
    pub fn location(&self, raw: &str) -> Option<String> {
        let is_number =
            |s: &str| !s.is_empty() && s.bytes().all(|b| b.is_ascii_digit());
        let (rest, last) = raw.trim().rsplit_once(':')?;
        let (path, line) = match rest.rsplit_once(':') {
            Some((path, line)) if is_number(line) && is_number(last) => {
                (path, line)
            }
            _ if is_number(last) => (rest, last),
            _ => return None,
        };
        let path = lexically_normal(Path::new(path));
        let absolute = if path.is_absolute() {
            path.clone()
        } else {
            match &self.workspace {
                Some(root) => lexically_normal(&root.join(&path)),
                None => return Some(format!("{}:{line}", slashed(&path))),
            }
        };
        let within = |dir: &Option<PathBuf>| {
            let dir = lexically_normal(dir.as_ref()?);
            absolute.strip_prefix(dir).ok().map(Path::to_path_buf)
        };
        let shown =
            within(&self.package).or_else(|| within(&self.workspace))?;
        Some(format!("{}:{line}", slashed(&shown)))
    }
}

/// `a/src/../b` as `a/b`, `./a` as `a` (without touching the file system).
fn lexically_normal(path: &Path) -> PathBuf {
    use std::path::Component;
    let mut normal = PathBuf::new();
    for part in path.components() {
        match part {
            Component::CurDir => {}
            Component::ParentDir
                if matches!(
                    normal.components().next_back(),
                    Some(Component::Normal(_))
                ) =>
            {
                normal.pop();
            }
            other => normal.push(other),
        }
    }
    normal
}

/// A relative path with `/` between its parts, on every system.
fn slashed(path: &Path) -> String {
    path.components()
        .map(|c| c.as_os_str().to_string_lossy())
        .collect::<Vec<_>>()
        .join("/")
}

/// Reads what one test binary printed on stdout.
#[cfg(test)]
pub fn parse_output(stdout: &str) -> Output {
    parse_output_in(stdout, &Context::default())
}

/// [`parse_output`], reading the snapshot files failures name and saying
/// locations as `context` tells.
pub fn parse_output_in(stdout: &str, context: &Context) -> Output {
    let mut results = Vec::new();
    let mut slow = Vec::new();
    let mut failures: HashMap<&str, Failure> = HashMap::new();
    let mut finished = false;
    let mut section: Option<(&str, Vec<&str>)> = None;
    // The failure section of one test ends: read its panic.
    fn close<'a>(
        section: &mut Option<(&'a str, Vec<&'a str>)>,
        failures: &mut HashMap<&'a str, Failure>,
        context: &Context,
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
}

/// One binary's results from what it printed and how it ended.
#[cfg(test)]
pub fn test_binary(target: Target, stdout: &str, ended: &Ended) -> TestBinary {
    test_binary_in(target, stdout, ended, &Context::default())
}

/// [`test_binary`], reading snapshot files and saying locations as
/// `context` tells.
pub fn test_binary_in(
    target: Target,
    stdout: &str,
    ended: &Ended,
    context: &Context,
) -> TestBinary {
    let output = parse_output_in(stdout, context);
    let (crashed, timed_out) = match ended {
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
        // Killed by a signal after its `test result:` line: libtest itself
        // never does that, so the line may not be libtest's.
        Ended::Exited {
            success: false,
            how,
        } if output.finished && how.contains("signal: ") => {
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
fn still_running(
    output: &Output,
    listed: &[String],
    threads: usize,
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
    /// operating system (see [`crate::submission_rules`]): where, and what.
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

/// The verdict on every exercise, the count of the chapter's other tests,
/// and the snapshot files that are not the reference.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct Report {
    /// Each exercise and its verdict, in the order given.
    pub exercises: Vec<(String, Verdict)>,
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
    /// (see [`held_out_name`]), if it has one.
    pub held_out_runner: Option<PathBuf>,
}

impl Report {
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
        } else {
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
            writeln!(f, "  {OTHER:width$}  {}", self.other_tests())?;
        }
        for line in
            snapshot_changes::advice(&self.changed_snapshots, &self.package_dir)
        {
            writeln!(f, "{line}")?;
        }
        if self.build_failure.is_some() {
            return Ok(());
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
/// `sources` holds the text of the `tests/*.rs` files by stem, to put
/// failing tests in source order (otherwise, and for unit tests, by name).
pub fn report(
    exercises: &[String],
    binaries: &[TestBinary],
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
    exercise: &str,
    binaries: &[&TestBinary],
    source: Option<&str>,
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_stack_overflow_names_its_test() {
        let stderr = "\nthread 'recursion::depth_one' (7761) has overflowed \
                      its stack\nfatal runtime error: stack overflow\n";
        assert_eq!(overflowed(stderr), Some("recursion::depth_one"));
        assert_eq!(overflowed("thread 'x' panicked at a.rs:1:1:\n"), None);
    }

    #[test]
    fn a_failure_cut_short_by_a_crash_says_so() {
        let binary = TestBinary {
            target: Target::Test("recursion".into()),
            results: vec![TestResult {
                name: "depth_one".into(),
                outcome: Outcome::Failed(None),
            }],
            crashed: Some("the test binary crashed (signal: 6)".into()),
            timed_out: None,
        };
        assert_eq!(
            verdict("recursion", &[&binary], None),
            Verdict::Failed(
                "depth_one: failed, and the test binary crashed (signal: 6) \
                 before it could say why"
                    .into()
            )
        );
    }

    fn exercises(names: &[&str]) -> Vec<String> {
        names.iter().map(|s| s.to_string()).collect()
    }

    /// `running 1 test`, `running 12 tests`: where one binary's output starts.
    fn is_running_line(line: &str) -> bool {
        line.strip_prefix("running ")
            .and_then(|rest| {
                rest.strip_suffix(" tests")
                    .or_else(|| rest.strip_suffix(" test"))
            })
            .is_some_and(|n| {
                !n.is_empty() && n.bytes().all(|b| b.is_ascii_digit())
            })
    }

    /// The fixtures hold what several test binaries printed one after the
    /// other (as `cargo test` shows it): split at each `running N tests`.
    fn split(stdout: &str) -> Vec<String> {
        let mut outputs: Vec<String> = Vec::new();
        for line in stdout.lines() {
            if is_running_line(line) {
                outputs.push(String::new());
            }
            if let Some(output) = outputs.last_mut() {
                output.push_str(line);
                output.push('\n');
            }
        }
        outputs
    }

    /// Binaries that exited with libtest's failure status.
    fn exited(targets: Vec<Target>, stdout: &str) -> Vec<TestBinary> {
        let outputs = split(stdout);
        assert_eq!(outputs.len(), targets.len());
        let ended = Ended::Exited {
            success: false,
            how: "exit status: 101".to_string(),
        };
        targets
            .into_iter()
            .zip(outputs)
            .map(|(target, output)| test_binary(target, &output, &ended))
            .collect()
    }

    fn sample_targets() -> Vec<Target> {
        vec![
            Target::Unit("src/lib.rs".into()),
            Target::Test("add".into()),
            Target::Test("other".into()),
            Target::Test("triple".into()),
        ]
    }

    /// A chapter with exercises `add` (both tests hit `todo!()`) and `triple`
    /// (a wrong answer: an insta snapshot and an `assert_eq!` fail), other
    /// tests in `src/lib.rs` and `tests/other.rs`.
    fn student() -> Vec<TestBinary> {
        exited(sample_targets(), include_str!("../testdata/student.stdout"))
    }

    #[test]
    fn test_executables_are_read_from_cargos_messages() {
        let executables =
            test_executables(include_str!("../testdata/artifacts.jsonl"));
        let manifest = PathBuf::from(
            "/work/check-wt/chapters/ch01-implicit-lines-planes/Cargo.toml",
        );
        let deps = Path::new("/work/main/target/debug/deps");
        assert_eq!(
            executables,
            [
                Executable {
                    target: Target::Unit("src/lib.rs".into()),
                    path: deps.join("ch01-754aa3f610206f77"),
                    manifest_path: manifest.clone(),
                },
                Executable {
                    target: Target::Unit("src/bin/ch01-figures.rs".into()),
                    path: deps.join("ch01_figures-f9cb07e01a0e3669"),
                    manifest_path: manifest.clone(),
                },
                Executable {
                    target: Target::Test("line_through_points".into()),
                    path: deps.join("line_through_points-94ea8b96c78fea7c"),
                    manifest_path: manifest.clone(),
                },
                Executable {
                    target: Target::Test("plane_through_points".into()),
                    path: deps.join("plane_through_points-b61bbc251acfa3bc"),
                    manifest_path: manifest.clone(),
                },
            ]
        );
        assert_eq!(
            executables[0].package_dir(),
            Path::new("/work/check-wt/chapters/ch01-implicit-lines-planes")
        );
        assert_eq!(executables[0].target.to_string(), "unittests src/lib.rs");
        assert_eq!(
            executables[2].target.to_string(),
            "tests/line_through_points.rs"
        );
    }

    #[test]
    fn lines_that_are_not_test_artifacts_are_skipped() {
        let messages = "   Compiling ch01 v0.1.0\n\
            {\"reason\":\"compiler-artifact\",\"profile\":{\"test\":true},\"executable\":null,\
             \"manifest_path\":\"/p/Cargo.toml\",\"target\":{\"kind\":[\"lib\"],\"name\":\"p\",\"src_path\":\"/p/src/lib.rs\"}}\n\
            {\"reason\":\"compiler-message\",\"profile\":{\"test\":true},\"executable\":\"/t/x\",\
             \"manifest_path\":\"/p/Cargo.toml\",\"target\":{\"kind\":[\"test\"],\"name\":\"x\",\"src_path\":\"/p/tests/x.rs\"}}\n\
            {\"reason\":\"compiler-artifact\",\"profile\":{\"test\":true},\"executable\":\"/t/y\",\
             \"manifest_path\":\"/p/Cargo.toml\",\"target\":{\"kind\":[\"test\"],\"name\":\"y\",\"src_path\":\"/p/tests/y/main.rs\"}}\n\
            {\"reason\":\"build-finished\",\"success\":true}\n";
        let executables = test_executables(messages);
        assert_eq!(executables.len(), 1);
        assert_eq!(executables[0].target, Target::Test("y".into()));
        assert_eq!(executables[0].path, Path::new("/t/y"));
    }

    #[test]
    fn each_binarys_output_is_read() {
        let binaries = student();
        assert!(
            binaries
                .iter()
                .all(|b| b.crashed.is_none() && b.timed_out.is_none())
        );
        let counts: Vec<usize> =
            binaries.iter().map(|b| b.results.len()).collect();
        assert_eq!(counts, [1, 2, 1, 3]);
        let output =
            parse_output(&split(include_str!("../testdata/student.stdout"))[1]);
        assert!(output.finished);
        assert!(output.slow.is_empty());
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
        let failed = |message: &str, at: &str| {
            Outcome::Failed(Some(Failure {
                message: message.into(),
                at: Some(at.into()),
            }))
        };
        // Where it panicked, without `src/../` and the column.
        assert_eq!(
            outcome(1, "adds_small"),
            failed("not yet implemented", "exercise/ex.rs:1")
        );
        assert_eq!(
            outcome(3, "triple_eq"),
            failed(
                "assertion `left == right` failed: triple of two (left: 8, right: 6)",
                "tests/triple.rs:4"
            )
        );
        // A snapshot: where it is asserted (insta panics in its own
        // code); the snapshot file is not there, so the diff alone says
        // which line differs.
        assert_eq!(
            outcome(3, "triple_snapshot"),
            failed(
                "snapshot triples, line 1: expected `3`, got `4`",
                "tests/triple.rs:2"
            )
        );
        assert_eq!(outcome(3, "triple_zero"), Outcome::Passed);
    }

    #[test]
    fn student_verdicts() {
        let sources = HashMap::from([(
            "triple".to_string(),
            "#[test]\nfn triple_snapshot() {}\n#[test]\nfn triple_eq() {}\n"
                .to_string(),
        )]);
        let report =
            report(&exercises(&["add", "triple"]), &student(), &sources);
        assert_eq!(
            report.exercises,
            [
                ("add".to_string(), Verdict::NotAttempted),
                (
                    "triple".to_string(),
                    Verdict::Failed(
                        "triple_snapshot (tests/triple.rs:2): snapshot triples, \
                         line 1: expected `3`, got `4`"
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
             \x20 triple       failed: triple_snapshot (tests/triple.rs:2): snapshot \
             triples, line 1: expected `3`, got `4`\n\
             \x20 other tests  2 passed\n\
             0 of 2 exercises passed\n"
        );
    }

    #[test]
    fn without_sources_the_first_failure_is_alphabetical() {
        let report =
            report(&exercises(&["triple"]), &student(), &HashMap::new());
        assert_eq!(
            report.exercises[0].1,
            Verdict::Failed(
                "triple_eq (tests/triple.rs:4): assertion `left == right` \
                 failed: triple of two (left: 8, right: 6)"
                    .into()
            )
        );
    }

    #[test]
    fn reference_verdicts() {
        let binaries = exited(
            sample_targets(),
            include_str!("../testdata/reference.stdout"),
        );
        let report =
            report(&exercises(&["add", "triple"]), &binaries, &HashMap::new());
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
        let report =
            report(&exercises(&["missing"]), &student(), &HashMap::new());
        assert_eq!(
            report.exercises[0].1,
            Verdict::Failed("no tests ran (expected tests/missing.rs)".into())
        );
    }

    #[test]
    fn compile_errors_are_reported_with_their_location() {
        let failure =
            cargo_failure(include_str!("../testdata/compile-error.stderr"));
        assert_eq!(
            failure.to_string(),
            "the tests do not compile: error[E0308]: mismatched types (at exercise/ex.rs:3:26)"
        );
        // Every error, not cargo's own lines.
        assert_eq!(
            compile_errors(include_str!("../testdata/compile-error.stderr")),
            [CompileError {
                message: "error[E0308]: mismatched types".into(),
                at: Some("exercise/ex.rs:3:26".into()),
            }]
        );
    }

    #[test]
    fn a_killed_compiler_is_reported_with_how_it_stopped() {
        let failure =
            cargo_failure(include_str!("../testdata/compiler-killed.stderr"));
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

    #[test]
    fn a_crashing_binary_fails_its_exercise() {
        let outputs = split(include_str!("../testdata/crash.stdout"));
        let abort = Ended::Exited {
            success: false,
            how: "signal: 6, SIGABRT: process abort signal".to_string(),
        };
        let ok = Ended::Exited {
            success: true,
            how: "exit status: 0".to_string(),
        };
        let binaries = [
            test_binary(Target::Test("crash".into()), &outputs[0], &abort),
            test_binary(Target::Test("other".into()), &outputs[1], &ok),
        ];
        assert_eq!(
            binaries[0].crashed.as_deref(),
            Some(
                "the test binary crashed (signal: 6, SIGABRT: process abort signal)"
            )
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
    fn out_of_memory_is_said_with_its_size() {
        let stderr = "\nmemory allocation of 6442450944 bytes failed\n";
        assert_eq!(
            out_of_memory(stderr).as_deref(),
            Some("it asked for 6.0 GiB at once")
        );
        assert_eq!(
            out_of_memory("memory allocation of 4096 bytes failed").as_deref(),
            Some("it asked for 4096 bytes at once")
        );
        assert_eq!(out_of_memory("thread 'x' panicked"), None);
    }

    /// A `test result:` line followed by a death by signal is not
    /// libtest's: the binary crashed, whatever it printed before.
    #[test]
    fn a_result_line_before_a_crash_is_not_believed() {
        let forged = "\nrunning 1 tests\ntest a ... ok\n\n\
            test result: ok. 1 passed; 0 failed; 0 ignored; 0 measured; 0 filtered out; finished in 0.00s\n";
        let abort = Ended::Exited {
            success: false,
            how: "signal: 6, SIGABRT: process abort signal".to_string(),
        };
        let binary = test_binary(Target::Test("a".into()), forged, &abort);
        assert_eq!(
            binary.crashed.as_deref(),
            Some(
                "the test binary crashed (signal: 6, SIGABRT: process abort signal)"
            )
        );
        let report = report(&exercises(&["a"]), &[binary], &HashMap::new());
        assert_eq!(report.exercises[0].1.kind(), "failed");
    }

    #[test]
    fn a_binary_that_stops_early_or_never_starts_fails() {
        let started = "\nrunning 2 tests\ntest a ... ok\n";
        let ok = Ended::Exited {
            success: true,
            how: "exit status: 0".to_string(),
        };
        let binary = test_binary(Target::Test("early".into()), started, &ok);
        assert_eq!(
            binary.crashed.as_deref(),
            Some("the test binary stopped early")
        );
        let missing = Ended::NotStarted(
            "No such file or directory (os error 2)".to_string(),
        );
        let binary = test_binary(Target::Test("gone".into()), "", &missing);
        assert_eq!(
            binary.crashed.as_deref(),
            Some(
                "the test binary could not be started (No such file or directory (os error 2))"
            )
        );
    }

    #[test]
    fn ignored_tests_module_paths_and_other_binaries() {
        let lib = "\nrunning 3 tests\n\
            test tests::fits ... ok\n\
            test tests::slow ... ignored, takes a minute\n\
            test tests::rounds - should panic ... ok\n\n\
            test result: ok. 2 passed; 0 failed; 1 ignored; 0 measured; 0 filtered out; finished in 0.00s\n\n";
        let bin = "\nrunning 1 test\n\
            test tests::draws ... FAILED\n\n\
            failures:\n\n\
            ---- tests::draws stdout ----\n\n\
            thread 'tests::draws' (42) panicked at chapters/ch01/src/bin/figures.rs:5:1:\n\
            not yet implemented\n\
            note: run with `RUST_BACKTRACE=1` environment variable to display a backtrace\n\n\n\
            failures:\n    tests::draws\n\n\
            test result: FAILED. 0 passed; 1 failed; 0 ignored; 0 measured; 0 filtered out; finished in 0.10s\n\n";
        let failed = Ended::Exited {
            success: false,
            how: "exit status: 101".to_string(),
        };
        let binaries = [
            test_binary(Target::Unit("src/lib.rs".into()), lib, &failed),
            test_binary(
                Target::Unit("src/bin/figures.rs".into()),
                bin,
                &failed,
            ),
        ];
        let report = report(&[], &binaries, &HashMap::new());
        assert_eq!(report.other_passed, 2);
        // Stopped at a todo!(): waiting for the exercises, not failed.
        assert_eq!(report.other_waiting, 1);
        assert!(report.other_failed.is_empty());
        assert!(!report.all_passed());
        assert!(
            report
                .to_string()
                .ends_with("this chapter has no exercises\n")
        );
    }

    /// Other tests that stopped at `todo!()` wait for the exercises; real
    /// failures are named in source order whatever order the threads
    /// finished in.
    #[test]
    fn other_tests_wait_or_fail_in_source_order() {
        let panic = |name: &str, at: &str, message: &str| {
            format!(
                "---- {name} stdout ----\n\
                 thread '{name}' (1) panicked at {at}:\n{message}\n\
                 note: run with `RUST_BACKTRACE=1` environment variable to display a backtrace\n\n"
            )
        };
        let output = |order: [&str; 4]| {
            let mut text = "\nrunning 4 tests\n".to_string();
            for name in order {
                let status = if name == "fits" { "ok" } else { "FAILED" };
                text.push_str(&format!("test {name} ... {status}\n"));
            }
            text.push_str("\nfailures:\n\n");
            text.push_str(&panic(
                "waits",
                "src/../exercise/ex.rs:3:5",
                "not yet implemented",
            ));
            text.push_str(&panic("late", "tests/other.rs:9:5", "late broke"));
            text.push_str(&panic("early", "tests/other.rs:2:5", "early broke"));
            text.push_str("failures:\n    early\n    late\n    waits\n\n\
                test result: FAILED. 1 passed; 3 failed; 0 ignored; 0 measured; 0 filtered out; finished in 0.01s\n");
            text
        };
        let source = "#[test]\nfn late() {}\n#[test]\nfn fits() {}\n\
                      #[test]\nfn early() {}\n#[test]\nfn waits() {}\n";
        let sources =
            HashMap::from([("other".to_string(), source.to_string())]);
        let ended = Ended::Exited {
            success: false,
            how: "exit status: 101".to_string(),
        };
        let reports: Vec<Report> = [
            ["waits", "fits", "early", "late"],
            ["late", "early", "waits", "fits"],
        ]
        .into_iter()
        .map(|order| {
            let binary = test_binary(
                Target::Test("other".into()),
                &output(order),
                &ended,
            );
            report(&[], &[binary], &sources)
        })
        .collect();
        assert_eq!(
            reports[0], reports[1],
            "the order of completion matters not"
        );
        let report = &reports[0];
        assert_eq!(
            report.other_failed,
            [
                "late (tests/other.rs:9): late broke",
                "early (tests/other.rs:2): early broke"
            ]
        );
        assert_eq!(report.other_waiting, 1);
        assert_eq!(
            report.other_tests(),
            "1 passed, 1 wait for your exercises (todo!()), 2 failed \
             (first: late (tests/other.rs:9): late broke)"
        );
        // Only waiting: no word of failure.
        let waiting = Report {
            other_passed: 20,
            other_waiting: 6,
            ..Report::default()
        };
        assert_eq!(
            waiting.other_tests(),
            "20 passed, 6 wait for your exercises (todo!())"
        );
        assert!(!waiting.all_passed());
    }

    /// `recursion.rs` of a chapter, killed while `facing_mirrors_terminate` loops.
    const KILLED: &str = "\nrunning 4 tests\n\
        test a_mirror_reflects ... ok\n\
        test depth_is_limited ... FAILED\n";

    fn listed() -> Vec<String> {
        exercises(&[
            "a_mirror_reflects",
            "depth_is_limited",
            "facing_mirrors_terminate",
            "weights_shrink",
        ])
    }

    fn timed_out(threads: usize, listed: Vec<String>) -> Ended {
        Ended::TimedOut {
            limit: Duration::from_secs(60),
            listed,
            threads,
        }
    }

    #[test]
    fn a_timed_out_exercise_names_its_unfinished_tests() {
        let binaries = [
            test_binary(
                Target::Unit("src/lib.rs".into()),
                "\nrunning 0 tests\n\ntest result: ok. 0 passed\n",
                &Ended::Exited {
                    success: true,
                    how: "exit status: 0".into(),
                },
            ),
            test_binary(
                Target::Test("recursion".into()),
                KILLED,
                &timed_out(1, listed()),
            ),
        ];
        assert_eq!(binaries[1].crashed, None);
        let report =
            report(&exercises(&["recursion"]), &binaries, &HashMap::new());
        assert_eq!(
            report.exercises[0].1,
            Verdict::TimedOut(TimedOut {
                limit: Duration::from_secs(60),
                still_running: exercises(&["facing_mirrors_terminate"]),
            })
        );
        assert_eq!(
            report.to_string(),
            "  recursion    timed out after 60 s (still running: facing_mirrors_terminate)\n\
             \x20 other tests  0 passed\n\
             0 of 1 exercises passed\n"
        );
        assert!(!report.all_passed());
    }

    #[test]
    fn running_tests_follow_the_list_order_and_the_thread_count() {
        let running = |ended: &Ended| {
            test_binary(Target::Test("recursion".into()), KILLED, ended)
                .timed_out
                .unwrap()
                .still_running
        };
        // Two threads: both tests after the two that reported had started.
        assert_eq!(
            running(&timed_out(2, listed())),
            ["facing_mirrors_terminate", "weights_shrink"]
        );
        assert_eq!(
            running(&timed_out(8, listed())),
            ["facing_mirrors_terminate", "weights_shrink"]
        );
        // A test that reported but would not have started yet: another order.
        let shuffled = exercises(&[
            "facing_mirrors_terminate",
            "weights_shrink",
            "a_mirror_reflects",
            "depth_is_limited",
        ]);
        assert!(running(&timed_out(1, shuffled)).is_empty());
        // No list: nothing to say.
        assert!(running(&timed_out(1, Vec::new())).is_empty());
        // Unless libtest itself said which test was slow.
        let warned = format!(
            "{KILLED}test weights_shrink has been running for over 60 seconds\n"
        );
        let binary = test_binary(
            Target::Test("r".into()),
            &warned,
            &timed_out(1, Vec::new()),
        );
        assert_eq!(
            binary.timed_out.unwrap().to_string(),
            "timed out after 60 s (still running: weights_shrink)"
        );
    }

    #[test]
    fn a_timed_out_other_binary_is_an_other_failure() {
        let ended = Ended::TimedOut {
            limit: Duration::from_millis(2500),
            listed: exercises(&["tests::spins"]),
            threads: 4,
        };
        let binaries = [test_binary(
            Target::Unit("src/lib.rs".into()),
            "\nrunning 1 test\n",
            &ended,
        )];
        let report = report(&[], &binaries, &HashMap::new());
        assert_eq!(
            report.other_failed,
            [
                "unittests src/lib.rs: timed out after 2.5 s (still running: tests::spins)"
            ]
        );
        assert!(!report.all_passed());
        // Without a list or a warning the message names no test.
        let unknown = Ended::TimedOut {
            limit: Duration::from_secs(3),
            listed: Vec::new(),
            threads: 4,
        };
        let binary = test_binary(Target::Test("x".into()), "", &unknown);
        assert_eq!(
            binary.timed_out.unwrap().to_string(),
            "timed out after 3 s"
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

    /// A target folder of another workspace: this workspace's crates get
    /// a setting of their own; in its own `target/`, nothing changes.
    #[test]
    fn own_artifacts_apart_in_a_foreign_target_folder() {
        let dir = tempfile::tempdir().unwrap();
        let root = dir.path();
        let write = |path: &str, text: &str| {
            let path = root.join(path);
            std::fs::create_dir_all(path.parent().unwrap()).unwrap();
            std::fs::write(path, text).unwrap();
        };
        write(
            "Cargo.toml",
            "[workspace]\nmembers = [\"crates/a\", \"chapters/b\"]\n",
        );
        write("crates/a/Cargo.toml", "[package]\nname = \"a-core\"\n");
        write("chapters/b/Cargo.toml", "[package]\nname = \"ch09-b\"\n");
        assert!(
            separate_artifacts(root, Some(&root.join("target"))).is_empty()
        );
        assert_eq!(
            separate_artifacts(root, Some(Path::new("/elsewhere/target"))),
            [
                "--config",
                "profile.dev.package.\"a-core\".codegen-units=256",
                "--config",
                "profile.dev.package.\"ch09-b\".codegen-units=256",
            ]
        );
        // Unreadable members: nothing to add.
        write("Cargo.toml", "[workspace\n");
        assert!(separate_artifacts(root, Some(Path::new("/x"))).is_empty());
    }

    #[test]
    fn nested_test_folders_are_named_by_folder() {
        assert_eq!(test_stem("tests/line.rs"), "line");
        assert_eq!(test_stem("tests/line/main.rs"), "line");
    }

    #[cfg(unix)]
    fn shell(script: &str) -> Command {
        let mut command = Command::new("sh");
        command.args(["-c", script]);
        command
    }

    #[cfg(unix)]
    #[test]
    fn a_process_past_its_limit_is_killed() {
        let ran = run_with_limit(
            Command::new("sleep").arg("30"),
            Duration::from_millis(300),
        )
        .unwrap();
        assert!(matches!(ran.exit, Exit::TimedOut), "{ran:?}");
    }

    /// The processes a test binary started die with it.
    #[cfg(target_os = "linux")]
    #[test]
    fn a_killed_process_takes_its_children_along() {
        let ran = run_with_limit(
            &mut shell("sleep 30 & echo $!; wait"),
            Duration::from_millis(300),
        )
        .unwrap();
        assert!(matches!(ran.exit, Exit::TimedOut), "{ran:?}");
        let sleep: u32 = ran.stdout.trim().parse().expect("the child's pid");
        // Dead (or a zombie nobody has reaped yet); SIGKILL is delivered at once,
        // give the kernel a moment all the same.
        let dead = || {
            std::fs::read_to_string(format!("/proc/{sleep}/stat")).map_or(
                true,
                |stat| {
                    stat.rsplit_once(") ")
                        .is_some_and(|(_, s)| s.starts_with('Z'))
                },
            )
        };
        let until = Instant::now() + Duration::from_secs(5);
        while !dead() && Instant::now() < until {
            std::thread::sleep(Duration::from_millis(10));
        }
        assert!(dead(), "sleep {sleep} outlived the kill");
    }

    #[cfg(unix)]
    #[test]
    fn how_a_process_ended_is_said_as_cargo_says_it() {
        let ran = run_with_limit(
            &mut shell("echo partial; exit 3"),
            Duration::from_secs(30),
        )
        .unwrap();
        assert_eq!(ran.stdout, "partial\n");
        let Exit::Status(status) = ran.exit else {
            panic!("{ran:?}")
        };
        assert_eq!(describe_status(status), "exit status: 3");
        let ran = run_with_limit(
            &mut shell("kill -ABRT $$"),
            Duration::from_secs(30),
        )
        .unwrap();
        let Exit::Status(status) = ran.exit else {
            panic!("{ran:?}")
        };
        assert_eq!(
            describe_status(status),
            "signal: 6, SIGABRT: process abort signal"
        );
        assert_eq!(describe_signal(64), "signal: 64");
    }
}
