//! The chart of chapter 04: wrong pixels against scene scale and against
//! render time, drawn from `book/src/figures/ch04/acne.csv` (written by
//! `raystep measure`).
use raystep_figure::plotters::prelude::*;
use raystep_figure::{ChartError, Figure, chart, measured};

use crate::measurements::{AcneRow, CHART_STRATEGIES};

/// Fractions below this are drawn at the chart's floor (log axes have no 0).
const FLOOR: f64 = 1e-4;

/// One colour per strategy (Okabe–Ito, colour-blind safe).
const COLOURS: [RGBColor; 5] = [
    RGBColor(0, 0, 0),
    RGBColor(230, 159, 0),
    RGBColor(86, 180, 233),
    RGBColor(0, 114, 178),
    RGBColor(0, 158, 115),
];

/// The chart, or an error naming the CSV file if it is missing or bad.
pub fn acne_chart() -> Result<Figure, ChartError> {
    let rows: Vec<AcneRow> = measured("ch04", "acne.csv")?;
    chart(
        "acne-chart",
        "Wrongly shadowed or wrongly lit pixels for each strategy, by scene scale (left) and against render time (right); t_min 1e-4 and scale-aware get none wrong at any scale here, on the bottom edge.",
        900,
        410,
        |area| draw(area, &rows),
    )
}

/// A y-axis label: the floor reads "0", the rest as powers of ten.
fn fraction_label(y: &f64) -> String {
    if *y <= FLOOR {
        "0".to_string()
    } else {
        format!("{y:.0e}")
    }
}

fn wrong(row: &AcneRow) -> f64 {
    (row.acne + row.leaks).max(FLOOR)
}

fn draw(
    area: &raystep_figure::ChartArea,
    rows: &[AcneRow],
) -> Result<(), ChartError> {
    // a legend strip across the top, then the two panels
    let (legend, panels) = area.split_vertically(34);
    for (i, ((name, _), colour)) in
        CHART_STRATEGIES.iter().zip(COLOURS).enumerate()
    {
        let x = 90 + 160 * i as i32;
        legend.draw(&PathElement::new(
            vec![(x, 20), (x + 24, 20)],
            colour.stroke_width(3),
        ))?;
        legend.draw(&Text::new(*name, (x + 30, 12), ("sans-serif", 15)))?;
    }
    let (left, right) = panels.split_horizontally(470);
    let label_style = ("sans-serif", 15);
    let max_ms = rows.iter().map(|r| r.millis).fold(0.0, f64::max) * 1.1;
    let min_ms =
        rows.iter().map(|r| r.millis).fold(f64::INFINITY, f64::min) * 0.9;

    // Left: wrong pixels by scale, one line per strategy.
    let mut by_scale = ChartBuilder::on(&left)
        .caption("wrong pixels by scene scale", ("sans-serif", 17))
        .margin(10)
        .x_label_area_size(34)
        .y_label_area_size(56)
        .build_cartesian_2d(
            (1e-3f64..1e4f64).log_scale(),
            (FLOOR..1f64).log_scale(),
        )?;
    by_scale
        .configure_mesh()
        .x_desc("scale")
        .y_desc("acne + leaks (fraction; 0 at the bottom)")
        .x_label_formatter(&|x| format!("{x:.0e}"))
        .y_label_formatter(&fraction_label)
        .label_style(label_style)
        .light_line_style(WHITE)
        .draw()?;
    for ((name, _), colour) in CHART_STRATEGIES.iter().zip(COLOURS) {
        let points: Vec<(f64, f64)> = rows
            .iter()
            .filter(|r| r.strategy == *name)
            .map(|r| (r.scale, wrong(r)))
            .collect();
        by_scale.draw_series(LineSeries::new(
            points.clone(),
            colour.stroke_width(2),
        ))?;
        by_scale.draw_series(
            points
                .into_iter()
                .map(|p| Circle::new(p, 3, colour.filled())),
        )?;
    }

    // Right: every (strategy, scale) run as a point: time against errors.
    let mut by_time = ChartBuilder::on(&right)
        .caption("accuracy against speed", ("sans-serif", 17))
        .margin(10)
        .x_label_area_size(34)
        .y_label_area_size(56)
        .build_cartesian_2d(min_ms..max_ms, (FLOOR..1f64).log_scale())?;
    by_time
        .configure_mesh()
        .x_desc("render time, ms (160×90, one thread)")
        .y_desc("acne + leaks (fraction; 0 at the bottom)")
        .y_label_formatter(&fraction_label)
        .label_style(label_style)
        .light_line_style(WHITE)
        .draw()?;
    for ((name, _), colour) in CHART_STRATEGIES.iter().zip(COLOURS) {
        by_time.draw_series(
            rows.iter()
                .filter(|r| r.strategy == *name)
                .map(|r| Circle::new((r.millis, wrong(r)), 4, colour.filled())),
        )?;
    }
    Ok(())
}
