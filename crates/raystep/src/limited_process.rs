//! Running a process with a time limit: its output captured, and at the
//! limit it is killed with every process it started (its process group);
//! how it ended, said as cargo says it.

use std::io::{self, Read};
use std::process::{Child, Command, ExitStatus, Stdio};
use std::sync::{Arc, Mutex, mpsc};
use std::time::{Duration, Instant};

use crate::process_group;

/// How a process run by [`run_with_limit`] ended.
#[derive(Debug)]
pub(crate) enum Exit {
    /// By itself.
    Status(ExitStatus),
    /// It was still running at the limit, and was killed with every process
    /// of its process group.
    TimedOut,
}

/// What [`run_with_limit`] saw.
#[derive(Debug)]
pub(crate) struct Ran {
    /// Everything the process printed on stdout (until it was killed).
    pub stdout: String,
    /// Everything it printed on stderr: where a crash says what it was
    /// (`thread 'x' has overflowed its stack`).
    pub stderr: String,
    /// How it ended.
    pub exit: Exit,
}

/// Runs `command` (stdin empty, stdout and stderr captured) for at
/// most `limit`. On Unix the process leads a process group of its own, and
/// at the limit the whole group is killed: the process and anything it
/// started. Ctrl-C still stops it: raystep's terminal signals are forwarded
/// to the group (see [`process_group`]).
pub(crate) fn run_with_limit(
    command: &mut Command, limit: Duration,
) -> io::Result<Ran> {
    command
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped());
    process_group::prepare(command);
    let mut child = command.spawn()?;
    let group = process_group::Group::new(&child);

    let stdout = capture(child.stdout.take().expect("stdout is piped"));
    let stderr = capture(child.stderr.take().expect("stderr is piped"));
    let exit = wait_with_limit(&mut child, &group, Instant::now() + limit);
    drop(group);
    let exit = exit?;
    Ok(Ran {
        stdout: stdout.text(),
        stderr: stderr.text(),
        exit,
    })
}

/// A pipe read to its end on a thread of its own.
struct Captured {
    bytes: Arc<Mutex<Vec<u8>>>,
    finished: mpsc::Receiver<()>,
}

fn capture(mut pipe: impl Read + Send + 'static) -> Captured {
    let bytes = Arc::new(Mutex::new(Vec::new()));
    let (done, finished) = mpsc::channel();
    let sink = Arc::clone(&bytes);
    std::thread::spawn(move || {
        let mut buffer = [0; 8192];
        while let Ok(n @ 1..) = pipe.read(&mut buffer) {
            sink.lock()
                .unwrap_or_else(|e| e.into_inner())
                .extend_from_slice(&buffer[..n]);
        }
        let _ = done.send(());
    });
    Captured { bytes, finished }
}

impl Captured {
    /// What came through. The pipe closes when the last process holding it
    /// has ended: at once after a kill. A process the binary started that
    /// outlives it (in another process group) could hold it open: do not
    /// wait for that.
    fn text(self) -> String {
        let _ = self.finished.recv_timeout(Duration::from_secs(2));
        String::from_utf8_lossy(
            &self.bytes.lock().unwrap_or_else(|e| e.into_inner()),
        )
        .into_owned()
    }
}

/// Waits for `child` until `deadline`, then kills its process group.
fn wait_with_limit(
    child: &mut Child, group: &process_group::Group, deadline: Instant,
) -> io::Result<Exit> {
    let mut pause = Duration::from_millis(1);
    loop {
        match child.try_wait() {
            Ok(Some(status)) => return Ok(Exit::Status(status)),
            Ok(None) => {}
            Err(error) => {
                group.kill(child);
                let _ = child.wait();
                return Err(error);
            }
        }
        let now = Instant::now();
        if now >= deadline {
            group.kill(child);
            child.wait()?;
            return Ok(Exit::TimedOut);
        }
        std::thread::sleep(pause.min(deadline - now));
        pause = (pause * 2).min(Duration::from_millis(20));
    }
}

