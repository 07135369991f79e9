//! `raystep progress`: every chapter's exercises and paper questions with
//! the verdict `check` last gave them (kept in `.raystep/progress.json`,
//! see [`crate::progress_file`]), what passed per chapter and overall, and
//! the next exercise to do.

use std::fmt::Write as _;
use std::path::Path;
use std::process::ExitCode;

use raystep_figure::Chapter;

use crate::error::Error;
use crate::progress_file::{self, Entry, Progress};
use crate::{chapters, questions, workspace};

/// One exercise or paper question of a chapter.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Item {
    /// `line_through_points`, `q1`.
    pub name: String,
    /// Worked on paper (answered in `exercise/answers.toml`).
    pub paper: bool,
    /// `★★`, or empty if not known.
    pub stars: String,
}

impl Item {
    /// `exercise shadow` or `paper question q2`.
    pub fn described(&self) -> String {
        let what = if self.paper {
            "paper question"
        } else {
            "exercise"
        };
        format!("{what} {}", self.name)
    }
}

/// A chapter and what the student does in it: its exercises, then its
/// paper questions.
#[derive(Debug)]
pub struct ChapterItems<'a> {
    pub chapter: &'a Chapter,
    pub items: Vec<Item>,
}

/// Runs `raystep progress`.
pub fn run() -> Result<ExitCode, Error> {
    let root = workspace::root();
    let (lecture, notes) = lecture(&root, chapters::CHAPTERS);
    let mut notes = notes;
    let progress = match progress_file::read(&root) {
        Ok(Some(progress)) => progress,
        Ok(None) => {
            notes.insert(
                0,
                "nothing checked yet: `raystep check chNN` (or `raystep \
                 watch`) records each verdict"
                    .to_string(),
            );
            Progress::default()
        }
        Err(error) => {
            let note =
                format!("{error}; showing every exercise as not checked");
            notes.insert(0, note);
            Progress::default()
        }
    };
    for note in &notes {
        println!("{note}");
    }
    if !notes.is_empty() {
        println!();
    }
    print!("{}", shown(&lecture, &progress));
    Ok(ExitCode::SUCCESS)
}

/// Every chapter of `chapters` with its items (paper questions from its
/// `questions.toml` in the workspace at `root`), and a line for each
/// questions file that could not be read.
pub fn lecture<'a>(
    root: &Path, chapters: &[&'a Chapter],
) -> (Vec<ChapterItems<'a>>, Vec<String>) {
    let mut notes = Vec::new();
    let lecture = chapters
        .iter()
        .map(|&chapter| {
            let mut items: Vec<Item> = chapter
                .exercises
                .iter()
                .enumerate()
                .map(|(i, name)| Item {
                    name: name.to_string(),
                    paper: false,
                    stars: chapter
                        .stars
                        .get(i)
                        .map(|&n| raystep_check::questions::stars(n))
                        .unwrap_or_default(),
                })
                .collect();
            match questions::read(root, chapter) {
                Ok(Some(file)) => {
                    items.extend(file.questions.into_iter().map(|q| Item {
                        name: q.id,
                        paper: true,
                        stars: raystep_check::questions::stars(q.stars),
                    }));
                }
                Ok(None) => {}
                Err(error) => notes.push(format!(
                    "{error}; {}'s paper questions are left out",
                    chapter.id
                )),
            }
            ChapterItems { chapter, items }
        })
        .collect();
    (lecture, notes)
}

/// The first item not passed, in lecture order, of the first chapter
/// after `after` that has one, else of the first chapter up to `after`
/// (from the start if `after` is `None`).
pub fn next<'l, 'a>(
    lecture: &'l [ChapterItems<'a>], progress: &Progress, after: Option<&str>,
) -> Option<(&'a Chapter, &'l Item)> {
    let start = after
        .and_then(|id| lecture.iter().position(|c| c.chapter.id == id))
        .map_or(0, |i| i + 1);
    let (earlier, later) = lecture.split_at(start.min(lecture.len()));
    later.iter().chain(earlier).find_map(|c| {
        let item = c.items.iter().find(|item| {
            !progress
                .entry(c.chapter.id, &item.name)
                .is_some_and(Entry::passed)
        })?;
        Some((c.chapter, item))
    })
}

/// `2 of 4 exercises and 1 of 3 paper questions passed`, as `check`
/// says it.
pub fn summary(
    code: usize, code_of: usize, paper: usize, paper_of: usize,
) -> String {
    match (code_of, paper_of) {
        (0, 0) => "no exercises".to_string(),
        (_, 0) => format!("{code} of {code_of} exercises passed"),
        (0, _) => format!("{paper} of {paper_of} paper questions passed"),
        _ => format!(
            "{code} of {code_of} exercises and {paper} of {paper_of} paper \
             questions passed"
        ),
    }
}

