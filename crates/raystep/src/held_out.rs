//! `raystep grade`'s held-out cases (the protocol is
//! `raystep_check::held_out`): per student, the chapter's held-out program
//! built with the student's code answers cases drawn from a new secret
//! seed; the same program built with the reference, in the instructor's
//! workspace and a process of its own, judges the answers.
//!
//! Why this cannot be forged: the verdict is printed by the reference's
//! process, which the student's code never runs in, on inputs drawn after
//! the submission was handed in. Printing a harness's `ok` lines, ending the
//! process early or reading the snapshots' rows (which hold other inputs)
//! leaves cases unanswered or wrong.

use std::collections::BTreeMap;
use std::hash::{BuildHasher, Hasher};
use std::io::{BufRead, BufReader};
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::Duration;

use raystep_check::held_out::Verdict;
use raystep_figure::Chapter;

use crate::cargo_artifacts::examples;
use crate::error::Error;
use crate::limited_process::{Exit, Limits, Ran, run_with_limit};
use crate::run_options::Run;
use crate::test_build::cargo_program;

/// The name of a chapter's held-out program: `examples/ch01_held_out.rs`
/// (see `raystep_check::held_out`).
pub fn held_out_name(chapter: &Chapter) -> String {
    format!("{}_held_out", chapter.id)
}

/// How long the judge (the reference) may take.
const JUDGE_LIMIT: Duration = Duration::from_secs(120);

/// A seed no one can know before it is drawn: the operating system's
/// randomness behind the standard library's hash keys, and the clock.
pub fn new_seed() -> u64 {
    let mut hasher =
        std::collections::hash_map::RandomState::new().build_hasher();
    hasher.write_u128(
        std::time::SystemTime::now()
            .duration_since(std::time::UNIX_EPOCH)
            .map_or(0, |d| d.as_nanos()),
    );
    hasher.write_u32(std::process::id());
    hasher.finish()
}

/// Builds the chapter's held-out program with the reference, in the
/// workspace at `root` (the instructor's), and keeps a copy of it in
/// `keep` (a later build of a student's copy in the same target folder
/// would put its own program at the same path). `None` if the chapter has
/// no held-out program.
pub fn build_reference(
    root: &Path, chapter: &Chapter, target_dir: Option<&Path>, keep: &Path,
) -> Result<Option<PathBuf>, Error> {
    let name = held_out_name(chapter);
    let source = root
        .join("chapters")
        .join(chapter.package)
        .join("examples")
        .join(format!("{name}.rs"));
    if !source.is_file() {
        return Ok(None);
    }
    let cargo = cargo_program();
    let mut command = Command::new(&cargo);
    command
        .current_dir(root)
        .args(["build", "--message-format=json-render-diagnostics"])
        .args([
            "--color",
            "never",
            "-p",
            chapter.package,
            "--example",
            &name,
        ])
        .env("CARGO_TERM_QUIET", "true")
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped());
    if let Some(dir) = target_dir {
        command.env("CARGO_TARGET_DIR", dir);
    }
    let out = command.output().map_err(|source| Error::Spawn {
        program: cargo.clone(),
        source,
    })?;
    let stdout = String::from_utf8_lossy(&out.stdout);
    let built = examples(&stdout)
        .into_iter()
        .find(|(n, _)| *n == name)
        .map(|(_, path)| path);
    let Some(built) = built.filter(|_| out.status.success()) else {
        let stderr = String::from_utf8_lossy(&out.stderr);
        return Err(Error::Usage(format!(
            "the reference's held-out program ({}) does not build: {}",
            crate::shown_path::relative(&source).display(),
            stderr
                .lines()
                .find(|l| l.starts_with("error"))
                .unwrap_or("cargo failed")
        )));
    };
    std::fs::create_dir_all(keep).map_err(|e| Error::io(keep, e))?;
    let kept = keep.join(&name);
    std::fs::copy(&built, &kept).map_err(|e| Error::io(&built, e))?;
    Ok(Some(kept))
}

