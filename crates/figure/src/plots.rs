//! Chart parts several chapters draw with: colours, log–log axes, lines
//! through dots, a legend row and point labels that cover nothing.
use plotters::prelude::*;

use crate::{ChartArea, ChartError, Labels, Spot, font};

/// Okabe–Ito blue (the chart colours are colour-blind safe).
pub const BLUE: RGBColor = RGBColor(0, 114, 178);
/// Okabe–Ito vermilion.
pub const ORANGE: RGBColor = RGBColor(213, 94, 0);
/// Okabe–Ito bluish green.
pub const GREEN: RGBColor = RGBColor(0, 158, 115);
/// A dark grey for secondary text.
pub const GREY: RGBColor = RGBColor(90, 90, 90);

/// A chart with a log scale on both axes.
pub type LogChart<'a, 'b> =
    ChartContext<'a, SVGBackend<'b>, Cartesian2d<LogCoord<f64>, LogCoord<f64>>>;

/// A range on a log axis around `values`, a little wider.
pub fn log_range(values: impl Iterator<Item = f64>) -> std::ops::Range<f64> {
    padded_log_range(values, 1.6)
}

/// A range on a log axis around `values`, `pad` times wider each way.
pub fn padded_log_range(
    values: impl Iterator<Item = f64>,
    pad: f64,
) -> std::ops::Range<f64> {
    let (lo, hi) = values
        .filter(|v| *v > 0.0 && v.is_finite())
        .fold((f64::INFINITY, 0.0f64), |(lo, hi), v| {
            (lo.min(v), hi.max(v))
        });
    if !lo.is_finite() {
        return 0.1..10.0;
    }
    (lo / pad)..(hi * pad)
}

/// A number as an axis label: 0.5, 3, 250, 12 000.
pub fn number_label(x: &f64) -> String {
    if *x >= 10_000.0 {
        crate::numbers::grouped(x.round() as u64)
    } else if *x >= 10.0 {
        format!("{x:.0}")
    } else {
        let text = format!("{x:.2}");
        text.trim_end_matches('0').trim_end_matches('.').to_string()
    }
}

/// A log–log chart on `area` with the given ranges and axis names.
pub fn log_log<'a, 'b>(
    area: &'a ChartArea<'b>,
    x: std::ops::Range<f64>,
    y: std::ops::Range<f64>,
    x_desc: &str,
    y_desc: &str,
) -> Result<LogChart<'a, 'b>, ChartError> {
    let mut c = ChartBuilder::on(area)
        .margin(14)
        .margin_right(110)
        .x_label_area_size(58)
        .y_label_area_size(90)
        .build_cartesian_2d(x.log_scale(), y.log_scale())?;
    c.configure_mesh()
        .x_desc(x_desc)
        .y_desc(y_desc)
        .x_label_formatter(&number_label)
        .y_label_formatter(&number_label)
        .label_style(font(16.0))
        .axis_desc_style(font(16.0))
        .light_line_style(WHITE)
        .draw()?;
    Ok(c)
}

/// A label beside the point `at`, where it covers nothing else.
pub fn label<DB: DrawingBackend, X, Y>(
    c: &mut ChartContext<'_, DB, Cartesian2d<X, Y>>,
    labels: &mut Labels,
    at: (X::ValueType, Y::ValueType),
    text: &str,
    colour: &RGBColor,
) -> Result<(), ChartError>
where
    X: Ranged,
    Y: Ranged,
    X::ValueType: Clone,
    Y::ValueType: Clone,
    DB::ErrorType: 'static,
{
    let pixel = c.backend_coord(&at);
    // in a crowd, a smaller label (still above the book's 11 px) may fit
    for size in [15.0, 13.0] {
        if let Some((offset, pos)) = labels.place(pixel, text, size, &Spot::ALL)
        {
            c.draw_series(std::iter::once(
                EmptyElement::at(at)
                    + Text::new(
                        text.to_string(),
                        offset,
                        font(size).color(colour).pos(pos),
                    ),
            ))?;
            break;
        }
    }
    Ok(())
}

/// A pale line through `points` (x, y) and a dot of `radius` on each.
pub fn line_with_dots(
    c: &mut LogChart,
    points: &[(f64, f64)],
    colour: RGBColor,
    radius: i32,
) -> Result<(), ChartError> {
    c.draw_series(LineSeries::new(
        points.iter().copied(),
        colour.mix(0.6).stroke_width(2),
    ))?;
    c.draw_series(
        points
            .iter()
            .map(|&p| Circle::new(p, radius, colour.filled())),
    )?;
    Ok(())
}

/// A legend row of coloured dots and names, at the top of `area`.
pub fn legend(
    area: &ChartArea,
    entries: &[(&str, RGBColor)],
    x: i32,
    spacing: i32,
) -> Result<(), ChartError> {
    for (i, (name, colour)) in entries.iter().enumerate() {
        let x = x + spacing * i as i32;
        area.draw(&Circle::new((x, 20), 6, colour.filled()))?;
        area.draw(&Text::new(*name, (x + 14, 11), font(16.0)))?;
    }
    Ok(())
}

/// The label of row `y` in a chart of named rows, the first name on top
/// (row `n − 1`) and the last at the bottom (row 0); no label between
/// rows. For `y_label_formatter(&|y| row_label(&names, *y))`.
pub fn row_label<S: AsRef<str>>(names: &[S], y: f64) -> String {
    let n = names.len() as f64;
    let k = n - 1.0 - y.round();
    if (y - y.round()).abs() > 1e-6 || k < 0.0 || k >= n {
        return String::new();
    }
    names[k as usize].as_ref().to_string()
}
