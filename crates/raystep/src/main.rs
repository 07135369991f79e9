//! `raystep`: the lecture's command line.
//!
//! * `raystep book` builds the book (figures and HTML) and says where it is;
//! * `raystep figures` draws every lecture figure into `book/src/figures/`
//!   (`--check` compares instead of writing);
//! * `raystep measure` times the renders behind the charts (slow) and
//!   writes CSV beside the figures;
//! * `raystep render SCENE.toml` renders a scene file to a PNG;
//! * `raystep check ch01` runs a chapter's tests in student mode and says,
//!   exercise by exercise, what passes;
//! * `raystep hint ch01 EXERCISE` shows an exercise's hints, one level
//!   at a time;
//! * `raystep watch [ch01]` checks a chapter again on every save and shows
//!   the first exercise not passed;
//! * `raystep progress` shows every exercise's last verdict and what is
//!   next;
//! * `raystep grade SUBMISSIONS --chapter ch01` checks every student's
//!   exercise files in a scratch copy of the workspace, into one table;
//! * `raystep student-edition OUT` writes the workspace with only the
//!   exercise stubs, for students.

mod atomic_file;
mod bench;
mod book;
mod cargo_artifacts;
mod chapters;
mod check;
mod check_child;
mod committed_stubs;
mod compile_isolation;
mod error;
mod figures;
mod git;
mod grade;
mod grade_partial;
mod grade_rows;
mod held_out;
mod hint;
mod limited_process;
mod measure;
mod memory_limit;
mod process_group;
mod progress;
mod progress_file;
mod questions;
mod reference_module;
mod render;
mod report_formats;
mod run_options;
mod sandbox;
mod separate_artifacts;
mod shown_path;
mod stability;
mod student_edition;
mod submission_rules;
mod test_build;
#[cfg(test)]
mod test_files;
mod test_run;
mod watch;
mod watch_view;
mod workspace;
mod workspace_copy;

use std::io::{self, IsTerminal};
use std::path::PathBuf;
use std::process::ExitCode;

use clap::{Parser, Subcommand, ValueEnum};

// The commands' error, at the crate root for `bench.rs`.
use error::Error;

