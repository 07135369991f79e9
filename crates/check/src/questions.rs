//! Paper questions: worked by hand, answered in `exercise/answers.toml`,
//! judged by `raystep check` like the code exercises.
//!
//! A chapter's figures crate states its questions with the answers its own
//! code computes; `raystep figures` writes them to
//! `book/src/figures/chNN/questions.toml` (the book shows them from there,
//! `check` judges from there). The student edition keeps the questions and
//! drops their answers: each answer becomes [digests](Question::digests),
//! which judge as the answer does without showing it.
//!
//! The rule for a number: the reference and the student's answer are each
//! rounded to whole multiples of the question's `step`; the answer passes
//! when they are at most one multiple apart (so `step = 0.01` accepts 4.01
//! and 3.99 for 4, and refuses 4.03). The same rule holds with the digests.

use std::collections::BTreeMap;
use std::fmt::Write as _;

use serde::{Deserialize, Serialize};
use sha2::{Digest, Sha256};

use crate::verdicts::Verdict;

/// A chapter's questions file.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, Default)]
pub struct Questions {
    /// The questions, in the order the book asks them.
    #[serde(rename = "question", default)]
    pub questions: Vec<Question>,
}

/// What kind of answer a question takes.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Kind {
    /// A number, judged to within a step.
    Number,
    /// One of the listed options.
    Choice,
}

/// One question worked on paper.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Question {
    /// `q1`: the key in `answers.toml`.
    pub id: String,
    /// Difficulty, 1 to 3 stars.
    pub stars: u8,
    /// A few words: `t where a ray meets a plane`.
    pub title: String,
    /// The question in full (Markdown with `$…$` math), givens included.
    pub prompt: String,
    /// The figure the question needs, a file of the chapter's figure
    /// folder (`ray-plane.svg`), if any.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub figure: Option<String>,
    /// A number or a choice.
    pub kind: Kind,
    /// The number's name in messages: `t`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub quantity: Option<String>,
    /// A number's precision: answers within one step pass.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub step: Option<f64>,
    /// A choice's options, as the student writes them.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub options: Vec<String>,
    /// The answer: the number (as a TOML float) or the option. Absent in
    /// the student edition.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub answer: Option<toml::Value>,
    /// The worked solution (Markdown), folded in the book. Absent in the
    /// student edition.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub worked: Option<String>,
    /// The student edition's stand-in for `answer`: the digests of every
    /// answer that passes (see [`Question::without_answer`]).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub digests: Vec<String>,
}

/// A question whose answer is a number.
pub struct NumberQuestion<'a> {
    /// `q1`.
    pub id: &'a str,
    /// 1 to 3.
    pub stars: u8,
    /// A few words.
    pub title: &'a str,
    /// The question in full.
    pub prompt: String,
    /// The figure it needs.
    pub figure: Option<&'a str>,
    /// The number's name in messages.
    pub quantity: &'a str,
    /// The answer, as the chapter's code computes it.
    pub value: f64,
    /// Answers within one step pass.
    pub step: f64,
    /// The worked solution.
    pub worked: String,
}

/// A question whose answer is one of some options.
pub struct ChoiceQuestion<'a> {
    /// `q2`.
    pub id: &'a str,
    /// 1 to 3.
    pub stars: u8,
    /// A few words.
    pub title: &'a str,
    /// The question in full.
    pub prompt: String,
    /// The figure it needs.
    pub figure: Option<&'a str>,
    /// The options.
    pub options: &'a [&'a str],
    /// The right option, as the chapter's code decides it.
    pub answer: &'a str,
    /// The worked solution.
    pub worked: String,
}

impl From<NumberQuestion<'_>> for Question {
    fn from(q: NumberQuestion) -> Question {
        Question {
            id: q.id.into(),
            stars: q.stars,
            title: q.title.into(),
            prompt: q.prompt,
            figure: q.figure.map(Into::into),
            kind: Kind::Number,
            quantity: Some(q.quantity.into()),
            step: Some(q.step),
            options: Vec::new(),
            answer: Some(toml::Value::Float(q.value)),
            worked: Some(q.worked),
            digests: Vec::new(),
        }
    }
}

impl From<ChoiceQuestion<'_>> for Question {
    fn from(q: ChoiceQuestion) -> Question {
        Question {
            id: q.id.into(),
            stars: q.stars,
            title: q.title.into(),
            prompt: q.prompt,
            figure: q.figure.map(Into::into),
            kind: Kind::Choice,
            quantity: None,
            step: None,
            options: q.options.iter().map(|o| o.to_string()).collect(),
            answer: Some(toml::Value::String(q.answer.into())),
            worked: Some(q.worked),
            digests: Vec::new(),
        }
    }
}