/// How many items passed, of how many: (code, code_of, paper, paper_of).
#[derive(Debug, Default, Clone, Copy)]
struct Counts([usize; 4]);

impl Counts {
    fn add(&mut self, item: &Item, passed: bool) {
        let at = if item.paper { 2 } else { 0 };
        self.0[at] += usize::from(passed);
        self.0[at + 1] += 1;
    }

    fn add_all(&mut self, other: Counts) {
        for (a, b) in self.0.iter_mut().zip(other.0) {
            *a += b;
        }
    }

    fn summary(self) -> String {
        let [code, code_of, paper, paper_of] = self.0;
        summary(code, code_of, paper, paper_of)
    }
}

/// The progress as printed: per chapter a table (name, stars, last
/// verdict or `not checked`) and what passed; then the overall count and
/// the next exercise.
pub fn shown(lecture: &[ChapterItems], progress: &Progress) -> String {
    let width = lecture
        .iter()
        .flat_map(|c| &c.items)
        .map(|item| shown_name(item).chars().count())
        .max()
        .unwrap_or(0);
    let mut overall = Counts::default();
    let mut text = String::new();
    for c in lecture {
        let id = c.chapter.id;
        if !text.is_empty() {
            text.push('\n');
        }
        if c.items.is_empty() {
            let _ = writeln!(text, "{id} {}: no exercises", c.chapter.title);
            continue;
        }
        let _ = writeln!(text, "{id} {}", c.chapter.title);
        let mut counts = Counts::default();
        for item in &c.items {
            let entry = progress.entry(id, &item.name);
            counts.add(item, entry.is_some_and(Entry::passed));
            let verdict = entry.map_or("not checked".to_string(), Entry::shown);
            let name = shown_name(item);
            let pad = width - name.chars().count() + 2;
            let after = 5 - item.stars.chars().count();
            let _ = writeln!(
                text,
                "  {name}{:pad$}{}{:after$}{verdict}",
                "", item.stars, ""
            );
        }
        let when = progress
            .chapters
            .get(id)
            .map_or("not checked yet".to_string(), |p| {
                format!("checked {}", utc_minute(p.checked))
            });
        let _ = writeln!(text, "  {}, {when}", counts.summary());
        overall.add_all(counts);
    }
    let _ = writeln!(text, "\noverall: {}", overall.summary());
    match next(lecture, progress, None) {
        Some((chapter, item)) => {
            let _ = writeln!(
                text,
                "next: raystep watch {} ({})",
                chapter.id,
                item.described()
            );
        }
        None => text.push_str("all passed\n"),
    }
    text
}

/// `q1 (paper)` or `shadow`.
fn shown_name(item: &Item) -> String {
    if item.paper {
        format!("{} (paper)", item.name)
    } else {
        item.name.clone()
    }
}

