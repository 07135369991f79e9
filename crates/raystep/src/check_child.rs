//! `raystep watch`'s check: this same program run as `raystep check chNN
//! --quiet --json FILE`, in a process group of its own so that stopping it
//! stops cargo, the compiler and the test binary with it.
//!
//! It is stopped with SIGTERM sent to its group: cargo and the compiler
//! end, and the check's own handler ([`crate::process_group`]) kills the
//! test binary's group (a group of its own) before it dies. A check that
//! has not ended after [`GRACE`] is killed with its group.

use std::io::Read;
use std::path::Path;
use std::process::{Child, Command, Stdio};
use std::thread::JoinHandle;

use crate::error::Error;

/// How long a stopped check may take to stop its test binary and end.
#[cfg(unix)]
const GRACE: std::time::Duration = std::time::Duration::from_secs(5);

/// A running check.
pub struct CheckChild {
    /// `None` once it has ended (and been reaped).
    child: Option<Child>,
    /// What it says on stderr, read to its end on a thread of its own.
    stderr: Option<JoinHandle<String>>,
}

impl CheckChild {
    /// Starts `program check <chapter> --quiet --json <json>` in the
    /// workspace at `root`; errors name the program.
    pub fn start(
        program: &Path, root: &Path, chapter: &str, json: &Path,
    ) -> Result<CheckChild, Error> {
        let mut command = Command::new(program);
        command
            .args(["check", chapter, "--quiet", "--json"])
            .arg(json)
            .current_dir(root)
            .stdin(Stdio::null())
            .stdout(Stdio::null())
            .stderr(Stdio::piped());
        #[cfg(unix)]
        std::os::unix::process::CommandExt::process_group(&mut command, 0);
        let mut child = command.spawn().map_err(|source| Error::Spawn {
            program: program.display().to_string(),
            source,
        })?;
        let mut pipe = child.stderr.take().expect("stderr is piped");
        let stderr = std::thread::spawn(move || {
            let mut bytes = Vec::new();
            let _ = pipe.read_to_end(&mut bytes);
            String::from_utf8_lossy(&bytes).into_owned()
        });
        Ok(CheckChild {
            child: Some(child),
            stderr: Some(stderr),
        })
    }

    /// Whether it has ended (its report, if any, is written).
    pub fn ended(&mut self) -> bool {
        let Some(child) = self.child.as_mut() else {
            return true;
        };
        match child.try_wait() {
            Ok(Some(_)) => {
                self.child = None;
                true
            }
            Ok(None) => false,
            // Cannot tell: stop it, to be sure.
            Err(_) => {
                self.stop();
                true
            }
        }
    }

    /// What it said on stderr, once it has ended.
    pub fn stderr(&mut self) -> String {
        self.stderr
            .take()
            .and_then(|thread| thread.join().ok())
            .unwrap_or_default()
    }

    /// Stops it (see the module's comment) and waits until it has ended.
    pub fn stop(&mut self) {
        let Some(mut child) = self.child.take() else {
            return;
        };
        #[cfg(unix)]
        {
            let group = libc::pid_t::try_from(child.id()).unwrap_or(0);
            let signal = |sig| {
                if group > 0 {
                    // SAFETY: sending a signal has no memory-safety
                    // preconditions; the group's leader is not reaped yet,
                    // so its id is still this group's.
                    unsafe {
                        libc::kill(-group, sig);
                    }
                }
            };
            signal(libc::SIGTERM);
            let deadline = std::time::Instant::now() + GRACE;
            while std::time::Instant::now() < deadline {
                if !matches!(child.try_wait(), Ok(None)) {
                    return;
                }
                std::thread::sleep(std::time::Duration::from_millis(20));
            }
            signal(libc::SIGKILL);
        }
        let _ = child.kill();
        let _ = child.wait();
    }
}

impl Drop for CheckChild {
    /// A check is never left running.
    fn drop(&mut self) {
        self.stop();
    }
}