/// The question's number (`1` for `q1`), for messages.
fn number(id: &str) -> &str {
    id.strip_prefix('q').unwrap_or(id)
}

/// A number as a person writes it: at most six significant digits, no
/// trailing zeros.
fn shown(x: f64) -> String {
    if x == 0.0 {
        return "0".into();
    }
    let digits = (5 - x.abs().log10().floor() as i32).clamp(0, 12) as usize;
    let text = format!("{x:.digits$}");
    if text.contains('.') {
        text.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        text
    }
}

/// `x` rounded to the decimals of `step`, without trailing zeros.
fn to_step(x: f64, step: f64) -> String {
    let decimals = (-step.log10().floor()).clamp(0.0, 12.0) as usize;
    let text = format!("{x:.decimals$}");
    if text.contains('.') {
        text.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        text
    }
}

/// An option as compared: trimmed, lower case.
fn normal(option: &str) -> String {
    option.trim().to_lowercase()
}

/// The digest of one passing answer's key.
fn digest(chapter: &str, id: &str, key: &str) -> String {
    let hash = Sha256::digest(format!("raystep/{chapter}/{id}/{key}"));
    let mut text = String::new();
    for byte in &hash[..16] {
        let _ = write!(text, "{byte:02x}");
    }
    text
}

/// A number's key: the whole multiple of `step` nearest to it.
fn multiple(x: f64, step: f64) -> i64 {
    (x / step).round() as i64
}

impl Question {
    /// The stars as the book and `check` show them: `★★`.
    pub fn difficulty(&self) -> String {
        stars(self.stars)
    }

    /// What the stub and the book say about the form of the answer:
    /// `a number, to within 0.01` or `one of "left", "right"`.
    pub fn form(&self) -> String {
        match self.kind {
            Kind::Number => format!(
                "a number, to within {}",
                shown(self.step.unwrap_or(0.0))
            ),
            Kind::Choice => {
                let options: Vec<String> =
                    self.options.iter().map(|o| format!("\"{o}\"")).collect();
                format!("one of {}", options.join(", "))
            }
        }
    }

    /// The same question with its answer and worked solution replaced by
    /// the digests of every passing answer (salted with the chapter and
    /// the question, so no two questions share one).
    pub fn without_answer(&self, chapter: &str) -> Question {
        let mut digests: Vec<String> = match (&self.kind, &self.answer) {
            (Kind::Number, Some(value)) => {
                let step = self.step.unwrap_or(1.0);
                let centre = multiple(as_number(value).unwrap_or(0.0), step);
                (centre - 1..=centre + 1)
                    .map(|k| digest(chapter, &self.id, &k.to_string()))
                    .collect()
            }
            (Kind::Choice, Some(toml::Value::String(answer))) => {
                vec![digest(chapter, &self.id, &normal(answer))]
            }
            _ => self.digests.clone(),
        };
        digests.sort();
        Question {
            answer: None,
            worked: None,
            digests,
            ..self.clone()
        }
    }

    /// Judges `given` (the student's value of this question's key in
    /// `answers.toml`; `None` when absent), in chapter `chapter`.
    pub fn judge(&self, chapter: &str, given: Option<&toml::Value>) -> Verdict {
        let n = number(&self.id);
        let Some(given) = given else {
            return Verdict::NotAttempted;
        };
        if let toml::Value::String(text) = given
            && normal(text) == "todo"
        {
            return Verdict::NotAttempted;
        }
        match self.kind {
            Kind::Number => self.judge_number(chapter, n, given),
            Kind::Choice => self.judge_choice(chapter, n, given),
        }
    }