/// `2025-06-01 14:03 UTC` for seconds since 1970.
fn utc_minute(secs: u64) -> String {
    let days = i64::try_from(secs / 86_400).unwrap_or(0);
    let minutes = secs % 86_400 / 60;
    // Days to the civil date (proleptic Gregorian), after Howard
    // Hinnant's `civil_from_days`: eras of 400 years from 0000-03-01.
    let z = days + 719_468;
    let era = z.div_euclid(146_097);
    let doe = z.rem_euclid(146_097);
    let yoe = (doe - doe / 1_460 + doe / 36_524 - doe / 146_096) / 365;
    let doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    let mp = (5 * doy + 2) / 153;
    let day = doy - (153 * mp + 2) / 5 + 1;
    let month = if mp < 10 { mp + 3 } else { mp - 9 };
    let year = yoe + era * 400 + i64::from(month <= 2);
    format!(
        "{year}-{month:02}-{day:02} {:02}:{:02} UTC",
        minutes / 60,
        minutes % 60
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::progress_file::ChapterProgress;

    const CH01: Chapter =
        Chapter::new("ch01-lines", "Lines", &["line", "plane"]).stars(&[1, 2]);
    const CH02: Chapter = Chapter::new("ch02-hits", "Hits", &["ray_plane"]);
    const CH03: Chapter = Chapter::new("ch03-appendix", "Appendix", &[]);

    fn lecture() -> Vec<ChapterItems<'static>> {
        let (mut lecture, notes) = super::lecture(
            Path::new("/no/such/workspace"),
            &[&CH01, &CH02, &CH03],
        );
        assert_eq!(notes, Vec::<String>::new());
        lecture[0].items.push(Item {
            name: "q1".into(),
            paper: true,
            stars: "★".into(),
        });
        lecture
    }

    fn entry(name: &str, verdict: &str, message: Option<&str>) -> Entry {
        Entry {
            exercise: name.into(),
            kind: if name.starts_with('q') {
                "paper"
            } else {
                "code"
            }
            .into(),
            verdict: verdict.into(),
            message: message.map(String::from),
        }
    }

    fn checked(entries: Vec<Entry>) -> ChapterProgress {
        ChapterProgress {
            checked: 1_748_786_580,
            exercises: entries,
        }
    }

    #[test]
    fn every_chapter_is_shown_with_its_last_verdicts() {
        let mut progress = Progress::default();
        progress.chapters.insert(
            "ch01".into(),
            checked(vec![
                entry("line", "passed", None),
                entry("plane", "failed", Some("t (tests/plane.rs:3): 1 != 2")),
                entry("q1", "not attempted", None),
            ]),
        );
        assert_eq!(
            shown(&lecture(), &progress),
            "ch01 Lines\
             \n  line        ★    passed\
             \n  plane       ★★   failed: t (tests/plane.rs:3): 1 != 2\
             \n  q1 (paper)  ★    not attempted\
             \n  1 of 2 exercises and 0 of 1 paper questions passed, \
             checked 2025-06-01 14:03 UTC\
             \n\nch02 Hits\
             \n  ray_plane        not checked\
             \n  0 of 1 exercises passed, not checked yet\
             \n\nch03 Appendix: no exercises\
             \n\noverall: 1 of 3 exercises and 0 of 1 paper questions passed\
             \nnext: raystep watch ch01 (exercise plane)\n"
        );
    }

    #[test]
    fn the_next_exercise_is_the_first_not_passed() {
        let lecture = lecture();
        let mut progress = Progress::default();
        let next_of = |progress: &Progress, after| {
            next(&lecture, progress, after)
                .map(|(c, item)| format!("{} {}", c.id, item.described()))
        };
        assert_eq!(next_of(&progress, None).unwrap(), "ch01 exercise line");
        progress.chapters.insert(
            "ch01".into(),
            checked(vec![
                entry("line", "passed", None),
                entry("plane", "passed", None),
                entry("q1", "failed", Some("question 1")),
            ]),
        );
        assert_eq!(next_of(&progress, None).unwrap(), "ch01 paper question q1");
        // After ch01 passes (in `watch`): the next chapter first.
        assert_eq!(
            next_of(&progress, Some("ch01")).unwrap(),
            "ch02 exercise ray_plane"
        );
        progress.chapters.insert(
            "ch02".into(),
            checked(vec![entry("ray_plane", "passed", None)]),
        );
        assert_eq!(
            next_of(&progress, Some("ch02")).unwrap(),
            "ch01 paper question q1"
        );
        progress.chapters.get_mut("ch01").unwrap().exercises[2] =
            entry("q1", "passed", None);
        assert_eq!(next_of(&progress, Some("ch02")), None);
        assert!(shown(&lecture, &progress).ends_with(
            "overall: 3 of 3 exercises and 1 of 1 paper questions passed\n\
             all passed\n"
        ));
    }

    #[test]
    fn times_are_shown_in_utc_to_the_minute() {
        assert_eq!(utc_minute(0), "1970-01-01 00:00 UTC");
        assert_eq!(utc_minute(951_782_399), "2000-02-28 23:59 UTC");
        assert_eq!(utc_minute(951_868_800), "2000-03-01 00:00 UTC");
        assert_eq!(utc_minute(1_748_786_580), "2025-06-01 14:03 UTC");
    }

    /// The real lecture: every chapter with exercises has its paper
    /// questions, from the committed questions files.
    #[test]
    fn the_lecture_lists_the_paper_questions() {
        let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
        let (lecture, notes) = super::lecture(&root, chapters::CHAPTERS);
        assert_eq!(notes, Vec::<String>::new());
        for c in &lecture {
            let paper = c.items.iter().filter(|i| i.paper).count();
            assert_eq!(
                paper > 0,
                !c.chapter.exercises.is_empty(),
                "{}",
                c.chapter.id
            );
            assert!(
                c.items.iter().all(|i| !i.stars.is_empty()),
                "{}",
                c.chapter.id
            );
        }
    }
}
