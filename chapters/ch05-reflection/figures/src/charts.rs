//! The chart of chapter 05: the error each stopping rule leaves (RMSE and
//! max error) against the time its render takes, on each mirror scene; drawn from `book/src/figures/ch05/stopping.csv` (written by
//! `raystep measure`).
use raystep_figure::numbers::floored;
use raystep_figure::plotters::prelude::*;
use raystep_figure::plotters::style::text_anchor::{HPos, Pos, VPos};
use raystep_figure::{ChartError, Figure, chart, measured};

use crate::measurements::{
    CHART_SCENES, CONTRIBUTION_RULE, DEPTH_RULE, StopRow,
};

/// Errors below this are drawn at the chart's floor (log axes have no 0).
const FLOOR: f64 = 0.01;

/// Rule 1 and rule 2 (Okabe–Ito, colour-blind safe).
const DEPTH_COLOUR: RGBColor = RGBColor(0, 114, 178);
const CONTRIBUTION_COLOUR: RGBColor = RGBColor(230, 159, 0);

/// The chart, or an error naming the CSV file if it is missing or bad.
pub fn stopping_chart() -> Result<Figure, ChartError> {
    let rows: Vec<StopRow> = measured("ch05", "stopping.csv")?;
    chart(
        "stopping-chart",
        "Render time against image error for each stopping rule on each scene: rule 1 at depths 0 … 32 and rule 2 at thresholds 10⁻¹ … 10⁻⁴; above, the RMSE against the whole ray tree, below, the largest error of any pixel, in 8-bit levels.",
        1000,
        760,
        |area| draw(area, &rows),
    )
}

/// What a panel plots against time: the RMSE or the max error, each in
/// 8-bit levels, with 0 drawn on the floor.
#[derive(Clone, Copy)]
enum Metric {
    Rmse,
    Max,
}

impl Metric {
    fn of(self, row: &StopRow) -> f64 {
        match self {
            Metric::Rmse => row.rmse,
            Metric::Max => row.max_error,
        }
        .max(FLOOR)
    }

    fn axis(self) -> &'static str {
        match self {
            Metric::Rmse => "RMSE, 8-bit levels (0 at the bottom)",
            Metric::Max => "max error, 8-bit levels (0 at the bottom)",
        }
    }
}

/// The depths labelled on the chart (the others would crowd).
const LABELLED_DEPTHS: [f64; 9] =
    [0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 10.0, 18.0, 32.0];

/// A point's label: the depth, or the threshold as a power of ten.
fn parameter_label(row: &StopRow) -> String {
    if row.rule == DEPTH_RULE {
        format!("{}", row.parameter)
    } else {
        format!("{:.0e}", row.parameter)
    }
}

fn draw(
    area: &raystep_figure::ChartArea,
    rows: &[StopRow],
) -> Result<(), ChartError> {
    // a legend strip across the top, then the RMSE above the max error,
    // one column per scene
    let (legend, panels) = area.split_vertically(34);
    let entries = [
        ("rule 1: Stop::depth(d), d beside each point", DEPTH_COLOUR),
        (
            "rule 2: Stop::contribution(c), c beside each point",
            CONTRIBUTION_COLOUR,
        ),
    ];
    for (i, (name, colour)) in entries.iter().enumerate() {
        let x = 90 + 430 * i as i32;
        legend.draw(&PathElement::new(
            vec![(x, 20), (x + 24, 20)],
            colour.stroke_width(3),
        ))?;
        legend.draw(&Text::new(*name, (x + 30, 12), ("sans-serif", 15)))?;
    }
    let panels = panels.split_evenly((2, 2));
    for (row, metric) in [Metric::Rmse, Metric::Max].into_iter().enumerate() {
        for (column, (scene, _)) in CHART_SCENES.iter().enumerate() {
            let of_scene: Vec<&StopRow> =
                rows.iter().filter(|r| r.scene == *scene).collect();
            panel(&panels[2 * row + column], scene, &of_scene, metric)?;
        }
    }
    Ok(())
}