    fn judge_number(
        &self, chapter: &str, n: &str, given: &toml::Value,
    ) -> Verdict {
        let quantity = self.quantity.as_deref().unwrap_or("the number");
        let Some(value) = as_number(given).filter(|v| v.is_finite()) else {
            return Verdict::Failed(format!(
                "question {n} wants a number for {quantity}; your answer {} \
                 is not one",
                given_text(given)
            ));
        };
        let step = self.step.unwrap_or(1.0);
        let key = multiple(value, step);
        if let Some(reference) = self.answer.as_ref().and_then(as_number) {
            if (key - multiple(reference, step)).abs() <= 1 {
                return Verdict::Passed;
            }
            let off = if reference != 0.0 {
                let percent =
                    100.0 * (value - reference).abs() / reference.abs();
                format!("{} %", shown(percent.round().max(1.0)))
            } else {
                shown((value - reference).abs())
            };
            return Verdict::Failed(format!(
                "question {n}, {quantity} expected about {} (your {} is off \
                 by {off})",
                to_step(reference, step),
                shown(value)
            ));
        }
        if self
            .digests
            .contains(&digest(chapter, &self.id, &key.to_string()))
        {
            Verdict::Passed
        } else {
            Verdict::Failed(format!(
                "question {n}, {quantity}: your {} is not within {} of the \
                 answer",
                shown(value),
                shown(step)
            ))
        }
    }

    fn judge_choice(
        &self, chapter: &str, n: &str, given: &toml::Value,
    ) -> Verdict {
        let chosen = match given {
            toml::Value::String(text) => normal(text),
            other => other.to_string(),
        };
        if !self.options.iter().any(|o| normal(o) == chosen) {
            return Verdict::Failed(format!(
                "question {n} wants {}; your answer {} is not one",
                self.form(),
                given_text(given)
            ));
        }
        let right = match &self.answer {
            Some(toml::Value::String(answer)) => normal(answer) == chosen,
            _ => self.digests.contains(&digest(chapter, &self.id, &chosen)),
        };
        // The option as the question spells it.
        let option = self
            .options
            .iter()
            .find(|o| normal(o) == chosen)
            .map_or(chosen.as_str(), String::as_str);
        match (&self.answer, right) {
            (_, true) => Verdict::Passed,
            (Some(toml::Value::String(answer)), false) => {
                Verdict::Failed(format!(
                    "question {n}, expected \"{answer}\" (your answer \
                     \"{option}\")"
                ))
            }
            _ => Verdict::Failed(format!(
                "question {n}: \"{option}\" is not the answer"
            )),
        }
    }
}

/// A TOML value as a number, if it is one (an integer, a float, or a
/// string that reads as one).
fn as_number(value: &toml::Value) -> Option<f64> {
    match value {
        toml::Value::Float(x) => Some(*x),
        toml::Value::Integer(i) => Some(*i as f64),
        toml::Value::String(s) => s.trim().parse().ok(),
        _ => None,
    }
}

/// What the student wrote, as a message quotes it.
fn given_text(given: &toml::Value) -> String {
    match given {
        toml::Value::String(s) => format!("\"{s}\""),
        other => other.to_string(),
    }
}

/// `2` for `ch02`.
pub fn chapter_number(chapter: &str) -> &str {
    chapter.trim_start_matches("ch").trim_start_matches('0')
}

/// Whether `text` is an answers file in which no question is answered
/// yet (every value is `"todo"`).
pub fn untouched(text: &str) -> bool {
    toml::from_str::<BTreeMap<String, toml::Value>>(text).is_ok_and(|t| {
        t.values()
            .all(|v| matches!(v, toml::Value::String(s) if normal(s) == "todo"))
    })
}

/// `★`, `★★` or `★★★`.
pub fn stars(n: u8) -> String {
    "★".repeat(n as usize)
}

impl Questions {
    /// The questions file's text, as `raystep figures` writes it.
    pub fn to_toml(&self, header: &str) -> String {
        let mut text = String::new();
        for line in header.lines() {
            let _ = writeln!(text, "# {line}");
        }
        text.push('\n');
        text.push_str(
            &toml::to_string_pretty(self).expect("questions serialise"),
        );
        text
    }

    /// Reads a questions file (`file` names it in errors).
    pub fn parse(file: &str, text: &str) -> Result<Questions, String> {
        toml::from_str(text).map_err(|e| toml_error(file, text, &e))
    }

    /// The same questions without their answers (see
    /// [`Question::without_answer`]).
    pub fn without_answers(&self, chapter: &str) -> Questions {
        Questions {
            questions: self
                .questions
                .iter()
                .map(|q| q.without_answer(chapter))
                .collect(),
        }
    }

    /// The stub of `exercise/answers.toml`: one `"todo"` per question, each
    /// with its title, difficulty and the form of its answer.
    pub fn answers_stub(&self, chapter: &str) -> String {
        let mut text = format!(
            "# Chapter {}'s paper questions. Work each on paper (the book \
             asks it where\n# the idea is taught, with its figure), then \
             replace \"todo\" by your answer.\n# `cargo run --release -- \
             check {chapter}` judges them with the code exercises.\n",
            chapter_number(chapter)
        );
        for q in &self.questions {
            let _ = write!(
                text,
                "\n# Question {} ({}): {}.\n# Answer: {}.\n{} = \"todo\"\n",
                number(&q.id),
                q.difficulty(),
                q.title,
                q.form(),
                q.id
            );
        }
        text
    }

