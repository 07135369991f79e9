//! The judgement from end to end: what test binaries printed (the
//! fixtures in `testdata/` hold real runs) and how they ended, read into
//! each exercise's verdict and the chapter's report.

use std::collections::HashMap;
use std::time::Duration;

use super::libtest_output::parse_output;
use super::*;

/// One binary's results from what it printed and how it ended (paths as
/// printed).
fn test_binary(target: Target, stdout: &str, ended: &Ended) -> TestBinary {
    test_binary_in(target, stdout, ended, &Context::default())
}

#[test]
fn a_failure_cut_short_by_a_crash_says_so() {
    let binary = TestBinary {
        target: Target::Test("recursion".into()),
        results: vec![TestResult {
            name: "depth_one".into(),
            outcome: Outcome::Failed(None),
        }],
        crashed: Some("the test binary crashed (signal: 6)".into()),
        timed_out: None,
        stopped: None,
    };
    let report = report(&exercises(&["recursion"]), &[binary], &HashMap::new());
    assert_eq!(
        report.exercises[0].1,
        Verdict::Failed(
            "depth_one: failed, and the test binary crashed (signal: 6) \
             before it could say why"
                .into()
        )
    );
}

fn exercises(names: &[&str]) -> Vec<String> {
    names.iter().map(|s| s.to_string()).collect()
}

/// `running 1 test`, `running 12 tests`: where one binary's output starts.
fn is_running_line(line: &str) -> bool {
    line.strip_prefix("running ")
        .and_then(|rest| {
            rest.strip_suffix(" tests")
                .or_else(|| rest.strip_suffix(" test"))
        })
        .is_some_and(|n| !n.is_empty() && n.bytes().all(|b| b.is_ascii_digit()))
}

/// The fixtures hold what several test binaries printed one after the
/// other (as `cargo test` shows it): split at each `running N tests`.
fn split(stdout: &str) -> Vec<String> {
    let mut outputs: Vec<String> = Vec::new();
    for line in stdout.lines() {
        if is_running_line(line) {
            outputs.push(String::new());
        }
        if let Some(output) = outputs.last_mut() {
            output.push_str(line);
            output.push('\n');
        }
    }
    outputs
}

/// Binaries that exited as libtest does: with its failure status if a
/// test failed, else with success.
fn exited(targets: Vec<Target>, stdout: &str) -> Vec<TestBinary> {
    let outputs = split(stdout);
    assert_eq!(outputs.len(), targets.len());
    let ended = |output: &str| {
        let failed = output.contains("test result: FAILED");
        Ended::Exited {
            success: !failed,
            how: if failed {
                "exit status: 101"
            } else {
                "exit status: 0"
            }
            .to_string(),
        }
    };
    targets
        .into_iter()
        .zip(outputs)
        .map(|(target, output)| test_binary(target, &output, &ended(&output)))
        .collect()
}

fn sample_targets() -> Vec<Target> {
    vec![
        Target::Unit("src/lib.rs".into()),
        Target::Test("add".into()),
        Target::Test("other".into()),
        Target::Test("triple".into()),
    ]
}

/// A chapter with exercises `add` (both tests hit `todo!()`) and `triple`
/// (a wrong answer: an insta snapshot and an `assert_eq!` fail), other
/// tests in `src/lib.rs` and `tests/other.rs`.
fn student() -> Vec<TestBinary> {
    exited(
        sample_targets(),
        include_str!("../../testdata/student.stdout"),
    )
}

#[test]
fn each_binarys_output_is_read() {
    let binaries = student();
    assert!(
        binaries
            .iter()
            .all(|b| b.crashed.is_none() && b.timed_out.is_none())
    );
    let counts: Vec<usize> = binaries.iter().map(|b| b.results.len()).collect();
    assert_eq!(counts, [1, 2, 1, 3]);
    let output =
        parse_output(&split(include_str!("../../testdata/student.stdout"))[1]);
    assert!(output.finished);
    assert!(output.slow.is_empty());
}

