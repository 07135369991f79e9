//! Running a student's build and tests inside bubblewrap (`bwrap`, Debian's
//! `bubblewrap`): no network, nothing of the file system visible but the
//! system's programs and libraries, the Rust toolchain and cargo's registry
//! (read-only) and the scratch copy being graded (the only place it may
//! write). The instructor's home and workspace are not there at all.
//!
//! Inside, every process is in a process-id namespace of its own: when the
//! sandbox ends (or raystep dies, `--die-with-parent`) the kernel kills
//! every process in it, even one that left its process group. The
//! environment is cleared but for what cargo and the toolchain read (`PATH`,
//! `HOME`, `CARGO*`, `RUST*`) and what raystep sets for the command, and
//! cargo is told it is offline.

use std::ffi::OsString;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

use crate::error::Error;

/// `--sandbox`: whether the student's build and tests run in bubblewrap.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum Mode {
    /// Inside bubblewrap where it is installed and works, with one warning
    /// where it is not.
    Auto,
    /// Inside bubblewrap, or not at all (an error names what is missing).
    Required,
    /// As they are, with the limits of time, memory and output only.
    Off,
}

/// The folders a sandboxed command sees, and how.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Sandbox {
    /// The `bwrap` program.
    program: PathBuf,
    /// Seen and written: the scratch copy, its target folder.
    writable: Vec<PathBuf>,
    /// Seen, not written: the toolchain, cargo's registry, test data.
    readable: Vec<PathBuf>,
}

/// The system's folders every program needs, read-only where they are
/// folders, as the same links where they are links (a merged `/usr`).
const SYSTEM: &[&str] = &["/usr", "/bin", "/sbin", "/lib", "/lib32", "/lib64"];

/// The files of `/etc` the dynamic linker and the C compiler driver read
/// (`cc` is a link through `/etc/alternatives` on Debian); nothing else of
/// `/etc` is seen.
const ETC: &[&str] = &[
    "/etc/ld.so.cache",
    "/etc/ld.so.conf",
    "/etc/ld.so.conf.d",
    "/etc/alternatives",
];

impl Sandbox {
    /// The sandbox `mode` asks for, writing only in `writable` and reading
    /// `readable` besides the toolchain: `None` when off, or when `auto` and
    /// bubblewrap is missing or cannot run here (with one warning on stderr).
    pub fn choose(
        mode: Mode, writable: &[PathBuf], readable: &[PathBuf],
    ) -> Result<Option<Sandbox>, Error> {
        if mode == Mode::Off {
            return Ok(None);
        }
        let missing = |why: String| -> Result<Option<Sandbox>, Error> {
            match mode {
                Mode::Required => Err(Error::Usage(format!(
                    "--sandbox required: {why} (Debian: apt-get install bubblewrap)"
                ))),
                _ => {
                    eprintln!(
                        "warning: {why}: grading without a sandbox (time, \
                         memory and output limits only; --sandbox off to \
                         silence this)"
                    );
                    Ok(None)
                }
            }
        };
        let Some(program) = find_on_path("bwrap") else {
            return missing("bubblewrap (bwrap) is not installed".to_string());
        };
        let mut readable: Vec<PathBuf> = readable.to_vec();
        readable.extend(toolchain());
        let sandbox = Sandbox {
            program,
            writable: writable.iter().map(|p| absolute(p)).collect(),
            readable: readable.iter().map(|p| absolute(p)).collect(),
        };
        // A first run shows whether it works here (user namespaces may be
        // turned off).
        let mut probe = sandbox.wrap(Command::new("true"));
        match probe.stdin(Stdio::null()).output() {
            Ok(out) if out.status.success() => Ok(Some(sandbox)),
            Ok(out) => {
                let stderr = String::from_utf8_lossy(&out.stderr);
                let why = stderr.lines().next().unwrap_or("").trim();
                missing(format!("bubblewrap cannot run here ({why})"))
            }
            Err(error) => {
                missing(format!("bubblewrap cannot run here ({error})"))
            }
        }
    }

