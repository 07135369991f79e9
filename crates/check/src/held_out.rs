//! Held-out cases for `raystep grade`: inputs that no file of a student's
//! copy holds, drawn at grading time from a seed the student cannot know,
//! answered by the student's code in one process and judged against the
//! reference's answers in another.
//!
//! A chapter lists its exercises' cases in `examples/chNN_held_out.rs`
//! (a name of its own, as cargo wants for examples of one workspace):
//!
//! ```text
//! fn main() -> ExitCode {
//!     held_out::main(&[Exercise { name: "line_through_points", run: line, tolerance: 1e-9 }])
//! }
//! ```
//!
//! The one program is built twice. Built in the grading copy with the
//! student's code (feature `exercise`), `held_out answer SEED EXERCISE`
//! prints one line per case: the student's answer (one process per
//! exercise, so that one that loops or crashes leaves the others judged). Built in the instructor's
//! workspace with the reference, `held_out judge SEED ANSWERS` draws the
//! same inputs, computes the reference's answers, compares, and prints one
//! verdict per exercise. The verdict is made outside the student's process,
//! on answers the student's code had to compute: printing a test harness's
//! lines, ending early or reading the snapshots gains nothing.
//!
//! Each case draws its input from its own generator (seeded by the seed,
//! the exercise and the case's number), so a case that panics or loops
//! does not change the inputs of the others.

use std::collections::BTreeMap;
use std::fmt::{self, Display, Write as _};
use std::io::Write as _;
use std::panic::{AssertUnwindSafe, catch_unwind};
use std::process::ExitCode;

use raystep_core::{DVec2, DVec3};

/// Cases per exercise.
pub const CASES: usize = 64;

/// The panic message of `todo!()`.
const TODO: &str = "not yet implemented";

/// One exercise's held-out cases.
#[derive(Clone, Copy)]
pub struct Exercise {
    /// The exercise (the stem of `exercise/<name>.rs`).
    pub name: &'static str,
    /// Draws one case's input from the generator, says it
    /// ([`Case::ask`]) before calling the exercise, then writes the
    /// exercise's answer into the case.
    pub run: fn(&mut Rng, &mut Case),
    /// Numbers of an answer agree when they differ by at most
    /// `tolerance · max(1, |expected|)`; words must be equal.
    pub tolerance: f64,
}

impl Exercise {
    /// The held-out cases of exercise `name`: `run` draws and answers
    /// one, answers agree within `tolerance`.
    pub const fn new(
        name: &'static str, run: fn(&mut Rng, &mut Case), tolerance: f64,
    ) -> Exercise {
        Exercise {
            name,
            run,
            tolerance,
        }
    }
}

/// A small seeded generator (SplitMix64): the same numbers for a seed on
/// every machine, with no dependency whose stream could change.
#[derive(Debug, Clone)]
pub struct Rng(u64);

impl Rng {
    /// The generator for `seed`.
    pub fn new(seed: u64) -> Rng {
        Rng(seed)
    }

    /// The generator of case `case` of `exercise` under `seed`.
    pub fn for_case(seed: u64, exercise: &str, case: usize) -> Rng {
        // FNV-1a of the name, then mixed with the seed and the case.
        let mut hash: u64 = 0xcbf2_9ce4_8422_2325;
        for byte in exercise.bytes() {
            hash = (hash ^ u64::from(byte)).wrapping_mul(0x0100_0000_01b3);
        }
        let mut rng = Rng(seed ^ hash);
        let mixed = rng.next_u64() ^ (case as u64).wrapping_mul(0x9e37_79b9);
        Rng(mixed)
    }

