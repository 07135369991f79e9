//! `raystep student-edition` end to end: one export of this workspace,
//! shared by the tests of this file, holds no reference solution, and
//! `raystep check ch01` in it says every exercise is not attempted.
//!
//! The nested cargo of `check` builds in the outer target folder (as
//! `tests/check.rs` does), so only the export's own crates are compiled.

use std::collections::BTreeSet;
use std::fs;
use std::hash::{DefaultHasher, Hash, Hasher};
use std::path::{Path, PathBuf};
use std::process::Command;
use std::sync::{Mutex, MutexGuard, OnceLock};

mod common;
use common::{outer_target, workspace};

/// Runs `raystep <args>` in `dir`: (success, stdout, stderr).
fn raystep(args: &[&str], dir: &Path) -> (bool, String, String) {
    raystep_with(args, dir, &[])
}

/// [`raystep`] with these environment variables set.
fn raystep_with(
    args: &[&str], dir: &Path, env: &[(&str, &str)],
) -> (bool, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_raystep"))
        .args(args)
        .current_dir(dir)
        .env("RAYSTEP_CHECK_TARGET_DIR", outer_target())
        .envs(env.iter().copied())
        .output()
        .expect("raystep runs");
    (
        out.status.success(),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

/// Held by the tests that read the export whole or change files in it.
fn exclusive() -> MutexGuard<'static, ()> {
    static LOCK: Mutex<()> = Mutex::new(());
    LOCK.lock().unwrap_or_else(|poisoned| poisoned.into_inner())
}

/// The student edition of this workspace, written once per run into the
/// system's temporary folder (a name of its own for each workspace).
///
/// Not below the target folder: cargo names the artifacts of a path
/// package by its path inside its workspace, so the export's crates and
/// this workspace's share artifacts; cargo would remember an export inside
/// the target folder by a path relative to it, and later builds of this
/// workspace would judge freshness by the export's files.
fn export() -> &'static Path {
    static EXPORT: OnceLock<PathBuf> = OnceLock::new();
    EXPORT.get_or_init(|| {
        let mut hasher = DefaultHasher::new();
        workspace().hash(&mut hasher);
        let out = std::env::temp_dir()
            .join(format!("raystep-student-edition-{:016x}", hasher.finish()));
        if out.exists() {
            fs::remove_dir_all(&out).unwrap();
        }
        let (ok, stdout, stderr) =
            raystep(&["student-edition", out.to_str().unwrap()], &workspace());
        assert!(ok, "student-edition failed:\n{stdout}{stderr}");
        assert!(stdout.contains("one git commit"), "{stdout}");
        // One commit, everything in it (checked before any test here
        // changes a file).
        let git = |args: &[&str]| {
            let out = Command::new("git")
                .args(args)
                .current_dir(&out)
                .output()
                .expect("git runs");
            assert!(out.status.success(), "git {args:?}");
            String::from_utf8_lossy(&out.stdout).trim().to_string()
        };
        assert_eq!(git(&["rev-list", "--count", "--all"]), "1");
        assert_eq!(git(&["status", "--porcelain"]), "");
        out
    })
}

/// Is the entry at `relative` left out of the reference workspace's files:
/// build output, git, the book's HTML, scratch output, insta's proposals.
fn skipped(relative: &Path) -> bool {
    let name = relative.file_name().unwrap().to_string_lossy();
    let path = relative.to_string_lossy().replace('\\', "/");
    ["target", ".git", "test-output"].contains(&name.as_ref())
        || ["book/book", "out"].contains(&path.as_str())
        || name.ends_with(".snap.new")
        || name.ends_with(".pending-snap")
}

/// Every text file below `root` (relative path → text), [`skipped`]
/// entries left out.
fn text_files(root: &Path) -> Vec<(PathBuf, String)> {
    let mut files = Vec::new();
    let mut folders = vec![PathBuf::new()];
    while let Some(folder) = folders.pop() {
        for entry in fs::read_dir(root.join(&folder)).unwrap() {
            let entry = entry.unwrap();
            let relative = folder.join(entry.file_name());
            if skipped(&relative) {
                continue;
            }
            if entry.file_type().unwrap().is_dir() {
                folders.push(relative);
            } else if let Ok(text) = fs::read_to_string(entry.path()) {
                files.push((relative, text));
            }
        }
    }
    files.sort();
    files
}

