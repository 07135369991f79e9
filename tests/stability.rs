//! The stability catalogue, every case with the test budget (a few
//! thousand rays, a few hundred inputs): at least 60 cases; every method
//! built to survive a case (every accelerator, the watertight test on
//! shared edges, …) fails none of its trials; and the whole table, with
//! the known weaknesses' counts, as a snapshot to read.
use raystep_stability::{Budget, Expect, run_catalogue, table};

#[test]
fn the_catalogue_holds() {
    let rows = run_catalogue(&Budget::TEST, &mut |_| {}).unwrap();
    let cases = table::cases(&rows);
    assert!(cases >= 60, "{cases} cases");
    let bugs: Vec<String> = rows
        .iter()
        .filter(|r| r.expect == Expect::Never && r.count.failures > 0)
        .map(|r| {
            format!(
                "{} / {}: {} of {}",
                r.case, r.count.method, r.count.failures, r.count.trials
            )
        })
        .collect();
    assert!(bugs.is_empty(), "failures where none may be:\n{bugs:#?}");
    // every case runs its trials, every method at least one
    assert!(rows.iter().all(|r| r.count.trials > 0));
    insta::assert_snapshot!(table::text(&rows));
}
