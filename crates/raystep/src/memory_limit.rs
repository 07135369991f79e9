//! How much memory a process may ask for: the operating system's limit on
//! its data (`RLIMIT_DATA`), set in the child just before it starts and
//! inherited by every process it starts.
//!
//! `RLIMIT_DATA` counts the private, writable memory a process maps: its
//! heap, every `Vec`'s buffer, the stacks of its threads; not the code it
//! runs or files it maps. A request past it fails at once (`mmap` says
//! `ENOMEM`), so Rust's runtime prints `memory allocation of N bytes
//! failed` and aborts: the test that asked for it ends, and the machine
//! never starts swapping. (On Linux since 4.7. Elsewhere this limit is not
//! set, and only the time limit stops a hog.)

use std::process::Command;

/// Limits the process `command` starts (and its children) to `bytes` of
/// data memory.
#[cfg(target_os = "linux")]
pub fn set(command: &mut Command, bytes: u64) {
    use std::os::unix::process::CommandExt;
    let limit = libc::rlimit {
        rlim_cur: bytes,
        rlim_max: bytes,
    };
    // SAFETY: the closure runs in the child between fork and exec, where
    // only async-signal-safe calls are allowed: `setrlimit` is a plain
    // system call, and nothing is allocated.
    unsafe {
        command.pre_exec(move || {
            if libc::setrlimit(libc::RLIMIT_DATA, &limit) == 0 {
                Ok(())
            } else {
                Err(std::io::Error::last_os_error())
            }
        });
    }
}

/// Not set off Linux (see the module's comment).
#[cfg(not(target_os = "linux"))]
pub fn set(_command: &mut Command, _bytes: u64) {}