/// Runs of whitespace as one space.
fn squeezed(text: &str) -> String {
    text.split_whitespace().collect::<Vec<_>>().join(" ")
}

/// (chapter folder, exercise) for every exercise of every chapter.
fn exercises() -> Vec<(String, String)> {
    let mut all = Vec::new();
    for chapter in fs::read_dir(workspace().join("chapters")).unwrap() {
        let chapter = chapter.unwrap().path();
        let Ok(stubs) = fs::read_dir(chapter.join("exercise")) else {
            continue;
        };
        for stub in stubs {
            let stub = stub.unwrap().path();
            if stub.extension().is_some_and(|x| x == "rs") {
                all.push((
                    chapter.file_name().unwrap().to_string_lossy().into_owned(),
                    stub.file_stem().unwrap().to_string_lossy().into_owned(),
                ));
            }
        }
    }
    all.sort();
    all
}

/// No reference solution is anywhere in the export. For every exercise
/// module `chapters/<ch>/src/<e>.rs` of this workspace:
///
/// * its *reference lines* are its lines that are not (trimmed) a line of
///   the stub `chapters/<ch>/exercise/<e>.rs`: the bodies the student
///   writes;
/// * each run of consecutive reference lines, whitespace squeezed, of at
///   least 20 characters, that is not in the (squeezed) text of the stub
///   or of any other file of this workspace (sources and book, no build
///   output), is in no file of the export (squeezed too);
/// * each *distinctive line*, a trimmed reference line of at least 20
///   characters that is not in the stub, not a comment or `use`, and not
///   one of the [`COMMON_LINES`] (idioms, steps taught again, each with its
///   reason), is a line of no file of the export, wherever else it stands
///   in this workspace (a builder's private copy of an exercise, a
///   shared type's method that is an exercise's answer, a figure that
///   computes the answer again); every module has at least one.
///
/// Files of the export are every text file but its `.git`; its git history
/// is one commit ([`export`] checks), so no earlier version of a file is in
/// it.
#[test]
fn no_reference_body_is_in_the_export() {
    let export = export();
    let _only_me = exclusive();
    let reference = text_files(&workspace());
    let exported = text_files(export);
    let exported_squeezed: Vec<String> =
        exported.iter().map(|(_, text)| squeezed(text)).collect();
    let mut leaks = Vec::new();
    // grade's held-out programs (their generators work answers out) are
    // not handed out.
    let held_out: Vec<&PathBuf> = exported
        .iter()
        .map(|(path, _)| path)
        .filter(|path| path.to_string_lossy().ends_with("_held_out.rs"))
        .collect();
    assert!(held_out.is_empty(), "{held_out:?}");
    // The paper questions are handed out without their answers and worked
    // solutions (digests stand in for them), every chapter's.
    let question_files: Vec<&(PathBuf, String)> = exported
        .iter()
        .filter(|(path, _)| path.ends_with("questions.toml"))
        .collect();
    assert_eq!(question_files.len(), 10);
    for (path, text) in question_files {
        for gone in ["\nanswer =", "\nworked ="] {
            assert!(!text.contains(gone), "{}: {gone}", path.display());
        }
        assert!(text.contains("\ndigests = ["), "{}", path.display());
    }
    for (chapter, exercise) in exercises() {
        // The reference module: the one `src/**/<exercise>.rs`.
        let src = PathBuf::from(format!("chapters/{chapter}/src"));
        let name = format!("{exercise}.rs");
        let modules: Vec<&PathBuf> = reference
            .iter()
            .map(|(p, _)| p)
            .filter(|p| p.starts_with(&src) && p.ends_with(&name))
            .collect();
        assert_eq!(modules.len(), 1, "{chapter}: {modules:?}");
        let module = modules[0].clone();
        let stub_path =
            PathBuf::from(format!("chapters/{chapter}/exercise/{exercise}.rs"));
        let text = |path: &Path| {
            reference
                .iter()
                .find(|(p, _)| p == path)
                .map(|(_, t)| t.clone())
                .unwrap_or_else(|| {
                    panic!("{} is not in the workspace", path.display())
                })
        };
        // The stub as committed (what the edition exports, whatever the
        // working tree holds now).
        let committed = Command::new("git")
            .args(["show", &format!("HEAD:./{}", stub_path.display())])
            .current_dir(workspace())
            .output()
            .expect("git runs");
        let stub = if committed.status.success() {
            String::from_utf8(committed.stdout).unwrap()
        } else {
            text(&stub_path)
        };
        let solution = text(&module);
        // The export's module is the stub, byte for byte.
        assert_eq!(
            fs::read_to_string(export.join(&module)).unwrap(),
            stub,
            "{}",
            module.display()
        );
        let stub_lines: BTreeSet<&str> = stub.lines().map(str::trim).collect();
        let elsewhere: Vec<&str> = reference
            .iter()
            .filter(|(p, _)| *p != module)
            .map(|(_, t)| t.as_str())
            .collect();
        let elsewhere_squeezed: Vec<String> =
            elsewhere.iter().map(|t| squeezed(t)).collect();

        // Runs of consecutive reference lines.
        let mut runs: Vec<Vec<&str>> = vec![Vec::new()];
        for line in solution.lines().map(str::trim) {
            if stub_lines.contains(line) {
                runs.push(Vec::new());
            } else {
                runs.last_mut().unwrap().push(line);
            }
        }
        for run in runs {
            let run = squeezed(&run.join("\n"));
            if run.len() < 20
                || elsewhere_squeezed.iter().any(|t| t.contains(&run))
            {
                continue;
            }
            for ((path, _), text) in exported.iter().zip(&exported_squeezed) {
                assert!(
                    !text.contains(&run),
                    "{} holds reference code of {}: {run}",
                    path.display(),
                    module.display()
                );
            }
        }

        // Every line the student writes that is not a common idiom (or a
        // step another chapter teaches again, listed with its reason).
        let distinctive: Vec<&str> = solution
            .lines()
            .map(str::trim)
            .filter(|line| {
                line.chars().count() >= 20
                    && !stub_lines.contains(line)
                    && !line.starts_with("//")
                    && !line.starts_with("use ")
            })
            .filter(|line| !COMMON_LINES.iter().any(|(l, _)| l == line))
            .collect();
        let slashed = module.to_string_lossy().replace('\\', "/");
        assert!(
            !distinctive.is_empty(),
            "{slashed}: no line of the reference that is not a common one, so \
             nothing distinctive to look for in the export"
        );
        for line in distinctive {
            for (path, text) in &exported {
                if text.lines().any(|l| l.trim() == line) {
                    leaks.push(format!(
                        "{} holds a line of the reference {slashed}: {line}",
                        path.display()
                    ));
                }
            }
        }
    }
    assert!(
        leaks.is_empty(),
        "{} reference lines in the export (remove the copy, call the \
         exercise, or list a line that is truly common in COMMON_LINES with \
         its reason):\n{}",
        leaks.len(),
        leaks.join("\n")
    );
}