    /// Every question judged against the student's `answers` (the text of
    /// `answers.toml`, `None` if there is none; `file` names it): one
    /// verdict per question, in order. A file that does not parse fails
    /// every question with the line and column of the fault.
    pub fn judge(
        &self, chapter: &str, file: &str, answers: Option<&str>,
    ) -> Vec<(String, Verdict)> {
        let table: Result<BTreeMap<String, toml::Value>, String> = match answers
        {
            None => Ok(BTreeMap::new()),
            Some(text) => {
                toml::from_str(text).map_err(|e| toml_error(file, text, &e))
            }
        };
        self.questions
            .iter()
            .map(|q| {
                let verdict = match &table {
                    Ok(table) => q.judge(chapter, table.get(&q.id)),
                    Err(error) => Verdict::Failed(error.clone()),
                };
                (q.id.clone(), verdict)
            })
            .collect()
    }

    /// Every question judged against its own answer: what `check
    /// --reference` reports (all pass, or the file lost its answers).
    pub fn judge_reference(&self, chapter: &str) -> Vec<(String, Verdict)> {
        self.questions
            .iter()
            .map(|q| {
                let verdict = match &q.answer {
                    Some(answer) => q.judge(chapter, Some(answer)),
                    None => Verdict::Failed(format!(
                        "question {} has no answer in this edition",
                        number(&q.id)
                    )),
                };
                (q.id.clone(), verdict)
            })
            .collect()
    }
}

