//! `raystep watch [chNN]`: the student's loop. Checks the chapter (by
//! default the first with an exercise not passed yet), then again on every
//! save in its `exercise/` folder, and shows after each check the first
//! exercise not passed, what passed, and the hint to ask for; or, once the
//! chapter passes, what is next.
//!
//! Each check is this program run as `raystep check chNN --quiet --json
//! FILE` ([`crate::check_child`]), which also records the verdicts for
//! `raystep progress`. One check runs at a time: a save while it runs
//! checks again when it ends. Ctrl-C stops the running check, with its
//! build and its test binary, and then the watch.
//!
//! On a terminal each view replaces the last (the screen is cleared);
//! otherwise the views follow each other as plain lines.

use std::io::{self, IsTerminal, Write};
use std::path::Path;
use std::process::ExitCode;
use std::sync::mpsc::{self, Receiver, RecvTimeoutError};
use std::time::Duration;

use notify_debouncer_full::notify::RecursiveMode;
use notify_debouncer_full::notify::event::{
    AccessKind, AccessMode, EventKind, MetadataKind, ModifyKind,
};
use notify_debouncer_full::{DebounceEventResult, new_debouncer};
use raystep_figure::Chapter;

use crate::check_child::CheckChild;
use crate::error::Error;
use crate::shown_path::relative;
use crate::watch_view::{CheckReport, view};
use crate::{chapters, progress, progress_file, workspace};

/// Saves closer together than this are one save (an editor writes a
/// file in several steps; "save all" writes several files).
const DEBOUNCE: Duration = Duration::from_millis(300);

/// The exit status after Ctrl-C, as a shell reports a process it ended.
const INTERRUPTED: u8 = 130;

/// ANSI: clear the screen and put the cursor at its top left.
const CLEAR: &str = "\x1b[2J\x1b[H";

/// What the loop waits for.
enum Event {
    /// A source file in the exercise folder was saved.
    Saved,
    /// Ctrl-C, hang-up or termination.
    Quit,
    /// The folder cannot be watched any more (why).
    Trouble(String),
}

/// Runs `raystep watch`, on the chapter named by `chapter` (`ch01`, `01`,
/// `1`) or else the first one not passed.
pub fn run(chapter: Option<&str>) -> Result<ExitCode, Error> {
    let root = workspace::root();
    let (lecture, _) = progress::lecture(&root, chapters::CHAPTERS);
    let Some(chapter) = chapter_to_watch(&root, &lecture, chapter)? else {
        println!(
            "every chapter passes (`raystep progress` lists them); to watch \
             one anyway: raystep watch chNN"
        );
        return Ok(ExitCode::SUCCESS);
    };
    let folder = root.join("chapters").join(chapter.package).join("exercise");
    if !folder.is_dir() {
        return Err(Error::io(
            &folder,
            io::Error::new(io::ErrorKind::NotFound, "no such folder"),
        ));
    }
    let program = std::env::current_exe()
        .map_err(|e| Error::io(Path::new("raystep"), e))?;
    let (events, _debouncer) = events(&folder)?;
    let scratch =
        tempfile::tempdir().map_err(|e| Error::io(&std::env::temp_dir(), e))?;
    let json = scratch.path().join("report.json");
    let terminal = io::stdout().is_terminal();
    let watched = format!("{}/", relative(&folder).display());
    loop {
        // (An error writing: no one reads what the watch says any more.)
        if say(&format!("checking {}…\n", chapter.id)).is_err() {
            return Ok(ExitCode::FAILURE);
        }
        let _ = std::fs::remove_file(&json);
        let mut check = CheckChild::start(&program, &root, chapter.id, &json)?;
        let Some(again) = wait_for(&mut check, &events) else {
            return Ok(ExitCode::from(INTERRUPTED));
        };
        let text = match std::fs::read_to_string(&json) {
            Ok(text) => match CheckReport::parse(&text) {
                Ok(report) => {
                    let next = next_chapter(&root, &lecture, chapter);
                    view(&report, next.as_deref(), &watched)
                }
                Err(why) => could_not_check(
                    &format!("its report is not one: {why}"),
                    &watched,
                ),
            },
            Err(_) => could_not_check(&check.stderr(), &watched),
        };
        let shown = if terminal {
            say(&format!("{CLEAR}{text}"))
        } else {
            say(&format!("{text}\n"))
        };
        if shown.is_err() {
            return Ok(ExitCode::FAILURE);
        }
        if !again && !wait_for_save(&events) {
            return Ok(ExitCode::from(INTERRUPTED));
        }
    }
}

