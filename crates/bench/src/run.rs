//! One benchmark run: every method built and traced on every ray set,
//! round after round, taking turns; the medians kept; every answer
//! checked against the first method's, and a sample against brute force.
use std::time::Instant;

use ch08::MeshBruteForce;
use indicatif::ProgressBar;
use rayon::prelude::*;
use raystep_core::{DVec3, Ray32};
use raystep_world::{MeshAccelerator, TraceCounts};

use crate::methods::Method;
use crate::rays::{Question, RaySet, interval};
use crate::report::{MethodReport, SetReport, agreement_name};

/// One ray's answer, as the hit file stores it: `t` (+∞ for a miss) and
/// the triangle (`u32::MAX` for a miss). Any-hit answers use `t` = 0 for
/// "blocked".
pub type Answer = (f32, u32);

/// The answer of no hit.
pub const MISS: Answer = (f32::INFINITY, u32::MAX);

/// Traces `set` with `tracer` on the current thread pool, in chunks; the
/// answers in the set's order, and the work counted.
pub fn trace(
    tracer: &dyn MeshAccelerator, set: &RaySet,
) -> (Vec<Answer>, TraceCounts) {
    let range = interval(set.question);
    let chunks: Vec<(Vec<Answer>, TraceCounts)> = set
        .rays
        .par_chunks(4096)
        .map(|rays| {
            let mut counts = TraceCounts::default();
            let answers = rays
                .iter()
                .map(|ray| {
                    answer(tracer, set.question, ray, range, &mut counts)
                })
                .collect();
            (answers, counts)
        })
        .collect();
    let mut all = Vec::with_capacity(set.rays.len());
    let mut counts = TraceCounts::default();
    for (answers, c) in chunks {
        all.extend(answers);
        counts.add(c);
    }
    (all, counts)
}

fn answer(
    tracer: &dyn MeshAccelerator, question: Question, ray: &Ray32,
    range: raystep_core::Interval, counts: &mut TraceCounts,
) -> Answer {
    match question {
        Question::Closest => tracer
            .closest_hit(ray, range, counts)
            .map_or(MISS, |hit| (hit.t as f32, hit.triangle)),
        Question::Any => {
            if tracer.any_hit(ray, range, counts) {
                (0.0, 0)
            } else {
                MISS
            }
        }
    }
}

/// Do two answers agree? Both miss, or both hit at the same `t` (the
/// triangle may differ only where two are hit at exactly that `t`).
pub fn agree(a: Answer, b: Answer) -> bool {
    a.0 == b.0 || (a.0.is_nan() && b.0.is_nan())
}

/// How far apart, relative to `t`, two hits may be and still agree when
/// one method tests triangles its own way ([`Method::own_triangle_test`]:
/// Embree's test, in `f32`): its `t` differs from the chapter's `f64` one
/// in the last bits, up to 2·10⁻⁵ (relative) on the bunny's rays;
/// 10⁻⁴ leaves room for that, while a hit on another surface further
/// along (a ray through a crack) still disagrees.
pub const OWN_TEST_TOLERANCE: f32 = 1e-4;

/// Do two answers agree within `tolerance` of `t` (relative)? As
/// [`agree`], or both hit with |t_a − t_b| ≤ tolerance · max(t_a, t_b).
/// Any-hit answers (blocked or not) agree only when they are the same.
pub fn agree_within(a: Answer, b: Answer, tolerance: f32) -> bool {
    agree(a, b)
        || (a.0.is_finite()
            && b.0.is_finite()
            && (a.0 - b.0).abs() <= tolerance * a.0.abs().max(b.0.abs()))
}

/// The tolerance `method`'s answers are checked against `reference`'s
/// with: none (the same `t`) unless either has its own triangle test.
pub fn tolerance(method: &Method, reference: &Method) -> Option<f32> {
    (method.own_triangle_test() || reference.own_triangle_test())
        .then_some(OWN_TEST_TOLERANCE)
}

/// [`agree`], or [`agree_within`] a tolerance.
fn agree_by(a: Answer, b: Answer, tolerance: Option<f32>) -> bool {
    match tolerance {
        None => agree(a, b),
        Some(tolerance) => agree_within(a, b, tolerance),
    }
}

/// The median of some numbers (the mean of the middle two for an even
/// count).
pub fn median(values: &mut [f64]) -> f64 {
    values.sort_by(f64::total_cmp);
    let n = values.len();
    if n == 0 {
        f64::NAN
    } else if n % 2 == 1 {
        values[n / 2]
    } else {
        0.5 * (values[n / 2 - 1] + values[n / 2])
    }
}

