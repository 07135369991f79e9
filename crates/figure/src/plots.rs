//! Chart parts several chapters draw with: colours, log–log axes, lines
//! through dots, a legend row and point labels that cover nothing.
use plotters::coord::types::RangedCoordf64;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use crate::log_axis::Ticked;
use crate::{AxisBreak, ChartArea, ChartError, Labels, LogAxis, Spot, font};

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
    values: impl Iterator<Item = f64>, pad: f64,
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
    area: &'a ChartArea<'b>, x: std::ops::Range<f64>, y: std::ops::Range<f64>,
    x_desc: &str, y_desc: &str,
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
    c: &mut ChartContext<'_, DB, Cartesian2d<X, Y>>, labels: &mut Labels,
    at: (X::ValueType, Y::ValueType), text: &str, colour: &RGBColor,
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

/// A dot of `colour` at `at`, moved `dy` px down (up if negative): one
/// of the dots of a row in a chart of named rows.
pub fn dot<DB: DrawingBackend, X, Y>(
    c: &mut ChartContext<'_, DB, Cartesian2d<X, Y>>,
    at: (X::ValueType, Y::ValueType), dy: i32, colour: &RGBColor,
) -> Result<(), ChartError>
where
    X: Ranged,
    Y: Ranged,
    DB::ErrorType: 'static,
{
    c.draw_series(std::iter::once(
        EmptyElement::at(at) + Circle::new((0, dy), 6, colour.filled()),
    ))?;
    Ok(())
}

/// `text` `px` tall in `colour`, `dx` px right of `at`, centred on it
/// vertically: a note at the end of a row.
pub fn note<DB: DrawingBackend, X, Y>(
    c: &mut ChartContext<'_, DB, Cartesian2d<X, Y>>,
    at: (X::ValueType, Y::ValueType), dx: i32, text: String,
    (px, colour): (f64, &RGBColor),
) -> Result<(), ChartError>
where
    X: Ranged,
    Y: Ranged,
    DB::ErrorType: 'static,
{
    let style = font(px)
        .color(colour)
        .pos(Pos::new(HPos::Left, VPos::Center));
    c.draw_series(std::iter::once(
        EmptyElement::at(at) + Text::new(text, (dx, 0), style),
    ))?;
    Ok(())
}

/// A pale line through `points` (x, y) and a dot of `radius` on each.
pub fn line_with_dots(
    c: &mut LogChart, points: &[(f64, f64)], colour: RGBColor, radius: i32,
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
    area: &ChartArea, entries: &[(&str, RGBColor)], x: i32, spacing: i32,
) -> Result<(), ChartError> {
    for (i, (name, colour)) in entries.iter().enumerate() {
        let x = x + spacing * i as i32;
        area.draw(&Circle::new((x, 20), 6, colour.filled()))?;
        area.draw(&Text::new(*name, (x + 14, 11), font(16.0)))?;
    }
    Ok(())
}

/// One series of a chart: the key its rows carry in the CSV, its name in
/// the legend, its colour.
#[derive(Clone, Copy, Debug)]
pub struct Series {
    /// What the rows of this series hold in their key column.
    pub key: &'static str,
    /// Its name in the legend.
    pub name: &'static str,
    /// Its colour.
    pub colour: RGBColor,
}

impl Series {
    /// The series `key`, shown as `name` in `colour`.
    pub const fn new(
        key: &'static str, name: &'static str, colour: RGBColor,
    ) -> Series {
        Series { key, name, colour }
    }

    /// The name of the series whose key is `key`, in `all`; `key` itself
    /// if none has it.
    pub fn name_of<'a>(all: &[Series], key: &'a str) -> &'a str {
        all.iter().find(|s| s.key == key).map_or(key, |s| s.name)
    }
}

/// The legend of `series` (their names and colours), as [`legend`]
/// draws one.
pub fn series_legend(
    area: &ChartArea, series: &[Series], x: i32, spacing: i32,
) -> Result<(), ChartError> {
    let entries: Vec<(&str, RGBColor)> =
        series.iter().map(|s| (s.name, s.colour)).collect();
    legend(area, &entries, x, spacing)
}

/// A legend row of short lines with a dot on each and names, at the top
/// of `area`, the names `px` tall: the legend of a chart of lines.
pub fn line_legend(
    area: &ChartArea, entries: &[(&str, RGBColor)], (x, spacing): (i32, i32),
    px: f64,
) -> Result<(), ChartError> {
    for (i, (name, colour)) in entries.iter().enumerate() {
        let x = x + spacing * i as i32;
        area.draw(&PathElement::new(
            vec![(x, 18), (x + 28, 18)],
            colour.stroke_width(3),
        ))?;
        area.draw(&Circle::new((x + 14, 18), 4, colour.filled()))?;
        area.draw(&Text::new(*name, (x + 36, 9), font(px)))?;
    }
    Ok(())
}

/// A chart of render time across and an error up.
pub type ErrorChart<'a, 'b> =
    ChartContext<'a, SVGBackend<'b>, Cartesian2d<RangedCoordf64, Ticked>>;

/// The panel "accuracy against speed" on `area`: the render times of
/// `millis` across (a little wider), the error named `error` up on
/// `errors`, with its break below the row of 0; every run is to be drawn
/// as a point on it.
pub fn accuracy_against_speed<'a, 'b>(
    area: &'a ChartArea<'b>, millis: impl Iterator<Item = f64> + Clone,
    errors: &LogAxis, error: &str,
) -> Result<ErrorChart<'a, 'b>, ChartError> {
    let max_ms = millis.clone().fold(0.0, f64::max) * 1.05;
    let min_ms = millis.fold(f64::INFINITY, f64::min) * 0.95;
    let mut c = ChartBuilder::on(area)
        .caption("accuracy against speed", font(17.0))
        .margin(10)
        .margin_right(24)
        .x_label_area_size(52)
        .y_label_area_size(72)
        .build_cartesian_2d(min_ms..max_ms, errors.range())?;
    c.configure_mesh()
        .x_desc("render time, ms (160×90, one thread)")
        .y_desc(error)
        .x_labels(10)
        .x_label_formatter(&|x| format!("{x:.1}"))
        .y_label_formatter(&|y| errors.label(y))
        .label_style(font(16.0))
        .axis_desc_style(font(15.0))
        .light_line_style(WHITE)
        .draw()?;
    if let Some(at) = errors.break_at() {
        c.draw_series([AxisBreak::y((min_ms, at))])?;
    }
    Ok(c)
}

/// The y of the row named `name` in a chart of named rows, the first name
/// on top (row `n − 1`, as [`row_label`] labels them); the top row if no
/// row has that name.
pub fn row_of<S: AsRef<str>>(names: &[S], name: &str) -> f64 {
    let k = names.iter().position(|n| n.as_ref() == name).unwrap_or(0);
    names.len() as f64 - 1.0 - k as f64
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_row_is_found_where_its_name_is_labelled() {
        let names = ["top", "middle", "bottom"];
        for name in names {
            assert_eq!(row_label(&names, row_of(&names, name)), name);
        }
        assert_eq!(row_of(&names, "top"), 2.0);
        assert_eq!(row_of(&names, "nowhere"), 2.0);
        assert_eq!(row_label(&names, 0.5), "");
    }
}
