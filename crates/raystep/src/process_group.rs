//! Process groups: a test binary and everything it starts can be killed
//! together, and raystep's own terminal signals (Ctrl-C) reach them although
//! they are not in the terminal's foreground group. Without process groups
//! (not on Unix), only the test binary itself is killed.

#[cfg(not(unix))]
pub use elsewhere::{Group, prepare};
#[cfg(unix)]
pub use unix::{Group, prepare};

#[cfg(unix)]
mod unix {
    use std::os::unix::process::CommandExt;
    use std::process::{Child, Command};
    use std::sync::Once;
    use std::sync::atomic::{AtomicI32, Ordering};

    use libc::{SIG_DFL, SIGHUP, SIGINT, SIGKILL, SIGTERM, c_int, pid_t};

    /// The process group of the test binary running now, 0 if none.
    static RUNNING: AtomicI32 = AtomicI32::new(0);

    /// Kills the running group, then dies of `sig` as if no handler were installed.
    extern "C" fn forward(sig: c_int) {
        let group = RUNNING.load(Ordering::SeqCst);
        // SAFETY: kill, signal and raise are async-signal-safe. The group is
        // one this process created; its leader is reaped just before
        // `RUNNING` is cleared.
        unsafe {
            if group > 0 {
                libc::kill(-group, SIGKILL);
            }
            libc::signal(sig, SIG_DFL);
            libc::raise(sig);
        }
    }

    /// Makes the process that `command` starts lead a new process group, and
    /// forwards Ctrl-C, hang-up and termination to such groups from now on.
    pub fn prepare(command: &mut Command) {
        static INSTALL: Once = Once::new();
        INSTALL.call_once(|| {
            for sig in [SIGHUP, SIGINT, SIGTERM] {
                // SAFETY: `forward` is an `extern "C" fn(c_int)` that only
                // calls async-signal-safe functions.
                unsafe {
                    libc::signal(
                        sig,
                        forward as extern "C" fn(c_int) as libc::sighandler_t,
                    );
                }
            }
        });
        command.process_group(0);
    }

    /// The process group of a running child; forgotten when dropped.
    pub struct Group(pid_t);

    impl Group {
        pub fn new(child: &Child) -> Group {
            let id = pid_t::try_from(child.id()).unwrap_or(0);
            RUNNING.store(id, Ordering::SeqCst);
            Group(id)
        }

        /// Kills every process in the group (the child is not reaped yet, so
        /// the group id is still ours).
        pub fn kill(&self, child: &mut Child) {
            if self.0 > 0 {
                // SAFETY: sending a signal has no memory-safety preconditions.
                unsafe {
                    libc::kill(-self.0, SIGKILL);
                }
            }
            let _ = child.kill();
        }
    }

    impl Drop for Group {
        fn drop(&mut self) {
            RUNNING.store(0, Ordering::SeqCst);
        }
    }
}

#[cfg(not(unix))]
mod elsewhere {
    use std::process::{Child, Command};

    pub fn prepare(_command: &mut Command) {}

    pub struct Group;

    impl Group {
        pub fn new(_child: &Child) -> Group {
            Group
        }

        pub fn kill(&self, child: &mut Child) {
            let _ = child.kill();
        }
    }
}
