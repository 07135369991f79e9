//! The chart of chapter 5: the error each stopping rule leaves (RMSE and
//! max error) against the time its render takes, on each mirror scene; drawn from `book/src/figures/ch05/stopping.csv` (written by
//! `raystep measure`).
use raystep_figure::numbers::power;
use raystep_figure::plots::line_legend;
use raystep_figure::plotters::prelude::*;
use raystep_figure::{
    AxisBreak, ChartError, Figure, Labels, LogAxis, Spot, chart, font, measured,
};

use crate::measurements::{
    CHART_SCENES, CONTRIBUTION_RULE, DEPTH_RULE, StopRow,
};

/// Rule 1 and rule 2 (Okabe–Ito, colour-blind safe).
const DEPTH_COLOUR: RGBColor = RGBColor(0, 114, 178);
const CONTRIBUTION_COLOUR: RGBColor = RGBColor(230, 159, 0);

/// Where each rule's zeros lie in the row of 0, in decades from its
/// middle: rule 1 above, rule 2 below, so both stay visible.
const DEPTH_LANE: f64 = 0.15;
const CONTRIBUTION_LANE: f64 = -0.15;

/// The chart, or an error naming the CSV file if it is missing or bad.
pub fn stopping_chart() -> Result<Figure, ChartError> {
    let rows: Vec<StopRow> = measured("ch05", "stopping.csv")?;
    chart(
        "stopping-chart",
        "Render time against image error for each stopping rule on each scene: rule 1 at depths 0 … 32 and rule 2 at thresholds 10⁻¹ … 10⁻⁴; above, the RMSE against the whole ray tree, below, the largest error of any pixel, in 8-bit levels.",
        900,
        820,
        |area| draw(area, &rows),
    )
}

/// What a panel plots against time: the RMSE or the max error, each in
/// 8-bit levels.
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
    }

    fn axis(self) -> &'static str {
        match self {
            Metric::Rmse => "RMSE, 8-bit levels",
            Metric::Max => "max error, 8-bit levels",
        }
    }
}

/// The depths labelled on the chart (the others would crowd).
const LABELLED_DEPTHS: [f64; 9] =
    [0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 10.0, 18.0, 32.0];

/// A point's label: the depth, or the threshold as a power of ten (label
/// markup: `10^{−1}`, `3·10^{−2}`).
fn parameter_label(row: &StopRow) -> String {
    if row.rule == DEPTH_RULE {
        format!("{}", row.parameter)
    } else {
        power(row.parameter).replace(".0·", "·")
    }
}

fn draw(
    area: &raystep_figure::ChartArea, rows: &[StopRow],
) -> Result<(), ChartError> {
    // a legend strip across the top, then the RMSE above the max error,
    // one column per scene
    let (legend, panels) = area.split_vertically(64);
    let entries = [
        ("rule 1: Stop::depth(d), d beside each point", DEPTH_COLOUR),
        (
            "rule 2: Stop::contribution(c), c beside each point",
            CONTRIBUTION_COLOUR,
        ),
    ];
    line_legend(&legend, &entries, (20, 420), 15.0)?;
    legend.draw(&Text::new(
        "row 0: no error at all; each rule gets a line of its own there",
        (20, 40),
        font(15.0),
    ))?;
    let panels = panels.split_evenly((2, 2));
    for (row, metric) in [Metric::Rmse, Metric::Max].into_iter().enumerate() {
        // one error axis for both scenes
        let axis = LogAxis::covering(rows.iter().map(|r| metric.of(r)));
        for (column, (scene, _)) in CHART_SCENES.iter().enumerate() {
            let of_scene: Vec<&StopRow> =
                rows.iter().filter(|r| r.scene == *scene).collect();
            panel(&panels[2 * row + column], scene, &of_scene, metric, &axis)?;
        }
    }
    Ok(())
}