/// A TOML error in one line: `FILE:LINE:COLUMN: message`.
fn toml_error(file: &str, text: &str, error: &toml::de::Error) -> String {
    let message = error.message().trim();
    match error.span() {
        Some(span) => {
            let before = &text[..span.start.min(text.len())];
            let line = before.matches('\n').count() + 1;
            let column =
                before.len() - before.rfind('\n').map_or(0, |i| i + 1) + 1;
            format!("{file}:{line}:{column}: {message}")
        }
        None => format!("{file}: {message}"),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn t_question() -> Question {
        NumberQuestion {
            id: "q2",
            stars: 1,
            title: "t where a ray meets a plane",
            prompt: "The ray … meets the plane …; what is $t$?".into(),
            figure: None,
            quantity: "t",
            value: 4.0,
            step: 0.01,
            worked: "t = 4".into(),
        }
        .into()
    }

    fn side_question() -> Question {
        ChoiceQuestion {
            id: "q3",
            stars: 2,
            title: "which side",
            prompt: "Which side of the line is P on?".into(),
            figure: Some("line.svg"),
            options: &["left", "right", "on the line"],
            answer: "left",
            worked: "f(P) > 0".into(),
        }
        .into()
    }

    fn judged(q: &Question, answers: &str) -> Verdict {
        let file = Questions {
            questions: vec![q.clone()],
        };
        file.judge("ch02", "exercise/answers.toml", Some(answers))
            .remove(0)
            .1
    }

    #[test]
    fn a_number_within_one_step_passes() {
        let q = t_question();
        for answer in ["q2 = 4.0", "q2 = 4", "q2 = 4.01", "q2 = \" 3.99 \""] {
            assert_eq!(judged(&q, answer), Verdict::Passed, "{answer}");
        }
    }

    #[test]
    fn a_number_out_of_tolerance_fails_saying_by_how_much() {
        assert_eq!(
            judged(&t_question(), "q2 = 4.4"),
            Verdict::Failed(
                "question 2, t expected about 4 (your 4.4 is off by 10 %)"
                    .into()
            )
        );
        assert!(matches!(
            judged(&t_question(), "q2 = 4.03"),
            Verdict::Failed(_)
        ));
    }

    #[test]
    fn a_wrong_kind_of_answer_fails_naming_it() {
        assert_eq!(
            judged(&t_question(), "q2 = \"four\""),
            Verdict::Failed(
                "question 2 wants a number for t; your answer \"four\" is \
                 not one"
                    .into()
            )
        );
        assert!(matches!(
            judged(&t_question(), "q2 = nan"),
            Verdict::Failed(_)
        ));
        assert_eq!(
            judged(&side_question(), "q3 = \"up\""),
            Verdict::Failed(
                "question 3 wants one of \"left\", \"right\", \"on the \
                 line\"; your answer \"up\" is not one"
                    .into()
            )
        );
    }

    #[test]
    fn untouched_or_absent_answers_are_not_attempted() {
        assert_eq!(
            judged(&t_question(), "q2 = \"todo\""),
            Verdict::NotAttempted
        );
        assert_eq!(judged(&t_question(), "q1 = 3"), Verdict::NotAttempted);
        let file = Questions {
            questions: vec![t_question()],
        };
        assert_eq!(
            file.judge("ch02", "answers.toml", None),
            [("q2".to_string(), Verdict::NotAttempted)]
        );
    }

    #[test]
    fn a_choice_is_compared_in_any_case_and_a_wrong_one_named() {
        let q = side_question();
        assert_eq!(judged(&q, "q3 = \" Left\""), Verdict::Passed);
        let on = judged(&q, "q3 = \"ON THE LINE\"");
        assert_eq!(
            on,
            Verdict::Failed(
                "question 3, expected \"left\" (your answer \"on the line\")"
                    .into()
            )
        );
        assert_eq!(
            judged(&q, "q3 = \"right\""),
            Verdict::Failed(
                "question 3, expected \"left\" (your answer \"right\")".into()
            )
        );
    }

    #[test]
    fn a_file_that_does_not_parse_fails_every_question_at_its_line() {
        let file = Questions {
            questions: vec![t_question(), side_question()],
        };
        let verdicts = file.judge(
            "ch02",
            "exercise/answers.toml",
            Some("# answers\nq2 = 4.0\nq3 = left\n"),
        );
        for (_, verdict) in &verdicts {
            let Verdict::Failed(why) = verdict else {
                panic!("{verdict:?}")
            };
            assert!(why.starts_with("exercise/answers.toml:3:6: "), "{why}");
        }
    }

    /// Without the answers, the digests judge every answer as the answer
    /// did, and the file holds neither the answer nor the worked solution.
    #[test]
    fn the_digests_judge_as_the_answer_does() {
        for q in [t_question(), side_question()] {
            let hidden = q.without_answer("ch02");
            assert!(hidden.answer.is_none() && hidden.worked.is_none());
            let text = toml::to_string(&hidden).unwrap();
            assert!(!text.contains("left\"\n") && !text.contains("4.0"));
            for answer in [
                "4", "4.01", "3.99", "4.02", "3.98", "4.4", "0", "left",
                "right", "LEFT ",
            ] {
                let given = toml::Value::String(answer.into());
                let with = q.judge("ch02", Some(&given));
                let without = hidden.judge("ch02", Some(&given));
                assert_eq!(
                    with == Verdict::Passed,
                    without == Verdict::Passed,
                    "{} {answer}: {with:?} / {without:?}",
                    q.id
                );
            }
            // Another chapter's digests do not pass.
            let other = q.without_answer("ch03");
            let given = q.answer.clone().unwrap();
            assert_ne!(hidden.digests, other.digests);
            assert_eq!(hidden.judge("ch02", Some(&given)), Verdict::Passed);
        }
        assert_eq!(
            t_question()
                .without_answer("ch02")
                .judge("ch02", Some(&toml::Value::Float(4.4))),
            Verdict::Failed(
                "question 2, t: your 4.4 is not within 0.01 of the answer"
                    .into()
            )
        );
    }

    #[test]
    fn the_file_and_the_stub_round_trip() {
        let file = Questions {
            questions: vec![t_question(), side_question()],
        };
        let text = file.to_toml("Chapter 2's questions.\nDo not edit.");
        assert!(text.starts_with("# Chapter 2's questions.\n# Do not edit.\n"));
        assert_eq!(Questions::parse("q.toml", &text).unwrap(), file);
        let stub = file.answers_stub("ch02");
        assert!(stub.contains(
            "# Question 2 (★): t where a ray meets a plane.\n# Answer: a \
             number, to within 0.01.\nq2 = \"todo\"\n"
        ));
        let verdicts = file.judge("ch02", "answers.toml", Some(&stub));
        assert!(verdicts.iter().all(|(_, v)| *v == Verdict::NotAttempted));
        assert!(
            file.judge_reference("ch02")
                .iter()
                .all(|(_, v)| *v == Verdict::Passed)
        );
        let hidden = file.without_answers("ch02");
        assert!(
            hidden
                .judge_reference("ch02")
                .iter()
                .all(|(_, v)| matches!(v, Verdict::Failed(_)))
        );
    }
}