    /// The next 64 random bits.
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }

    /// A number in `[0, 1)`.
    pub fn unit(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64
    }

    /// A number in `[lo, hi)`.
    pub fn uniform(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.unit()
    }

    /// A number whose size is spread evenly over the decades from `lo` to
    /// `hi` (both positive), with a random sign.
    pub fn magnitude(&mut self, lo: f64, hi: f64) -> f64 {
        let size = (lo.ln() + (hi.ln() - lo.ln()) * self.unit()).exp();
        if self.chance(0.5) { -size } else { size }
    }

    /// An index in `0..n`.
    pub fn below(&mut self, n: usize) -> usize {
        (self.unit() * n as f64) as usize % n.max(1)
    }

    /// True with probability `p`.
    pub fn chance(&mut self, p: f64) -> bool {
        self.unit() < p
    }

    /// A point of the square `[-r, r]²`.
    pub fn vec2(&mut self, r: f64) -> DVec2 {
        DVec2::new(self.uniform(-r, r), self.uniform(-r, r))
    }

    /// A point of the cube `[-r, r]³`.
    pub fn vec3(&mut self, r: f64) -> DVec3 {
        DVec3::new(
            self.uniform(-r, r),
            self.uniform(-r, r),
            self.uniform(-r, r),
        )
    }

    /// A unit vector, every direction equally likely.
    pub fn unit_vec3(&mut self) -> DVec3 {
        loop {
            let v = self.vec3(1.0);
            let length = v.length();
            if (0.1..=1.0).contains(&length) {
                return v / length;
            }
        }
    }
}

/// One case: what was asked, and the answer as words and numbers.
#[derive(Debug, Clone, Default)]
pub struct Case {
    input: String,
    answer: Vec<String>,
}

impl Case {
    /// Says what the case asks (shown when the case fails). Call it
    /// before the exercise, so that a case that panics is still named.
    pub fn ask(&mut self, input: impl Display) {
        self.input = input.to_string();
    }

    /// Adds a word to the answer (`hit`, `miss`, an error's name).
    pub fn word(&mut self, word: impl Display) {
        let word = word.to_string();
        let word: String =
            word.split_whitespace().collect::<Vec<_>>().join("_");
        self.answer
            .push(if word.is_empty() { "_".into() } else { word });
    }

    /// Adds a labelled number to the answer.
    pub fn num(&mut self, label: &str, x: f64) {
        self.word(label);
        self.answer.push(format!("{x:?}"));
    }

    /// Adds a labelled 2D vector to the answer.
    pub fn vec2(&mut self, label: &str, v: DVec2) {
        self.word(label);
        self.answer.extend([v.x, v.y].map(|x| format!("{x:?}")));
    }

    /// Adds a labelled 3D vector to the answer.
    pub fn vec3(&mut self, label: &str, v: DVec3) {
        self.word(label);
        self.answer
            .extend([v.x, v.y, v.z].map(|x| format!("{x:?}")));
    }
}

/// A 2D point for [`Case::ask`]: `(1.5, -2)`.
pub fn show2(v: DVec2) -> String {
    format!("({}, {})", short(v.x), short(v.y))
}

/// A 3D point for [`Case::ask`]: `(1.5, -2, 0.25)`.
pub fn show3(v: DVec3) -> String {
    format!("({}, {}, {})", short(v.x), short(v.y), short(v.z))
}

/// A number as a message shows it: at most 7 significant digits.
pub fn short(x: f64) -> String {
    if x == 0.0 || !x.is_finite() {
        return format!("{x}");
    }
    if (1e-4..1e7).contains(&x.abs()) {
        let digits = (6 - x.abs().log10().floor() as i32).max(0) as usize;
        let text = format!("{x:.digits$}");
        if text.contains('.') {
            text.trim_end_matches('0').trim_end_matches('.').to_string()
        } else {
            text
        }
    } else {
        format!("{x:.6e}")
    }
}

/// What a case came to: an answer, or a panic.
#[derive(Debug, Clone, PartialEq)]
enum Outcome {
    Answer(Vec<String>),
    Panicked(String),
}

impl Outcome {
    /// The line it travels as (after `answer <exercise> <case> `).
    fn line(&self) -> String {
        match self {
            Outcome::Answer(words) => format!("ok {}", words.join(" ")),
            Outcome::Panicked(why) => {
                let why: Vec<&str> = why.split_whitespace().collect();
                format!("panicked {}", why.join(" "))
            }
        }
    }

    fn parse(line: &str) -> Outcome {
        match line.split_once(' ').unwrap_or((line, "")) {
            ("ok", words) => Outcome::Answer(
                words.split_whitespace().map(str::to_string).collect(),
            ),
            ("panicked", why) => Outcome::Panicked(why.to_string()),
            _ => {
                Outcome::Panicked(format!("an answer that is not one: {line}"))
            }
        }
    }
}