/// Runs the comparison: `rounds` rounds, in each every method built and
/// traced on every set in turn. The first method's answers are the
/// reference the others are checked against (the same `t`, or within
/// [`OWN_TEST_TOLERANCE`] where either tests triangles its own way); the
/// answers of the first method on the first set are returned for the hit
/// file. `step` is called after each round.
pub fn compare(
    triangles: &[[DVec3; 3]], sets: &[RaySet], methods: &[Method],
    rounds: usize, progress: &ProgressBar, step: &mut dyn FnMut(),
) -> (Vec<MethodReport>, Vec<Answer>) {
    let mut reports: Vec<MethodReport> =
        methods.iter().map(|m| MethodReport::new(m, sets)).collect();
    let tolerances: Vec<Option<f32>> =
        methods.iter().map(|m| tolerance(m, &methods[0])).collect();
    for (report, &tolerance) in reports.iter_mut().zip(&tolerances) {
        report.agreement = agreement_name(tolerance);
    }
    let mut reference: Vec<Vec<Answer>> = Vec::new();
    let mut build_ms: Vec<Vec<f64>> = vec![Vec::new(); methods.len()];
    let mut seconds: Vec<Vec<Vec<f64>>> =
        vec![vec![Vec::new(); sets.len()]; methods.len()];
    for round in 0..rounds {
        for (m, method) in methods.iter().enumerate() {
            progress.set_message(format!(
                "round {}: {}",
                round + 1,
                method.name()
            ));
            let built = method.build(triangles);
            build_ms[m].push(built.build_ms);
            reports[m].bytes = built.bytes;
            reports[m].tree = built.tree;
            progress.inc(1);
            for (s, set) in sets.iter().enumerate() {
                let start = Instant::now();
                let (answers, counts) = trace(built.tracer.as_ref(), set);
                seconds[m][s].push(start.elapsed().as_secs_f64());
                progress.inc(1);
                if round > 0 {
                    continue; // answers and counts do not change
                }
                let set_report: &mut SetReport = &mut reports[m].sets[s];
                set_report.counts = counts;
                if m == 0 {
                    reference.push(answers);
                } else {
                    set_report.disagreements = answers
                        .iter()
                        .zip(&reference[s])
                        .filter(|(a, b)| !agree_by(**a, **b, tolerances[m]))
                        .count();
                }
            }
        }
        step();
    }
    for (m, report) in reports.iter_mut().enumerate() {
        report.build_ms = median(&mut build_ms[m]);
        for (s, set) in report.sets.iter_mut().enumerate() {
            let t = median(&mut seconds[m][s]);
            set.mrays_per_s = sets[s].rays.len() as f64 / t / 1e6;
        }
    }
    let first = reference.into_iter().next().unwrap_or_default();
    (reports, first)
}

/// Checks `count` rays of each set (evenly spread; all if `count` is at
/// least the set's size) against brute force: how many were checked, and
/// how many of the reference answers differ (beyond `tolerance`, if any).
pub fn check_brute_force(
    triangles: &[[DVec3; 3]], sets: &[RaySet], reference: &dyn MeshAccelerator,
    tolerance: Option<f32>, count: usize, progress: &ProgressBar,
) -> Vec<(usize, usize)> {
    let brute = MeshBruteForce(triangles);
    sets.iter()
        .map(|set| {
            // exactly min(count, len) rays, evenly spread: ray k·len/n
            let (len, n) = (set.rays.len(), count.min(set.rays.len()));
            let sample: Vec<Ray32> =
                (0..n).map(|k| set.rays[k * len / n]).collect();
            let sampled = RaySet {
                name: set.name.clone(),
                question: set.question,
                rays: sample,
            };
            progress.set_message(format!("brute force: {}", set.name));
            let (truth, _) = trace(&brute, &sampled);
            let (ours, _) = trace(reference, &sampled);
            progress.inc(1);
            let wrong = truth
                .iter()
                .zip(&ours)
                .filter(|(a, b)| !agree_by(**a, **b, tolerance));
            (sampled.rays.len(), wrong.count())
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_tolerance_forgives_the_last_bits_only() {
        let hit = |t: f32| (t, 7);
        assert!(!agree(hit(2.0), hit(2.0001)));
        assert!(agree_within(hit(2.0), hit(2.0001), 1e-4));
        assert!(!agree_within(hit(2.0), hit(2.001), 1e-4));
        // a miss and a hit never agree, however far the hit
        assert!(agree_within(MISS, MISS, 1e-4));
        assert!(!agree_within(hit(f32::MAX), MISS, 1e-4));
        // any hit: blocked (t = 0) or not
        assert!(agree_within((0.0, 0), (0.0, 0), 1e-4));
        assert!(!agree_within((0.0, 0), MISS, 1e-4));
    }

    #[test]
    fn only_a_method_with_its_own_test_is_checked_within_it() {
        let ours = Method::Ours(
            ch08::Builder::BinnedSah { bins: 16 },
            ch08::NodePrecision::Single,
        );
        let embree = Method::Embree {
            version: 31305,
            robust: false,
            isa: None,
        };
        assert_eq!(tolerance(&Method::BvhCrate, &ours), None);
        assert_eq!(tolerance(&embree, &ours), Some(OWN_TEST_TOLERANCE));
        assert_eq!(tolerance(&ours, &embree), Some(OWN_TEST_TOLERANCE));
        assert_eq!(agreement_name(None), "exact");
        assert_eq!(agreement_name(Some(1e-4)), "t within 1e-4");
    }
}
