//! Running a chapter's built test binaries one after the other, each as
//! cargo would run it (in its package folder, with cargo's variables and
//! none of the user's that change what libtest or insta print) under a
//! time limit, and judging what they printed. A binary that crashed or was
//! killed names the tests it was still running, and why it died when the
//! runtime said so (a stack overflow, an allocation that failed).

use std::collections::HashMap;
use std::path::Path;
use std::process::Command;
use std::time::Duration;

use raystep_check::verdicts::{
    Context, Ended, Report, TestBinary, parse_list, parse_output_in, report,
    still_running, test_binary_in,
};
use raystep_figure::Chapter;

use crate::cargo_artifacts::Executable;
use crate::held_out::held_out_name;
use crate::limited_process::{
    Exit, Limits, Ran, out_of_memory, run_with_limit,
};
use crate::run_options::{Run, shown_size};
use crate::test_build::{Built, cargo_program};

/// How long `--list` may take after a binary timed out (to name its unfinished tests).
const LIST_LIMIT: Duration = Duration::from_secs(10);

/// Runs the test binaries of `chapter` that a build of the workspace at
/// `root` made, and judges each exercise.
pub(crate) fn run_built(
    root: &Path, chapter: &Chapter, run: &Run, built: Built,
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
            run_tests(executable, &cargo, run, threads, &context)
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
    executable: &Executable, cargo: &str, args: &[&str], context: &Context,
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
        // `raystep_check::verdicts`).
        .env("INSTA_OUTPUT", "diff");
    if let Some(root) = &context.workspace {
        command.env("INSTA_WORKSPACE_ROOT", root);
    }
    command
}

/// Runs one test binary within the limits of `run` (and in its sandbox,
/// if any) and reads what it printed.
fn run_tests(
    executable: &Executable, cargo: &str, run: &Run, threads: usize,
    context: &Context,
) -> TestBinary {
    let limit = run.timeout;
    let threads_arg = threads.to_string();
    let args = [
        "--test-threads",
        threads_arg.as_str(),
        "--color",
        "never",
        "--format",
        "pretty",
    ];
    let command = test_command(executable, cargo, &args, context);
    let ran = run_with_limit(&mut run.contained(command), run.limits());
    let (stdout, ended) = match ran {
        Err(error) => (String::new(), Ended::NotStarted(error.to_string())),
        Ok(Ran {
            stdout,
            stderr,
            exit: Exit::Status(status),
        }) if !status.success() && out_of_memory(&stderr).is_some() => {
            let listed = list_tests(executable, cargo, run, context);
            let why = format!(
                "out of memory (limit {}, --memory)",
                shown_size(run.memory)
            );
            let how = run.described(status);
            (
                stdout,
                Ended::Stopped {
                    why,
                    how,
                    listed,
                    threads,
                },
            )
        }
        Ok(Ran {
            stdout,
            exit: Exit::OutputCut,
            ..
        }) => {
            let listed = list_tests(executable, cargo, run, context);
            let why = format!(
                "printed more than {} (limit, --output)",
                shown_size(run.output)
            );
            let how = "killed".to_string();
            (
                stdout,
                Ended::Stopped {
                    why,
                    how,
                    listed,
                    threads,
                },
            )
        }
        Ok(Ran {
            stdout,
            stderr,
            exit: Exit::Status(status),
        }) => {
            let mut how = run.described(status);
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
                    let listed = list_tests(executable, cargo, run, context);
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
            let listed = list_tests(executable, cargo, run, context);
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
    executable: &Executable, cargo: &str, run: &Run, context: &Context,
) -> Vec<String> {
    let list = test_command(
        executable,
        cargo,
        &["--list", "--format", "terse"],
        context,
    );
    let limits = Limits {
        time: LIST_LIMIT.min(run.timeout),
        ..run.limits()
    };
    match run_with_limit(&mut run.contained(list), limits) {
        Ok(Ran {
            stdout,
            exit: Exit::Status(status),
            ..
        }) if status.success() => parse_list(&stdout),
        _ => Vec::new(),
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
}