/// Runs case `case` of `exercise`: its input, and what it came to.
fn run_case(exercise: &Exercise, seed: u64, case: usize) -> (String, Outcome) {
    let mut rng = Rng::for_case(seed, exercise.name, case);
    let mut asked = Case::default();
    let ran = catch_unwind(AssertUnwindSafe(|| {
        (exercise.run)(&mut rng, &mut asked);
    }));
    let outcome = match ran {
        Ok(()) => Outcome::Answer(asked.answer),
        Err(payload) => Outcome::Panicked(
            payload
                .downcast_ref::<&str>()
                .map(|s| s.to_string())
                .or_else(|| payload.downcast_ref::<String>().cloned())
                .unwrap_or_else(|| "a panic".to_string()),
        ),
    };
    (asked.input, outcome)
}

/// The verdict on one exercise.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Verdict {
    /// Every case agrees with the reference.
    Passed,
    /// The cases stopped at `todo!()`.
    NotAttempted,
    /// The first case that disagrees, said in one line.
    Failed(String),
}

impl Display for Verdict {
    /// As `judge` prints it after `verdict <exercise> `.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Verdict::Passed => write!(f, "passed"),
            Verdict::NotAttempted => write!(f, "not-attempted"),
            Verdict::Failed(why) => write!(f, "failed {why}"),
        }
    }
}

impl Verdict {
    /// Reads a verdict as [`Display`] wrote it.
    pub fn parse(text: &str) -> Option<Verdict> {
        match text.split_once(' ').unwrap_or((text, "")) {
            ("passed", _) => Some(Verdict::Passed),
            ("not-attempted", _) => Some(Verdict::NotAttempted),
            ("failed", why) => Some(Verdict::Failed(why.to_string())),
            _ => None,
        }
    }
}

/// Do two words of answers agree: equal, or numbers within `tolerance`?
fn agree_word(e: &str, g: &str, tolerance: f64) -> bool {
    match (e.parse::<f64>(), g.parse::<f64>()) {
        (Ok(e), Ok(g)) => {
            (e.is_nan() && g.is_nan())
                || e == g
                || (e - g).abs() <= tolerance * e.abs().max(1.0)
        }
        _ => e == g,
    }
}

/// Do two answers agree: the same words, numbers within `tolerance`?
fn agree(expected: &[String], got: &[String], tolerance: f64) -> bool {
    expected.len() == got.len()
        && expected
            .iter()
            .zip(got)
            .all(|(e, g)| agree_word(e, g, tolerance))
}

/// Where two answers that do not agree part: the part of the answer
/// (from its last word before the first difference, `c 9.25e23`) as
/// expected and as got; the whole answers if their shapes differ.
fn difference(
    expected: &[String], got: &[String], tolerance: f64,
) -> (String, String) {
    let is_word = |w: &String| w.parse::<f64>().is_err();
    let first = expected
        .iter()
        .zip(got)
        .position(|(e, g)| !agree_word(e, g, tolerance));
    match first {
        Some(i) if expected.len() == got.len() => {
            let start =
                (0..=i).rev().find(|&k| is_word(&expected[k])).unwrap_or(0);
            let end = (i + 1..expected.len())
                .find(|&k| is_word(&expected[k]))
                .unwrap_or(expected.len());
            (shown(&expected[start..end]), shown(&got[start..end]))
        }
        _ => (shown(expected), shown(got)),
    }
}

/// An answer as a message shows it: numbers with 7 digits at most.
fn shown(words: &[String]) -> String {
    let words: Vec<String> = words
        .iter()
        .map(|w| w.parse::<f64>().map_or_else(|_| w.clone(), short))
        .collect();
    words.join(" ")
}

