//! `raystep watch` end to end, in a throwaway one-chapter workspace with
//! stdout piped (so plain lines): the first check, a save that fixes the
//! exercise and the check it starts, then Ctrl-C while a test binary
//! runs, after which nothing of the workspace is left running.
//!
//! Linux only: it sends signals and reads `/proc` to find what is left.
#![cfg(target_os = "linux")]

use std::fs;
use std::io::{BufRead, BufReader, Read};
use std::path::{Path, PathBuf};
use std::process::{Child, Command, ExitStatus, Stdio};
use std::sync::mpsc::{self, Receiver};
use std::time::{Duration, Instant};

mod one_chapter;

/// How long one check may take (a cold build of the tiny chapter takes
/// seconds).
const CHECK: Duration = Duration::from_secs(120);

/// A running `raystep watch`: its stdout line by line; Ctrl-C'd and then
/// killed when dropped (if a test fails half-way).
struct Watch {
    child: Child,
    lines: Receiver<String>,
    seen: Vec<String>,
    stderr: Receiver<String>,
}

impl Watch {
    fn start(root: &Path) -> Watch {
        let mut child = Command::new(env!("CARGO_BIN_EXE_raystep"))
            .args(["watch", "ch01"])
            .current_dir(root)
            .env("RAYSTEP_CHECK_TARGET_DIR", root.join("target"))
            .stdin(Stdio::null())
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .spawn()
            .expect("raystep runs");
        let (send, lines) = mpsc::channel();
        let stdout = BufReader::new(child.stdout.take().unwrap());
        std::thread::spawn(move || {
            for line in stdout.lines().map_while(Result::ok) {
                let _ = send.send(line);
            }
        });
        let (send, stderr) = mpsc::channel();
        let mut pipe = child.stderr.take().unwrap();
        std::thread::spawn(move || {
            let mut text = String::new();
            let _ = pipe.read_to_string(&mut text);
            let _ = send.send(text);
        });
        Watch {
            child,
            lines,
            seen: Vec::new(),
            stderr,
        }
    }

    /// The lines up to the first that `done` accepts, which must come
    /// within `limit`.
    fn until(
        &mut self, limit: Duration, done: impl Fn(&str) -> bool,
    ) -> Vec<String> {
        let deadline = Instant::now() + limit;
        let mut lines = Vec::new();
        loop {
            let left = deadline.saturating_duration_since(Instant::now());
            let Ok(line) = self.lines.recv_timeout(left) else {
                panic!(
                    "no such line within {limit:?}; raystep watch said:\n{}",
                    self.seen.join("\n")
                );
            };
            self.seen.push(line.clone());
            lines.push(line);
            if done(lines.last().unwrap()) {
                return lines;
            }
        }
    }

    /// Sends Ctrl-C (SIGINT).
    fn interrupt(&self) {
        signal(self.child.id(), libc::SIGINT);
    }

    /// How it ended, within `limit`.
    fn ended(&mut self, limit: Duration) -> Option<ExitStatus> {
        let deadline = Instant::now() + limit;
        while Instant::now() < deadline {
            if let Some(status) = self.child.try_wait().unwrap() {
                return Some(status);
            }
            std::thread::sleep(Duration::from_millis(20));
        }
        None
    }
}

impl Drop for Watch {
    fn drop(&mut self) {
        if self.child.try_wait().ok().flatten().is_none() {
            self.interrupt();
            if self.ended(Duration::from_secs(10)).is_none() {
                let _ = self.child.kill();
                let _ = self.child.wait();
            }
        }
    }
}

fn signal(pid: u32, sig: libc::c_int) {
    // SAFETY: sending a signal has no memory-safety preconditions.
    unsafe {
        libc::kill(pid as libc::pid_t, sig);
    }
}

