//! Process groups: a test binary and everything it starts can be killed
//! together, and raystep's own terminal signals (Ctrl-C) reach them although
//! they are not in the terminal's foreground group. Without process groups
//! (not on Unix), only the test binary itself is killed.
//!
//! On Ctrl-C (or hang-up, or termination) every running group is killed,
//! no new process is started, the folders registered with
//! [`remove_on_interrupt`] (`raystep grade`'s scratch copy) are removed,
//! and raystep then dies of the signal as if it had no handler.

#[cfg(not(unix))]
pub use elsewhere::{Group, prepare, remove_on_interrupt};
#[cfg(unix)]
pub use unix::{Group, prepare, remove_on_interrupt};

#[cfg(unix)]
mod unix {
    use std::io;
    use std::os::unix::process::CommandExt;
    use std::path::{Path, PathBuf};
    use std::process::{Child, Command};
    use std::sync::atomic::{AtomicBool, AtomicI32, Ordering};
    use std::sync::{Mutex, Once, OnceLock};

    use libc::{SIG_DFL, SIGHUP, SIGINT, SIGKILL, SIGTERM, c_int, pid_t};

    /// The process groups of the processes running now (0: a free slot):
    /// `raystep grade --jobs N` runs up to N at once.
    static RUNNING: [AtomicI32; 64] = [const { AtomicI32::new(0) }; 64];

    /// Set once a terminal signal has arrived: nothing new is started.
    static STOPPING: AtomicBool = AtomicBool::new(false);

    /// The write end of the pipe the signal handler wakes the remover
    /// with (-1: no remover, die at once).
    static WAKE: AtomicI32 = AtomicI32::new(-1);

    /// The folders to remove on a terminal signal.
    static FOLDERS: Mutex<Vec<PathBuf>> = Mutex::new(Vec::new());

    /// Kills every running group; then wakes the remover, or dies of `sig`
    /// as if no handler were installed.
    extern "C" fn forward(sig: c_int) {
        STOPPING.store(true, Ordering::SeqCst);
        // SAFETY: kill, write, signal and raise are async-signal-safe. Each
        // group is one this process created; a slot is cleared only after
        // its leader is reaped.
        unsafe {
            for slot in &RUNNING {
                let group = slot.load(Ordering::SeqCst);
                if group > 0 {
                    libc::kill(-group, SIGKILL);
                }
            }
            let wake = WAKE.load(Ordering::SeqCst);
            let byte = sig as u8;
            if wake >= 0 && libc::write(wake, (&raw const byte).cast(), 1) == 1
            {
                return;
            }
            libc::signal(sig, SIG_DFL);
            libc::raise(sig);
        }
    }

    fn install() {
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
    }

    /// Makes the process that `command` starts lead a new process group,
    /// and forwards Ctrl-C, hang-up and termination to such groups from now
    /// on. After such a signal nothing more is started: this waits for the
    /// remover to finish and end raystep (or, without one, says so).
    pub fn prepare(command: &mut Command) -> io::Result<()> {
        install();
        if STOPPING.load(Ordering::SeqCst) {
            while WAKE.load(Ordering::SeqCst) >= 0 {
                std::thread::sleep(std::time::Duration::from_millis(50));
            }
            return Err(io::Error::new(
                io::ErrorKind::Interrupted,
                "interrupted",
            ));
        }
        command.process_group(0);
        Ok(())
    }

    /// A folder removed on a terminal signal until this is dropped.
    pub struct Removal(PathBuf);

    impl Drop for Removal {
        fn drop(&mut self) {
            let mut folders = FOLDERS.lock().unwrap_or_else(|e| e.into_inner());
            folders.retain(|folder| *folder != self.0);
        }
    }