/// Lines of a reference solution that may stand elsewhere in the student
/// edition: idioms any code of the lecture writes, and steps another
/// chapter teaches again on its own, each with its reason.
const COMMON_LINES: &[(&str, &str)] = &[
    // Parameter lists (signatures keep their parameters on one line): the
    // same inputs as other functions of the lecture, no answer.
    (
        "v: &[DVec3; 3], ray: &Ray, interval: Interval,",
        "every ray–triangle test of chapter 8 takes a triangle, a ray, an interval",
    ),
    (
        "lattice: &Lattice, ray: &Ray, interval: Interval,",
        "every walk of chapter 9's lattice takes these, as its tests do",
    ),
    // Idioms: any closest-hit loop, any ray or quadric, any struct literal.
    (
        "let mut closest = None;",
        "every closest-hit loop starts so",
    ),
    (
        "let mut interval = interval;",
        "every closest-hit loop shrinks it",
    ),
    (
        "closest = Some((index, hit));",
        "every closest-hit loop keeps it",
    ),
    (
        "let mut test = |index: u32, interval: &mut Interval| {",
        "the grid's and the kd-tree's leaf loops test a candidate so",
    ),
    ("test(index, &mut interval);", "the same leaf loops"),
    ("let d = ray.direction;", "a name for the direction"),
    (
        "let d = ray.direction[axis];",
        "a name for one of its components",
    ),
    ("let point = ray.at(t);", "every shape's hit point"),
    ("if discriminant < 0.0 {", "every quadratic's miss"),
    ("interval.contains(t).then_some(t)", "every hit ends so"),
    (
        "let normal = hit.facing(ray.direction);",
        "chapter 3's API, called",
    ),
    (
        "let reflected = Ray::new(",
        "every reflected ray is a new ray",
    ),
    (
        "offset_scale_aware(hit.point, normal),",
        "chapter 4's offset, called by every secondary ray",
    ),
    ("center: DVec3::ZERO,", "a struct literal"),
    ("return BoundingSphere {", "a struct literal"),
    ("BoundingSphere { center, radius }", "a struct literal"),
    (
        "near_until: t_plane,",
        "a field of chapter 10's Step a test expects",
    ),
    // Steps another part of the lecture teaches again, on its own terms.
    (
        "let q = b + b.signum() * discriminant.sqrt();",
        "chapter 8's root solver for every quadric teaches the stable \
         quadratic again, after chapter 3's sphere",
    ),
    (
        "let cos_phi = (1.0 - sin2_phi).sqrt();",
        "the exact Fresnel split of chapter 6 needs cos φ itself",
    ),
    (
        "if sin2_phi >= 1.0 {",
        "the same: total internal reflection",
    ),
    (
        "let cos_theta = cos_theta.clamp(0.0, 1.0);",
        "the same: its cos θ clamped",
    ),
    (
        "let r0 = ((n_theta - n_phi) / (n_theta + n_phi)).powi(2);",
        "the stability catalogue's textbook Schlick, which it compares \
         chapter 6's with",
    ),
    (
        "if normal.dot(light.position - hit.point) <= 0.0 {",
        "chapter 5's tracer asks whether a shadow ray is shot at all, to \
         count and draw it",
    ),
    (
        "let approach = plane.normal.dot(ray.direction);",
        "chapter 2's figure labels N·D, one call of chapter 1's API",
    ),
    (
        "let distance = plane.eval(ray.origin);",
        "the same figure labels N·P₀ + d",
    ),
    (
        "let [a, b, c] = *corners;",
        "chapter 7's figure names the corners",
    ),
    (
        "[(a, b), (b, c), (c, a)]",
        "chapter 7's figure draws the edges in both windings",
    ),
    ("[(a, c), (c, b), (b, a)]", "the same figure"),
    (
        "let (mut t0, mut t1) = (interval.min, interval.max);",
        "tests/slab.rs keeps the naive slab test the catalogue shows \
         failing (min/max ordering, no widened exit)",
    ),
    (
        "let inverse = 1.0 / ray.direction[axis];",
        "the same naive test, and the box primitive's normal",
    ),
    (
        "let kz = d.abs().max_position();",
        "tests/watertight.rs nudges a ray along the axes step 1 names (the \
         stub's TODO spells the step out)",
    ),
    (
        "let (left, right) = (p.x * q.y, p.y * q.x);",
        "the appendix's f32 leaves inline the fast edge function to decide \
         the signs they are sure of; the rest go to chapter 8's test whole",
    ),
    ("let fast = left - right;", "the same"),
    (
        "let det = e[0] + e[1] + e[2];",
        "the appendix's AVX2 triangle test sums the same edge functions",
    ),
    (
        "let (mut below, mut above) = (*node, *node);",
        "chapter 10's event sweep cuts a node in two as the exercise does",
    ),
    // Follow-up (issue 30: one walk per structure): the mesh hierarchy's
    // walk takes the nearer child first as exercise 6 does.
    (
        "while let Some((k, entry)) = stack.pop() {",
        "the mesh hierarchy's own walk (issue 30 joins the two walks)",
    ),
    ("(Some(ta), Some(tb)) if tb < ta => {", "the same walk"),
    ("(Some(ta), None) => stack.push((a, ta)),", "the same walk"),
    ("(None, Some(tb)) => stack.push((b, tb)),", "the same walk"),
];