/// Judges the `answers` (lines `answer <exercise> <case> …`, other lines
/// ignored) against the reference's, for every exercise.
pub fn judge(
    exercises: &[Exercise], seed: u64, answers: &str,
) -> Vec<(String, Verdict)> {
    let mut given: BTreeMap<(&str, usize), Outcome> = BTreeMap::new();
    for line in answers.lines() {
        let mut parts = line.splitn(4, ' ');
        let (Some("answer"), Some(name), Some(case), Some(rest)) =
            (parts.next(), parts.next(), parts.next(), parts.next())
        else {
            continue;
        };
        let Ok(case) = case.parse::<usize>() else {
            continue;
        };
        given
            .entry((name, case))
            .or_insert_with(|| Outcome::parse(rest));
    }
    exercises
        .iter()
        .map(|exercise| {
            let mut todo = 0;
            let mut first_failure = None;
            for case in 0..CASES {
                let (input, expected) = run_case(exercise, seed, case);
                let Outcome::Answer(expected) = expected else {
                    // The reference itself panicked: this case says
                    // nothing about the student's code.
                    continue;
                };
                let at =
                    format!("held-out case {} of {CASES} ({input})", case + 1);
                let failure = match given.get(&(exercise.name, case)) {
                    None => Some(format!(
                        "{at}: no answer (the program stopped before it)"
                    )),
                    Some(Outcome::Panicked(why)) if why.contains(TODO) => {
                        todo += 1;
                        None
                    }
                    Some(Outcome::Panicked(why)) => {
                        Some(format!("{at}: panicked: {why}"))
                    }
                    Some(Outcome::Answer(got)) => (!agree(
                        &expected,
                        got,
                        exercise.tolerance,
                    ))
                    .then(|| {
                        let (e, g) =
                            difference(&expected, got, exercise.tolerance);
                        format!("{at}: expected `{e}`, got `{g}`")
                    }),
                };
                if first_failure.is_none() {
                    first_failure = failure;
                }
            }
            let verdict = match first_failure {
                Some(why) => Verdict::Failed(why),
                None if todo > 0 => Verdict::NotAttempted,
                None => Verdict::Passed,
            };
            (exercise.name.to_string(), verdict)
        })
        .collect()
}

/// The answer lines of every case of every exercise, as `answer` prints them.
pub fn answers(exercises: &[Exercise], seed: u64) -> String {
    let mut text = String::new();
    for exercise in exercises {
        for case in 0..CASES {
            let (_, outcome) = run_case(exercise, seed, case);
            let _ = writeln!(
                text,
                "answer {} {case} {}",
                exercise.name,
                outcome.line()
            );
        }
    }
    text
}

/// The held-out program's `main`: `answer SEED` or `judge SEED ANSWERS`.
pub fn main(exercises: &[Exercise]) -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let seed = |text: Option<&String>| text.and_then(|s| s.parse::<u64>().ok());
    match args.first().map(String::as_str) {
        Some("answer") if args.len() == 2 || args.len() == 3 => {
            let Some(seed) = seed(args.get(1)) else {
                return usage();
            };
            // The panics are answers: no report of each on stderr.
            std::panic::set_hook(Box::new(|_| {}));
            let stdout = std::io::stdout();
            let only = args.get(2);
            for exercise in exercises {
                if only.is_some_and(|name| name != exercise.name) {
                    continue;
                }
                for case in 0..CASES {
                    let (_, outcome) = run_case(exercise, seed, case);
                    // Line by line, so that what came before a crash or a
                    // loop is judged.
                    let mut out = stdout.lock();
                    let _ = writeln!(
                        out,
                        "answer {} {case} {}",
                        exercise.name,
                        outcome.line()
                    );
                    let _ = out.flush();
                }
            }
            ExitCode::SUCCESS
        }
        Some("judge") if args.len() == 3 => {
            let Some(seed) = seed(args.get(1)) else {
                return usage();
            };
            let text = match std::fs::read(&args[2]) {
                Ok(bytes) => String::from_utf8_lossy(&bytes).into_owned(),
                Err(e) => {
                    eprintln!("held_out: {}: {e}", args[2]);
                    return ExitCode::from(2);
                }
            };
            std::panic::set_hook(Box::new(|_| {}));
            for (name, verdict) in judge(exercises, seed, &text) {
                println!("verdict {name} {verdict}");
            }
            ExitCode::SUCCESS
        }
        Some("list") => {
            for exercise in exercises {
                println!("{}", exercise.name);
            }
            ExitCode::SUCCESS
        }
        _ => usage(),
    }
}

