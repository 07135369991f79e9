//! `raystep grade SUBMISSIONS --chapter chNN`: every student's exercise
//! files checked in turn, as `raystep check` would, into one table.
//!
//! The instructor's workspace is never changed: it is copied once into a
//! scratch folder (sources only), where the graded chapter's exercise
//! modules in `src/` are its committed stubs (no reference body of the
//! chapter is in the copy). Before each student the chapter's `exercise/`
//! (the committed stubs) and `tests/snapshots/` are put back; then the
//! student's files go in, unless one names another file, the environment
//! or the operating system (`refused`, see `crate::submission_rules`).
//! Every student shares one target folder, so only the chapter crate is
//! rebuilt. A pass of the tests stands only if the chapter's held-out
//! cases, judged by the reference in a process of its own, agree too (see
//! `crate::held_out`). A submission that is missing a file, does not
//! compile or loops gets its verdict; it never stops the others.

use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::fs;
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::Duration;

use raystep_figure::Chapter;
use serde::Serialize;

use raystep_check::verdicts::{CargoFailure, advice, changed_snapshots};

use crate::committed_stubs::{self, Stubs};
use crate::compile_isolation::{blamed_files, compile_message};
use crate::error::Error;
use crate::grade_partial::Partial;
pub use crate::grade_rows::{Graded, Ignored, Row};
use crate::run_options::Run;
use crate::sandbox::{self, Sandbox};
use crate::shown_path::{relative, shown};
use crate::{
    atomic_file, check, grade_partial, held_out, process_group, questions,
    submission_rules, workspace, workspace_copy,
};

/// What `raystep grade` was asked to do.
#[derive(Debug)]
pub struct Options {
    /// One folder per student.
    pub submissions: PathBuf,
    /// `ch01`, `01` or `1`.
    pub chapter: String,
    /// The CSV table to write.
    pub out: PathBuf,
    /// Also write the table as JSON here.
    pub json: Option<PathBuf>,
    /// How long one test binary may run.
    pub timeout: Duration,
    /// How much memory the build and each test binary may ask for, in bytes.
    pub memory: u64,
    /// How much one test binary may print, in bytes.
    pub output: u64,
    /// Whether the student's build and tests run inside bubblewrap.
    pub sandbox: sandbox::Mode,
    /// How many students are graded at once.
    pub jobs: u32,
    /// Keep the rows an interrupted run graded (`FILE.csv.partial`).
    pub resume: bool,
    /// A target folder to build in (kept); else one in the scratch folder.
    pub target_dir: Option<PathBuf>,
    /// The held-out cases' seed, to replay a run; else a new secret one.
    pub seed: Option<u64>,
}

/// The JSON document: the table and the files not taken.
#[derive(Serialize)]
struct JsonGrades<'a> {
    chapter: &'a str,
    package: &'a str,
    /// The seed the held-out cases were drawn from (to replay them), if
    /// the chapter has held-out cases.
    held_out_seed: Option<u64>,
    rows: &'a [Row],
    ignored: &'a [Ignored],
}