/// Each exercise's held-out verdict: the student's `runner` answers the
/// cases of `seed` for each of `exercises` in a process of its own (within
/// the limits of `run`, in its sandbox if any; the answers are kept in
/// `answers`), then the `reference` judges them.
pub fn judge(
    reference: &Path, runner: &Path, exercises: &[&str], seed: u64, run: &Run,
    answers: &Path,
) -> Result<BTreeMap<String, Verdict>, Error> {
    let limit = run.timeout;
    let mut text = String::new();
    let mut stopped = BTreeMap::new();
    for exercise in exercises {
        let mut answer = Command::new(runner);
        answer
            .args(["answer", &seed.to_string(), exercise])
            .current_dir(answers.parent().unwrap_or(Path::new(".")))
            .env("RUST_BACKTRACE", "0");
        let ran = run_with_limit(&mut run.contained(answer), run.limits())
            .map_err(|source| Error::Spawn {
                program: runner.display().to_string(),
                source,
            })?;
        // Only this exercise's lines: a program that prints another's
        // answers gains nothing.
        let prefix = format!("answer {exercise} ");
        for line in ran.stdout.lines().filter(|l| l.starts_with(&prefix)) {
            text.push_str(line);
            text.push('\n');
        }
        let why = match &ran.exit {
            Exit::TimedOut => Some(format!(
                "the held-out program timed out after {} s",
                limit.as_secs_f64()
            )),
            Exit::OutputCut => Some(format!(
                "the held-out program printed more than {} (limit, --output)",
                crate::run_options::shown_size(run.output)
            )),
            Exit::Status(status)
                if !status.success()
                    && crate::limited_process::out_of_memory(&ran.stderr)
                        .is_some() =>
            {
                Some(format!(
                    "the held-out program ran out of memory (limit {}, --memory)",
                    crate::run_options::shown_size(run.memory)
                ))
            }
            Exit::Status(status) if !status.success() => Some(format!(
                "the held-out program stopped ({})",
                run.described(*status)
            )),
            Exit::Status(_) => None,
        };
        if let Some(why) = why {
            stopped.insert(exercise.to_string(), why);
        }
    }
    std::fs::write(answers, &text).map_err(|e| Error::io(answers, e))?;

    let mut judge = Command::new(reference);
    judge
        .args(["judge", &seed.to_string()])
        .arg(answers)
        .env("RUST_BACKTRACE", "0");
    // The reference prints one line per exercise: a flood means this is
    // not the reference's program.
    let limits = Limits {
        output: Some(1 << 20),
        ..Limits::time(JUDGE_LIMIT)
    };
    let Ran { stdout, exit, .. } =
        run_with_limit(&mut judge, limits).map_err(|source| Error::Spawn {
            program: reference.display().to_string(),
            source,
        })?;
    if !matches!(exit, Exit::Status(status) if status.success()) {
        return Err(Error::Usage(format!(
            "the reference's held-out program failed to judge ({}): {exit:?}",
            reference.display()
        )));
    }
    let mut verdicts = BTreeMap::new();
    for line in BufReader::new(stdout.as_bytes())
        .lines()
        .map_while(Result::ok)
    {
        let mut parts = line.splitn(3, ' ');
        if let (Some("verdict"), Some(name), Some(rest)) =
            (parts.next(), parts.next(), parts.next())
            && let Some(mut verdict) = Verdict::parse(rest)
        {
            // Say why answers are missing, when the program stopped.
            if let (Verdict::Failed(why), Some(stopped)) =
                (&mut verdict, stopped.get(name))
                && why.ends_with("(the program stopped before it)")
            {
                *why = why.replace("the program stopped before it", stopped);
            }
            verdicts.insert(name.to_string(), verdict);
        }
    }
    Ok(verdicts)
}

/// The verdict of an exercise once its held-out cases are judged: a pass
/// of the tests stands only if the held-out cases pass too.
pub fn merged(
    verdict: (String, String), held_out: Option<&Verdict>,
) -> (String, String) {
    match (verdict.0.as_str(), held_out) {
        ("passed", Some(Verdict::Failed(why))) => {
            ("failed".to_string(), why.clone())
        }
        ("passed", Some(Verdict::NotAttempted)) => (
            "failed".to_string(),
            "held-out cases: not yet implemented (todo!()), yet the tests passed"
                .to_string(),
        ),
        _ => verdict,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_pass_stands_only_with_its_held_out_cases() {
        let passed = || ("passed".to_string(), String::new());
        assert_eq!(merged(passed(), Some(&Verdict::Passed)), passed());
        assert_eq!(merged(passed(), None), passed());
        assert_eq!(
            merged(passed(), Some(&Verdict::Failed("held-out case 3".into()))),
            ("failed".to_string(), "held-out case 3".to_string())
        );
        assert_eq!(merged(passed(), Some(&Verdict::NotAttempted)).0, "failed");
        // A failure of the tests says more than the held-out cases.
        let failed = ("failed".to_string(), "t (tests/x.rs:3): …".to_string());
        assert_eq!(
            merged(failed.clone(), Some(&Verdict::Failed("case 1".into()))),
            failed
        );
    }

    #[test]
    fn seeds_differ() {
        assert_ne!(new_seed(), new_seed());
    }
}
