//! The data behind chapter 04's chart: for each strategy and scene scale,
//! how many pixels it gets wrong (computed, the same on every machine) and
//! how long a render takes (measured, on this machine).
//!
//! `raystep measure` runs [`measure_acne`] and writes [`to_csv`] into
//! `book/src/figures/ch04/acne.csv`; `raystep figures` draws the chart
//! from that file, so the figures stay byte-identical between runs.
use std::time::Instant;

use raystep_render::{Progress, RenderOptions};

use crate::{Offset, render, scaled_scene, shadow_errors};

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

/// One strategy at one scale.
#[derive(Clone, Debug, PartialEq)]
pub struct AcneRow {
    /// The strategy's name in [`CHART_STRATEGIES`].
    pub strategy: String,
    /// The scene's scale.
    pub scale: f64,
    /// The fraction of judged pixels wrongly in shadow.
    pub acne: f64,
    /// The fraction of judged pixels wrongly lit.
    pub leaks: f64,
    /// The median time of one single-threaded render, in milliseconds.
    pub millis: f64,
}

/// Measures every strategy at every scale: errors once, render time as the
/// median of `repeats` single-threaded renders. `step` is called after each
/// (strategy, scale) pair, for a progress bar.
pub fn measure_acne(repeats: usize, mut step: impl FnMut()) -> Vec<AcneRow> {
    let options = RenderOptions {
        threads: Some(1),
        progress: Progress::Never,
    };
    let mut rows = Vec::new();
    for (name, offset) in CHART_STRATEGIES {
        for scale in CHART_SCALES {
            let mut world = scaled_scene(scale);
            (world.width, world.height) = CHART_SIZE;
            let errors = shadow_errors(&world, offset);
            let _ = render(&world, offset, &options); // warm the caches first
            let mut times: Vec<f64> = (0..repeats.max(1))
                .map(|_| {
                    let start = Instant::now();
                    let _ = render(&world, offset, &options);
                    start.elapsed().as_secs_f64() * 1e3
                })
                .collect();
            times.sort_by(f64::total_cmp);
            rows.push(AcneRow {
                strategy: name.to_string(),
                scale,
                acne: errors.acne_fraction(),
                leaks: errors.leak_fraction(),
                millis: times[times.len() / 2],
            });
            step();
        }
    }
    rows
}

/// The CSV header.
pub const CSV_HEADER: &str = "strategy,scale,acne,leaks,millis";

/// The rows as CSV, one line per row after [`CSV_HEADER`].
pub fn to_csv(rows: &[AcneRow]) -> String {
    let mut csv = format!("{CSV_HEADER}\n");
    for r in rows {
        csv.push_str(&format!(
            "{},{:e},{:.6},{:.6},{:.3}\n",
            r.strategy, r.scale, r.acne, r.leaks, r.millis
        ));
    }
    csv
}

/// Reads [`to_csv`]'s output back; an error names the line and what is wrong.
pub fn from_csv(text: &str) -> Result<Vec<AcneRow>, String> {
    let mut lines = text.lines().enumerate();
    match lines.next() {
        Some((_, header)) if header.trim() == CSV_HEADER => {}
        _ => return Err(format!("line 1: expected the header `{CSV_HEADER}`")),
    }
    let mut rows = Vec::new();
    for (i, line) in lines {
        if line.trim().is_empty() {
            continue;
        }
        let fields: Vec<&str> = line.split(',').collect();
        let number = |k: usize, name: &str| -> Result<f64, String> {
            fields[k]
                .trim()
                .parse::<f64>()
                .ok()
                .filter(|x| x.is_finite())
                .ok_or_else(|| format!("line {}: {name} `{}` is not a number", i + 1, fields[k]))
        };
        if fields.len() != 5 {
            return Err(format!(
                "line {}: expected 5 fields, got {}",
                i + 1,
                fields.len()
            ));
        }
        rows.push(AcneRow {
            strategy: fields[0].trim().to_string(),
            scale: number(1, "scale")?,
            acne: number(2, "acne")?,
            leaks: number(3, "leaks")?,
            millis: number(4, "millis")?,
        });
    }
    Ok(rows)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn csv_round_trip_and_errors() {
        let rows = vec![AcneRow {
            strategy: "scale-aware".into(),
            scale: 1e-3,
            acne: 0.0,
            leaks: 0.0025,
            millis: 12.5,
        }];
        assert_eq!(from_csv(&to_csv(&rows)).unwrap(), rows);
        assert!(from_csv("nope\n").unwrap_err().starts_with("line 1:"));
        let bad = format!("{CSV_HEADER}\nnone,1e0,x,0,1\n");
        assert_eq!(
            from_csv(&bad).unwrap_err(),
            "line 2: acne `x` is not a number"
        );
    }
}