/// Runs `raystep grade`.
pub fn run(options: &Options) -> Result<ExitCode, Error> {
    let root = workspace::root();
    let chapter =
        crate::chapters::find(&options.chapter, crate::chapters::CHAPTERS)?;
    let (students, mut ignored) = students(&options.submissions)?;
    // Refuse a table that could not be written before the long work.
    atomic_file::can_write(&options.out)?;
    if let Some(path) = &options.json {
        atomic_file::can_write(path)?;
    }
    let code: Vec<String> =
        chapter.exercises.iter().map(|e| e.to_string()).collect();
    // The table's columns: the code exercises, then the paper questions.
    let mut exercises = code.clone();
    if let Some(file) = questions::read(&root, chapter)? {
        exercises.extend(file.questions.iter().map(|q| q.id.clone()));
    }

    let instructor = root.join("chapters").join(chapter.package);
    // The stubs as committed: an instructor trying the exercises in
    // `exercise/` must not give a student who left a file out a solution.
    let stubs = committed_stubs::committed(&root, &[chapter])?;
    if let Some(note) = stubs.note() {
        eprintln!("{note}");
    }
    let changed = changed_snapshots(&instructor);
    for line in advice(&changed, &relative(&instructor)) {
        eprintln!("{line}");
    }

    // What an interrupted run graded already, and its seed.
    let partial_path = grade_partial::path(&options.out);
    let left = if options.resume {
        grade_partial::read(&partial_path, chapter.id)?
    } else {
        if partial_path.exists() {
            eprintln!(
                "note: {} from an earlier run is replaced (--resume keeps its rows)",
                shown(&partial_path)
            );
        }
        None
    };
    let kept: Vec<Graded> = left
        .as_ref()
        .map(|left| {
            left.graded
                .iter()
                .filter(|g| students.iter().any(|(name, _)| *name == g.student))
                .cloned()
                .collect()
        })
        .unwrap_or_default();
    let to_grade: Vec<(usize, &Student)> = students
        .iter()
        .enumerate()
        .filter(|(_, (name, _))| !kept.iter().any(|g| g.student == *name))
        .collect();
    if !kept.is_empty() {
        eprintln!(
            "resuming: {} students graded already, {} to go",
            kept.len(),
            to_grade.len()
        );
    }

    let scratch = tempfile::Builder::new()
        .prefix("raystep-grade-")
        .tempdir()
        .map_err(|e| Error::io(&std::env::temp_dir(), e))?;
    // Ctrl-C (or a hang-up) removes it too.
    let _removal = process_group::remove_on_interrupt(scratch.path());
    // One copy of the workspace per student graded at once.
    let jobs = (options.jobs as usize).clamp(1, to_grade.len().max(1));
    let copies: Vec<PathBuf> = (0..jobs)
        .map(|k| match k {
            0 => scratch.path().join("workspace"),
            k => scratch.path().join(format!("workspace-{}", k + 1)),
        })
        .collect();
    for copy in &copies {
        eprintln!("copying the workspace to {}…", copy.display());
        workspace_copy::copy_sources(&root, copy, &[])?;
        // No reference body of the graded chapter in the copy: its exercise
        // modules in `src/` are the stubs too, as in the student edition.
        stubs.write(copy, chapter, true)?;
    }
    let shared = link_shared(&root, scratch.path());
    let seed = options
        .seed
        .or(left.as_ref().and_then(|left| left.held_out_seed))
        .unwrap_or_else(held_out::new_seed);
    let target = options
        .target_dir
        .clone()
        .unwrap_or_else(|| scratch.path().join("target"));
    // Copies of the workspace in one target folder share their crates'
    // artifacts (see `separate_artifacts`): two runs grading into one
    // folder at once would run each other's builds. They take turns.
    let _turn = grading_turn(&target)?;
    // The held-out cases' judge: the reference, built in the instructor's
    // workspace (in our turn: another run's student could otherwise put
    // its program where cargo puts the reference's).
    let reference = held_out::build_reference(
        &root,
        chapter,
        options.target_dir.as_deref(),
        &scratch.path().join("reference"),
    )?;
    if reference.is_none() {
        eprintln!(
            "note: {} has no held-out cases (examples/{}.rs): only its tests judge",
            chapter.package,
            held_out::held_out_name(chapter)
        );
    }
    // The student's build and tests see the scratch folder (the copies,
    // the target folder, the answers) and the test data, nothing else of
    // the instructor's.
    let mut writable = vec![scratch.path().to_path_buf()];
    writable.extend(options.target_dir.clone());
    let sandbox = Sandbox::choose(options.sandbox, &writable, &shared)?;
    let runs: Vec<Run> = (0..jobs)
        .map(|k| Run {
            reference: false,
            target_dir: Some(target.clone()),
            quiet: true,
            timeout: options.timeout,
            memory: options.memory,
            output: options.output,
            sandbox: sandbox.clone(),
            copy: k as u32,
            keep_examples: Some(
                scratch.path().join(format!("examples-{}", k + 1)),
            ),
        })
        .collect();
    let partial = Partial::start(
        &partial_path,
        chapter.id,
        reference.is_some().then_some(seed),
        &kept,
    )?;
    eprintln!(
        "grading {} students on {}{} (the first build takes a few minutes)",
        to_grade.len(),
        chapter.package,
        match jobs {
            1 => String::new(),
            n => format!(", {n} at once"),
        }
    );

    // Each worker takes the next student not yet taken, in its own copy.
    let next = std::sync::atomic::AtomicUsize::new(0);
    let graded = std::sync::Mutex::new(Vec::<Graded>::new());
    let failed = std::sync::Mutex::new(None::<Error>);
    let count = students.len();
    std::thread::scope(|scope| {
        for (copy, run) in copies.iter().zip(&runs) {
            let (next, graded, failed) = (&next, &graded, &failed);
            let (partial, stubs, code, to_grade) =
                (&partial, &stubs, &code, &to_grade);
            let (reference, root, scratch) =
                (reference.as_deref(), &root, scratch.path());
            scope.spawn(move || {
                loop {
                    if failed
                        .lock()
                        .unwrap_or_else(|e| e.into_inner())
                        .is_some()
                    {
                        return;
                    }
                    let taken =
                        next.fetch_add(1, std::sync::atomic::Ordering::SeqCst);
                    let Some((i, (name, folder))) = to_grade.get(taken) else {
                        return;
                    };
                    eprintln!("[{}/{count}] {name}", i + 1);
                    let judge = reference.map(|reference| Judge {
                        reference,
                        seed,
                        answers: scratch.join(format!("answers-{}.txt", i + 1)),
                    });
                    let result = grade_one(
                        root,
                        copy,
                        chapter,
                        stubs,
                        name,
                        folder,
                        code,
                        run,
                        judge.as_ref(),
                    )
                    .and_then(|one| partial.add(&one).map(|()| one));
                    match result {
                        Ok(one) => graded
                            .lock()
                            .unwrap_or_else(|e| e.into_inner())
                            .push(one),
                        Err(error) => {
                            let mut first = failed
                                .lock()
                                .unwrap_or_else(|e| e.into_inner());
                            first.get_or_insert(error);
                            return;
                        }
                    }
                }
            });
        }
    });
    if let Some(error) = failed.into_inner().unwrap_or_else(|e| e.into_inner())
    {
        return Err(error);
    }
    // The table in the students' order, however the work was shared.
    let mut all = kept;
    all.extend(graded.into_inner().unwrap_or_else(|e| e.into_inner()));
    let mut rows = Vec::new();
    for (name, _) in &students {
        if let Some(one) = all.iter().find(|g| g.student == *name) {
            rows.extend(one.rows.iter().cloned());
            ignored.extend(one.ignored.iter().cloned());
        }
    }

    atomic_file::write(&options.out, csv_table(&rows)?.as_bytes())?;
    if let Some(path) = &options.json {
        let document = JsonGrades {
            chapter: chapter.id,
            package: chapter.package,
            held_out_seed: reference.is_some().then_some(seed),
            rows: &rows,
            ignored: &ignored,
        };
        let mut text = serde_json::to_string_pretty(&document)
            .expect("the table serialises");
        text.push('\n');
        atomic_file::write(path, text.as_bytes())?;
    }
    print!("{}", summary(chapter, &exercises, &rows));
    for file in &ignored {
        let path = Path::new(&file.student).join(&file.file);
        println!("ignored: {}", path.display());
    }
    let mut written = vec![shown(&options.out)];
    written.extend(options.json.as_deref().map(shown));
    println!("wrote {}", written.join(" and "));
    partial.finish()?;
    Ok(ExitCode::SUCCESS)
}

