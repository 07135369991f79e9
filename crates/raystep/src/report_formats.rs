//! A check report for machines: JSON (`raystep check --json FILE`) and
//! JUnit XML (`--junit FILE`, one test suite for the chapter, one test case
//! per exercise and one for the other tests), as text; `check` writes them.

use std::io;

use quick_xml::Writer;
use quick_xml::events::{BytesDecl, BytesText, Event};
use serde::Serialize;

use raystep_check::verdicts::{Report, Verdict, advice};

/// Which chapter a report is about, and how it was run.
#[derive(Debug, Clone, Copy)]
pub struct Heading<'a> {
    /// `ch02`.
    pub chapter: &'a str,
    /// `ch02-plane-polygon-hits`.
    pub package: &'a str,
    /// The reference solution was tested, not the exercise stubs.
    pub reference: bool,
}

impl Heading<'_> {
    fn mode(&self) -> &'static str {
        if self.reference {
            "reference"
        } else {
            "student"
        }
    }
}

/// The JSON document.
#[derive(Serialize)]
struct JsonReport<'a> {
    chapter: &'a str,
    package: &'a str,
    /// `student` or `reference`.
    mode: &'a str,
    /// Everything passed (the exit status of `raystep check`).
    passed: bool,
    exercises: Vec<JsonExercise>,
    other_tests: JsonOtherTests<'a>,
    /// Why nothing was built, if so.
    build_failure: Option<JsonBuildFailure<'a>>,
    changed_snapshots: Vec<JsonSnapshot<'a>>,
}

/// One exercise's verdict.
#[derive(Serialize)]
struct JsonExercise {
    exercise: String,
    /// `code` (an exercise file) or `paper` (a question answered in
    /// `exercise/answers.toml`).
    kind: &'static str,
    /// The difficulty, 1 to 3 stars, if known.
    stars: Option<usize>,
    /// `passed`, `failed`, `not attempted`, `timed out`, `does not compile`
    /// or `cargo failed`.
    verdict: &'static str,
    /// The rest of the verdict (which test, where, why), if any.
    message: Option<String>,
}

/// Why nothing was built: in one line, and every compiler error.
#[derive(Serialize)]
struct JsonBuildFailure<'a> {
    message: String,
    errors: Vec<JsonCompileError<'a>>,
}

/// One compiler error and where it is.
#[derive(Serialize)]
struct JsonCompileError<'a> {
    message: &'a str,
    at: Option<&'a str>,
}

/// The chapter's other tests.
#[derive(Serialize)]
struct JsonOtherTests<'a> {
    passed: usize,
    /// Stopped at a `todo!()`.
    waiting: usize,
    failed: &'a [String],
}

/// A snapshot file that is not the reference.
#[derive(Serialize)]
struct JsonSnapshot<'a> {
    path: &'a str,
    change: String,
}

/// The report as a JSON document.
pub fn json(heading: &Heading, report: &Report) -> String {
    let document = JsonReport {
        chapter: heading.chapter,
        package: heading.package,
        mode: heading.mode(),
        passed: report.all_passed(),
        exercises: report
            .exercises
            .iter()
            .map(|(exercise, verdict)| JsonExercise {
                exercise: exercise.clone(),
                kind: if report.labels.get(exercise).is_some_and(|l| l.paper) {
                    "paper"
                } else {
                    "code"
                },
                stars: report
                    .labels
                    .get(exercise)
                    .map(|l| l.stars.chars().count())
                    .filter(|n| *n > 0),
                verdict: verdict.kind(),
                message: verdict.message(),
            })
            .collect(),
        other_tests: JsonOtherTests {
            passed: report.other_passed,
            waiting: report.other_waiting,
            failed: &report.other_failed,
        },
        build_failure: report.build_failure.as_ref().map(|b| {
            JsonBuildFailure {
                message: b.failure.to_string(),
                errors: b
                    .errors
                    .iter()
                    .map(|e| JsonCompileError {
                        message: &e.message,
                        at: e.at.as_deref(),
                    })
                    .collect(),
            }
        }),
        changed_snapshots: report
            .changed_snapshots
            .iter()
            .map(|s| JsonSnapshot {
                path: &s.path,
                change: s.change.to_string(),
            })
            .collect(),
    };
    let mut text =
        serde_json::to_string_pretty(&document).expect("a report serialises");
    text.push('\n');
    text
}