/// raystep: a lecture on ray tracing in Rust.
#[derive(Debug, Parser)]
#[command(version, about, long_about = None)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Debug, Subcommand)]
enum Command {
    /// Build the book: draw every figure, then the HTML pages (with typeset
    /// math and the exercises' solutions folded), and say where it is.
    Book {
        /// The folder to write the HTML book into [default: <workspace>/target/book].
        #[arg(long, value_name = "DIR")]
        out: Option<PathBuf>,
        /// Open the book in the default browser when it is built.
        #[arg(long)]
        open: bool,
        /// Use the figures in book/src/figures as they are (do not redraw them).
        #[arg(long)]
        no_figures: bool,
    },
    /// mdBook's preprocessor protocol (book/book.toml runs it for `mdbook serve book`).
    #[command(hide = true)]
    BookPreprocessor {
        /// `supports RENDERER`, or nothing (the book comes as JSON on stdin).
        args: Vec<String>,
    },
    /// Draw every lecture figure into the book (or check the committed ones).
    Figures {
        /// Only this chapter: `01`, `1` or `ch01`.
        #[arg(long, value_name = "CHAPTER")]
        chapter: Option<String>,
        /// The folder that holds one folder per chapter [default: <workspace>/book/src/figures].
        #[arg(long, value_name = "DIR")]
        out: Option<PathBuf>,
        /// Which files to draw for each figure.
        #[arg(long, value_enum, default_value_t = FormatArg::Both)]
        format: FormatArg,
        /// Write nothing; fail and name every figure file that differs, is missing or is extra.
        #[arg(long)]
        check: bool,
    },
    /// Time the renders behind the charts (slow) and write their CSV beside the figures.
    Measure(measure::Options),
    /// Run the stability catalogue: every case where a method is known to
    /// fail (parallel rays, shared edges, grazing rays, self-intersection,
    /// huge coordinates, NaN, malformed inputs, …) against every method,
    /// counted, as one table. Slow at the full count (10⁶ rays per
    /// accelerator case); exits with failure where a method fails a case
    /// it is built to survive.
    Stability(stability::Options),
    /// Render a scene file (TOML) to a PNG.
    Render(render::Options),
    /// Time chapter 8's hierarchies, chapter 9's grid and chapter 10's
    /// kd-tree on a triangle mesh (build, trace, the work per ray), beside
    /// obvhs and bvh with `--peers`.
    ///
    /// Ray sets: `primary` (a SIZE × SIZE pinhole camera fitted to the
    /// mesh), `shadow` (from a point light to every primary hit; any hit),
    /// `incoherent` (origins on a sphere of 1.5 bounding radii aimed at
    /// uniform points in the box; seeded); or `--rays FILE`. Every method
    /// is built and traced on the same triangles and rays, round after
    /// round, taking turns; times are medians. Every answer is checked
    /// against the first method's, a sample of rays against brute force.
    /// The peers need a raystep built with them:
    /// `cargo run --release --features peers -- bench MESH --peers`.
    Bench {
        /// The OBJ mesh, e.g. ../shared/meshes/bunny.obj.
        mesh: PathBuf,
        /// Trace these rays instead (records of six little-endian f32:
        /// origin xyz, direction xyz), for the closest hit.
        #[arg(long, value_name = "FILE")]
        rays: Option<PathBuf>,
        /// The primary camera's image is SIZE × SIZE pixels.
        #[arg(long, value_name = "SIZE", default_value_t = 1024,
              value_parser = clap::value_parser!(u32).range(1..=8192))]
        size: u32,
        /// How many incoherent rays.
        #[arg(long, value_name = "N", default_value_t = 1 << 20)]
        incoherent: usize,
        /// The incoherent rays' seed.
        #[arg(long, default_value_t = 1)]
        seed: u64,
        /// Threads tracing.
        #[arg(long, value_name = "N", default_value_t = 1,
              value_parser = clap::value_parser!(u16).range(1..=1024))]
        threads: u16,
        /// Rounds; times are medians over them.
        #[arg(long, value_name = "N", default_value_t = 3,
              value_parser = clap::value_parser!(u16).range(1..=100))]
        rounds: u16,
        /// Our builders, comma-separated.
        #[arg(long, value_delimiter = ',', default_value = "sah16")]
        builders: Vec<bench::BuilderArg>,
        /// Our node precisions, comma-separated (each builder with each).
        #[arg(long, value_delimiter = ',', default_value = "f32,f64")]
        precision: Vec<bench::PrecisionArg>,
        /// What to run of ours, comma-separated: chapter 8's hierarchies
        /// (`bvh`: each of --builders in each --precision), chapter 9's
        /// uniform grid (`grid`: each --grid-fill; its "nodes" are the
        /// cells a ray visits) and chapter 10's kd-tree (`kdtree`: SAH
        /// from events, each --kd-clip; its "nodes" are the nodes a ray
        /// reaches) and the appendix's fast hierarchies (`fast`: each
        /// --fast step).
        #[arg(long, value_delimiter = ',', default_value = "bvh")]
        accel: Vec<bench::AccelArg>,
        /// The grid's cells along the longest axis [default: the rule,
        /// 3·∛N for N triangles].
        #[arg(long, value_name = "N",
              value_parser = clap::value_parser!(u16).range(1..=512))]
        grid_cells: Option<u16>,
        /// How the grid lists triangles in cells, comma-separated: by
        /// their bounding boxes, or exactly (the triangle–box test).
        #[arg(long, value_delimiter = ',', default_value = "exact")]
        grid_fill: Vec<bench::FillArg>,
        /// How the kd-tree's builder weighs a triangle in a node,
        /// comma-separated: by its bounding box cut to the node, or by the
        /// triangle clipped to the node (`triangles`: perfect splits).
        #[arg(long, value_delimiter = ',', default_value = "boxes")]
        kd_clip: Vec<bench::ClipArg>,
        /// The appendix's steps to run with `--accel fast`,
        /// comma-separated (all of them by default).
        #[arg(
            long,
            value_enum,
            value_delimiter = ',',
            default_values_t = <bench::FastArg as clap::ValueEnum>::value_variants()
                .to_vec()
        )]
        fast: Vec<bench::FastArg>,
        /// Also run obvhs (Bvh2, CwBvh) and bvh on the same input, and
        /// Embree in a raystep built with `--features embree` (its library,
        /// libembree3, loaded at run time: reported skipped if missing).
        #[arg(long)]
        peers: bool,
        /// With `--peers`, Embree's default build a third time, its kernels
        /// kept to this instruction set (its row named so): to compare
        /// Embree's kernels for two instruction sets in one run.
        #[arg(long, value_name = "ISA", requires = "peers")]
        embree_isa: Option<bench::EmbreeIsaArg>,
        /// With `--peers`, Embree's default mode the only peer (no obvhs,
        /// no bvh, not its robust mode): for counting its instructions
        /// with callgrind, where both of its modes run `rtcIntersect1`.
        #[arg(long, requires = "peers")]
        embree_alone: bool,
        /// Rays of each set checked against brute force (evenly spread).
        #[arg(long, value_name = "N", default_value_t = 1000)]
        brute_force: usize,
        /// Also write the report as JSON to this file.
        #[arg(long, value_name = "FILE")]
        json: Option<PathBuf>,
        /// Write the first method's answers on the first set (records of
        /// little-endian f32 t, +inf for a miss, and u32 triangle,
        /// u32::MAX for a miss).
        #[arg(long, value_name = "FILE")]
        write_hits: Option<PathBuf>,
    },
    /// Run a chapter's tests in student mode and report each exercise.
    ///
    /// Cargo builds the chapter's tests (`cargo test --no-run`, with the
    /// `exercise` feature unless `--reference`); raystep then runs each test
    /// binary itself, one after the other: the unit tests (the library's
    /// first), then `tests/*.rs` by name.
    /// Each exercise gets one verdict: `passed`, `failed: <test>
    /// (<file>:<line>): <message>` (for a snapshot table, the first row whose
    /// values differ), `not attempted` (every failing test stopped at
    /// `todo!()`) or `timed out after N s`; the chapter's other tests are
    /// counted as passed, waiting for the exercises (`todo!()`) or failed.
    /// No snapshot is ever written or accepted, and snapshot files that
    /// differ from git's `HEAD` (or insta's `.snap.new` proposals) are named.
    /// The verdicts do not depend on cargo's `term` settings or insta's
    /// variables. Doc tests are not run (the chapters have none).
    Check {
        /// The chapter: `ch01`, `01` or `1`.
        chapter: String,
        /// Run the reference solution instead of the exercise stubs.
        #[arg(long)]
        reference: bool,
        /// Build in this target directory [env: RAYSTEP_CHECK_TARGET_DIR; default: cargo's].
        #[arg(long, value_name = "DIR")]
        target_dir: Option<PathBuf>,
        #[command(flatten)]
        limits: run_options::LimitArgs,
        /// Do not echo cargo's progress on stderr.
        #[arg(long, short)]
        quiet: bool,
        /// Also write the report as JSON to this file.
        #[arg(long, value_name = "FILE")]
        json: Option<PathBuf>,
        /// Also write the report as JUnit XML to this file (one test case
        /// per exercise, one for the other tests).
        #[arg(long, value_name = "FILE")]
        junit: Option<PathBuf>,
    },
    /// Show the hints for one exercise or paper question, each level
    /// more concrete: 1 the idea, 2 the step usually missed, 3 the shape
    /// of the code (or the working) without the code (or the answer).
    Hint {
        /// The chapter: `ch01`, `01` or `1`.
        chapter: String,
        /// The exercise (`line_through_points`) or paper question (`q1`).
        exercise: String,
        /// Show the hints up to this level.
        #[arg(long, default_value_t = 1,
              value_parser = clap::value_parser!(u8).range(1..=3))]
        level: u8,
    },
    /// Check a chapter now and again on every save in its `exercise/`
    /// folder; show the first exercise not passed, with its message and
    /// the hint to ask for, or what is next once the chapter passes.
    ///
    /// Each check is `raystep check CHAPTER` (it records the verdicts for
    /// `raystep progress`); a save while one runs checks again when it
    /// ends. Ctrl-C stops the running check and quits. On a terminal each
    /// view replaces the last; otherwise they follow as plain lines.
    Watch {
        /// The chapter: `ch01`, `01` or `1` [default: the first with an
        /// exercise or paper question not passed yet].
        chapter: Option<String>,
    },
    /// Show every chapter's exercises and paper questions with the verdict
    /// `raystep check` last gave them, what passed per chapter and
    /// overall, and the next exercise to do.
    Progress,
    /// Check every student's exercise files in a scratch copy of the
    /// workspace, into one table of verdicts.
    ///
    /// The students are checked one after the other, by folder name.
    /// SUBMISSIONS holds one folder per student. A student's files are
    /// `<student>/exercise/<exercise>.rs` or `<student>/<exercise>.rs`
    /// (the first if both exist), named after the chapter's exercises;
    /// every other file is ignored and reported. Before each student the
    /// chapter's `exercise/` and `tests/snapshots/` are restored from this
    /// workspace, which is never changed. An exercise without a file is
    /// `missing file` (its stub is used, so the others are still judged);
    /// a file that does not compile is `does not compile` (its stub is then
    /// used for the others); a file that names another file, the
    /// environment or the operating system (`#[path]`, `include!`, `env!`,
    /// `std::process`, `unsafe`, …) is `refused` and not run. The graded
    /// chapter's reference is not in the copy: its exercise modules there
    /// are the committed stubs. A pass of the tests stands only if the
    /// chapter's held-out cases (`examples/chNN_held_out.rs`), drawn from a
    /// new secret seed, agree with the reference too; the reference judges
    /// them in a process of its own.
    Grade {
        /// The folder of submissions, one folder per student.
        submissions: PathBuf,
        /// The chapter: `ch01`, `01` or `1`.
        #[arg(long, value_name = "CHAPTER")]
        chapter: String,
        /// The CSV table to write (student, exercise, verdict, message).
        #[arg(long, value_name = "FILE.csv", default_value = "grades.csv")]
        out: PathBuf,
        /// Also write the table as JSON to this file.
        #[arg(long, value_name = "FILE")]
        json: Option<PathBuf>,
        #[command(flatten)]
        limits: run_options::LimitArgs,
        /// Build and run each student's code inside bubblewrap: no network,
        /// only the scratch copy writable, the toolchain and cargo's registry
        /// read-only, nothing else of the file system visible. `auto`: where
        /// bubblewrap is installed and works, else with one warning.
        #[arg(long, value_enum, default_value_t = sandbox::Mode::Auto)]
        sandbox: sandbox::Mode,
        /// Grade this many students at once, each in a scratch copy of its
        /// own (the table is the same as one at a time).
        #[arg(long, short, value_name = "N", default_value_t = 1,
              value_parser = clap::value_parser!(u32).range(1..=16))]
        jobs: u32,
        /// Keep the rows of the students an interrupted run (Ctrl-C, a
        /// crash) had graded, kept beside the table in FILE.csv.partial,
        /// and grade only the others.
        #[arg(long)]
        resume: bool,
        /// Build in this target directory, kept for the next run [env:
        /// RAYSTEP_CHECK_TARGET_DIR; default: one inside the scratch copy,
        /// removed at the end].
        #[arg(long, value_name = "DIR")]
        target_dir: Option<PathBuf>,
        /// Draw the held-out cases from this seed, to replay a run (the
        /// JSON report names each run's seed) [default: a new secret seed].
        #[arg(long, value_name = "N")]
        held_out_seed: Option<u64>,
    },
    /// Write a copy of the workspace for students, without the solutions.
    ///
    /// Every exercise module holds its stub: no reference solution is
    /// anywhere in the copy.
    /// For every chapter and exercise `e`, `chapters/<ch>/src/<e>.rs` gets
    /// the text of `chapters/<ch>/exercise/<e>.rs`, and a chapter's
    /// `exercise` feature turns on the one of the chapters it builds on
    /// (so later chapters run on the student's earlier exercises). Build
    /// output (`target/`, `book/book/`) and `.git` are left out; a new git
    /// repository with one commit is made if `git` is installed.
    StudentEdition {
        /// The folder to create; it must not exist or be empty.
        out: PathBuf,
    },
}