#[test]
fn panic_messages_are_found() {
    let binaries = student();
    let outcome = |binary: usize, name: &str| {
        binaries[binary]
            .results
            .iter()
            .find(|r| r.name == name)
            .map(|r| r.outcome.clone())
            .unwrap()
    };
    let failed = |message: &str, at: &str| {
        Outcome::Failed(Some(Failure {
            message: message.into(),
            at: Some(at.into()),
        }))
    };
    // Where it panicked, without `src/../` and the column.
    assert_eq!(
        outcome(1, "adds_small"),
        failed("not yet implemented", "exercise/ex.rs:1")
    );
    assert_eq!(
        outcome(3, "triple_eq"),
        failed(
            "assertion `left == right` failed: triple of two (left: 8, right: 6)",
            "tests/triple.rs:4"
        )
    );
    // A snapshot: where it is asserted (insta panics in its own
    // code); the snapshot file is not there, so the diff alone says
    // which line differs.
    assert_eq!(
        outcome(3, "triple_snapshot"),
        failed(
            "snapshot triples, line 1: expected `3`, got `4`",
            "tests/triple.rs:2"
        )
    );
    assert_eq!(outcome(3, "triple_zero"), Outcome::Passed);
}

#[test]
fn student_verdicts() {
    let sources = HashMap::from([(
        "triple".to_string(),
        "#[test]\nfn triple_snapshot() {}\n#[test]\nfn triple_eq() {}\n"
            .to_string(),
    )]);
    let report = report(&exercises(&["add", "triple"]), &student(), &sources);
    assert_eq!(
        report.exercises,
        [
            ("add".to_string(), Verdict::NotAttempted),
            (
                "triple".to_string(),
                Verdict::Failed(
                    "triple_snapshot (tests/triple.rs:2): snapshot triples, \
                     line 1: expected `3`, got `4`"
                        .into()
                )
            ),
        ]
    );
    assert_eq!(report.other_passed, 2);
    assert!(report.other_failed.is_empty());
    assert!(!report.all_passed());
    assert_eq!(
        report.to_string(),
        "  add          not attempted\n\
         \x20 triple       failed: triple_snapshot (tests/triple.rs:2): snapshot \
         triples, line 1: expected `3`, got `4`\n\
         \x20 other tests  2 passed\n\
         0 of 2 exercises passed\n"
    );
}

#[test]
fn without_sources_the_first_failure_is_alphabetical() {
    let report = report(&exercises(&["triple"]), &student(), &HashMap::new());
    assert_eq!(
        report.exercises[0].1,
        Verdict::Failed(
            "triple_eq (tests/triple.rs:4): assertion `left == right` \
             failed: triple of two (left: 8, right: 6)"
                .into()
        )
    );
}

#[test]
fn reference_verdicts() {
    let binaries = exited(
        sample_targets(),
        include_str!("../../testdata/reference.stdout"),
    );
    let report =
        report(&exercises(&["add", "triple"]), &binaries, &HashMap::new());
    assert_eq!(
        report.exercises,
        [
            ("add".to_string(), Verdict::Passed),
            ("triple".to_string(), Verdict::Passed)
        ]
    );
    assert!(report.all_passed());
    assert!(report.to_string().ends_with("2 of 2 exercises passed\n"));
}

#[test]
fn an_exercise_without_tests_fails() {
    let report = report(&exercises(&["missing"]), &student(), &HashMap::new());
    assert_eq!(
        report.exercises[0].1,
        Verdict::Failed("no tests ran (expected tests/missing.rs)".into())
    );
}