/// The one turn to grade into the target folder `target`, held until
/// dropped: a lock on `target/.raystep-grade.lock`, waited for (and said)
/// when another run holds it.
fn grading_turn(target: &Path) -> Result<fs::File, Error> {
    fs::create_dir_all(target).map_err(|e| Error::io(target, e))?;
    let path = target.join(".raystep-grade.lock");
    let file = fs::File::create(&path).map_err(|e| Error::io(&path, e))?;
    match file.try_lock() {
        Ok(()) => return Ok(file),
        Err(fs::TryLockError::WouldBlock) => eprintln!(
            "waiting for another `raystep grade` building in {}…",
            shown(target)
        ),
        Err(fs::TryLockError::Error(e)) => return Err(Error::io(&path, e)),
    }
    file.lock().map_err(|e| Error::io(&path, e))?;
    Ok(file)
}

/// Grades one student (`name`, handing in `folder`) in the scratch
/// workspace `copy`: their rows and the files of theirs not taken.
#[allow(clippy::too_many_arguments)]
fn grade_one(
    root: &Path, copy: &Path, chapter: &Chapter, stubs: &Stubs, name: &str,
    folder: &Path, code: &[String], run: &Run, judge: Option<&Judge>,
) -> Result<Graded, Error> {
    let submission = submission(folder, code);
    let ignored = submission
        .ignored
        .iter()
        .map(|file| Ignored {
            student: name.to_string(),
            file: file.clone(),
        })
        .collect();
    let verdicts =
        grade_student(root, copy, chapter, stubs, &submission, run, judge)?;
    let rows = verdicts
        .into_iter()
        .map(|(exercise, (verdict, message))| Row {
            student: name.to_string(),
            exercise,
            verdict,
            message,
        })
        .collect();
    Ok(Graded {
        student: name.to_string(),
        rows,
        ignored,
    })
}