/// One scene's error against the measured render time, both rules.
fn panel(
    area: &raystep_figure::ChartArea,
    scene: &str,
    of_scene: &[&StopRow],
    metric: Metric,
) -> Result<(), ChartError> {
    let label_style = ("sans-serif", 14);
    // from a little below the fastest render; room on the right for the
    // thresholds' labels
    let min_ms =
        of_scene.iter().map(|r| r.millis).fold(f64::MAX, f64::min) * 0.85;
    let max_ms = of_scene.iter().map(|r| r.millis).fold(0.0, f64::max) * 1.15;
    let mut c = ChartBuilder::on(area)
        .caption(format!("{scene}.toml"), ("sans-serif", 17))
        .margin(10)
        .x_label_area_size(34)
        .y_label_area_size(52)
        .build_cartesian_2d(
            min_ms..max_ms,
            (0.8 * FLOOR..300f64).log_scale(),
        )?;
    c.configure_mesh()
        .x_desc("render time, ms (160×90, one thread, this machine)")
        .y_desc(metric.axis())
        .x_labels(6)
        .x_label_formatter(&|x| format!("{x:.2}"))
        .y_label_formatter(&|y: &f64| floored(*y, FLOOR))
        .label_style(label_style)
        .light_line_style(WHITE)
        .draw()?;
    let at = |r: &StopRow| (r.millis, metric.of(r));
    for (rule, colour) in [
        (DEPTH_RULE, DEPTH_COLOUR),
        (CONTRIBUTION_RULE, CONTRIBUTION_COLOUR),
    ] {
        let points: Vec<(f64, f64)> = of_scene
            .iter()
            .filter(|r| r.rule == rule)
            .map(|r| at(r))
            .collect();
        c.draw_series(LineSeries::new(points.clone(), colour.stroke_width(2)))?;
        c.draw_series(
            points
                .into_iter()
                .map(|p| Circle::new(p, 3, colour.filled())),
        )?;
    }
    // the times of the points with no error at all
    let floor = of_scene
        .iter()
        .filter(|r| metric.of(r) <= FLOOR)
        .fold((f64::MAX, f64::MIN), |(lo, hi), r| {
            (lo.min(r.millis), hi.max(r.millis))
        });
    // label the points: the depths to the left, the thresholds to the
    // right; rows that shoot the same rays and give the same error share
    // one label, "4 … 32", at the first of them
    for (rule, colour, offset) in [
        (DEPTH_RULE, DEPTH_COLOUR, (-8, 0)),
        (CONTRIBUTION_RULE, CONTRIBUTION_COLOUR, (8, 0)),
    ] {
        let rows: Vec<&StopRow> = of_scene
            .iter()
            .copied()
            .filter(|r| r.rule == rule)
            .collect();
        for group in rows.chunk_by(|a, b| {
            a.secondary == b.secondary && metric.of(a) == metric.of(b)
        }) {
            let (first, last) = (group[0], group[group.len() - 1]);
            if rule == DEPTH_RULE && !LABELLED_DEPTHS.contains(&first.parameter)
            {
                continue;
            }
            let text = if group.len() == 1 {
                parameter_label(first)
            } else {
                format!(
                    "{} … {}",
                    parameter_label(first),
                    parameter_label(last)
                )
            };
            let side = if rule == DEPTH_RULE {
                HPos::Right
            } else {
                HPos::Left
            };
            // on the floor the points of both rules crowd: rule 1's label
            // goes left of them all, rule 2's right of them all
            let anchor = if metric.of(first) > FLOOR {
                at(first)
            } else if rule == DEPTH_RULE {
                (floor.0, FLOOR)
            } else {
                (floor.1, FLOOR)
            };
            let style = ("sans-serif", 13)
                .into_font()
                .color(&colour)
                .pos(Pos::new(side, VPos::Center));
            c.draw_series(std::iter::once(
                EmptyElement::at(anchor) + Text::new(text, offset, style),
            ))?;
        }
    }
    Ok(())
}