    /// Removes `folder` (and everything in it) if raystep is stopped by
    /// Ctrl-C, hang-up or termination while the returned [`Removal`] lives.
    pub fn remove_on_interrupt(folder: &Path) -> Removal {
        install();
        static REMOVER: OnceLock<()> = OnceLock::new();
        REMOVER.get_or_init(|| {
            let mut fds = [0; 2];
            // SAFETY: `fds` has room for the two descriptors.
            if unsafe { libc::pipe(fds.as_mut_ptr()) } != 0 {
                return; // no remover: the folder stays, as before
            }
            let read = fds[0];
            std::thread::spawn(move || {
                let mut sig = 0u8;
                // SAFETY: one byte into `sig`.
                while unsafe { libc::read(read, (&raw mut sig).cast(), 1) } != 1
                {
                }
                // Let the processes that got the signal too (cargo, the
                // compiler) end before their folders go.
                std::thread::sleep(std::time::Duration::from_millis(300));
                let folders =
                    FOLDERS.lock().unwrap_or_else(|e| e.into_inner()).clone();
                for folder in folders {
                    for _ in 0..3 {
                        if std::fs::remove_dir_all(&folder).is_ok()
                            || !folder.exists()
                        {
                            break;
                        }
                        std::thread::sleep(std::time::Duration::from_millis(
                            200,
                        ));
                    }
                }
                // SAFETY: as in `forward`.
                unsafe {
                    libc::signal(c_int::from(sig), SIG_DFL);
                    libc::raise(c_int::from(sig));
                }
            });
            WAKE.store(fds[1], Ordering::SeqCst);
        });
        let folder = folder.to_path_buf();
        FOLDERS
            .lock()
            .unwrap_or_else(|e| e.into_inner())
            .push(folder.clone());
        Removal(folder)
    }

    /// The process group of a running child; forgotten when dropped.
    pub struct Group {
        id: pid_t,
        slot: Option<usize>,
    }

    impl Group {
        pub fn new(child: &Child) -> Group {
            let id = pid_t::try_from(child.id()).unwrap_or(0);
            let slot = RUNNING.iter().position(|slot| {
                slot.compare_exchange(0, id, Ordering::SeqCst, Ordering::SeqCst)
                    .is_ok()
            });
            Group { id, slot }
        }

        /// Whether the child has ended, without reaping it: while it is not
        /// reaped its process id (the group's) cannot be given to another
        /// process, so [`Group::kill`] reaches only what it started.
        pub fn exited(&self, child: &mut Child) -> io::Result<bool> {
            if self.id <= 0 {
                return child.try_wait().map(|status| status.is_some());
            }
            // SAFETY: `info` is written by waitid; zeroed is a valid value.
            let mut info: libc::siginfo_t = unsafe { std::mem::zeroed() };
            let flags = libc::WEXITED | libc::WNOHANG | libc::WNOWAIT;
            // SAFETY: a child of this process, `info` is valid.
            let done = unsafe {
                libc::waitid(
                    libc::P_PID,
                    self.id as libc::id_t,
                    &mut info,
                    flags,
                )
            };
            if done != 0 {
                return Err(io::Error::last_os_error());
            }
            // SAFETY: set by waitid (0 while the child still runs).
            Ok(unsafe { info.si_pid() } != 0)
        }

        /// Kills every process in the group (the child is not reaped yet, so
        /// the group id is still ours).
        pub fn kill(&self, child: &mut Child) {
            if self.id > 0 {
                // SAFETY: sending a signal has no memory-safety preconditions.
                unsafe {
                    libc::kill(-self.id, SIGKILL);
                }
            }
            let _ = child.kill();
        }
    }

    impl Drop for Group {
        fn drop(&mut self) {
            if let Some(slot) = self.slot {
                RUNNING[slot].store(0, Ordering::SeqCst);
            }
        }
    }
}

#[cfg(not(unix))]
mod elsewhere {
    use std::io;
    use std::path::Path;
    use std::process::{Child, Command};

    pub fn prepare(_command: &mut Command) -> io::Result<()> {
        Ok(())
    }

    pub struct Removal;

    pub fn remove_on_interrupt(_folder: &Path) -> Removal {
        Removal
    }

    pub struct Group;

    impl Group {
        pub fn new(_child: &Child) -> Group {
            Group
        }

        pub fn exited(&self, child: &mut Child) -> io::Result<bool> {
            child.try_wait().map(|status| status.is_some())
        }

        pub fn kill(&self, child: &mut Child) {
            let _ = child.kill();
        }
    }
}