#[test]
fn a_crashing_binary_fails_its_exercise() {
    let outputs = split(include_str!("../../testdata/crash.stdout"));
    let abort = Ended::Exited {
        success: false,
        how: "signal: 6, SIGABRT: process abort signal".to_string(),
    };
    let ok = Ended::Exited {
        success: true,
        how: "exit status: 0".to_string(),
    };
    let binaries = [
        test_binary(Target::Test("crash".into()), &outputs[0], &abort),
        test_binary(Target::Test("other".into()), &outputs[1], &ok),
    ];
    assert_eq!(
        binaries[0].crashed.as_deref(),
        Some(
            "the test binary crashed (signal: 6, SIGABRT: process abort signal)"
        )
    );
    assert_eq!(binaries[1].crashed, None);
    let report = report(&exercises(&["crash"]), &binaries, &HashMap::new());
    assert_eq!(
        report.exercises[0].1,
        Verdict::Failed(
            "the test binary crashed (signal: 6, SIGABRT: process abort signal)".into()
        )
    );
    assert_eq!(report.other_passed, 1);
}

/// A `test result:` line followed by a death by signal is not
/// libtest's: the binary crashed, whatever it printed before.
#[test]
fn a_result_line_before_a_crash_is_not_believed() {
    let forged = "\nrunning 1 tests\ntest a ... ok\n\n\
        test result: ok. 1 passed; 0 failed; 0 ignored; 0 measured; 0 filtered out; finished in 0.00s\n";
    let abort = Ended::Exited {
        success: false,
        how: "signal: 6, SIGABRT: process abort signal".to_string(),
    };
    let binary = test_binary(Target::Test("a".into()), forged, &abort);
    assert_eq!(
        binary.crashed.as_deref(),
        Some(
            "the test binary crashed (signal: 6, SIGABRT: process abort signal)"
        )
    );
    let report = report(&exercises(&["a"]), &[binary], &HashMap::new());
    assert_eq!(report.exercises[0].1.kind(), "failed");
    // Nor is one that says every test passed and then exits with failure
    // (a sandbox reports a death by signal as exit status 128 + N).
    let exit = Ended::Exited {
        success: false,
        how: "exit status: 134".to_string(),
    };
    let binary = test_binary(Target::Test("a".into()), forged, &exit);
    assert_eq!(
        binary.crashed.as_deref(),
        Some("the test binary crashed (exit status: 134)")
    );
    // libtest's own failure is believed: a test failed, exit status 101.
    let failed = "\nrunning 1 tests\ntest a ... FAILED\n\n\
        test result: FAILED. 0 passed; 1 failed; 0 ignored; 0 measured; 0 filtered out; finished in 0.00s\n";
    let exit = Ended::Exited {
        success: false,
        how: "exit status: 101".to_string(),
    };
    let binary = test_binary(Target::Test("a".into()), failed, &exit);
    assert_eq!(binary.crashed, None);
}

#[test]
fn a_binary_that_stops_early_or_never_starts_fails() {
    let started = "\nrunning 2 tests\ntest a ... ok\n";
    let ok = Ended::Exited {
        success: true,
        how: "exit status: 0".to_string(),
    };
    let binary = test_binary(Target::Test("early".into()), started, &ok);
    assert_eq!(
        binary.crashed.as_deref(),
        Some("the test binary stopped early")
    );
    let missing =
        Ended::NotStarted("No such file or directory (os error 2)".to_string());
    let binary = test_binary(Target::Test("gone".into()), "", &missing);
    assert_eq!(
        binary.crashed.as_deref(),
        Some(
            "the test binary could not be started (No such file or directory (os error 2))"
        )
    );
}