/// A student's name (the folder's) and folder.
type Student = (String, PathBuf);

/// The student folders in `submissions`, sorted by name, and the entries
/// that are not student folders (files, hidden folders).
fn students(submissions: &Path) -> Result<(Vec<Student>, Vec<Ignored>), Error> {
    let error = |e| Error::io(submissions, e);
    if !submissions.is_dir() {
        return Err(Error::Usage(format!(
            "{}: not a folder of submissions (one folder per student)",
            shown(submissions)
        )));
    }
    let mut students = Vec::new();
    let mut ignored = Vec::new();
    for entry in fs::read_dir(submissions).map_err(error)? {
        let entry = entry.map_err(error)?;
        let name = entry.file_name().to_string_lossy().into_owned();
        if entry.path().is_dir() && !name.starts_with('.') {
            students.push((name, entry.path()));
        } else {
            ignored.push(Ignored {
                student: String::new(),
                file: name,
            });
        }
    }
    if students.is_empty() {
        return Err(Error::Usage(format!(
            "{}: no student folders in it (one folder per student, each \
             holding exercise/*.rs)",
            shown(submissions)
        )));
    }
    students.sort();
    ignored.sort_by(|a, b| a.file.cmp(&b.file));
    Ok((students, ignored))
}

/// The files a student handed in.
#[derive(Debug, Default, PartialEq, Eq)]
pub struct Submission {
    /// Exercise name → its file.
    pub files: BTreeMap<String, PathBuf>,
    /// The answers to the paper questions, if handed in.
    pub answers: Option<PathBuf>,
    /// Every other file, relative to the student's folder, sorted.
    pub ignored: Vec<String>,
}

/// The exercise files in a student's folder: `exercise/<e>.rs`, else
/// `<e>.rs`, for each exercise `e` of the chapter, and the answers to the
/// paper questions, `exercise/answers.toml` else `answers.toml`. Every
/// other file is ignored (and listed).
pub fn submission(folder: &Path, exercises: &[String]) -> Submission {
    let mut found = Submission::default();
    let mut all: Vec<String> = walkdir::WalkDir::new(folder)
        .sort_by_file_name()
        .into_iter()
        .flatten()
        .filter(|e| !e.file_type().is_dir())
        .filter_map(|e| {
            let relative = e.path().strip_prefix(folder).ok()?;
            Some(
                relative
                    .components()
                    .map(|c| c.as_os_str().to_string_lossy())
                    .collect::<Vec<_>>()
                    .join("/"),
            )
        })
        .collect();
    all.sort();
    for exercise in exercises {
        let choices =
            [format!("exercise/{exercise}.rs"), format!("{exercise}.rs")];
        if let Some(file) = choices.iter().find(|c| all.contains(c)) {
            found.files.insert(exercise.clone(), folder.join(file));
            all.retain(|f| f != file);
        }
    }
    let answers = [
        format!("exercise/{}", questions::ANSWERS),
        questions::ANSWERS.to_string(),
    ];
    if let Some(file) = answers.iter().find(|c| all.contains(c)) {
        found.answers = Some(folder.join(file));
        all.retain(|f| f != file);
    }
    found.ignored = all;
    found
}

/// A verdict and its message.
type Verdict = (String, String);