/// The chapter named by `arg`, else the first with an item not passed as
/// the progress file says (`None` if every chapter passes); an error if it
/// has nothing to watch.
fn chapter_to_watch<'a>(
    root: &Path, lecture: &[progress::ChapterItems<'a>], arg: Option<&str>,
) -> Result<Option<&'a Chapter>, Error> {
    let recorded = progress_file::read(root).ok().flatten().unwrap_or_default();
    let chapter = match arg {
        Some(arg) => chapters::find(arg, chapters::CHAPTERS)?,
        None => match progress::next(lecture, &recorded, None) {
            Some((chapter, _)) => chapter,
            None => return Ok(None),
        },
    };
    let has_items = lecture
        .iter()
        .any(|c| c.chapter.id == chapter.id && !c.items.is_empty());
    if !has_items {
        return Err(Error::Usage(format!(
            "{}: this chapter has no exercises to watch",
            chapter.id
        )));
    }
    Ok(Some(chapter))
}

/// The file watcher on `folder`.
type Watcher = notify_debouncer_full::Debouncer<
    notify_debouncer_full::notify::RecommendedWatcher,
    notify_debouncer_full::RecommendedCache,
>;

/// The loop's events: saves in `folder` (from the returned watcher, which
/// watches while it lives) and Ctrl-C.
fn events(folder: &Path) -> Result<(Receiver<Event>, Watcher), Error> {
    let (send, events) = mpsc::channel();
    let quit = send.clone();
    ctrlc::set_handler(move || {
        let _ = quit.send(Event::Quit);
    })
    .map_err(|e| Error::Usage(format!("cannot catch Ctrl-C: {e}")))?;
    let mut watcher = new_debouncer(DEBOUNCE, None, move |result| {
        if let Some(event) = saved(result) {
            let _ = send.send(event);
        }
    })
    .map_err(|e| Error::Usage(format!("cannot watch files: {e}")))?;
    watcher
        .watch(folder, RecursiveMode::NonRecursive)
        .map_err(|e| Error::io(folder, io::Error::other(e.to_string())))?;
    Ok((events, watcher))
}

/// Waits until `check` ends: whether a file was saved meanwhile (check
/// again), or `None` on Ctrl-C (the check is stopped first).
fn wait_for(check: &mut CheckChild, events: &Receiver<Event>) -> Option<bool> {
    let mut again = false;
    while !check.ended() {
        match events.recv_timeout(Duration::from_millis(50)) {
            Ok(Event::Saved) => again = true,
            Ok(Event::Quit) => {
                check.stop();
                return None;
            }
            Ok(Event::Trouble(why)) => eprintln!("warning: {why}"),
            Err(RecvTimeoutError::Timeout) => {}
            // (Cannot happen: the Ctrl-C handler keeps a sender.)
            Err(RecvTimeoutError::Disconnected) => {
                std::thread::sleep(Duration::from_millis(50));
            }
        }
    }
    Some(again)
}

/// Waits for a save: `false` on Ctrl-C.
fn wait_for_save(events: &Receiver<Event>) -> bool {
    loop {
        match events.recv() {
            Ok(Event::Saved) => return true,
            Ok(Event::Quit) | Err(_) => return false,
            Ok(Event::Trouble(why)) => eprintln!("warning: {why}"),
        }
    }
}

/// The chapter to watch once `chapter` passes: the first after it with
/// an exercise not passed (else the first before it), as the progress
/// file now says; `None` if every chapter passes.
fn next_chapter(
    root: &Path, lecture: &[progress::ChapterItems], chapter: &Chapter,
) -> Option<String> {
    let recorded = progress_file::read(root).ok().flatten().unwrap_or_default();
    progress::next(lecture, &recorded, Some(chapter.id))
        .map(|(next, _)| next.id.to_string())
}

/// The view when the check wrote no report: the last lines it said (of
/// `said`).
fn could_not_check(said: &str, watched: &str) -> String {
    let lines: Vec<&str> =
        said.lines().filter(|l| !l.trim().is_empty()).collect();
    let last = &lines[lines.len().saturating_sub(5)..];
    let mut text = String::from("the check could not run:\n");
    for line in last {
        text.push_str(&format!("  {line}\n"));
    }
    text.push_str(&format!(
        "watching {watched} — save a file to check again, Ctrl-C to quit\n"
    ));
    text
}