    /// The same sandbox, writing in `dir` too.
    pub fn also_writable(&self, dir: &Path) -> Sandbox {
        let mut sandbox = self.clone();
        sandbox.writable.push(absolute(dir));
        sandbox
    }

    /// `command` as it runs inside the sandbox: `bwrap` with the folders,
    /// namespaces and environment, then the program, its arguments and its
    /// folder. The variables `command` sets are kept, the ones it removes
    /// stay removed. Where its input and output go is not kept: set them
    /// on the command returned.
    pub fn wrap(&self, command: Command) -> Command {
        let mut wrapped = Command::new(&self.program);
        wrapped.args([
            "--unshare-all",
            "--die-with-parent",
            "--new-session",
            "--proc",
            "/proc",
            "--dev",
            "/dev",
            "--tmpfs",
            "/tmp",
        ]);
        for dir in SYSTEM {
            let path = Path::new(dir);
            match std::fs::read_link(path) {
                Ok(target) => {
                    wrapped.arg("--symlink").arg(target).arg(path);
                }
                Err(_) => {
                    wrapped.arg("--ro-bind-try").arg(path).arg(path);
                }
            }
        }
        for file in ETC {
            wrapped.arg("--ro-bind-try").args([file, file]);
        }
        for dir in &self.readable {
            wrapped.arg("--ro-bind-try").arg(dir).arg(dir);
        }
        for dir in &self.writable {
            wrapped.arg("--bind-try").arg(dir).arg(dir);
        }
        if let Some(dir) = command.get_current_dir() {
            wrapped.arg("--chdir").arg(absolute(dir));
        }
        wrapped.arg("--clearenv");
        let set: Vec<&std::ffi::OsStr> =
            command.get_envs().map(|(name, _)| name).collect();
        for (name, value) in std::env::vars_os() {
            if kept(&name) && !set.contains(&name.as_os_str()) {
                wrapped.arg("--setenv").arg(&name).arg(value);
            }
        }
        for (name, value) in command.get_envs() {
            if let Some(value) = value {
                wrapped.arg("--setenv").arg(name).arg(value);
            }
        }
        wrapped.args(["--setenv", "CARGO_NET_OFFLINE", "true"]);
        wrapped.arg("--").arg(command.get_program());
        wrapped.args(command.get_args());
        wrapped
    }
}

/// The variables of raystep's environment a sandboxed command keeps: what
/// finds the programs and the toolchain, and what configures cargo and rustc.
fn kept(name: &OsString) -> bool {
    let name = name.to_string_lossy();
    ["PATH", "HOME", "LANG", "LC_ALL", "TERM"].contains(&name.as_ref())
        || name.starts_with("CARGO")
        || name.starts_with("RUST")
}

/// Where the Rust toolchain and cargo's registry are: `RUSTUP_HOME` and
/// `CARGO_HOME` (else `~/.rustup` and `~/.cargo`), and the folder of the
/// `cargo` that runs raystep, if it is elsewhere.
fn toolchain() -> Vec<PathBuf> {
    let home = std::env::var_os("HOME").map(PathBuf::from);
    let from = |var: &str, default: &str| {
        std::env::var_os(var)
            .map(PathBuf::from)
            .or_else(|| home.as_ref().map(|h| h.join(default)))
    };
    let mut folders: Vec<PathBuf> =
        [from("RUSTUP_HOME", ".rustup"), from("CARGO_HOME", ".cargo")]
            .into_iter()
            .flatten()
            .collect();
    // The cargo that runs raystep (as `crate::test_build` finds it).
    let cargo = std::env::var("CARGO").unwrap_or_else(|_| "cargo".to_string());
    let cargo = if Path::new(&cargo).is_absolute() {
        Some(PathBuf::from(cargo))
    } else {
        find_on_path(&cargo)
    };
    if let Some(dir) = cargo
        .and_then(|c| c.canonicalize().ok())
        .and_then(|c| c.parent().map(Path::to_path_buf))
        && !folders.iter().any(|f| dir.starts_with(f))
        && !dir.starts_with("/usr")
    {
        folders.push(dir);
    }
    folders
}

