//! The data behind chapter 5's chart: for each stopping rule on each
//! mirror scene, how far its image is from a deep reference and how many
//! rays it spends (computed, the same on every machine), and how long a
//! render takes (measured, on this machine).
//!
//! `raystep measure` runs [`measure_stopping`] and writes its rows into
//! `book/src/figures/ch05/stopping.csv`; `raystep figures` draws the chart
//! from that file, so the figures stay byte-identical between runs.
use raystep_figure::as_jobs;
use raystep_render::csv::{Decimals, Plain, Row};
use raystep_render::timing::Timing;
use raystep_render::{Image, Progress, RenderOptions, image_error};

use ch05::{RayCounts, SAFETY_DEPTH, Stop, World, render};
use serde::{Deserialize, Serialize, Serializer};

/// The scenes on the chart: their names in the CSV and their files.
pub const CHART_SCENES: [(&str, &str); 2] = [
    ("mirrors", include_str!("../../scenes/mirrors.toml")),
    (
        "facing-mirrors",
        include_str!("../../scenes/facing-mirrors.toml"),
    ),
];

/// Rule 1's maximum depths on the chart: every one from 0 to 10, then
/// sparser up to 32, where no ray of the facing mirrors is cut any more.
pub const CHART_DEPTHS: [u32; 19] = [
    0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 12, 14, 16, 18, 20, 24, 28, 32,
];

/// Rule 2's thresholds on the chart: 10⁻¹ … 10⁻⁴, two a decade.
pub const CHART_THRESHOLDS: [f64; 7] =
    [1e-1, 3e-2, 1e-2, 3e-3, 1e-3, 3e-4, 1e-4];

/// What every image is compared with: rule 1 alone at [`SAFETY_DEPTH`],
/// which cuts no ray at all in either scene (a test checks it), so the
/// reference is each pixel's whole ray tree. (Depth 20 would not do: the
/// facing mirrors keep rays of weight 0.88²⁰ ≈ 0.08 at that depth.)
pub const REFERENCE: Stop = Stop::depth(SAFETY_DEPTH);

/// The image size measured: 160 × 90.
pub const CHART_SIZE: (u32, u32) = (160, 90);

/// How a render is timed: 8 renders per sample (a 160 × 90 render takes
/// a few ms), the rules of a scene taking turns; `raystep measure
/// --repeats` sets the number of rounds.
pub const TIMING: Timing = Timing {
    rounds: 11,
    batch: 8,
};

/// The name of rule 1 in the CSV.
pub const DEPTH_RULE: &str = "depth";
/// The name of rule 2 in the CSV.
pub const CONTRIBUTION_RULE: &str = "contribution";

/// Every stopping rule on the chart: its name in the CSV, its parameter
/// (the depth, or the threshold), and the [`Stop`].
pub fn chart_rules() -> Vec<(&'static str, f64, Stop)> {
    let depths = CHART_DEPTHS
        .iter()
        .map(|&d| (DEPTH_RULE, f64::from(d), Stop::depth(d)));
    let thresholds = CHART_THRESHOLDS
        .iter()
        .map(|&c| (CONTRIBUTION_RULE, c, Stop::contribution(c)));
    depths.chain(thresholds).collect()
}

/// The chart scene `name` at [`CHART_SIZE`].
///
/// # Panics
/// If `name` is not one of [`CHART_SCENES`].
pub fn chart_world(name: &str) -> World {
    let (_, text) = CHART_SCENES
        .iter()
        .find(|(scene, _)| *scene == name)
        .unwrap_or_else(|| panic!("no chart scene `{name}`"));
    let file = format!("{name}.toml");
    let mut world =
        ch03::parse(text, &file).expect("the chapter's scene builds");
    (world.width, world.height) = CHART_SIZE;
    world
}

/// One stopping rule on one scene: a line of `stopping.csv`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct StopRow {
    /// The scene's name in [`CHART_SCENES`].
    pub scene: String,
    /// [`DEPTH_RULE`] or [`CONTRIBUTION_RULE`].
    pub rule: String,
    /// The maximum depth, or the threshold.
    #[serde(serialize_with = "depth_or_threshold")]
    pub parameter: f64,
    /// RMSE against the [`REFERENCE`] image, in 8-bit levels.
    #[serde(with = "Decimals::<6>")]
    pub rmse: f64,
    /// The largest error against it, in 8-bit levels.
    #[serde(with = "Plain")]
    pub max_error: f64,
    /// Every ray shot: primary, shadow and reflected.
    pub rays: u64,
    /// The reflected rays alone, the ones the rules decide about.
    pub secondary: u64,
    /// The median time of one single-threaded render, in milliseconds.
    #[serde(with = "Decimals::<3>")]
    pub millis: f64,
}

