//! Running a process under limits: time, memory and output. Its output is
//! captured; at the time limit, or once it has printed more than the output
//! limit, it is killed with every process it started (its process group),
//! and when it ends by itself whatever it started and left running is
//! killed too. How it ended, said as cargo says it.

use std::io::{self, Read};
use std::process::{Child, Command, ExitStatus, Stdio};
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::{Arc, Mutex, mpsc};
use std::time::{Duration, Instant};

use crate::{memory_limit, process_group};

/// How a process run by [`run_with_limit`] ended.
#[derive(Debug)]
pub(crate) enum Exit {
    /// By itself.
    Status(ExitStatus),
    /// It was still running at the limit, and was killed with every process
    /// of its process group.
    TimedOut,
    /// It printed more than the output limit (stdout and stderr together),
    /// and was killed with every process of its process group.
    OutputCut,
}

/// What a process run by [`run_with_limit`] may use.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct Limits {
    /// How long it may run.
    pub time: Duration,
    /// How many bytes of memory it (and each process it starts) may ask
    /// for; see [`crate::memory_limit`].
    pub memory: Option<u64>,
    /// How many bytes it may print, stdout and stderr together; what comes
    /// after is not kept.
    pub output: Option<u64>,
}

impl Limits {
    /// A time limit only.
    pub fn time(time: Duration) -> Limits {
        Limits {
            time,
            memory: None,
            output: None,
        }
    }
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

/// Runs `command` (stdin empty, stdout and stderr captured) within
/// `limits`. On Unix the process leads a process group of its own: at the
/// time limit, or past the output limit, the whole group is killed (the
/// process and anything it started), and when the process ends by itself
/// the rest of its group is killed before it is reaped. Ctrl-C still stops
/// it: raystep's terminal signals are forwarded to the group (see
/// [`process_group`]). The memory limit is the operating system's, set in
/// the process before it starts ([`memory_limit`]).
pub(crate) fn run_with_limit(
    command: &mut Command, limits: Limits,
) -> io::Result<Ran> {
    command
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped());
    process_group::prepare(command)?;
    if let Some(bytes) = limits.memory {
        memory_limit::set(command, bytes);
    }
    let mut child = command.spawn()?;
    let group = process_group::Group::new(&child);

    let budget = Arc::new(Budget::new(limits.output));
    let stdout =
        capture(child.stdout.take().expect("stdout is piped"), &budget);
    let stderr =
        capture(child.stderr.take().expect("stderr is piped"), &budget);
    let exit = wait_with_limit(
        &mut child,
        &group,
        Instant::now() + limits.time,
        &budget,
    );
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

/// How many bytes the process may still print, over both pipes.
struct Budget {
    limit: Option<u64>,
    printed: AtomicU64,
}

impl Budget {
    fn new(limit: Option<u64>) -> Budget {
        Budget {
            limit,
            printed: AtomicU64::new(0),
        }
    }

    /// Counts `n` more bytes: how many of them may be kept.
    fn take(&self, n: usize) -> usize {
        let before = self.printed.fetch_add(n as u64, Ordering::SeqCst);
        match self.limit {
            None => n,
            Some(limit) => usize::try_from(limit.saturating_sub(before))
                .map_or(n, |left| left.min(n)),
        }
    }