/// `program` as found on `PATH`.
fn find_on_path(program: &str) -> Option<PathBuf> {
    std::env::split_paths(&std::env::var_os("PATH")?)
        .map(|dir| dir.join(program))
        .find(|path| path.is_file())
}

/// `path` from the file system's root (the sandbox knows no current folder).
fn absolute(path: &Path) -> PathBuf {
    std::path::absolute(path).unwrap_or_else(|_| path.to_path_buf())
}

#[cfg(all(test, target_os = "linux"))]
mod tests {
    use super::*;

    /// A sandbox writing only in `dir`, or `None` where bubblewrap is not
    /// installed (CI installs it: `.ci/run`).
    fn sandbox(dir: &Path) -> Option<Sandbox> {
        let chosen = Sandbox::choose(Mode::Auto, &[dir.to_path_buf()], &[]);
        chosen.expect("auto never fails")
    }

    fn shell(
        sandbox: &Sandbox, dir: &Path, script: &str,
    ) -> std::process::Output {
        let mut command = Command::new("sh");
        command
            .args(["-c", script])
            .current_dir(dir)
            .env("GIVEN", "yes");
        sandbox.wrap(command).stdin(Stdio::null()).output().unwrap()
    }

    #[test]
    fn only_the_scratch_folder_is_seen_and_written() {
        let scratch = tempfile::tempdir().unwrap();
        let Some(sandbox) = sandbox(scratch.path()) else {
            eprintln!("bubblewrap is not installed here: nothing to test");
            return;
        };
        // This test's own source, by absolute path: the instructor's
        // workspace is not there.
        let source =
            Path::new(env!("CARGO_MANIFEST_DIR")).join("src/sandbox.rs");
        let script = format!(
            "test -e {} && echo workspace; \
             echo written > inside.txt; touch /usr/escaped 2>/dev/null && echo usr; \
             echo \"$GIVEN\"; pwd",
            source.display()
        );
        let out = shell(&sandbox, scratch.path(), &script);
        let stdout = String::from_utf8_lossy(&out.stdout);
        let dir = absolute(scratch.path());
        assert_eq!(stdout, format!("yes\n{}\n", dir.display()), "{out:?}");
        assert_eq!(
            std::fs::read_to_string(scratch.path().join("inside.txt")).unwrap(),
            "written\n"
        );
        assert!(!Path::new("/usr/escaped").exists());
        // The toolchain is there, read-only.
        let out = shell(&sandbox, scratch.path(), "rustc --version");
        assert!(out.status.success(), "{out:?}");
    }

    #[test]
    fn there_is_no_network_and_nothing_outlives_the_sandbox() {
        let scratch = tempfile::tempdir().unwrap();
        let Some(sandbox) = sandbox(scratch.path()) else {
            eprintln!("bubblewrap is not installed here: nothing to test");
            return;
        };
        // Only the loopback device.
        let out = shell(&sandbox, scratch.path(), "cat /proc/net/dev");
        let stdout = String::from_utf8_lossy(&out.stdout);
        let devices: Vec<&str> = stdout
            .lines()
            .filter_map(|l| l.split_once(':').map(|(d, _)| d.trim()))
            .collect();
        assert_eq!(devices, ["lo"], "{stdout}");
        // A process that leaves its session and process group (`setsid`)
        // still ends with the sandbox: the marker it would write after a
        // second never appears.
        let out = shell(
            &sandbox,
            scratch.path(),
            "setsid sh -c 'sleep 1; echo escaped > late.txt' >/dev/null 2>&1 & echo started",
        );
        assert!(out.status.success(), "{out:?}");
        std::thread::sleep(std::time::Duration::from_millis(1500));
        assert!(!scratch.path().join("late.txt").exists());
    }

    #[test]
    fn off_is_none_and_required_names_what_is_missing() {
        assert_eq!(Sandbox::choose(Mode::Off, &[], &[]).unwrap(), None);
        // Where bwrap is missing, `required` says how to install it.
        if find_on_path("bwrap").is_none() {
            let error = Sandbox::choose(Mode::Required, &[], &[]).unwrap_err();
            assert!(error.to_string().contains("apt-get install bubblewrap"));
        }
    }
}