/// One scene's error against the measured render time, both rules.
fn panel(
    area: &raystep_figure::ChartArea, scene: &str, of_scene: &[&StopRow],
    metric: Metric, axis: &LogAxis,
) -> Result<(), ChartError> {
    // from a little below the fastest render; room on the right for the
    // thresholds' labels
    let min_ms =
        of_scene.iter().map(|r| r.millis).fold(f64::MAX, f64::min) * 0.85;
    let max_ms = of_scene.iter().map(|r| r.millis).fold(0.0, f64::max) * 1.2;
    let mut c = ChartBuilder::on(area)
        .caption(format!("{scene}.toml"), font(17.0))
        .margin(10)
        .x_label_area_size(52)
        .y_label_area_size(64)
        .build_cartesian_2d(min_ms..max_ms, axis.range())?;
    c.configure_mesh()
        .x_desc("render time, ms (160×90, one thread)")
        .y_desc(metric.axis())
        .x_labels(5)
        .x_label_formatter(&|x| format!("{x:.1}"))
        .y_label_formatter(&|y| axis.label(y))
        .label_style(font(16.0))
        .axis_desc_style(font(15.0))
        .light_line_style(WHITE)
        .draw()?;
    if let Some(at) = axis.break_at() {
        c.draw_series([AxisBreak::y((min_ms, at))])?;
    }
    // a point: its error on the axis, a 0 on its rule's lane
    let at = |r: &StopRow| {
        let y = match metric.of(r) {
            0.0 if r.rule == DEPTH_RULE => axis.zero_row() + DEPTH_LANE,
            0.0 => axis.zero_row() + CONTRIBUTION_LANE,
            e => axis.at(e),
        };
        (r.millis, y)
    };
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
    // label the points where they cover no line, marker or other label:
    // the depths to the left if they can, the thresholds to the right;
    // rows that shoot the same rays and give the same error share one
    // label, "4 … 32", at the first of them, or on the row of 0 beside all
    // of the rule's zeros; a depth with no clear spot goes unlabelled
    let mut labels = Labels::new();
    for rule in [DEPTH_RULE, CONTRIBUTION_RULE] {
        let line: Vec<(i32, i32)> = of_scene
            .iter()
            .filter(|r| r.rule == rule)
            .map(|r| c.backend_coord(&at(r)))
            .collect();
        labels.avoid_line(&line);
        for &p in &line {
            labels.avoid_point(p, 3);
        }
    }
    for (rule, colour) in [
        (DEPTH_RULE, DEPTH_COLOUR),
        (CONTRIBUTION_RULE, CONTRIBUTION_COLOUR),
    ] {
        let rows: Vec<&StopRow> = of_scene
            .iter()
            .copied()
            .filter(|r| r.rule == rule)
            .collect();
        let zeros = rows
            .iter()
            .filter(|r| metric.of(r) == 0.0)
            .fold((f64::MAX, f64::MIN), |(lo, hi), r| {
                (lo.min(r.millis), hi.max(r.millis))
            });
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
            let (x, y) = at(first);
            let (anchor, spots): ((f64, f64), &[Spot]) =
                match (metric.of(first), rule) {
                    (0.0, DEPTH_RULE) => ((zeros.0, y), &[Spot::W]),
                    (0.0, _) => ((zeros.1, y), &[Spot::E]),
                    (_, DEPTH_RULE) => (
                        (x, y),
                        &[Spot::W, Spot::SW, Spot::NW, Spot::S, Spot::N],
                    ),
                    _ => ((x, y), &[Spot::E, Spot::SE, Spot::NE]),
                };
            let size = 16.0;
            let Some((offset, pos)) =
                labels.place(c.backend_coord(&anchor), &text, size, spots)
            else {
                continue;
            };
            let style = font(size).color(&colour).pos(pos);
            c.draw_series(std::iter::once(
                EmptyElement::at(anchor) + Text::new(text, offset, style),
            ))?;
        }
    }
    Ok(())
}