/// What judges a student's held-out cases.
struct Judge<'a> {
    /// The held-out program built with the reference.
    reference: &'a Path,
    /// The run's secret seed.
    seed: u64,
    /// Where the student's answers are kept.
    answers: PathBuf,
}

/// Checks one student's files in the scratch workspace `copy`; the
/// chapter's `exercise/` (its committed `stubs`, the stub of the answers)
/// and `tests/snapshots/` (from `root`) are put back first.
fn grade_student(
    root: &Path, copy: &Path, chapter: &Chapter, stubs: &Stubs,
    submission: &Submission, run: &Run, judge: Option<&Judge>,
) -> Result<Vec<(String, Verdict)>, Error> {
    let files = &submission.files;
    let instructor = root.join("chapters").join(chapter.package);
    let scratch = copy.join("chapters").join(chapter.package);
    for folder in ["exercise", "tests/snapshots"] {
        workspace_copy::replace_folder(
            &instructor.join(folder),
            &scratch.join(folder),
        )?;
    }
    stubs.write(copy, chapter, false)?;
    questions::write_stub(copy, chapter)?;
    let stub = |exercise: &str| -> Result<(), Error> {
        let to = scratch.join("exercise").join(format!("{exercise}.rs"));
        fs::write(&to, stubs.text(chapter, exercise))
            .map_err(|e| Error::io(&to, e))
    };

    // Verdicts settled before the tests run.
    let mut settled: BTreeMap<String, Verdict> = BTreeMap::new();
    let mut submitted: Vec<String> = Vec::new();
    for exercise in chapter.exercises {
        let Some(file) = files.get(*exercise) else {
            settled.insert(
                exercise.to_string(),
                (
                    "missing file".into(),
                    format!("no exercise/{exercise}.rs (the stub was used)"),
                ),
            );
            continue;
        };
        let to = scratch.join("exercise").join(format!("{exercise}.rs"));
        let bytes = fs::read(file);
        // A file that names another file, the environment or the
        // operating system is not run at all (one that is not UTF-8 does
        // not compile).
        if let Ok(text) = bytes.as_deref().map(std::str::from_utf8)
            && let Ok(text) = text
            && let Some(refusal) = submission_rules::first_refusal(text)
        {
            settled.insert(
                exercise.to_string(),
                (
                    "refused".into(),
                    format!(
                        "{} (the stub was used)",
                        refusal.describe(&format!("exercise/{exercise}.rs"))
                    ),
                ),
            );
            continue;
        }
        match bytes.and_then(|bytes| fs::write(&to, bytes)) {
            Ok(()) => submitted.push(exercise.to_string()),
            Err(error) => {
                settled.insert(
                    exercise.to_string(),
                    (
                        "missing file".into(),
                        format!(
                            "{}: {error} (the stub was used)",
                            file.display()
                        ),
                    ),
                );
            }
        }
    }

    // The answers to the paper questions: data, judged without running
    // anything (`check` reads at most 64 KiB of them).
    let answers_file = format!("exercise/{}", questions::ANSWERS);
    match &submission.answers {
        Some(file) => {
            let to = scratch.join(&answers_file);
            if let Err(error) = fs::copy(file, &to) {
                let why = format!("{}: {error}", file.display());
                for question in paper_questions(copy, chapter)? {
                    settled
                        .insert(question, ("missing file".into(), why.clone()));
                }
            }
        }
        None => {
            for question in paper_questions(copy, chapter)? {
                let why = format!("no {answers_file} (not attempted)");
                settled.insert(question, ("missing file".into(), why));
            }
        }
    }

    // Files that do not compile are put back to their stubs, one build at a
    // time, so that the other exercises can still be judged.
    while let Some(failure) = check::build_failure(copy, chapter, run)? {
        if !matches!(failure.failure, CargoFailure::DoesNotCompile(_)) {
            break; // cargo itself failed: every verdict says so below
        }
        let mut blamed = blamed_files(&failure, chapter.package, &submitted);
        if blamed.is_empty() {
            blamed = alone_failing(copy, chapter, run, &submitted, &stub)?;
        }
        if blamed.is_empty() {
            // Not one file alone: together, or the stubs, do not compile.
            blamed = submitted.clone();
        }
        if blamed.is_empty() {
            break;
        }
        for exercise in &blamed {
            settled.insert(
                exercise.clone(),
                (
                    "does not compile".into(),
                    compile_message(&failure, chapter.package, exercise),
                ),
            );
            stub(exercise)?;
        }
        submitted.retain(|e| !blamed.contains(e));
    }

    let report = check::check_chapter(copy, chapter, run)?;
    let held_out = match (judge, &report.held_out_runner) {
        (Some(judge), Some(runner)) => held_out::judge(
            judge.reference,
            runner,
            chapter.exercises,
            judge.seed,
            run,
            &judge.answers,
        )?,
        _ => BTreeMap::new(),
    };
    Ok(report
        .exercises
        .into_iter()
        .map(|(exercise, verdict)| {
            let row = settled.remove(&exercise).unwrap_or_else(|| {
                held_out::merged(
                    (
                        verdict.kind().to_string(),
                        verdict.message().unwrap_or_default(),
                    ),
                    held_out.get(&exercise),
                )
            });
            (exercise, row)
        })
        .collect())
}

