//! Building a chapter's tests: `cargo test --no-run` with cargo's terminal
//! settings pinned in its environment and its compiler messages echoed;
//! the test binaries and examples it built, or why it built none.

use std::io::{BufRead, BufReader, Read};
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

use raystep_check::verdicts::{
    BuildFailure, CargoFailure, cargo_failure, compile_errors,
};

use crate::cargo_artifacts::{Executable, examples, test_executables};
use crate::error::Error;
use crate::run_options::Run;
use crate::separate_artifacts::{own_package, separate_artifacts};
use crate::{memory_limit, process_group};

/// What a test build built to run: the test binaries, and the examples by
/// name.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(crate) struct Built {
    pub tests: Vec<Executable>,
    pub examples: Vec<(String, PathBuf)>,
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
    cargo: &str, root: &Path, package: &str, options: &Run,
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
        .env("CARGO_TERM_HYPERLINKS", "false");
    if let Some(dir) = &options.target_dir {
        command.env("CARGO_TARGET_DIR", dir);
    }
    match artifacts {
        Artifacts::Workspace => command.args(separate_artifacts(
            root,
            options.target_dir.as_deref(),
            options.copy,
        )),
        Artifacts::OwnPackage(original) => {
            let own = own_package(package, options.copy);
            let prefix = format!("profile.dev.package.\"{package}\".");
            let shared = separate_artifacts(
                original,
                options.target_dir.as_deref(),
                options.copy,
            );
            for pair in shared.chunks(2) {
                if !pair.iter().any(|arg| arg.starts_with(&prefix)) {
                    command.args(pair);
                }
            }
            command.args(own)
        }
    };
    let spawn_error = |source| Error::Spawn {
        program: cargo.to_string(),
        source,
    };
    // The student's code is compiled (constant evaluation, the compiler's
    // own limits) under the same memory limit and sandbox as it runs, and
    // the build is a process group that Ctrl-C ends (see `process_group`).
    let mut command = options.contained(command);
    command
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped());
    memory_limit::set(&mut command, options.memory);
    process_group::prepare(&mut command).map_err(spawn_error)?;
    // One build at a time in this process, its examples kept before the
    // next build (see `keep_examples`).
    let _turn = BUILDS.lock().unwrap_or_else(|e| e.into_inner());
    let mut child = command.spawn().map_err(spawn_error)?;
    let group = process_group::Group::new(&child);

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
    drop(group);
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
    let examples = match &options.keep_examples {
        Some(dir) => keep_examples(examples(&stdout), dir)?,
        None => examples(&stdout),
    };
    Ok(Ok(Built {
        tests: executables,
        examples,
    }))
}

/// The builds of this process take turns: `raystep grade --jobs` builds
/// several copies of the workspace into one target folder, and cargo puts
/// an example's program at one path whichever copy built it.
static BUILDS: std::sync::Mutex<()> = std::sync::Mutex::new(());

/// The `examples` copied into `dir`, before another build can put its own
/// program at their path (`target/debug/examples/<name>`, the same for
/// every copy of the workspace).
fn keep_examples(
    examples: Vec<(String, PathBuf)>, dir: &Path,
) -> Result<Vec<(String, PathBuf)>, Error> {
    std::fs::create_dir_all(dir).map_err(|e| Error::io(dir, e))?;
    examples
        .into_iter()
        .map(|(name, path)| {
            let kept = dir.join(&name);
            std::fs::copy(&path, &kept).map_err(|e| Error::io(&path, e))?;
            Ok((name, kept))
        })
        .collect()
}
