//! One benchmark run: every method built and traced on every ray set,
//! round after round, taking turns; the medians kept; every answer
//! checked against the first method's, and a sample against brute force.
use std::time::Instant;

use ch08::{Ray32, TraceCounts};
use indicatif::ProgressBar;
use rayon::prelude::*;
use raystep_core::DVec3;

use crate::methods::{BruteForce, Method, Tracer};
use crate::rays::{Question, RaySet, interval};
use crate::report::{MethodReport, SetReport};

/// One ray's answer, as the hit file stores it: `t` (+∞ for a miss) and
/// the triangle (`u32::MAX` for a miss). Any-hit answers use `t` = 0 for
/// "blocked".
pub type Answer = (f32, u32);

/// The answer of no hit.
pub const MISS: Answer = (f32::INFINITY, u32::MAX);

/// Traces `set` with `tracer` on the current thread pool, in chunks; the
/// answers in the set's order, and the work counted.
pub fn trace(tracer: &dyn Tracer, set: &RaySet) -> (Vec<Answer>, TraceCounts) {
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
    tracer: &dyn Tracer,
    question: Question,
    ray: &Ray32,
    range: raystep_core::Interval,
    counts: &mut TraceCounts,
) -> Answer {
    match question {
        Question::Closest => tracer
            .closest(ray, range, counts)
            .map_or(MISS, |(triangle, t)| (t, triangle)),
        Question::Any => {
            if tracer.any(ray, range, counts) {
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
/// reference the others are checked against; the answers of the first
/// method on the first set are returned for the hit file. `step` is called
/// after each round.
pub fn compare(
    triangles: &[[DVec3; 3]],
    sets: &[RaySet],
    methods: &[Method],
    rounds: usize,
    progress: &ProgressBar,
    step: &mut dyn FnMut(),
) -> (Vec<MethodReport>, Vec<Answer>) {
    let mut reports: Vec<MethodReport> =
        methods.iter().map(|m| MethodReport::new(m, sets)).collect();
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
                        .filter(|(a, b)| !agree(**a, **b))
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
/// how many of the reference answers differ.
pub fn check_brute_force(
    triangles: &[[DVec3; 3]],
    sets: &[RaySet],
    reference: &dyn Tracer,
    count: usize,
    progress: &ProgressBar,
) -> Vec<(usize, usize)> {
    let brute = BruteForce(triangles);
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
            let wrong =
                truth.iter().zip(&ours).filter(|(a, b)| !agree(**a, **b));
            (sampled.rays.len(), wrong.count())
        })
        .collect()
}
