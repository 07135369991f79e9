//! `raystep grade` end to end on chapter 1 (the smallest): five fake
//! submissions, each gets its verdicts, and the instructor's workspace is
//! left as it was.
//!
//! The nested cargo builds in the outer target folder (as
//! `tests/check.rs` does), so only the scratch copy's own crates compile.

use std::collections::BTreeMap;
use std::fs;
use std::path::{Path, PathBuf};
use std::process::Command;

mod common;
use common::{outer_target, read_json, workspace};

const CHAPTER: &str = "chapters/ch01-implicit-lines-planes";

/// The reference module `src/<exercise>.rs` of chapter 1.
fn reference(exercise: &str) -> String {
    fs::read_to_string(workspace().join(format!("{CHAPTER}/src/{exercise}.rs")))
        .unwrap()
}

/// `text` with `from` replaced by `to` once; `from` must be in it. (Short
/// fragments, never a whole line of the reference: `tests/student_edition.rs`
/// looks for those in the student edition, which holds this file.)
fn edited(text: &str, from: &str, to: &str) -> String {
    assert!(text.contains(from), "{from:?} is not in the reference");
    text.replacen(from, to, 1)
}

/// Chapter 1's first exercise, every function calling `forge()`.
const FORGED_API: &str = "use crate::{Degenerate, Line2};
use raystep_core::DVec2;
pub fn rotate90(_: DVec2) -> DVec2 {
    forge()
}
impl Line2 {
    pub fn through(_: DVec2, _: DVec2) -> Result<Line2, Degenerate> {
        forge()
    }
    pub fn eval(&self, _: DVec2) -> f64 {
        forge()
    }
}
";

/// Writes `files` (relative path → text) into `dir`.
fn write_all(dir: &Path, files: &[(&str, String)]) {
    for (path, text) in files {
        let path = dir.join(path);
        fs::create_dir_all(path.parent().unwrap()).unwrap();
        fs::write(path, text).unwrap();
    }
}

/// The text of every file below `dir`, by path.
fn snapshot_of(dir: &Path) -> BTreeMap<PathBuf, Vec<u8>> {
    let mut files = BTreeMap::new();
    for entry in fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        if path.is_dir() {
            files.extend(snapshot_of(&path));
        } else {
            files.insert(path.clone(), fs::read(&path).unwrap());
        }
    }
    files
}