impl Row for StopRow {
    fn check(&self) -> Result<(), String> {
        match self.rule.as_str() {
            DEPTH_RULE | CONTRIBUTION_RULE => Ok(()),
            rule => Err(format!("unknown rule `{rule}`")),
        }
    }
}

/// A rule's parameter in the CSV: a depth as a whole number (`3`), a
/// threshold, which lies below 1, in e notation (`3e-3`).
fn depth_or_threshold<S: Serializer>(
    parameter: &f64, s: S,
) -> Result<S::Ok, S::Error> {
    if parameter.fract() == 0.0 {
        s.collect_str(parameter)
    } else {
        s.collect_str(&format_args!("{parameter:e}"))
    }
}

/// Runs every rule of [`chart_rules`] on every scene: error and ray counts
/// once (computed), render time per [`TIMING`] with `rounds` rounds, the
/// median of single-threaded renders (measured). `step` is called after
/// each round of each scene, for a progress bar.
pub fn measure_stopping(rounds: usize, mut step: impl FnMut()) -> Vec<StopRow> {
    let options = RenderOptions {
        threads: Some(1),
        progress: Progress::Never,
    };
    let mut rows = Vec::new();
    for (scene, _) in CHART_SCENES {
        let world = chart_world(scene);
        let (reference, _) =
            render(&world, &REFERENCE, &options).expect("a small render");
        let rules = chart_rules();
        for (rule, parameter, stop) in &rules {
            let (image, counts) =
                render(&world, stop, &options).expect("a small render");
            rows.push(row(scene, rule, *parameter, &image, &reference, counts));
        }
        // the rules take turns, so that drift on the machine shifts all alike
        let mut jobs: Vec<Box<dyn FnMut()>> = rules
            .iter()
            .map(|(_, _, stop)| {
                let world = &world;
                let options = &options;
                Box::new(move || {
                    let _ = render(world, stop, options);
                }) as Box<dyn FnMut()>
            })
            .collect();
        let times = TIMING
            .with_rounds(rounds)
            .median_ms(&mut as_jobs(&mut jobs), &mut step);
        let first = rows.len() - rules.len();
        for (row, millis) in rows[first..].iter_mut().zip(times) {
            row.millis = millis;
        }
    }
    rows
}

/// The computed part of a row (no time yet).
fn row(
    scene: &str, rule: &str, parameter: f64, image: &Image, reference: &Image,
    counts: RayCounts,
) -> StopRow {
    let error = image_error(image, reference);
    StopRow {
        scene: scene.to_string(),
        rule: rule.to_string(),
        parameter,
        rmse: error.rmse,
        max_error: error.max,
        rays: counts.total(),
        secondary: counts.secondary,
        millis: 0.0,
    }
}

/// Rule 2 against rule 1 at equal error: for the depth limit `depth` on
/// `scene`, the cheapest threshold whose RMSE is no larger.
#[derive(Clone, Debug, PartialEq)]
pub struct Saving {
    /// The scene's name.
    pub scene: String,
    /// Rule 1's row.
    pub depth: StopRow,
    /// The threshold of rule 2 with RMSE ≤ the depth's that spends the
    /// fewest reflected rays; None if no threshold is that accurate.
    pub threshold: Option<StopRow>,
}

impl Saving {
    /// The fraction of the depth rule's reflected rays that the threshold
    /// does not spend (negative: it spends more).
    pub fn secondary_saved(&self) -> Option<f64> {
        let t = self.threshold.as_ref()?;
        let d = self.depth.secondary as f64;
        (d > 0.0).then(|| 1.0 - t.secondary as f64 / d)
    }

    /// The same for every ray (primary, shadow and reflected).
    pub fn rays_saved(&self) -> Option<f64> {
        let t = self.threshold.as_ref()?;
        Some(1.0 - t.rays as f64 / self.depth.rays as f64)
    }
}

