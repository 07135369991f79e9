//! The chart of chapter 4: wrong pixels against scene scale and against
//! render time, drawn from `book/src/figures/ch04/acne.csv` (written by
//! `raystep measure`).
use raystep_figure::numbers::power;
use raystep_figure::plots::{accuracy_against_speed, line_legend};
use raystep_figure::plotters::prelude::*;
use raystep_figure::{
    AxisBreak, ChartError, Figure, LogAxis, chart, font, measured,
};

use ch04::Offset;

use crate::measurements::{AcneRow, CHART_STRATEGIES};

/// One colour per strategy (Okabe–Ito, colour-blind safe).
const COLOURS: [RGBColor; 5] = [
    RGBColor(0, 0, 0),
    RGBColor(230, 159, 0),
    RGBColor(86, 180, 233),
    RGBColor(0, 114, 178),
    RGBColor(0, 158, 115),
];

/// How far apart the strategies' lanes in the row of 0 are, in decades.
const LANE: f64 = 0.18;

/// The chart, or an error naming the CSV file if it is missing or bad.
pub fn acne_chart() -> Result<Figure, ChartError> {
    let rows: Vec<AcneRow> = measured("ch04", "acne.csv")?;
    chart(
        "acne-chart",
        "Wrongly shadowed or wrongly lit pixels for each strategy, by scene scale (top) and against render time (bottom); t_min 10⁻⁴ and the scale-aware offset get none wrong at any scale here (the row 0).",
        900,
        780,
        |area| draw(area, &rows),
    )
}

/// A strategy as the legend names it: `t_{min} 10^{−4}`.
fn name(offset: Offset) -> String {
    match offset {
        Offset::TMin(0.0) => "none".to_string(),
        Offset::TMin(eps) => format!("t_{{min}} {}", power(eps)),
        Offset::AlongNormal(eps) => format!("normal {}", power(eps)),
        Offset::ScaleAware => "scale-aware".to_string(),
    }
}

/// The fraction of pixels a run gets wrong.
fn wrong(row: &AcneRow) -> f64 {
    row.acne + row.leaks
}

fn draw(
    area: &raystep_figure::ChartArea, rows: &[AcneRow],
) -> Result<(), ChartError> {
    // a legend across the top, then the two panels, one above the other
    let (legend, panels) = area.split_vertically(64);
    let names = CHART_STRATEGIES.map(|(_, offset)| name(offset));
    let entries: Vec<(&str, RGBColor)> =
        names.iter().map(String::as_str).zip(COLOURS).collect();
    line_legend(&legend, &entries, (20, 176), 16.0)?;
    legend.draw(&Text::new(
        "row 0: no pixel wrong; each strategy gets a line of its own there",
        (20, 40),
        font(15.0),
    ))?;
    let (top, bottom) = panels.split_vertically(370);

    // every run's fraction, 0 included, on one axis for both panels; up to
    // 1 (every pixel wrong)
    let y_axis = LogAxis::covering(rows.iter().map(wrong).chain([1.0]));
    // the strategies that get 0 somewhere each have a lane in the row of 0
    let zero_lanes: Vec<&str> = CHART_STRATEGIES
        .iter()
        .map(|(name, _)| *name)
        .filter(|name| {
            rows.iter().any(|r| r.strategy == *name && wrong(r) == 0.0)
        })
        .collect();
    let y_of = |row: &AcneRow| {
        let lane = zero_lanes.iter().position(|s| *s == row.strategy);
        match lane {
            Some(k) if wrong(row) == 0.0 => {
                let middle = (zero_lanes.len() as f64 - 1.0) / 2.0;
                y_axis.zero_row() + LANE * (middle - k as f64)
            }
            _ => y_axis.at(wrong(row)),
        }
    };
    let of =
        |name: &'static str| rows.iter().filter(move |r| r.strategy == name);

    // Top: wrong pixels by scale, one line per strategy.
    let x_axis = LogAxis::covering(rows.iter().map(|r| r.scale));
    let mut by_scale = ChartBuilder::on(&top)
        .caption("wrong pixels by scene scale", font(17.0))
        .margin(10)
        .margin_right(24)
        .x_label_area_size(52)
        .y_label_area_size(72)
        .build_cartesian_2d(x_axis.range(), y_axis.range())?;
    by_scale
        .configure_mesh()
        .x_desc("scene scale")
        .y_desc("acne + leaks (fraction)")
        .x_label_formatter(&|x| x_axis.label(x))
        .y_label_formatter(&|y| y_axis.label(y))
        .label_style(font(16.0))
        .axis_desc_style(font(15.0))
        .draw()?;
    if let Some(at) = y_axis.break_at() {
        by_scale.draw_series([AxisBreak::y((x_axis.start(), at))])?;
    }
    for ((name, _), colour) in CHART_STRATEGIES.iter().zip(COLOURS) {
        let points: Vec<(f64, f64)> =
            of(name).map(|r| (x_axis.at(r.scale), y_of(r))).collect();
        by_scale.draw_series(LineSeries::new(
            points.clone(),
            colour.stroke_width(2),
        ))?;
        by_scale.draw_series(
            points
                .into_iter()
                .map(|p| Circle::new(p, 4, colour.filled())),
        )?;
    }

    // Bottom: every (strategy, scale) run as a point: time against errors.
    let millis = rows.iter().map(|r| r.millis);
    let mut by_time = accuracy_against_speed(
        &bottom,
        millis,
        &y_axis,
        "acne + leaks (fraction)",
    )?;
    for ((name, _), colour) in CHART_STRATEGIES.iter().zip(COLOURS) {
        by_time
            .draw_series(of(name).map(|r| {
                Circle::new((r.millis, y_of(r)), 5, colour.filled())
            }))?;
    }
    Ok(())
}