/// The ids of the chapter's paper questions in the workspace at `copy`.
fn paper_questions(
    copy: &Path, chapter: &Chapter,
) -> Result<Vec<String>, Error> {
    Ok(questions::read(copy, chapter)?
        .map(|file| file.questions.into_iter().map(|q| q.id).collect())
        .unwrap_or_default())
}

/// When no error names a file: the submitted exercises that do not compile
/// on their own, every other submitted file a stub.
fn alone_failing(
    copy: &Path, chapter: &Chapter, run: &Run, submitted: &[String],
    stub: &dyn Fn(&str) -> Result<(), Error>,
) -> Result<Vec<String>, Error> {
    if submitted.len() < 2 {
        return Ok(submitted.to_vec());
    }
    let scratch = copy.join("chapters").join(chapter.package);
    // Keep the student's files aside, then try each alone.
    let mut kept = BTreeMap::new();
    for exercise in submitted {
        let path = scratch.join("exercise").join(format!("{exercise}.rs"));
        kept.insert(
            exercise.clone(),
            fs::read(&path).map_err(|e| Error::io(&path, e))?,
        );
        stub(exercise)?;
    }
    let mut failing = Vec::new();
    for (exercise, text) in &kept {
        let path = scratch.join("exercise").join(format!("{exercise}.rs"));
        fs::write(&path, text).map_err(|e| Error::io(&path, e))?;
        if check::build_failure(copy, chapter, run)?.is_some() {
            failing.push(exercise.clone());
        }
        stub(exercise)?;
    }
    for (exercise, text) in &kept {
        let path = scratch.join("exercise").join(format!("{exercise}.rs"));
        fs::write(&path, text).map_err(|e| Error::io(&path, e))?;
    }
    Ok(failing)
}

/// The table as CSV: a header, then one row per student and exercise.
fn csv_table(rows: &[Row]) -> Result<String, Error> {
    let mut writer = csv::Writer::from_writer(Vec::new());
    for row in rows {
        writer.serialize(row).map_err(|e| {
            Error::Usage(format!("cannot write the CSV table: {e}"))
        })?;
    }
    if rows.is_empty() {
        writer
            .write_record(["student", "exercise", "verdict", "message"])
            .map_err(|e| {
                Error::Usage(format!("cannot write the CSV table: {e}"))
            })?;
    }
    let bytes = writer.into_inner().map_err(|e| {
        Error::Usage(format!("cannot write the CSV table: {e}"))
    })?;
    Ok(String::from_utf8(bytes).expect("the table is UTF-8"))
}