#[test]
fn each_submission_gets_its_verdicts() {
    let root = Path::new(env!("CARGO_TARGET_TMPDIR")).join("grade");
    if root.exists() {
        fs::remove_dir_all(&root).unwrap();
    }
    let submissions = root.join("submissions");
    let line = reference("line_through_points");
    let plane = reference("plane_through_points");
    // Every student but two hands in the reference's plane and a line of
    // their own, both in exercise/.
    let with_plane = |student: &str, line: String| {
        write_all(
            &submissions.join(student),
            &[
                ("exercise/line_through_points.rs", line),
                ("exercise/plane_through_points.rs", plane.clone()),
            ],
        );
    };
    // right: the reference bodies, one in exercise/, one beside it.
    write_all(
        &submissions.join("right"),
        &[
            ("exercise/line_through_points.rs", line.clone()),
            ("plane_through_points.rs", plane.clone()),
            // The paper questions: a choice and a number, both right.
            ("answers.toml", "q1 = \"Negative\"\nq2 = -0.82\n".into()),
        ],
    );
    // wrong: the line's constant c with its minus sign dropped.
    with_plane("wrong", edited(&line, "c = -normal", "c = normal"));
    write_all(
        &submissions.join("wrong"),
        &[
            ("notes.txt", "my notes".to_string()),
            // A wrong choice, and a number 10 % off.
            (
                "exercise/answers.toml",
                "q1 = \"positive\"\nq2 = -0.9\n".into(),
            ),
        ],
    );
    // looping answers one question, and leaves the other as the stub has it.
    write_all(
        &submissions.join("looping"),
        &[("answers.toml", "q1 = \"todo\"\nq2 = -0.81\n".into())],
    );
    // looping: the line's eval never returns.
    with_plane(
        "looping",
        edited(&line, "+ self.c", "+ { let c: f64 = loop {}; c }"),
    );
    // missing: only the plane.
    write_all(
        &submissions.join("missing"),
        &[("exercise/plane_through_points.rs", plane.clone())],
    );
    // Tricks (issue: "grades no submission can forge").
    let instructor_line = workspace()
        .join(CHAPTER)
        .join("src/line_through_points.rs")
        .canonicalize()
        .unwrap();
    // path: the reference module itself, by #[path].
    with_plane(
        "path",
        "#[path = \"../src/line_through_points.rs\"]\nmod reference;\n\
             pub use reference::*;\n"
            .to_string(),
    );
    // include: the instructor's reference by absolute path.
    with_plane(
        "include",
        format!("include!({:?});\n", instructor_line.display().to_string()),
    );
    // forger: on its first call, prints libtest's lines for every test of
    // the binary it runs in, then ends the process with success.
    let forge = r#"
fn forge() -> ! {
    let me = std::env::current_exe().unwrap();
    let list = std::process::Command::new(&me)
        .args(["--list", "--format", "terse"])
        .output()
        .unwrap();
    let list = String::from_utf8_lossy(&list.stdout).into_owned();
    let names: Vec<&str> =
        list.lines().filter_map(|l| l.strip_suffix(": test")).collect();
    println!("\nrunning {} tests", names.len());
    for name in &names {
        println!("test {name} ... ok");
    }
    println!("\ntest result: ok. {} passed; 0 failed; 0 ignored; 0 measured; 0 filtered out; finished in 0.01s\n", names.len());
    std::process::exit(0)
}
"#;
    with_plane("forger", format!("{FORGED_API}{forge}"));
    // quiet forger: the same lines with nothing the rules refuse (names
    // known in advance), then a crash by an endless recursion.
    let quiet = r#"
fn forge() -> ! {
    // Around libtest's capture of println!: to the real stdout.
    use std::io::Write as _;
    let mut out = std::io::stdout();
    for name in ["rotate90_turns_counter_clockwise", "line_table"] {
        let _ = writeln!(out, "test {name} ... ok");
    }
    let _ = writeln!(out, "\ntest result: ok. 2 passed; 0 failed; 0 ignored; 0 measured; 0 filtered out; finished in 0.01s\n");
    let depth = deeper(1.0);
    panic!("{depth}")
}
fn deeper(x: f64) -> f64 {
    deeper(x + 1.0) * x
}
"#;
    with_plane("quiet-forger", format!("{FORGED_API}{quiet}"));
    // oracle: right on every input a test looks at (the snapshots' rows,
    // the property tests' ranges up to 10⁶ and the huge degenerate rows),
    // wrong between.
    with_plane(
        "oracle",
        edited(
            &line,
            "-normal.dot(p0);",
            "-normal.dot(p0) * if (1e8..1e100).contains(&p0.abs().max_element()) { 1.0001 } else { 1.0 };",
        ),
    );
    // hog: rotate90 records every call without end (issue 33: a walk that
    // never ends while recording every visit asked for 6 GiB).
    with_plane(
        "hog",
        edited(
            &line,
            "-> DVec2 {",
            "-> DVec2 {\n    let mut visits = vec![v];\n    while visits.len() < usize::MAX {\n        visits.push(v);\n    }",
        ),
    );
    // peek: right, but looks for the instructor's reference by absolute
    // path (`Path::exists` reads no file, so the rules let it through): in
    // the sandbox it is not there. The probe itself works: `/usr/bin` is.
    let peek = format!(
        "fn peek() {{\n    assert!(std::path::Path::new(\"/usr/bin\").exists(), \"the probe is broken\");\n    let file = std::path::Path::new({:?});\n    assert!(!file.exists(), \"I could see {{}}\", file.display());\n}}\n",
        instructor_line.display().to_string()
    );
    with_plane(
        "peek",
        edited(&line, "-> DVec2 {", "-> DVec2 {\n    peek();") + &peek,
    );
    // flood: rotate90 prints without end, past libtest's capture.
    with_plane(
        "flood",
        edited(
            &line,
            "-> DVec2 {",
            "-> DVec2 {\n    use std::io::Write as _;\n    while writeln!(std::io::stdout(), \"{v}\").is_ok() {}",
        ),
    );
    // broken: the line's file does not compile.
    with_plane("broken", edited(&line, "(-v.y, v.x)", "(-v.y, v.x, 0)"));

    let instructor = workspace().join(CHAPTER);
    let before = (
        snapshot_of(&instructor.join("exercise")),
        snapshot_of(&instructor.join("tests")),
    );
    let csv = root.join("grades.csv");
    let json = root.join("grades.json");
    let out = Command::new(env!("CARGO_BIN_EXE_raystep"))
        .args(["grade", submissions.to_str().unwrap(), "--chapter", "ch01"])
        .args(["--out", csv.to_str().unwrap()])
        .args(["--json", json.to_str().unwrap()])
        .args(["--timeout", "5"])
        .args(["--target-dir", outer_target().to_str().unwrap()])
        // A fixed seed: the same held-out cases on every run of this test.
        .args(["--held-out-seed", "2026"])
        // Two at a time: one builds while the other's tests run.
        .args(["--jobs", "2"])
        // Inside bubblewrap where it is installed (CI installs it).
        .args(["--sandbox", if sandboxed() { "required" } else { "off" }])
        .current_dir(workspace())
        .output()
        .expect("raystep runs");
    let stdout = String::from_utf8_lossy(&out.stdout);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "{stdout}{stderr}");

    let table = read_json(&json);
    let rows = table["rows"].as_array().unwrap();
    let verdict = |student: &str, exercise: &str| -> (String, String) {
        let row = rows
            .iter()
            .find(|r| r["student"] == student && r["exercise"] == exercise)
            .unwrap_or_else(|| {
                panic!("no row {student} {exercise}:\n{table:#}")
            });
        (
            row["verdict"].as_str().unwrap().to_string(),
            row["message"].as_str().unwrap().to_string(),
        )
    };
    let context = format!("{table:#}\n{stdout}{stderr}");
    let plane = "plane_through_points";
    let line = "line_through_points";
    for student in [
        "right",
        "wrong",
        "looping",
        "hog",
        "flood",
        "peek",
        "missing",
        "broken",
        "path",
        "include",
        "forger",
        "quiet-forger",
        "oracle",
    ] {
        assert_eq!(verdict(student, plane).0, "passed", "{student}: {context}");
    }
    assert_eq!(verdict("right", line).0, "passed", "{context}");

    // The line's verdict of `student` is of `kind`: its message.
    let line_verdict = |student: &str, kind: &str| -> String {
        let (got, message) = verdict(student, line);
        assert_eq!(got, kind, "{student}: {context}");
        message
    };

    let message = line_verdict("wrong", "failed");
    assert!(
        message.contains("(tests/line_through_points.rs:"),
        "the failing test's location: {context}"
    );

    let message = line_verdict("looping", "timed out");
    assert!(message.starts_with("timed out after 5 s"), "{context}");

    let message = line_verdict("hog", "failed");
    assert!(
        message.starts_with(
            "out of memory (limit 2 GiB, --memory) while running "
        ),
        "{context}"
    );
    let message = line_verdict("flood", "failed");
    assert!(
        message.starts_with(
            "printed more than 8 MiB (limit, --output) while running "
        ),
        "{context}"
    );
    if sandboxed() {
        // Nothing outside the scratch copy is there to be seen.
        assert_eq!(line_verdict("peek", "passed"), "", "{context}");
    } else {
        // Without the sandbox the rules alone do not stop it.
        let message = line_verdict("peek", "failed");
        assert!(message.contains("I could see "), "{context}");
    }

    assert_eq!(
        line_verdict("missing", "missing file"),
        "no exercise/line_through_points.rs (the stub was used)",
        "{context}"
    );

    let message = line_verdict("broken", "does not compile");
    assert!(
        message.contains("(at exercise/line_through_points.rs:"),
        "{context}"
    );

    // Each trick is refused or fails, never passes.
    for (student, what) in [("path", "`#[path]`"), ("include", "`include!`")] {
        let message = line_verdict(student, "refused");
        assert!(
            message.starts_with("exercise/line_through_points.rs:1:")
                && message.contains(what)
                && message.ends_with("(the stub was used)"),
            "{student}: {context}"
        );
    }
    let message = line_verdict("forger", "refused");
    assert!(message.contains("`env`"), "{context}");
    let message = line_verdict("quiet-forger", "failed");
    assert!(message.contains("crashed"), "{context}");
    // The oracle passes every test; only the held-out cases, drawn from a
    // seed it could not know, find it out.
    let message = line_verdict("oracle", "failed");
    assert!(
        message.starts_with("held-out case ")
            && message.contains(" of 64 (rotate90(")
            && message
                .ends_with(": expected `c 9.246647e23`, got `c 9.247571e23`"),
        "{context}"
    );
    assert_eq!(table["held_out_seed"], 2026, "{context}");

    // The paper questions: right, wrong, off by more than the step,
    // untouched, and not handed in.
    for question in ["q1", "q2"] {
        assert_eq!(verdict("right", question).0, "passed", "{context}");
        assert_eq!(
            verdict("missing", question),
            (
                "missing file".to_string(),
                "no exercise/answers.toml (not attempted)".to_string()
            ),
            "{context}"
        );
    }
    assert_eq!(
        verdict("wrong", "q1"),
        (
            "failed".to_string(),
            "question 1, expected \"negative\" (your answer \"positive\")"
                .to_string()
        ),
        "{context}"
    );
    assert_eq!(
        verdict("wrong", "q2"),
        (
            "failed".to_string(),
            "question 2, f(O) expected about -0.82 (your -0.9 is off by 10 %)"
                .to_string()
        ),
        "{context}"
    );
    assert_eq!(verdict("looping", "q1").0, "not attempted", "{context}");
    assert_eq!(verdict("looping", "q2").0, "passed", "{context}");

    // Students in name order, four rows each (two exercises, two paper
    // questions); the CSV holds the same table.
    let students: Vec<&str> = rows
        .iter()
        .map(|r| r["student"].as_str().unwrap())
        .collect();
    let names = [
        "broken",
        "flood",
        "forger",
        "hog",
        "include",
        "looping",
        "missing",
        "oracle",
        "path",
        "peek",
        "quiet-forger",
        "right",
        "wrong",
    ];
    let expected: Vec<&str> = names.iter().flat_map(|n| [*n; 4]).collect();
    assert_eq!(students, expected);
    let exercises: Vec<&str> = rows[..4]
        .iter()
        .map(|r| r["exercise"].as_str().unwrap())
        .collect();
    assert_eq!(exercises, [line, plane, "q1", "q2"]);
    let csv_text = fs::read_to_string(&csv).unwrap();
    assert!(csv_text.starts_with("student,exercise,verdict,message\n"));
    assert_eq!(csv_text.lines().count(), 53, "{csv_text}");
    assert_eq!(
        table["ignored"],
        serde_json::json!([{"student": "wrong", "file": "notes.txt"}])
    );
    assert!(stdout.contains("ignored: wrong/notes.txt"), "{stdout}");

    // Nothing a student wrote is still running, and the scratch copy is gone.
    let scratch = stderr
        .lines()
        .find_map(|l| l.strip_prefix("copying the workspace to "))
        .and_then(|copy| Path::new(copy.trim_end_matches('…')).parent())
        .expect("the scratch copy is named");
    assert!(!scratch.exists(), "{}", scratch.display());
    #[cfg(target_os = "linux")]
    assert_eq!(processes_in(scratch), Vec::<String>::new());

    // The instructor's exercise stubs and snapshots are untouched.
    let after = (
        snapshot_of(&instructor.join("exercise")),
        snapshot_of(&instructor.join("tests")),
    );
    assert!(before == after, "grade changed the instructor's chapter");
}