/// For every depth row of every scene, the [`Saving`] of rule 2: computed
/// from the errors and counts, not from the times.
pub fn savings(rows: &[StopRow]) -> Vec<Saving> {
    rows.iter()
        .filter(|r| r.rule == DEPTH_RULE)
        .map(|depth| {
            let threshold = rows
                .iter()
                .filter(|r| {
                    r.scene == depth.scene
                        && r.rule == CONTRIBUTION_RULE
                        && r.rmse <= depth.rmse
                })
                .min_by_key(|r| r.secondary)
                .cloned();
            Saving {
                scene: depth.scene.clone(),
                depth: depth.clone(),
                threshold,
            }
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use raystep_render::csv::{from_csv, from_lines, to_csv};

    fn stop_row(
        rule: &str, parameter: f64, rmse: f64, secondary: u64,
    ) -> StopRow {
        StopRow {
            scene: "mirrors".into(),
            rule: rule.into(),
            parameter,
            rmse,
            max_error: 3.0,
            rays: 1000 + secondary,
            secondary,
            millis: 1.5,
        }
    }

    #[test]
    fn csv_round_trip_and_errors() {
        let rows = vec![
            stop_row(DEPTH_RULE, 3.0, 1.25, 500),
            stop_row(CONTRIBUTION_RULE, 3e-3, 0.5, 400),
        ];
        let csv = to_csv(&rows);
        assert!(csv.contains("\nmirrors,depth,3,1.250000,3,1500,500,1.500\n"));
        assert!(csv.contains("\nmirrors,contribution,3e-3,"));
        assert_eq!(from_csv::<StopRow>(&csv).unwrap(), rows);
        let bad = from_lines::<StopRow>("mirrors,rule3,1,0,0,1,1,1\n");
        assert_eq!(bad.unwrap_err(), "line 2: unknown rule `rule3`");
    }

    /// Every rule of the chart writes its parameter as the rule says: a
    /// depth whole, a threshold in e notation.
    #[test]
    fn depths_are_written_whole_and_thresholds_in_e_notation() {
        for (rule, parameter, _) in chart_rules() {
            let row = stop_row(rule, parameter, 1.0, 0);
            let written = if rule == DEPTH_RULE {
                format!("{parameter}")
            } else {
                format!("{parameter:e}")
            };
            let line = to_csv(&[row]);
            assert!(line.contains(&format!(",{rule},{written},")), "{line}");
        }
    }

    /// The committed file reads and writes back byte for byte: a new
    /// measurement writes its format.
    #[test]
    fn the_committed_csv_writes_back_unchanged() {
        raystep_figure::writes_back::<StopRow>("ch05", "stopping.csv").unwrap();
    }

    #[test]
    fn the_saving_is_the_cheapest_threshold_at_least_as_accurate() {
        let rows = vec![
            stop_row(DEPTH_RULE, 1.0, 4.0, 100),
            stop_row(DEPTH_RULE, 5.0, 1.0, 800),
            stop_row(CONTRIBUTION_RULE, 1e-1, 2.0, 200),
            stop_row(CONTRIBUTION_RULE, 1e-2, 1.0, 300),
            stop_row(CONTRIBUTION_RULE, 1e-3, 0.5, 600),
        ];
        let s = savings(&rows);
        assert_eq!(s.len(), 2);
        // depth 1 (RMSE 4): every threshold is as accurate; 1e-1 is cheapest
        // but spends more reflected rays than depth 1 itself
        assert_eq!(s[0].threshold.as_ref().unwrap().parameter, 1e-1);
        assert_eq!(s[0].secondary_saved(), Some(-1.0));
        // depth 5 (RMSE 1): 1e-2 equals it with 300 rays instead of 800
        assert_eq!(s[1].threshold.as_ref().unwrap().parameter, 1e-2);
        assert_eq!(s[1].secondary_saved(), Some(1.0 - 300.0 / 800.0));
        assert_eq!(s[1].rays_saved(), Some(1.0 - 1300.0 / 1800.0));
        // nothing is as accurate as RMSE 0.1
        let exact = vec![stop_row(DEPTH_RULE, 9.0, 0.1, 900), rows[4].clone()];
        assert_eq!(savings(&exact)[0].threshold, None);
    }

    /// The chart's reference cuts no ray (a fact about the reference
    /// tracer and the scenes).
    #[test]
    fn the_reference_is_the_whole_ray_tree() {
        let options = RenderOptions {
            threads: None,
            progress: Progress::Never,
        };
        for (scene, _) in CHART_SCENES {
            let (_, counts) =
                render(&chart_world(scene), &REFERENCE, &options).unwrap();
            assert_eq!(counts.cut_by_depth, 0, "{scene}: a ray was cut");
            assert_eq!(counts.cut_by_contribution, 0, "{scene}: a ray was cut");
            assert!(counts.secondary > 0, "{scene}: mirrors reflect");
        }
    }
}