/// A later chapter's `exercise` feature turns on the earlier chapter's, so
/// chapter 2's tests run on the student's chapter 1.
#[test]
fn exercise_features_chain_through_the_chapters() {
    let manifest = fs::read_to_string(
        export().join("chapters/ch02-plane-polygon-hits/Cargo.toml"),
    )
    .unwrap();
    assert!(
        manifest.contains("exercise = [\"ch01/exercise\"]"),
        "{manifest}"
    );
    let manifest = fs::read_to_string(
        export().join("chapters/ch01-implicit-lines-planes/Cargo.toml"),
    )
    .unwrap();
    assert!(manifest.contains("exercise = []"), "{manifest}");
}

/// The verdict line of `exercise` in a report.
fn verdict<'a>(report: &'a str, exercise: &str) -> &'a str {
    report
        .lines()
        .find_map(|l| l.trim_start().strip_prefix(&format!("{exercise} ")))
        .unwrap_or_else(|| panic!("no {exercise} in:\n{report}"))
        .trim()
        .trim_start_matches("(paper)")
        .trim_start()
        .trim_start_matches('★')
        .trim()
}

/// `raystep check ch01` in the export: every exercise is the untouched
/// stub. A wrong answer fails with the first wrong row even when the
/// user's environment asks insta to accept or pass it, and no snapshot is
/// written; one exercise that does not compile leaves the other its
/// verdict; a file that names another is refused; a snapshot changed by
/// hand is noticed (the export is a git repository).
#[test]
fn check_in_the_export() {
    let export = export();
    let _only_me = exclusive();
    let (ok, report, stderr) = raystep(&["check", "ch01", "--quiet"], export);
    let all = format!("{report}{stderr}");
    assert!(!ok, "{all}");
    for exercise in ["line_through_points", "plane_through_points"] {
        assert_eq!(verdict(&report, exercise), "not attempted", "{all}");
    }
    assert!(!report.contains("failed"), "{all}");
    assert!(!report.contains("warning"), "{all}");

    // The paper questions are asked without their answers, and judged as
    // in the instructor's workspace: untouched, right, wrong, off by more
    // than the step.
    let chapter = "chapters/ch01-implicit-lines-planes";
    let questions =
        fs::read_to_string(export.join("book/src/figures/ch01/questions.toml"))
            .unwrap();
    assert!(questions.contains("[[question]]"), "{questions}");
    for gone in ["answer =", "worked =", "negative\"\n"] {
        assert!(!questions.contains(gone), "{gone}: {questions}");
    }
    for q in ["q1", "q2"] {
        assert_eq!(verdict(&report, q), "not attempted", "{all}");
    }
    let answers = export.join(chapter).join("exercise/answers.toml");
    let answers_stub = fs::read_to_string(&answers).unwrap();
    fs::write(&answers, "q1 = \"negative\"\nq2 = -0.82\n").unwrap();
    let (ok, report, stderr) = raystep(&["check", "ch01", "--quiet"], export);
    let all = format!("{report}{stderr}");
    assert!(!ok, "{all}");
    assert_eq!(verdict(&report, "q1"), "passed", "{all}");
    assert_eq!(verdict(&report, "q2"), "passed", "{all}");
    fs::write(&answers, "q1 = \"positive\"\nq2 = -0.9\n").unwrap();
    let (_, report, stderr) = raystep(&["check", "ch01", "--quiet"], export);
    fs::write(&answers, &answers_stub).unwrap();
    let all = format!("{report}{stderr}");
    assert_eq!(
        verdict(&report, "q1"),
        "failed: question 1: \"positive\" is not the answer",
        "{all}"
    );
    assert_eq!(
        verdict(&report, "q2"),
        "failed: question 2, f(O): your -0.9 is not within 0.01 of the answer",
        "{all}"
    );

    // The reference with its constant's minus sign dropped, in the
    // student's file; insta told to accept and to pass everything.
    let file = export.join(chapter).join("exercise/line_through_points.rs");
    let stub = fs::read_to_string(&file).unwrap();
    let reference = fs::read_to_string(
        workspace().join(chapter).join("src/line_through_points.rs"),
    )
    .unwrap();
    assert!(reference.contains("c = -normal"));
    fs::write(&file, reference.replacen("c = -normal", "c = normal", 1))
        .unwrap();
    let hostile = [
        ("INSTA_UPDATE", "always"),
        ("INSTA_FORCE_PASS", "1"),
        ("INSTA_OUTPUT", "none"),
    ];
    let (ok, report, stderr) =
        raystep_with(&["check", "ch01", "--quiet"], export, &hostile);
    let changed = Command::new("git")
        .args(["status", "--porcelain", "--untracked-files=all"])
        .current_dir(export)
        .output()
        .unwrap();
    fs::write(&file, &stub).unwrap();
    let all = format!("{report}{stderr}");
    assert!(!ok, "{all}");
    let line = verdict(&report, "line_through_points");
    assert!(
        line.starts_with("failed: line_table (tests/line_through_points.rs:")
            && line.contains(
                "): snapshot line_table, row 3 (P1 \"(4.0, 5.0)\"): c expected \
                 `0.2000`, got `-0.2000`"
            ),
        "{all}"
    );
    assert!(!report.contains("warning"), "{all}");
    assert_eq!(
        String::from_utf8_lossy(&changed.stdout).trim(),
        format!("M {chapter}/exercise/line_through_points.rs"),
        "only the student's file changed, no snapshot was written"
    );

    // One exercise that does not compile leaves the other its verdict:
    // the right line passes, the broken plane names its error.
    let plane_file = export
        .join(chapter)
        .join("exercise/plane_through_points.rs");
    let plane_stub = fs::read_to_string(&plane_file).unwrap();
    fs::write(&file, &reference).unwrap();
    fs::write(&plane_file, "pub fn broken() -> f64 { \"x\" }\n").unwrap();
    let (ok, report, stderr) = raystep(&["check", "ch01", "--quiet"], export);
    fs::write(&plane_file, &plane_stub).unwrap();
    let all = format!("{report}{stderr}");
    assert!(!ok, "{all}");
    assert_eq!(verdict(&report, "line_through_points"), "passed", "{all}");
    let line = verdict(&report, "plane_through_points");
    assert!(
        line.starts_with("the tests do not compile: error[")
            && line.ends_with("(at exercise/plane_through_points.rs:1:26)"),
        "{all}"
    );

    // A file that takes the answer from elsewhere is refused, whatever its
    // tests say.
    fs::write(
        &file,
        "#[path = \"../src/line_through_points.rs\"]\nmod answer;\npub use answer::*;\n",
    )
    .unwrap();
    let (ok, report, stderr) = raystep(&["check", "ch01", "--quiet"], export);
    fs::write(&file, &stub).unwrap();
    let all = format!("{report}{stderr}");
    assert!(!ok, "{all}");
    assert!(
        verdict(&report, "line_through_points").starts_with(
            "refused: exercise/line_through_points.rs:1:3: `#[path]` names \
             another file"
        ),
        "{all}"
    );

    // A snapshot accepted by hand is not the reference: check says so.
    let snapshot = export
        .join(chapter)
        .join("tests/snapshots/line_through_points__line_table.snap");
    let original = fs::read_to_string(&snapshot).unwrap();
    fs::write(&snapshot, format!("{original}extra\n")).unwrap();
    let (ok, report, stderr) = raystep(&["check", "ch01", "--quiet"], export);
    fs::write(&snapshot, original).unwrap();
    assert!(!ok, "{report}{stderr}");
    assert!(
        report.contains(
            "  tests/snapshots/line_through_points__line_table.snap (changed)"
        ) && report.contains("restore them: git checkout -- "),
        "{report}{stderr}"
    );
}

/// A folder that is not empty is refused, named, and left as it was; no
/// partial export is left beside it.
#[test]
fn a_non_empty_folder_is_refused() {
    let parent = Path::new(env!("CARGO_TARGET_TMPDIR")).join("edition-refused");
    let out = parent.join("out");
    fs::create_dir_all(&out).unwrap();
    fs::write(out.join("notes.txt"), "mine").unwrap();
    let (ok, stdout, stderr) =
        raystep(&["student-edition", out.to_str().unwrap()], &workspace());
    assert!(!ok, "{stdout}{stderr}");
    // The path as the user would type it: relative to the current folder.
    let stderr = stderr.trim();
    assert!(
        stderr.starts_with("error: ")
            && stderr.ends_with(
                "edition-refused/out: not empty; the student edition is \
                 written only into a new or empty folder"
            ),
        "{stderr}"
    );
    let left: Vec<_> = fs::read_dir(&parent)
        .unwrap()
        .map(|e| e.unwrap().file_name())
        .collect();
    assert_eq!(left, ["out"]);
    assert_eq!(fs::read_to_string(out.join("notes.txt")).unwrap(), "mine");
}