/// `--format` values.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
enum FormatArg {
    Svg,
    Png,
    Both,
}

impl From<FormatArg> for raystep_figure::Format {
    fn from(format: FormatArg) -> raystep_figure::Format {
        match format {
            FormatArg::Svg => raystep_figure::Format::Svg,
            FormatArg::Png => raystep_figure::Format::Png,
            FormatArg::Both => raystep_figure::Format::Both,
        }
    }
}

/// `--target-dir`, else `RAYSTEP_CHECK_TARGET_DIR`, as an absolute path
/// (cargo runs in the workspace root: a relative folder means the current
/// one).
fn check_target_dir(arg: Option<PathBuf>) -> Option<PathBuf> {
    arg.or_else(|| {
        std::env::var_os("RAYSTEP_CHECK_TARGET_DIR").map(PathBuf::from)
    })
    .map(|dir| std::path::absolute(&dir).unwrap_or(dir))
}

/// clap's usage error on one line: `error: invalid value 'gif' for '--format <FORMAT>'; [possible values: svg, png, both]`.
fn one_line(message: &str) -> String {
    let mut line = String::new();
    for part in message.lines().map(str::trim) {
        if part.is_empty()
            || part.starts_with("Usage:")
            || part.starts_with("For more information")
        {
            continue;
        }
        if line.ends_with(':') {
            line.push(' ');
        } else if !line.is_empty() {
            line.push_str("; ");
        }
        line.push_str(part);
    }
    line
}

