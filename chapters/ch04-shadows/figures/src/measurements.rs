//! The data behind chapter 4's chart: for each strategy and scene scale,
//! how many pixels it gets wrong (computed, the same on every machine) and
//! how long a render takes (measured, on this machine).
//!
//! `raystep measure` runs [`measure_acne`] and writes its rows into
//! `book/src/figures/ch04/acne.csv`; `raystep figures` draws the chart
//! from that file, so the figures stay byte-identical between runs.

use raystep_figure::as_jobs;
use raystep_render::csv::{Decimals, Exp, Row};
use raystep_render::timing::Timing;
use raystep_render::{Progress, RenderOptions};

use ch04::{Offset, render, scaled_scene, shadow_errors};
use serde::{Deserialize, Serialize};

/// The strategies on the chart, with their names in the CSV.
pub const CHART_STRATEGIES: [(&str, Offset); 5] = [
    ("none", Offset::TMin(0.0)),
    ("t_min 1e-4", Offset::TMin(1e-4)),
    ("normal 1e-4", Offset::AlongNormal(1e-4)),
    ("normal 1e-12", Offset::AlongNormal(1e-12)),
    ("scale-aware", Offset::ScaleAware),
];

/// The scene scales on the chart: 1e-3 … 1e4.
pub const CHART_SCALES: [f64; 8] = [1e-3, 1e-2, 1e-1, 1.0, 1e1, 1e2, 1e3, 1e4];

/// The image size measured: 160 × 90.
pub const CHART_SIZE: (u32, u32) = (160, 90);

/// One strategy at one scale: a line of `acne.csv`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct AcneRow {
    /// The strategy's name in [`CHART_STRATEGIES`].
    pub strategy: String,
    /// The scene's scale.
    #[serde(with = "Exp")]
    pub scale: f64,
    /// The fraction of judged pixels wrongly in shadow.
    #[serde(with = "Decimals::<6>")]
    pub acne: f64,
    /// The fraction of judged pixels wrongly lit.
    #[serde(with = "Decimals::<6>")]
    pub leaks: f64,
    /// The median time of one single-threaded render, in milliseconds.
    #[serde(with = "Decimals::<3>")]
    pub millis: f64,
}

impl Row for AcneRow {}

/// How a render is timed: 8 renders per sample, the strategies taking
/// turns at each scale; `raystep measure --repeats` sets the number of
/// rounds.
pub const TIMING: Timing = Timing {
    rounds: 11,
    batch: 8,
};

/// Measures every strategy at every scale: errors once (computed), render
/// time per [`TIMING`] with `rounds` rounds, the median of single-threaded
/// renders (measured). `step` is called after each scale, for a progress
/// bar. The rows come strategy by strategy, each over every scale.
pub fn measure_acne(rounds: usize, mut step: impl FnMut()) -> Vec<AcneRow> {
    let options = RenderOptions {
        threads: Some(1),
        progress: Progress::Never,
    };
    let mut rows = Vec::new();
    for scale in CHART_SCALES {
        let mut world = scaled_scene(scale);
        (world.width, world.height) = CHART_SIZE;
        let world = &world;
        let options = &options;
        let mut jobs: Vec<Box<dyn FnMut() + '_>> = CHART_STRATEGIES
            .iter()
            .map(|&(_, offset)| {
                Box::new(move || {
                    let _ = render(world, offset, options);
                }) as Box<dyn FnMut() + '_>
            })
            .collect();
        let times = TIMING
            .with_rounds(rounds)
            .median_ms(&mut as_jobs(&mut jobs), || ());
        for ((name, offset), millis) in CHART_STRATEGIES.into_iter().zip(times)
        {
            let errors = shadow_errors(world, offset);
            rows.push(AcneRow {
                strategy: name.to_string(),
                scale,
                acne: errors.acne_fraction(),
                leaks: errors.leak_fraction(),
                millis,
            });
        }
        step();
    }
    // strategy by strategy, as the chart and the CSV list them
    let order =
        |name: &str| CHART_STRATEGIES.iter().position(|(n, _)| *n == name);
    rows.sort_by_key(|r| order(&r.strategy));
    rows
}

#[cfg(test)]
mod tests {
    use super::*;
    use raystep_render::csv::{from_csv, from_lines, to_csv};

    #[test]
    fn csv_round_trip_and_errors() {
        let rows = vec![AcneRow {
            strategy: "scale-aware".into(),
            scale: 1e-3,
            acne: 0.0,
            leaks: 0.0025,
            millis: 12.5,
        }];
        let csv = to_csv(&rows);
        assert_eq!(
            csv,
            "strategy,scale,acne,leaks,millis\n\
             scale-aware,1e-3,0.000000,0.002500,12.500\n"
        );
        assert_eq!(from_csv::<AcneRow>(&csv).unwrap(), rows);
        assert_eq!(
            from_lines::<AcneRow>("none,1e0,x,0,1\n").unwrap_err(),
            "line 2: acne `x` is not a number"
        );
    }

    /// The committed file reads and writes back byte for byte: a new
    /// measurement writes its format.
    #[test]
    fn the_committed_csv_writes_back_unchanged() {
        raystep_figure::writes_back::<AcneRow>("ch04", "acne.csv").unwrap();
    }
}