/// Writes `text` on stdout at once; an error if stdout is closed (a pipe
/// whose reader has gone).
fn say(text: &str) -> io::Result<()> {
    let mut out = io::stdout().lock();
    out.write_all(text.as_bytes())?;
    out.flush()
}

/// What a batch of file events means for the loop: a save of a source
/// file, trouble, or nothing (reads, editors' temporary files).
fn saved(result: DebounceEventResult) -> Option<Event> {
    match result {
        Ok(events) => events
            .iter()
            .any(|e| is_write(e.kind) && e.paths.iter().any(|p| is_source(p)))
            .then_some(Event::Saved),
        Err(errors) => Some(Event::Trouble(
            errors
                .iter()
                .map(ToString::to_string)
                .collect::<Vec<_>>()
                .join("; "),
        )),
    }
}

/// Does an event of this kind change the file? Opening and reading do
/// not (the compiler reads every exercise file at each check), nor does
/// a new access time.
fn is_write(kind: EventKind) -> bool {
    match kind {
        EventKind::Create(_) | EventKind::Remove(_) => true,
        EventKind::Modify(ModifyKind::Metadata(MetadataKind::AccessTime)) => {
            false
        }
        EventKind::Modify(_) => true,
        EventKind::Access(AccessKind::Close(AccessMode::Write)) => true,
        EventKind::Access(_) | EventKind::Any | EventKind::Other => false,
    }
}

/// Is this a file the check reads: `*.rs` or `*.toml`, and not an
/// editor's temporary file (`.x.rs.swp`, `.#x.rs`, `#x.rs#`, `x.rs~`)?
fn is_source(path: &Path) -> bool {
    let Some(name) = path.file_name().and_then(|n| n.to_str()) else {
        return false;
    };
    (name.ends_with(".rs") || name.ends_with(".toml"))
        && !name.starts_with('.')
        && !name.starts_with('#')
}

#[cfg(test)]
mod tests {
    use super::*;
    use notify_debouncer_full::DebouncedEvent;
    use notify_debouncer_full::notify::Event as NotifyEvent;
    use notify_debouncer_full::notify::event::{CreateKind, DataChange};
    use std::time::Instant;

    #[test]
    fn only_source_files_count() {
        for name in ["ray_plane.rs", "answers.toml", "/a/b/exercise/x.rs"] {
            assert!(is_source(Path::new(name)), "{name}");
        }
        for name in [
            ".ray_plane.rs.swp",
            ".#ray_plane.rs",
            "#ray_plane.rs#",
            "ray_plane.rs~",
            "4913",
            ".answers.toml.x1y2.partial",
            "notes.md",
        ] {
            assert!(!is_source(Path::new(name)), "{name}");
        }
    }

    fn batch(kind: EventKind, path: &str) -> DebounceEventResult {
        let event = NotifyEvent::new(kind).add_path(path.into());
        Ok(vec![DebouncedEvent::new(event, Instant::now())])
    }

    #[test]
    fn writes_are_saves_and_reads_are_not() {
        let save =
            |kind, path| matches!(saved(batch(kind, path)), Some(Event::Saved));
        let write = EventKind::Modify(ModifyKind::Data(DataChange::Content));
        assert!(save(write, "exercise/a.rs"));
        assert!(save(EventKind::Create(CreateKind::File), "exercise/a.rs"));
        assert!(save(
            EventKind::Access(AccessKind::Close(AccessMode::Write)),
            "exercise/answers.toml"
        ));
        assert!(!save(write, "exercise/.a.rs.swp"));
        assert!(!save(
            EventKind::Access(AccessKind::Open(AccessMode::Any)),
            "exercise/a.rs"
        ));
        assert!(!save(
            EventKind::Access(AccessKind::Close(AccessMode::Read)),
            "exercise/a.rs"
        ));
        assert!(!save(
            EventKind::Modify(ModifyKind::Metadata(MetadataKind::AccessTime)),
            "exercise/a.rs"
        ));
        assert!(saved(Ok(Vec::new())).is_none());
    }

    #[test]
    fn a_check_that_wrote_no_report_shows_its_last_lines() {
        let stderr = "\n".to_string()
            + &(1..=7).map(|n| format!("line {n}\n")).collect::<String>();
        assert_eq!(
            could_not_check(&stderr, "x/"),
            "the check could not run:\n  line 3\n  line 4\n  line 5\n  \
             line 6\n  line 7\nwatching x/ — save a file to check again, \
             Ctrl-C to quit\n"
        );
    }
}