#[test]
fn ignored_tests_module_paths_and_other_binaries() {
    let lib = "\nrunning 3 tests\n\
        test tests::fits ... ok\n\
        test tests::slow ... ignored, takes a minute\n\
        test tests::rounds - should panic ... ok\n\n\
        test result: ok. 2 passed; 0 failed; 1 ignored; 0 measured; 0 filtered out; finished in 0.00s\n\n";
    let bin = "\nrunning 1 test\n\
        test tests::draws ... FAILED\n\n\
        failures:\n\n\
        ---- tests::draws stdout ----\n\n\
        thread 'tests::draws' (42) panicked at chapters/ch01/src/bin/figures.rs:5:1:\n\
        not yet implemented\n\
        note: run with `RUST_BACKTRACE=1` environment variable to display a backtrace\n\n\n\
        failures:\n    tests::draws\n\n\
        test result: FAILED. 0 passed; 1 failed; 0 ignored; 0 measured; 0 filtered out; finished in 0.10s\n\n";
    let failed = Ended::Exited {
        success: false,
        how: "exit status: 101".to_string(),
    };
    let passed = Ended::Exited {
        success: true,
        how: "exit status: 0".to_string(),
    };
    let binaries = [
        test_binary(Target::Unit("src/lib.rs".into()), lib, &passed),
        test_binary(Target::Unit("src/bin/figures.rs".into()), bin, &failed),
    ];
    let report = report(&[], &binaries, &HashMap::new());
    assert_eq!(report.other_passed, 2);
    // Stopped at a todo!(): waiting for the exercises, not failed.
    assert_eq!(report.other_waiting, 1);
    assert!(report.other_failed.is_empty());
    assert!(!report.all_passed());
    assert!(
        report
            .to_string()
            .ends_with("this chapter has no exercises\n")
    );
}

/// Other tests that stopped at `todo!()` wait for the exercises; real
/// failures are named in source order whatever order the threads
/// finished in.
#[test]
fn other_tests_wait_or_fail_in_source_order() {
    let panic = |name: &str, at: &str, message: &str| {
        format!(
            "---- {name} stdout ----\n\
             thread '{name}' (1) panicked at {at}:\n{message}\n\
             note: run with `RUST_BACKTRACE=1` environment variable to display a backtrace\n\n"
        )
    };
    let output = |order: [&str; 4]| {
        let mut text = "\nrunning 4 tests\n".to_string();
        for name in order {
            let status = if name == "fits" { "ok" } else { "FAILED" };
            text.push_str(&format!("test {name} ... {status}\n"));
        }
        text.push_str("\nfailures:\n\n");
        text.push_str(&panic(
            "waits",
            "src/../exercise/ex.rs:3:5",
            "not yet implemented",
        ));
        text.push_str(&panic("late", "tests/other.rs:9:5", "late broke"));
        text.push_str(&panic("early", "tests/other.rs:2:5", "early broke"));
        text.push_str("failures:\n    early\n    late\n    waits\n\n\
            test result: FAILED. 1 passed; 3 failed; 0 ignored; 0 measured; 0 filtered out; finished in 0.01s\n");
        text
    };
    let source = "#[test]\nfn late() {}\n#[test]\nfn fits() {}\n\
                  #[test]\nfn early() {}\n#[test]\nfn waits() {}\n";
    let sources = HashMap::from([("other".to_string(), source.to_string())]);
    let ended = Ended::Exited {
        success: false,
        how: "exit status: 101".to_string(),
    };
    let reports: Vec<Report> = [
        ["waits", "fits", "early", "late"],
        ["late", "early", "waits", "fits"],
    ]
    .into_iter()
    .map(|order| {
        let binary =
            test_binary(Target::Test("other".into()), &output(order), &ended);
        report(&[], &[binary], &sources)
    })
    .collect();
    assert_eq!(
        reports[0], reports[1],
        "the order of completion matters not"
    );
    let report = &reports[0];
    assert_eq!(
        report.other_failed,
        [
            "late (tests/other.rs:9): late broke",
            "early (tests/other.rs:2): early broke"
        ]
    );
    assert_eq!(report.other_waiting, 1);
    assert_eq!(
        report.other_tests(),
        "1 passed, 1 wait for your exercises (todo!()), 2 failed \
         (first: late (tests/other.rs:9): late broke)"
    );
    // Only waiting: no word of failure.
    let waiting = Report {
        other_passed: 20,
        other_waiting: 6,
        ..Report::default()
    };
    assert_eq!(
        waiting.other_tests(),
        "20 passed, 6 wait for your exercises (todo!())"
    );
    assert!(!waiting.all_passed());
}