/// How a process ended, as cargo says it: `exit status: 101`,
/// `signal: 6, SIGABRT: process abort signal`.
pub(crate) fn describe_status(status: ExitStatus) -> String {
    #[cfg(unix)]
    {
        use std::os::unix::process::ExitStatusExt;
        if let Some(signal) = status.signal() {
            return describe_signal(signal);
        }
    }
    status.to_string()
}

/// `signal: 6, SIGABRT: process abort signal`, with cargo's names.
#[cfg(unix)]
fn describe_signal(signal: i32) -> String {
    let name = match signal {
        1 => "SIGHUP: hangup",
        2 => "SIGINT: terminal interrupt signal",
        3 => "SIGQUIT: terminal quit signal",
        4 => "SIGILL: illegal instruction",
        5 => "SIGTRAP: trace/breakpoint trap",
        6 => "SIGABRT: process abort signal",
        8 => "SIGFPE: erroneous arithmetic operation",
        9 => "SIGKILL: kill",
        11 => "SIGSEGV: invalid memory reference",
        13 => "SIGPIPE: write on a pipe with no one to read",
        14 => "SIGALRM: alarm clock",
        15 => "SIGTERM: termination signal",
        #[cfg(any(target_os = "linux", target_os = "android"))]
        7 => "SIGBUS: access to undefined memory",
        #[cfg(any(target_os = "linux", target_os = "android"))]
        31 => "SIGSYS: bad system call",
        #[cfg(not(any(target_os = "linux", target_os = "android")))]
        10 => "SIGBUS: access to undefined memory",
        #[cfg(not(any(target_os = "linux", target_os = "android")))]
        12 => "SIGSYS: bad system call",
        _ => return format!("signal: {signal}"),
    };
    format!("signal: {signal}, {name}")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[cfg(unix)]
    fn shell(script: &str) -> Command {
        let mut command = Command::new("sh");
        command.args(["-c", script]);
        command
    }

    #[cfg(unix)]
    #[test]
    fn a_process_past_its_limit_is_killed() {
        let ran = run_with_limit(
            Command::new("sleep").arg("30"),
            Duration::from_millis(300),
        )
        .unwrap();
        assert!(matches!(ran.exit, Exit::TimedOut), "{ran:?}");
    }

    /// The processes a test binary started die with it.
    #[cfg(target_os = "linux")]
    #[test]
    fn a_killed_process_takes_its_children_along() {
        let ran = run_with_limit(
            &mut shell("sleep 30 & echo $!; wait"),
            Duration::from_millis(300),
        )
        .unwrap();
        assert!(matches!(ran.exit, Exit::TimedOut), "{ran:?}");
        let sleep: u32 = ran.stdout.trim().parse().expect("the child's pid");
        // Dead (or a zombie nobody has reaped yet); SIGKILL is delivered at once,
        // give the kernel a moment all the same.
        let dead = || {
            std::fs::read_to_string(format!("/proc/{sleep}/stat")).map_or(
                true,
                |stat| {
                    stat.rsplit_once(") ")
                        .is_some_and(|(_, s)| s.starts_with('Z'))
                },
            )
        };
        let until = Instant::now() + Duration::from_secs(5);
        while !dead() && Instant::now() < until {
            std::thread::sleep(Duration::from_millis(10));
        }
        assert!(dead(), "sleep {sleep} outlived the kill");
    }

    #[cfg(unix)]
    #[test]
    fn how_a_process_ended_is_said_as_cargo_says_it() {
        let ran = run_with_limit(
            &mut shell("echo partial; exit 3"),
            Duration::from_secs(30),
        )
        .unwrap();
        assert_eq!(ran.stdout, "partial\n");
        let Exit::Status(status) = ran.exit else {
            panic!("{ran:?}")
        };
        assert_eq!(describe_status(status), "exit status: 3");
        let ran = run_with_limit(
            &mut shell("kill -ABRT $$"),
            Duration::from_secs(30),
        )
        .unwrap();
        let Exit::Status(status) = ran.exit else {
            panic!("{ran:?}")
        };
        assert_eq!(
            describe_status(status),
            "signal: 6, SIGABRT: process abort signal"
        );
        assert_eq!(describe_signal(64), "signal: 64");
    }
}