/// Every live process (not a zombie) whose command line names `root` or
/// whose current folder is inside it: (pid, command line).
fn running_in(root: &Path) -> Vec<(u32, String)> {
    let root_text = root.to_string_lossy().into_owned();
    let mut found = Vec::new();
    for entry in fs::read_dir("/proc").unwrap().flatten() {
        let Some(pid) = entry
            .file_name()
            .to_str()
            .and_then(|n| n.parse::<u32>().ok())
        else {
            continue;
        };
        if pid == std::process::id() {
            continue;
        }
        let dir = entry.path();
        let status = fs::read_to_string(dir.join("status")).unwrap_or_default();
        if status
            .lines()
            .any(|l| l.starts_with("State:") && l.contains("Z (zombie)"))
        {
            continue;
        }
        let cmdline = fs::read(dir.join("cmdline"))
            .map(|b| String::from_utf8_lossy(&b).replace('\0', " "))
            .unwrap_or_default();
        let inside = fs::read_link(dir.join("cwd"))
            .is_ok_and(|cwd| cwd.starts_with(root));
        if inside || cmdline.contains(&root_text) {
            found.push((pid, cmdline));
        }
    }
    found
}

/// The test binary of `line_through_points` of the workspace at `root`,
/// if one is running.
fn test_binary_running(root: &Path) -> bool {
    let target: PathBuf = root.join("target");
    fs::read_dir("/proc").unwrap().flatten().any(|entry| {
        fs::read_link(entry.path().join("exe")).is_ok_and(|exe| {
            exe.starts_with(&target)
                && exe.file_name().is_some_and(|n| {
                    n.to_string_lossy().starts_with("line_through_points-")
                })
        })
    })
}

#[test]
fn watch_checks_again_on_a_save_and_ctrl_c_leaves_nothing_running() {
    let root = one_chapter::workspace("watch-loop", one_chapter::WRONG_SLOPE);
    let root = root.canonicalize().unwrap();
    let exercise =
        one_chapter::chapter(&root).join("exercise/line_through_points.rs");
    let started = Instant::now();
    let mut watch = Watch::start(&root);

    // The first check: the wrong slope fails, the plane passes.
    let first = watch.until(CHECK, |l| l.starts_with("watching "));
    let first = first.join("\n");
    assert!(first.starts_with("checking ch01…\n"), "{first}");
    assert!(
        first.contains(
            "\nch01-implicit-lines-planes (student mode)\n\
             exercise line_through_points (★): failed\n  \
             slope_of_a_diagonal (tests/line_through_points.rs:3): "
        ),
        "{first}"
    );
    assert!(
        first.contains(
            "\n1 of 2 exercises passed\n\
             stuck? raystep hint ch01 line_through_points\n\
             watching chapters/ch01-implicit-lines-planes/exercise/ — save \
             a file to check again, Ctrl-C to quit"
        ),
        "{first}"
    );
    assert!(!first.contains('\x1b'), "no escapes when piped: {first:?}");

    // A save checks again: it passes, and the next chapter is named.
    fs::write(&exercise, one_chapter::RIGHT_SLOPE).unwrap();
    let second = watch
        .until(CHECK, |l| l.starts_with("watching "))
        .join("\n");
    assert!(
        second.contains(
            "ch01-implicit-lines-planes (student mode)\n\
             2 of 2 exercises passed\n\
             all of ch01 passes — next: raystep watch ch02\n"
        ),
        "{second}"
    );
    let recorded =
        fs::read_to_string(root.join(".raystep/progress.json")).unwrap();
    assert!(!recorded.contains("\"failed\""), "{recorded}");

    // A save that loops forever; Ctrl-C while its test binary runs.
    fs::write(&exercise, one_chapter::LOOPING_SLOPE).unwrap();
    watch.until(CHECK, |l| l == "checking ch01…");
    let deadline = Instant::now() + CHECK;
    while !test_binary_running(&root) {
        assert!(Instant::now() < deadline, "the looping test never ran");
        std::thread::sleep(Duration::from_millis(20));
    }
    std::thread::sleep(Duration::from_millis(300));
    watch.interrupt();
    let status = watch
        .ended(Duration::from_secs(15))
        .expect("watch ends on Ctrl-C");
    let stderr = watch
        .stderr
        .recv_timeout(Duration::from_secs(5))
        .unwrap_or_default();
    assert_eq!(status.code(), Some(130), "{stderr}");
    // Killed processes may take a moment to go.
    let deadline = Instant::now() + Duration::from_secs(5);
    let mut left = running_in(&root);
    while !left.is_empty() && Instant::now() < deadline {
        std::thread::sleep(Duration::from_millis(50));
        left = running_in(&root);
    }
    assert_eq!(left, Vec::new(), "left running after Ctrl-C");
    eprintln!("the watch test took {:.1?}", started.elapsed());
}