/// `recursion.rs` of a chapter, killed while `facing_mirrors_terminate` loops.
const KILLED: &str = "\nrunning 4 tests\n\
    test a_mirror_reflects ... ok\n\
    test depth_is_limited ... FAILED\n";

fn listed() -> Vec<String> {
    exercises(&[
        "a_mirror_reflects",
        "depth_is_limited",
        "facing_mirrors_terminate",
        "weights_shrink",
    ])
}

fn timed_out(threads: usize, listed: Vec<String>) -> Ended {
    Ended::TimedOut {
        limit: Duration::from_secs(60),
        listed,
        threads,
    }
}

#[test]
fn a_timed_out_exercise_names_its_unfinished_tests() {
    let binaries = [
        test_binary(
            Target::Unit("src/lib.rs".into()),
            "\nrunning 0 tests\n\ntest result: ok. 0 passed\n",
            &Ended::Exited {
                success: true,
                how: "exit status: 0".into(),
            },
        ),
        test_binary(
            Target::Test("recursion".into()),
            KILLED,
            &timed_out(1, listed()),
        ),
    ];
    assert_eq!(binaries[1].crashed, None);
    let report = report(&exercises(&["recursion"]), &binaries, &HashMap::new());
    assert_eq!(
        report.exercises[0].1,
        Verdict::TimedOut(TimedOut {
            limit: Duration::from_secs(60),
            still_running: exercises(&["facing_mirrors_terminate"]),
        })
    );
    assert_eq!(
        report.to_string(),
        "  recursion    timed out after 60 s (still running: facing_mirrors_terminate)\n\
         \x20 other tests  0 passed\n\
         0 of 1 exercises passed\n"
    );
    assert!(!report.all_passed());
}

/// A binary stopped at the memory or output limit fails its exercise with
/// the limit and the test it was running, even though a test failed
/// first: the limit is what the student must fix.
#[test]
fn an_exercise_stopped_at_a_limit_names_the_limit_and_the_test() {
    let stopped = Ended::Stopped {
        why: "out of memory (limit 2 GiB, --memory)".into(),
        how: "signal: 6, SIGABRT: process abort signal".into(),
        listed: listed(),
        threads: 1,
    };
    let binary =
        test_binary(Target::Test("recursion".into()), KILLED, &stopped);
    assert_eq!((&binary.crashed, &binary.timed_out), (&None, &None));
    let hog = report(&exercises(&["recursion"]), &[binary], &HashMap::new());
    assert_eq!(
        hog.exercises[0].1,
        Verdict::Failed(
            "out of memory (limit 2 GiB, --memory) while running \
             facing_mirrors_terminate"
                .into()
        )
    );
    // Nothing known to be running: the limit alone.
    let flood = Ended::Stopped {
        why: "printed more than 8 MiB (limit, --output)".into(),
        how: "killed".into(),
        listed: Vec::new(),
        threads: 1,
    };
    let binary = test_binary(Target::Unit("src/lib.rs".into()), "", &flood);
    assert_eq!(
        binary.stopped.as_deref(),
        Some("printed more than 8 MiB (limit, --output)")
    );
    let report = report(&exercises(&["recursion"]), &[binary], &HashMap::new());
    assert!(
        report.other_failed.contains(
            &"unittests src/lib.rs: printed more than 8 MiB (limit, --output)"
                .to_string()
        ),
        "{:?}",
        report.other_failed
    );
}