fn main() -> ExitCode {
    let cli = match Cli::try_parse() {
        Ok(cli) => cli,
        // --help and --version print to stdout and succeed.
        Err(error) if !error.use_stderr() => error.exit(),
        Err(error) => {
            eprintln!("{} (see raystep --help)", one_line(&error.to_string()));
            return ExitCode::from(2);
        }
    };
    let result = match cli.command {
        Command::Book {
            out,
            open,
            no_figures,
        } => book::run(&book::Options {
            out,
            open,
            figures: !no_figures,
        }),
        Command::BookPreprocessor { args } => book::preprocessor(&args),
        Command::Figures {
            chapter,
            out,
            format,
            check,
        } => figures::run(&figures::Options {
            chapter,
            out,
            format: format.into(),
            check,
        }),
        Command::Measure(options) => measure::run(&options),
        Command::Stability(options) => stability::run(&options),
        Command::Render(options) => render::run(&options),
        Command::Bench {
            mesh,
            rays,
            size,
            incoherent,
            seed,
            threads,
            rounds,
            builders,
            precision,
            accel,
            grid_cells,
            grid_fill,
            kd_clip,
            fast,
            peers,
            embree_isa,
            embree_alone,
            brute_force,
            json,
            write_hits,
        } => bench::run(&bench::Options {
            bench: raystep_bench::BenchOptions {
                mesh,
                rays,
                size,
                incoherent,
                seed,
                threads: usize::from(threads),
                rounds: usize::from(rounds),
                builders: if accel.contains(&bench::AccelArg::Bvh) {
                    builders.iter().map(|b| b.builder()).collect()
                } else {
                    Vec::new()
                },
                precisions: precision.iter().map(|p| p.precision()).collect(),
                grids: if accel.contains(&bench::AccelArg::Grid) {
                    grid_fill
                        .iter()
                        .map(|f| raystep_bench::GridSpec {
                            fill: f.fill(),
                            cells: grid_cells.map(usize::from),
                            mailbox: true,
                        })
                        .collect()
                } else {
                    Vec::new()
                },
                kd_trees: if accel.contains(&bench::AccelArg::KdTree) {
                    kd_clip
                        .iter()
                        .map(|c| raystep_bench::KdSpec::sah(c.clip()))
                        .collect()
                } else {
                    Vec::new()
                },
                fast: if accel.contains(&bench::AccelArg::Fast) {
                    fast.clone()
                } else {
                    Vec::new()
                },
                peers,
                embree_isa: embree_isa.map(bench::EmbreeIsaArg::isa),
                embree_alone,
                brute_force,
                progress: io::stderr().is_terminal(),
            },
            json,
            write_hits,
        }),
        Command::Check {
            chapter,
            reference,
            target_dir,
            limits,
            quiet,
            json,
            junit,
        } => check::run(&check::Options {
            chapter,
            reference,
            target_dir: check_target_dir(target_dir),
            timeout: limits.timeout(),
            memory: limits.memory,
            output: limits.output,
            quiet,
            json,
            junit,
        }),
        Command::Hint {
            chapter,
            exercise,
            level,
        } => hint::run(&hint::Options {
            chapter,
            exercise,
            level,
        }),
        Command::Grade {
            submissions,
            chapter,
            out,
            json,
            limits,
            sandbox,
            jobs,
            resume,
            target_dir,
            held_out_seed,
        } => grade::run(&grade::Options {
            submissions,
            chapter,
            out,
            json,
            timeout: limits.timeout(),
            memory: limits.memory,
            output: limits.output,
            sandbox,
            jobs,
            resume,
            target_dir: check_target_dir(target_dir),
            seed: held_out_seed,
        }),
        Command::Watch { chapter } => watch::run(chapter.as_deref()),
        Command::Progress => progress::run(),
        Command::StudentEdition { out } => student_edition::run(&out),
    };
    match result {
        Ok(code) => code,
        Err(error) => {
            eprintln!("error: {error}");
            ExitCode::FAILURE
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn usage_errors_fit_on_one_line() {
        let error =
            Cli::try_parse_from(["raystep", "figures", "--format", "gif"])
                .unwrap_err();
        assert_eq!(
            one_line(&error.to_string()),
            "error: invalid value 'gif' for '--format <FORMAT>'; [possible values: svg, png, both]"
        );
        let error = Cli::try_parse_from(["raystep", "check"]).unwrap_err();
        assert_eq!(
            one_line(&error.to_string()),
            "error: the following required arguments were not provided: <CHAPTER>"
        );
    }

    #[test]
    fn the_timeout_is_a_positive_number_of_seconds() {
        let timeout = |args: &[&str]| match Cli::try_parse_from(args) {
            Ok(Cli {
                command: Command::Check { limits, .. },
            }) => Ok(limits.timeout),
            Ok(other) => panic!("{other:?}"),
            Err(error) => Err(one_line(&error.to_string())),
        };
        assert_eq!(timeout(&["raystep", "check", "1"]), Ok(60.0));
        assert_eq!(
            timeout(&["raystep", "check", "1", "--timeout", "2.5"]),
            Ok(2.5)
        );
        for bad in ["0", "-3", "NaN", "inf", "1e30", "soon"] {
            assert_eq!(
                timeout(&[
                    "raystep",
                    "check",
                    "1",
                    &format!("--timeout={bad}")
                ]),
                Err(format!(
                    "error: invalid value '{bad}' for '--timeout <SECS>': \
                     expected a positive number of seconds"
                )),
            );
        }
    }

    #[test]
    fn the_command_line_is_consistent() {
        use clap::CommandFactory;
        Cli::command().debug_assert();
    }
}