    /// Whether more than the limit has been printed.
    fn exceeded(&self) -> bool {
        self.limit
            .is_some_and(|limit| self.printed.load(Ordering::SeqCst) > limit)
    }
}

/// Reads `pipe` to its end on a thread of its own, keeping what `budget`
/// allows (the rest is read and dropped, so the process is never blocked
/// on a full pipe before it is killed).
fn capture(
    mut pipe: impl Read + Send + 'static, budget: &Arc<Budget>,
) -> Captured {
    let bytes = Arc::new(Mutex::new(Vec::new()));
    let (done, finished) = mpsc::channel();
    let sink = Arc::clone(&bytes);
    let budget = Arc::clone(budget);
    std::thread::spawn(move || {
        let mut buffer = [0; 8192];
        while let Ok(n @ 1..) = pipe.read(&mut buffer) {
            let kept = budget.take(n);
            sink.lock()
                .unwrap_or_else(|e| e.into_inner())
                .extend_from_slice(&buffer[..kept]);
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

/// Waits for `child` until `deadline` or until it has printed more than
/// its `budget`, then kills its process group. When it ends by itself,
/// what it left running in its group is killed before it is reaped.
fn wait_with_limit(
    child: &mut Child, group: &process_group::Group, deadline: Instant,
    budget: &Budget,
) -> io::Result<Exit> {
    let mut pause = Duration::from_millis(1);
    loop {
        match group.exited(child) {
            Ok(true) => {
                group.kill(child);
                return Ok(Exit::Status(child.wait()?));
            }
            Ok(false) => {}
            Err(error) => {
                group.kill(child);
                let _ = child.wait();
                return Err(error);
            }
        }
        if budget.exceeded() {
            group.kill(child);
            child.wait()?;
            return Ok(Exit::OutputCut);
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

/// How a process run inside the sandbox ended. The sandbox's first
/// process reports a death by signal N as exit status 128 + N, so such a
/// status is said as the signal it most likely was.
pub(crate) fn describe_sandboxed_status(status: ExitStatus) -> String {
    #[cfg(unix)]
    if let Some(code @ 129..=192) = status.code() {
        return format!(
            "{} (exit status {code} from the sandbox)",
            describe_signal(code - 128)
        );
    }
    describe_status(status)
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

/// The runtime's note when an allocation failed (the process then
/// aborts): `memory allocation of 6442450944 bytes failed`, as `6 GiB`.
pub(crate) fn out_of_memory(stderr: &str) -> Option<String> {
    stderr.lines().find_map(|line| {
        let bytes: u64 = line
            .trim()
            .strip_prefix("memory allocation of ")?
            .strip_suffix(" bytes failed")?
            .parse()
            .ok()?;
        let gib = bytes as f64 / (1u64 << 30) as f64;
        Some(if gib >= 0.1 {
            format!("it asked for {gib:.1} GiB at once")
        } else {
            format!("it asked for {bytes} bytes at once")
        })
    })
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
            Limits::time(Duration::from_millis(300)),
        )
        .unwrap();
        assert!(matches!(ran.exit, Exit::TimedOut), "{ran:?}");
    }

    /// Whether process `pid` has ended (or is a zombie nobody has reaped
    /// yet), waiting up to 5 s: SIGKILL is delivered at once, but give the
    /// kernel a moment all the same.
    #[cfg(target_os = "linux")]
    fn ends(pid: u32) -> bool {
        let dead = || {
            std::fs::read_to_string(format!("/proc/{pid}/stat")).map_or(
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
        dead()
    }

    /// The processes a test binary started die with it.
    #[cfg(target_os = "linux")]
    #[test]
    fn a_killed_process_takes_its_children_along() {
        let ran = run_with_limit(
            &mut shell("sleep 30 & echo $!; wait"),
            Limits::time(Duration::from_millis(300)),
        )
        .unwrap();
        assert!(matches!(ran.exit, Exit::TimedOut), "{ran:?}");
        let sleep: u32 = ran.stdout.trim().parse().expect("the child's pid");
        assert!(ends(sleep), "sleep {sleep} outlived the kill");
    }

    /// A process that ends by itself leaves nothing running: a child it
    /// left behind in its group is killed before the process is reaped.
    #[cfg(target_os = "linux")]
    #[test]
    fn nothing_a_process_started_outlives_it() {
        let ran = run_with_limit(
            &mut shell("sleep 30 >/dev/null 2>&1 & echo $!"),
            Limits::time(Duration::from_secs(30)),
        )
        .unwrap();
        assert!(
            matches!(ran.exit, Exit::Status(status) if status.success()),
            "{ran:?}"
        );
        let sleep: u32 = ran.stdout.trim().parse().expect("the child's pid");
        assert!(ends(sleep), "sleep {sleep} outlived its parent");
    }

    /// Printing without end is cut at the output limit: the process is
    /// killed, and only the limit's bytes are kept.
    #[cfg(unix)]
    #[test]
    fn a_flood_of_output_is_cut_at_the_limit() {
        let limits = Limits {
            output: Some(100_000),
            ..Limits::time(Duration::from_secs(30))
        };
        let ran = run_with_limit(&mut shell("yes flood"), limits).unwrap();
        assert!(matches!(ran.exit, Exit::OutputCut), "{:?}", ran.exit);
        assert_eq!(ran.stdout.len() + ran.stderr.len(), 100_000);
        assert!(ran.stdout.starts_with("flood\nflood\n"));
        // Under the limit nothing is cut.
        let ran = run_with_limit(&mut shell("echo fine"), limits).unwrap();
        assert_eq!(ran.stdout, "fine\n");
    }

    /// Not a test of its own: the process [`memory_past_the_limit_is_refused`]
    /// starts, which asks for 6 GiB at once when `RAYSTEP_TEST_HOG` is set.
    #[test]
    fn memory_hog() {
        if std::env::var_os("RAYSTEP_TEST_HOG").is_some() {
            let hog = vec![1u8; 6 << 30];
            println!("held {} bytes", std::hint::black_box(hog).len());
        }
    }

    /// A process that asks for more memory than its limit is refused it,
    /// and the runtime says so as it aborts; within the limit it is not.
    #[cfg(target_os = "linux")]
    #[test]
    fn memory_past_the_limit_is_refused() {
        let hog = || {
            let mut command = Command::new(std::env::current_exe().unwrap());
            command
                .args(["--exact", "limited_process::tests::memory_hog"])
                .args(["--nocapture", "--test-threads", "1"])
                .env("RAYSTEP_TEST_HOG", "1");
            command
        };
        let limits = Limits {
            memory: Some(1 << 30),
            ..Limits::time(Duration::from_secs(60))
        };
        let ran = run_with_limit(&mut hog(), limits).unwrap();
        assert!(
            matches!(ran.exit, Exit::Status(status) if !status.success()),
            "{ran:?}"
        );
        assert!(
            ran.stderr
                .contains("memory allocation of 6442450944 bytes failed"),
            "{}",
            ran.stderr
        );
        assert!(!ran.stdout.contains("held"), "{}", ran.stdout);
        // The same process without the variable is well within the limit.
        let mut small = hog();
        small.env_remove("RAYSTEP_TEST_HOG");
        let ran = run_with_limit(&mut small, limits).unwrap();
        assert!(
            matches!(ran.exit, Exit::Status(status) if status.success()),
            "{ran:?}"
        );
    }

    #[cfg(unix)]
    #[test]
    fn how_a_process_ended_is_said_as_cargo_says_it() {
        let ran = run_with_limit(
            &mut shell("echo partial; exit 3"),
            Limits::time(Duration::from_secs(30)),
        )
        .unwrap();
        assert_eq!(ran.stdout, "partial\n");
        let Exit::Status(status) = ran.exit else {
            panic!("{ran:?}")
        };
        assert_eq!(describe_status(status), "exit status: 3");
        let ran = run_with_limit(
            &mut shell("kill -ABRT $$"),
            Limits::time(Duration::from_secs(30)),
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
        let ran = run_with_limit(
            &mut shell("exit 134"),
            Limits::time(Duration::from_secs(30)),
        )
        .unwrap();
        let Exit::Status(status) = ran.exit else {
            panic!("{ran:?}")
        };
        assert_eq!(
            describe_sandboxed_status(status),
            "signal: 6, SIGABRT: process abort signal (exit status 134 from the sandbox)"
        );
        assert_eq!(describe_status(status), "exit status: 134");
    }

    #[test]
    fn out_of_memory_is_said_with_its_size() {
        let stderr = "\nmemory allocation of 6442450944 bytes failed\n";
        assert_eq!(
            out_of_memory(stderr).as_deref(),
            Some("it asked for 6.0 GiB at once")
        );
        assert_eq!(
            out_of_memory("memory allocation of 4096 bytes failed").as_deref(),
            Some("it asked for 4096 bytes at once")
        );
        assert_eq!(out_of_memory("thread 'x' panicked"), None);
    }
}