/// One JUnit test case: its name and, unless it passed, the failure's type
/// (the verdict's kind) and message (the verdict as `check` prints it).
struct Case {
    name: String,
    failure: Option<(&'static str, String)>,
}

/// The test cases: one per exercise, then `other tests`.
fn cases(report: &Report) -> Vec<Case> {
    let mut cases: Vec<Case> = report
        .exercises
        .iter()
        .map(|(exercise, verdict)| Case {
            name: report.shown_name(exercise),
            failure: (*verdict != Verdict::Passed)
                .then(|| (verdict.kind(), verdict.to_string())),
        })
        .collect();
    let other = match &report.build_failure {
        Some(build) => Some((
            Verdict::NotBuilt(build.failure.clone()).kind(),
            build.failure.to_string(),
        )),
        None if !report.other_failed.is_empty() => {
            Some(("failed", report.other_tests()))
        }
        None if report.other_waiting > 0 => {
            Some(("not attempted", report.other_tests()))
        }
        None => None,
    };
    cases.push(Case {
        name: "other tests".to_string(),
        failure: other,
    });
    cases
}

/// The report as a JUnit XML document: `<testsuites>` holding one
/// `<testsuite>` named after the chapter's package.
pub fn junit(heading: &Heading, report: &Report) -> String {
    let cases = cases(report);
    let failures = cases.iter().filter(|c| c.failure.is_some()).count();
    let mut writer = Writer::new_with_indent(Vec::new(), b' ', 2);
    let written: io::Result<()> = (|| {
        writer.write_event(Event::Decl(BytesDecl::new(
            "1.0",
            Some("UTF-8"),
            None,
        )))?;
        let tests = cases.len().to_string();
        let failures = failures.to_string();
        writer
            .create_element("testsuites")
            .with_attribute(("name", "raystep check"))
            .with_attribute(("tests", tests.as_str()))
            .with_attribute(("failures", failures.as_str()))
            .write_inner_content(|writer| {
                writer
                    .create_element("testsuite")
                    .with_attribute(("name", heading.package))
                    .with_attribute(("tests", tests.as_str()))
                    .with_attribute(("failures", failures.as_str()))
                    .with_attribute(("errors", "0"))
                    .with_attribute(("skipped", "0"))
                    .write_inner_content(|writer| {
                        suite_content(writer, heading, report, &cases)
                    })?;
                Ok(())
            })?;
        Ok(())
    })();
    written.expect("writing to memory cannot fail");
    let mut text =
        String::from_utf8(writer.into_inner()).expect("the XML is UTF-8");
    text.push('\n');
    text
}

/// The properties, the test cases, and the snapshot advice of the suite.
fn suite_content(
    writer: &mut Writer<Vec<u8>>, heading: &Heading, report: &Report,
    cases: &[Case],
) -> io::Result<()> {
    writer
        .create_element("properties")
        .write_inner_content(|writer| {
            for (name, value) in
                [("chapter", heading.chapter), ("mode", heading.mode())]
            {
                writer
                    .create_element("property")
                    .with_attribute(("name", name))
                    .with_attribute(("value", value))
                    .write_empty()?;
            }
            Ok(())
        })?;
    for case in cases {
        let element = writer
            .create_element("testcase")
            .with_attribute(("classname", heading.package))
            .with_attribute(("name", xml_text(&case.name).as_str()));
        match &case.failure {
            None => {
                element.write_empty()?;
            }
            Some((kind, message)) => {
                let message = xml_text(message);
                element.write_inner_content(|writer| {
                    writer
                        .create_element("failure")
                        .with_attribute(("type", *kind))
                        .with_attribute(("message", message.as_str()))
                        .write_text_content(BytesText::new(&message))?;
                    Ok(())
                })?;
            }
        }
    }
    let advice = advice(&report.changed_snapshots, &report.package_dir);
    if !advice.is_empty() {
        writer.create_element("system-err").write_text_content(
            BytesText::new(&xml_text(&advice.join("\n"))),
        )?;
    }
    Ok(())
}

/// `text` without the characters XML 1.0 cannot hold even escaped (control
/// characters other than tab, line feed and carriage return; U+FFFE and
/// U+FFFF), each replaced by U+FFFD.
fn xml_text(text: &str) -> String {
    text.chars()
        .map(|c| match c {
            '\t' | '\n' | '\r' => c,
            c if (c as u32) < 0x20 || c == '\u{FFFE}' || c == '\u{FFFF}' => {
                '\u{FFFD}'
            }
            c => c,
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use raystep_check::verdicts::{
        BuildFailure, CargoFailure, Change, ChangedSnapshot, CompileError,
        Label,
    };

    const HEADING: Heading = Heading {
        chapter: "ch02",
        package: "ch02-plane-polygon-hits",
        reference: false,
    };

    fn sample() -> Report {
        Report {
            exercises: vec![
                ("ray_plane".into(), Verdict::Passed),
                (
                    "inside_polygon".into(),
                    Verdict::Failed(
                        "inside_table (tests/inside_polygon.rs:17): snapshot \
                         inside_table, row 2 (point \"a <b> & 'c'\"): f1 \
                         expected `4`, got `-4`\u{1b}"
                            .into(),
                    ),
                ),
                (
                    "q1".into(),
                    Verdict::Failed(
                        "question 1, t expected about 4 (your 4.4 is off by \
                         10 %)"
                            .into(),
                    ),
                ),
            ],
            labels: [
                ("ray_plane", "★", false),
                ("inside_polygon", "★★", false),
                ("q1", "★", true),
            ]
            .into_iter()
            .map(|(e, stars, paper)| {
                let stars = stars.to_string();
                (e.to_string(), Label { stars, paper })
            })
            .collect(),
            other_passed: 3,
            other_waiting: 2,
            other_failed: Vec::new(),
            build_failure: None,
            changed_snapshots: vec![ChangedSnapshot {
                path: "tests/snapshots/a.snap".into(),
                change: Change::Modified,
            }],
            package_dir: "chapters/ch02".into(),
            held_out_runner: None,
        }
    }

    #[test]
    fn json_holds_every_verdict() {
        let value: serde_json::Value =
            serde_json::from_str(&json(&HEADING, &sample())).unwrap();
        assert_eq!(
            value,
            serde_json::json!({
                "chapter": "ch02",
                "package": "ch02-plane-polygon-hits",
                "mode": "student",
                "passed": false,
                "exercises": [
                    {
                        "exercise": "ray_plane",
                        "kind": "code",
                        "stars": 1,
                        "verdict": "passed",
                        "message": null
                    },
                    {
                        "exercise": "inside_polygon",
                        "kind": "code",
                        "stars": 2,
                        "verdict": "failed",
                        "message": "inside_table (tests/inside_polygon.rs:17): snapshot \
                            inside_table, row 2 (point \"a <b> & 'c'\"): f1 expected `4`, \
                            got `-4`\u{1b}"
                    },
                    {
                        "exercise": "q1",
                        "kind": "paper",
                        "stars": 1,
                        "verdict": "failed",
                        "message": "question 1, t expected about 4 (your 4.4 is off by 10 %)"
                    }
                ],
                "other_tests": {"passed": 3, "waiting": 2, "failed": []},
                "build_failure": null,
                "changed_snapshots": [
                    {"path": "tests/snapshots/a.snap", "change": "changed"}
                ]
            })
        );
    }

    #[test]
    fn junit_is_escaped_xml_with_one_case_per_exercise() {
        let xml = junit(&HEADING, &sample());
        assert_eq!(
            xml,
            r#"<?xml version="1.0" encoding="UTF-8"?>
<testsuites name="raystep check" tests="4" failures="3">
  <testsuite name="ch02-plane-polygon-hits" tests="4" failures="3" errors="0" skipped="0">
    <properties>
      <property name="chapter" value="ch02"/>
      <property name="mode" value="student"/>
    </properties>
    <testcase classname="ch02-plane-polygon-hits" name="ray_plane"/>
    <testcase classname="ch02-plane-polygon-hits" name="inside_polygon">
      <failure type="failed" message="failed: inside_table (tests/inside_polygon.rs:17): snapshot inside_table, row 2 (point &quot;a &lt;b&gt; &amp; &apos;c&apos;&quot;): f1 expected `4`, got `-4`�">failed: inside_table (tests/inside_polygon.rs:17): snapshot inside_table, row 2 (point &quot;a &lt;b&gt; &amp; &apos;c&apos;&quot;): f1 expected `4`, got `-4`�</failure>
    </testcase>
    <testcase classname="ch02-plane-polygon-hits" name="q1 (paper)">
      <failure type="failed" message="failed: question 1, t expected about 4 (your 4.4 is off by 10 %)">failed: question 1, t expected about 4 (your 4.4 is off by 10 %)</failure>
    </testcase>
    <testcase classname="ch02-plane-polygon-hits" name="other tests">
      <failure type="not attempted" message="3 passed, 2 wait for your exercises (todo!())">3 passed, 2 wait for your exercises (todo!())</failure>
    </testcase>
    <system-err>warning: these snapshot files are not the reference, so the tests that use them prove nothing:
  tests/snapshots/a.snap (changed)
restore them: git checkout -- chapters/ch02/tests/snapshots/a.snap</system-err>
  </testsuite>
</testsuites>
"#
        );
        // A reader gets the message back exactly.
        let mut reader = quick_xml::Reader::from_str(&xml);
        let mut messages = Vec::new();
        loop {
            match reader.read_event().unwrap() {
                Event::Eof => break,
                Event::Empty(e) | Event::Start(e)
                    if e.name().as_ref() == b"failure" =>
                {
                    let message = e
                        .try_get_attribute("message")
                        .unwrap()
                        .unwrap()
                        .unescape_value()
                        .unwrap()
                        .into_owned();
                    messages.push(message);
                }
                _ => {}
            }
        }
        assert_eq!(messages.len(), 3);
        assert!(messages[0].contains("(point \"a <b> & 'c'\")"));
    }

    #[test]
    fn a_build_failure_fails_every_case() {
        let failure = BuildFailure {
            failure: CargoFailure::DoesNotCompile(
                "error[E0308]: mismatched types (at exercise/ray_plane.rs:3:26)"
                    .into(),
            ),
            errors: vec![CompileError {
                message: "error[E0308]: mismatched types".into(),
                at: Some("exercise/ray_plane.rs:3:26".into()),
            }],
        };
        let report = Report::not_built(
            &["ray_plane".to_string(), "inside_polygon".to_string()],
            failure,
        );
        let xml = junit(&HEADING, &report);
        assert_eq!(
            xml.matches("<failure type=\"does not compile\"").count(),
            3
        );
        let value: serde_json::Value =
            serde_json::from_str(&json(&HEADING, &report)).unwrap();
        assert_eq!(value["exercises"][1]["verdict"], "does not compile");
        assert_eq!(
            value["build_failure"],
            serde_json::json!({
                "message": "the tests do not compile: error[E0308]: mismatched \
                    types (at exercise/ray_plane.rs:3:26)",
                "errors": [{
                    "message": "error[E0308]: mismatched types",
                    "at": "exercise/ray_plane.rs:3:26"
                }]
            })
        );
    }
}