/// Whether bubblewrap is installed here: then every grading test runs in
/// it, with `--sandbox required`.
fn sandboxed() -> bool {
    std::env::var_os("PATH").is_some_and(|path| {
        std::env::split_paths(&path).any(|dir| dir.join("bwrap").is_file())
    })
}

/// A folder that does not exist is an error naming it.
#[test]
fn a_missing_submissions_folder_is_named() {
    let missing = Path::new(env!("CARGO_TARGET_TMPDIR")).join("no-such-folder");
    let out = Command::new(env!("CARGO_BIN_EXE_raystep"))
        .args(["grade", missing.to_str().unwrap(), "--chapter", "ch01"])
        .current_dir(workspace())
        .output()
        .expect("raystep runs");
    assert!(!out.status.success());
    // The path as the user would type it: relative to the current folder.
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        stderr.starts_with("error: ")
            && stderr.trim_end().ends_with(
                "tmp/no-such-folder: not a folder of submissions (one folder \
                 per student)"
            ),
        "{stderr}"
    );
    assert!(!workspace().join("grades.csv").exists());
}

/// `raystep grade` with `args` on `submissions`, writing `csv`: spawned,
/// its output piped.
fn grade(submissions: &Path, csv: &Path, args: &[&str]) -> Command {
    let mut command = Command::new(env!("CARGO_BIN_EXE_raystep"));
    command
        .args(["grade", submissions.to_str().unwrap(), "--chapter", "ch01"])
        .args(["--out", csv.to_str().unwrap()])
        .args(["--timeout", "5"])
        .args(["--target-dir", outer_target().to_str().unwrap()])
        .args(["--held-out-seed", "2026"])
        .args(["--sandbox", if sandboxed() { "required" } else { "off" }])
        .args(args)
        .current_dir(workspace());
    command
}