#[test]
fn running_tests_follow_the_list_order_and_the_thread_count() {
    let running = |ended: &Ended| {
        test_binary(Target::Test("recursion".into()), KILLED, ended)
            .timed_out
            .unwrap()
            .still_running
    };
    // Two threads: both tests after the two that reported had started.
    assert_eq!(
        running(&timed_out(2, listed())),
        ["facing_mirrors_terminate", "weights_shrink"]
    );
    assert_eq!(
        running(&timed_out(8, listed())),
        ["facing_mirrors_terminate", "weights_shrink"]
    );
    // A test that reported but would not have started yet: another order.
    let shuffled = exercises(&[
        "facing_mirrors_terminate",
        "weights_shrink",
        "a_mirror_reflects",
        "depth_is_limited",
    ]);
    assert!(running(&timed_out(1, shuffled)).is_empty());
    // No list: nothing to say.
    assert!(running(&timed_out(1, Vec::new())).is_empty());
    // Unless libtest itself said which test was slow.
    let warned = format!(
        "{KILLED}test weights_shrink has been running for over 60 seconds\n"
    );
    let binary = test_binary(
        Target::Test("r".into()),
        &warned,
        &timed_out(1, Vec::new()),
    );
    assert_eq!(
        binary.timed_out.unwrap().to_string(),
        "timed out after 60 s (still running: weights_shrink)"
    );
}

#[test]
fn a_timed_out_other_binary_is_an_other_failure() {
    let ended = Ended::TimedOut {
        limit: Duration::from_millis(2500),
        listed: exercises(&["tests::spins"]),
        threads: 4,
    };
    let binaries = [test_binary(
        Target::Unit("src/lib.rs".into()),
        "\nrunning 1 test\n",
        &ended,
    )];
    let report = report(&[], &binaries, &HashMap::new());
    assert_eq!(
        report.other_failed,
        [
            "unittests src/lib.rs: timed out after 2.5 s (still running: tests::spins)"
        ]
    );
    assert!(!report.all_passed());
    // Without a list or a warning the message names no test.
    let unknown = Ended::TimedOut {
        limit: Duration::from_secs(3),
        listed: Vec::new(),
        threads: 4,
    };
    let binary = test_binary(Target::Test("x".into()), "", &unknown);
    assert_eq!(binary.timed_out.unwrap().to_string(), "timed out after 3 s");
}

/// With labels the table shows each exercise's difficulty and marks the
/// paper questions, and the last line counts the two kinds apart; a
/// chapter that did not build still shows its paper questions.
#[test]
fn the_table_shows_difficulty_and_paper_questions() {
    let label = |stars: &str, paper: bool| Label {
        stars: stars.into(),
        paper,
    };
    let mut report = Report {
        exercises: vec![
            ("ray_plane".into(), Verdict::Passed),
            (
                "q1".into(),
                Verdict::Failed(
                    "question 1, t expected about 4 (your 4.4 is off by 10 %)"
                        .into(),
                ),
            ),
            ("q2".into(), Verdict::Passed),
        ],
        labels: [
            ("ray_plane".to_string(), label("★", false)),
            ("q1".to_string(), label("★★", true)),
            ("q2".to_string(), label("★★★", true)),
        ]
        .into(),
        other_passed: 2,
        ..Report::default()
    };
    assert_eq!(
        report.to_string(),
        "  ray_plane    ★    passed\n\
        \x20 q1 (paper)   ★★   failed: question 1, t expected about 4 (your 4.4 is off by 10 %)\n\
        \x20 q2 (paper)   ★★★  passed\n\
        \x20 other tests       2 passed\n\
        1 of 1 exercises and 1 of 2 paper questions passed\n"
    );
    report.build_failure = Some(BuildFailure {
        failure: CargoFailure::DoesNotCompile(
            "the tests do not compile".into(),
        ),
        errors: Vec::new(),
    });
    let text = report.to_string();
    assert!(text.contains("\n  q2 (paper)  passed\n"), "{text}");
    assert!(!text.contains("ray_plane"), "{text}");
}