/// The summary on stdout: one line per student, one column per exercise,
/// and how many exercises passed.
fn summary(chapter: &Chapter, exercises: &[String], rows: &[Row]) -> String {
    let mut students: Vec<&str> =
        rows.iter().map(|r| r.student.as_str()).collect();
    students.dedup();
    let verdict = |student: &str, exercise: &str| {
        rows.iter()
            .find(|r| r.student == student && r.exercise == exercise)
            .map_or("", |r| r.verdict.as_str())
    };
    let mut table: Vec<Vec<String>> = vec![
        std::iter::once("student".to_string())
            .chain(exercises.iter().cloned())
            .chain(["passed".to_string()])
            .collect(),
    ];
    for student in &students {
        let verdicts: Vec<&str> =
            exercises.iter().map(|e| verdict(student, e)).collect();
        let passed = verdicts.iter().filter(|v| **v == "passed").count();
        table.push(
            std::iter::once(student.to_string())
                .chain(verdicts.iter().map(|v| v.to_string()))
                .chain([format!("{passed} of {}", exercises.len())])
                .collect(),
        );
    }
    let widths: Vec<usize> = (0..table[0].len())
        .map(|c| {
            table
                .iter()
                .map(|r| r[c].chars().count())
                .max()
                .unwrap_or(0)
        })
        .collect();
    let mut text =
        format!("{} ({} students)\n", chapter.package, students.len());
    for row in &table {
        let cells: Vec<String> = row
            .iter()
            .zip(&widths)
            .map(|(cell, w)| format!("{cell:w$}"))
            .collect();
        let _ = writeln!(text, "  {}", cells.join("  ").trim_end());
    }
    text
}

/// Chapter 7's tests read `../shared/meshes` beside the workspace: the
/// scratch workspace gets a link to the instructor's, if there is one
/// (returned, for the sandbox to show it).
fn link_shared(root: &Path, scratch: &Path) -> Vec<PathBuf> {
    let shared = root.join("..").join("shared");
    let Ok(shared) = shared.canonicalize() else {
        return Vec::new();
    };
    #[cfg(unix)]
    let _ = std::os::unix::fs::symlink(&shared, scratch.join("shared"));
    vec![shared]
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::test_files::{folder_with, names};

    #[test]
    fn exercise_files_are_taken_from_either_place() {
        let dir = folder_with(&[
            "exercise/ray_plane.rs",
            "ray_plane.rs",
            "answers.toml",
            "inside_polygon.rs",
            "notes.txt",
            "exercise/other.rs",
        ]);
        let student = dir.path();
        let found = submission(
            student,
            &names(&["ray_plane", "inside_polygon", "missing"]),
        );
        assert_eq!(
            found.files,
            BTreeMap::from([
                (
                    "inside_polygon".to_string(),
                    student.join("inside_polygon.rs")
                ),
                (
                    "ray_plane".to_string(),
                    student.join("exercise/ray_plane.rs")
                ),
            ])
        );
        assert_eq!(found.answers, Some(student.join("answers.toml")));
        assert_eq!(
            found.ignored,
            ["exercise/other.rs", "notes.txt", "ray_plane.rs"]
        );
    }

    #[test]
    fn submissions_must_be_a_folder_of_folders() {
        let dir = tempfile::tempdir().unwrap();
        let error = students(&dir.path().join("nope")).unwrap_err().to_string();
        assert!(
            error.ends_with(
                "nope: not a folder of submissions (one folder per student)"
            ),
            "{error}"
        );
        fs::write(dir.path().join("readme.txt"), "").unwrap();
        let error = students(dir.path()).unwrap_err().to_string();
        assert!(error.contains("no student folders"), "{error}");
        for name in ["zoe", "adam", ".hidden"] {
            fs::create_dir(dir.path().join(name)).unwrap();
        }
        let (found, ignored) = students(dir.path()).unwrap();
        let found: Vec<&str> = found.iter().map(|(n, _)| n.as_str()).collect();
        assert_eq!(found, ["adam", "zoe"]);
        let ignored: Vec<&str> =
            ignored.iter().map(|i| i.file.as_str()).collect();
        assert_eq!(ignored, [".hidden", "readme.txt"]);
    }

    #[test]
    fn the_table_is_csv_with_a_header() {
        let rows = [Row {
            student: "ann".into(),
            exercise: "ray_plane".into(),
            verdict: "failed".into(),
            message: "t (tests/x.rs:3): expected `a, b`, got \"c\"".into(),
        }];
        assert_eq!(
            csv_table(&rows).unwrap(),
            "student,exercise,verdict,message\n\
             ann,ray_plane,failed,\"t (tests/x.rs:3): expected `a, b`, got \"\"c\"\"\"\n"
        );
        assert_eq!(
            csv_table(&[]).unwrap(),
            "student,exercise,verdict,message\n"
        );
    }
}