/// The processes whose command line or folder names `path`.
#[cfg(target_os = "linux")]
fn processes_in(path: &Path) -> Vec<String> {
    let needle = path.to_string_lossy().into_owned();
    fs::read_dir("/proc")
        .unwrap()
        .flatten()
        .filter(|entry| {
            entry.file_name().to_string_lossy().parse::<u32>().is_ok()
        })
        .filter_map(|entry| {
            let cmdline = fs::read(entry.path().join("cmdline")).ok()?;
            let cmdline = String::from_utf8_lossy(&cmdline).replace('\0', " ");
            let cwd =
                fs::read_link(entry.path().join("cwd")).unwrap_or_default();
            (cmdline.contains(&needle) || cwd.starts_with(path))
                .then_some(cmdline)
        })
        .collect()
}

/// Grading two students at once gives the table of one at a time; Ctrl-C
/// ends a run with nothing left running and its scratch copy removed,
/// keeping the students it had graded; `--resume` grades only the others,
/// into the same table.
#[cfg(target_os = "linux")]
#[test]
fn two_at_once_or_interrupted_and_resumed_give_the_same_table() {
    use std::io::{BufRead, BufReader};
    let root = Path::new(env!("CARGO_TARGET_TMPDIR")).join("grade-jobs");
    if root.exists() {
        fs::remove_dir_all(&root).unwrap();
    }
    let submissions = root.join("submissions");
    let line = reference("line_through_points");
    let plane = reference("plane_through_points");
    for (student, line) in [
        ("ada", line.clone()),
        ("bob", edited(&line, "c = -normal", "c = normal")),
        ("cy", line),
    ] {
        write_all(
            &submissions.join(student),
            &[
                ("line_through_points.rs", line),
                ("plane_through_points.rs", plane.clone()),
            ],
        );
    }
    let run = |csv: &Path, args: &[&str]| {
        let out = grade(&submissions, csv, args).output().unwrap();
        let stderr = String::from_utf8_lossy(&out.stderr).into_owned();
        assert!(out.status.success(), "{:?}\n{stderr}", out.status);
        (fs::read_to_string(csv).unwrap(), stderr)
    };
    let (one, _) = run(&root.join("one.csv"), &["--jobs", "1"]);
    assert_eq!(one.lines().count(), 1 + 3 * 4, "{one}");
    assert!(one.contains("\nbob,line_through_points,failed,"), "{one}");
    let (two, stderr) = run(&root.join("two.csv"), &["--jobs", "2"]);
    assert!(stderr.contains(", 2 at once"), "{stderr}");
    assert_eq!(two, one);

    // Interrupted once the first student's rows are kept.
    let csv = root.join("resumed.csv");
    let partial = root.join("resumed.csv.partial");
    let mut child = grade(&submissions, &csv, &["--jobs", "1"])
        .stderr(std::process::Stdio::piped())
        .stdout(std::process::Stdio::null())
        .spawn()
        .unwrap();
    let mut stderr = BufReader::new(child.stderr.take().unwrap());
    let mut scratch = None;
    let mut seen = String::new();
    let mut line = String::new();
    while stderr.read_line(&mut line).unwrap() > 0 {
        seen.push_str(&line);
        if let Some(copy) = line.strip_prefix("copying the workspace to ") {
            let copy = Path::new(copy.trim_end().trim_end_matches('…'));
            scratch = copy.parent().map(Path::to_path_buf);
        }
        if line.starts_with("[2/3]") {
            break;
        }
        line.clear();
    }
    let scratch =
        scratch.unwrap_or_else(|| panic!("no scratch copy named:\n{seen}"));
    let kept = fs::read_to_string(&partial).unwrap();
    assert_eq!(kept.lines().count(), 2, "the run and ada's rows:\n{kept}");
    // Ctrl-C, as the terminal sends it.
    let killed = Command::new("kill")
        .args(["-INT", &child.id().to_string()])
        .status()
        .unwrap();
    assert!(killed.success());
    let status = child.wait().unwrap();
    std::io::Read::read_to_string(stderr.get_mut(), &mut seen).unwrap();
    {
        use std::os::unix::process::ExitStatusExt;
        assert_eq!(status.signal(), Some(2), "{status:?}\n{seen}");
    }
    assert!(!scratch.exists(), "{} was left behind", scratch.display());
    let left = processes_in(&scratch);
    assert!(left.is_empty(), "still running: {left:?}");
    assert!(!csv.exists());

    let (resumed, stderr) = run(&csv, &["--jobs", "2", "--resume"]);
    assert!(
        stderr.contains("resuming: 1 students graded already, 2 to go"),
        "{stderr}"
    );
    assert_eq!(resumed, one);
    assert!(
        !partial.exists(),
        "the kept rows are removed once the table is written"
    );
}