fn usage() -> ExitCode {
    eprintln!(
        "usage: held_out answer SEED [EXERCISE] | held_out judge SEED ANSWERS | \
         held_out list (raystep grade runs this program)"
    );
    ExitCode::from(2)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A made-up exercise: the length of a 2D vector.
    fn length(rng: &mut Rng, case: &mut Case) {
        let v = rng.vec2(10.0);
        case.ask(format!("v = {}", show2(v)));
        case.num("length", v.length());
    }

    /// The same, wrong by 1 % beyond 5.
    fn length_wrong_far(rng: &mut Rng, case: &mut Case) {
        let v = rng.vec2(10.0);
        case.ask(format!("v = {}", show2(v)));
        let l = v.length();
        case.num("length", if l > 5.0 { l * 1.01 } else { l });
    }

    fn stub(rng: &mut Rng, case: &mut Case) {
        let v = rng.vec2(10.0);
        case.ask(format!("v = {}", show2(v)));
        // What an untouched stub's `todo!()` panics with.
        panic!("not yet implemented")
    }

    fn exercise(run: fn(&mut Rng, &mut Case)) -> [Exercise; 1] {
        [Exercise {
            name: "length",
            run,
            tolerance: 1e-9,
        }]
    }

    #[test]
    fn the_reference_s_own_answers_pass_and_a_wrong_one_fails() {
        let right = answers(&exercise(length), 7);
        assert_eq!(right.lines().count(), CASES);
        assert_eq!(
            judge(&exercise(length), 7, &right),
            [("length".to_string(), Verdict::Passed)]
        );
        // Another seed draws other inputs: these answers do not fit.
        let other = judge(&exercise(length), 8, &right);
        assert!(
            matches!(&other[0].1, Verdict::Failed(why) if why.starts_with("held-out case 1 of 64 (v = (")),
            "{other:?}"
        );
        let wrong = answers(&exercise(length_wrong_far), 7);
        let verdict = &judge(&exercise(length), 7, &wrong)[0].1;
        let Verdict::Failed(why) = verdict else {
            panic!("{verdict:?}")
        };
        assert!(
            why.contains(": expected `length ")
                && why.contains("`, got `length "),
            "{why}"
        );
    }

    #[test]
    fn missing_panicking_and_untouched_answers() {
        let right = answers(&exercise(length), 3);
        let cut: String =
            right.lines().take(10).map(|l| format!("{l}\n")).collect();
        let verdict = &judge(&exercise(length), 3, &cut)[0].1;
        assert!(
            matches!(verdict, Verdict::Failed(why) if why.starts_with("held-out case 11 of 64 (") && why.ends_with("no answer (the program stopped before it)")),
            "{verdict:?}"
        );
        let stubbed = answers(&exercise(stub), 3);
        assert_eq!(
            judge(&exercise(length), 3, &stubbed)[0].1,
            Verdict::NotAttempted
        );
        let forged = "test length ... ok\ntest result: ok. 1 passed\n";
        assert!(matches!(
            judge(&exercise(length), 3, forged)[0].1,
            Verdict::Failed(_)
        ));
    }

    #[test]
    fn numbers_agree_within_the_tolerance_words_exactly() {
        let words = |s: &str| -> Vec<String> {
            s.split(' ').map(str::to_string).collect()
        };
        assert!(agree(
            &words("hit t 1000"),
            &words("hit t 1000.0000001"),
            1e-9
        ));
        assert!(!agree(&words("hit t 1000"), &words("hit t 1000.001"), 1e-9));
        assert!(agree(&words("t 0"), &words("t 1e-10"), 1e-9));
        assert!(agree(&words("t NaN"), &words("t NaN"), 1e-9));
        assert!(agree(&words("t inf"), &words("t inf"), 1e-9));
        assert!(!agree(&words("hit t 1"), &words("miss t 1"), 1e-9));
        assert!(!agree(&words("hit t 1"), &words("hit t"), 1e-9));
    }

    #[test]
    fn cases_are_seeded_by_exercise_and_number() {
        let a = Rng::for_case(1, "a", 0).next_u64();
        assert_eq!(a, Rng::for_case(1, "a", 0).next_u64());
        assert_ne!(a, Rng::for_case(1, "a", 1).next_u64());
        assert_ne!(a, Rng::for_case(1, "b", 0).next_u64());
        assert_ne!(a, Rng::for_case(2, "a", 0).next_u64());
        let mut rng = Rng::new(5);
        for _ in 0..1000 {
            let x = rng.magnitude(1e-3, 1e6);
            assert!((1e-3..=1e6).contains(&x.abs()), "{x}");
            assert!((rng.unit_vec3().length() - 1.0).abs() < 1e-12);
        }
        assert_eq!(short(0.1 + 0.2), "0.3");
        assert_eq!(short(-1234.5678), "-1234.568");
        assert_eq!(short(1e200), "1.000000e200");
    }
}
