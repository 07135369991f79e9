//! Log axes for charts that also show zero.
//!
//! A log axis has no place for 0, yet a chart of errors is full of zeros.
//! [`LogAxis`] draws a linear axis in decades (a value v sits at log₁₀ v),
//! labels every whole decade as a power of ten, and gives zero a row of its
//! own below the lowest decade, set apart by a break in the axis
//! ([`AxisBreak`]): the reader sees a "0", not a value to decode.

use std::ops::Range;

use plotters::coord::ranged1d::{DefaultFormatting, KeyPointHint, Ranged};
use plotters::coord::types::RangedCoordf64;
use plotters::element::{Drawable, PointCollection};
use plotters::prelude::{BLACK, Color, DrawingBackend, WHITE};
use plotters_backend::{BackendCoord, DrawingErrorKind};

/// How far below the lowest decade zero's row sits, in decades.
const ZERO_GAP: f64 = 1.0;
/// Room beyond the first and last row, in decades.
const PAD: f64 = 0.3;
/// Room below zero's row, in decades: a chart may spread equal zeros over
/// a few lanes of that row, to keep each visible.
const ZERO_PAD: f64 = 0.5;

/// A log axis in decades, with an optional row for zero (see the module
/// documentation). Its coordinate is `f64`: build the chart with
/// [`LogAxis::range`] and place values with [`LogAxis::at`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LogAxis {
    /// The lowest labelled decade: 10^lowest.
    lowest: i32,
    /// The top of the axis, log₁₀ of the largest value shown.
    top: f64,
    /// Whether zero has a row.
    zero: bool,
}

impl LogAxis {
    /// The axis that shows every value of `values`: from the decade of the
    /// smallest positive value up to the largest, with a row for zero if
    /// some value is 0 (negative values count as 0).
    ///
    /// # Panics
    /// If no value is positive and finite.
    pub fn covering(values: impl IntoIterator<Item = f64>) -> LogAxis {
        let (mut min, mut max, mut zero) = (f64::INFINITY, 0.0f64, false);
        for v in values {
            if v > 0.0 && v.is_finite() {
                (min, max) = (min.min(v), max.max(v));
            } else {
                zero = true;
            }
        }
        assert!(min.is_finite(), "a log axis needs a positive value");
        let lowest = min.log10().floor() as i32;
        LogAxis {
            lowest,
            top: max.log10().max(f64::from(lowest)),
            zero,
        }
    }

    /// The axis from decade 10^lowest to 10^highest, without a row for zero.
    ///
    /// # Panics
    /// If `lowest` is not below `highest`.
    pub fn decades(lowest: i32, highest: i32) -> LogAxis {
        assert!(lowest < highest, "decades {lowest} .. {highest}");
        LogAxis {
            lowest,
            top: f64::from(highest),
            zero: false,
        }
    }

    /// The same axis with a row for zero.
    pub fn with_zero(self) -> LogAxis {
        LogAxis { zero: true, ..self }
    }

    /// Where `v` sits on the axis: log₁₀ v, or zero's row for 0.
    ///
    /// # Panics
    /// If `v` is 0 (or negative) and the axis has no row for zero.
    pub fn at(&self, v: f64) -> f64 {
        if v > 0.0 {
            v.log10()
        } else {
            assert!(self.zero, "{v} on a log axis without a row for 0");
            self.zero_row()
        }
    }

    /// The axis coordinate of zero's row.
    pub fn zero_row(&self) -> f64 {
        f64::from(self.lowest) - ZERO_GAP
    }

    /// Where the break between zero's row and the lowest decade goes, if
    /// the axis has a row for zero.
    pub fn break_at(&self) -> Option<f64> {
        self.zero.then(|| f64::from(self.lowest) - ZERO_GAP / 2.0)
    }

    /// The whole decades on the axis, lowest first.
    pub fn decade_exponents(&self) -> impl Iterator<Item = i32> {
        self.lowest..=self.top.floor() as i32
    }

    /// The first coordinate of [`LogAxis::range`]: where the other axis
    /// crosses this one.
    pub fn start(&self) -> f64 {
        if self.zero {
            self.zero_row() - ZERO_PAD
        } else {
            f64::from(self.lowest) - PAD
        }
    }

    /// The coordinate range to build the chart with: every decade (and
    /// zero's row) is a tick, with some room at both ends.
    pub fn range(&self) -> Ticked {
        let mut ticks: Vec<f64> =
            self.decade_exponents().map(f64::from).collect();
        if self.zero {
            ticks.insert(0, self.zero_row());
        }
        Ticked::new(self.start()..self.top + PAD, ticks)
    }

    /// A tick's label: "0" on zero's row, the decade as a power of ten
    /// (label markup: `1`, `10`, `10^{−3}`), nothing elsewhere.
    pub fn label(&self, y: &f64) -> String {
        if self.zero && (y - self.zero_row()).abs() < 1e-9 {
            "0".to_string()
        } else if (y - y.round()).abs() < 1e-9 {
            decade(y.round() as i32)
        } else {
            String::new()
        }
    }
}

/// A linear `f64` coordinate with ticks (and grid lines) exactly at the
/// values given: what [`LogAxis::range`] builds a chart with.
#[derive(Clone)]
pub struct Ticked {
    inner: RangedCoordf64,
    ticks: Vec<f64>,
}

impl Ticked {
    /// The coordinate `range` with ticks at `ticks`.
    pub fn new(range: Range<f64>, ticks: Vec<f64>) -> Ticked {
        Ticked {
            inner: range.into(),
            ticks,
        }
    }
}

impl Ranged for Ticked {
    type ValueType = f64;
    type FormatOption = DefaultFormatting;

    fn range(&self) -> Range<f64> {
        self.inner.range()
    }

    fn map(&self, value: &f64, limit: (i32, i32)) -> i32 {
        self.inner.map(value, limit)
    }

    fn key_points<Hint: KeyPointHint>(&self, hint: Hint) -> Vec<f64> {
        // no light grid lines between the ticks
        if hint.weight().allow_light_points() {
            Vec::new()
        } else {
            self.ticks.clone()
        }
    }
}

/// 10 to the power `k` as label markup: `1`, `10`, else `10^{k}` with a
/// real minus sign (`10^{−3}`).
pub fn decade(k: i32) -> String {
    match k {
        0 => "1".to_string(),
        1 => "10".to_string(),
        _ => format!("10^{{{}}}", k.to_string().replace('-', "−")),
    }
}

/// The break mark in an axis: the axis line cut, with two short slanted
/// strokes, at a point of the axis line given in chart coordinates.
/// Draw it with `chart.draw_series([AxisBreak::y((x_start, y))])`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AxisBreak {
    at: (f64, f64),
    /// A break in a vertical axis (the y axis), else in a horizontal one.
    vertical: bool,
}

impl AxisBreak {
    /// A break in the y axis at `at`, a point on the axis line.
    pub fn y(at: (f64, f64)) -> AxisBreak {
        AxisBreak { at, vertical: true }
    }

    /// A break in the x axis at `at`, a point on the axis line.
    pub fn x(at: (f64, f64)) -> AxisBreak {
        AxisBreak {
            at,
            vertical: false,
        }
    }
}

impl<'a> PointCollection<'a, (f64, f64)> for &'a AxisBreak {
    type Point = &'a (f64, f64);
    type IntoIter = std::iter::Once<&'a (f64, f64)>;

    fn point_iter(self) -> Self::IntoIter {
        std::iter::once(&self.at)
    }
}

impl<DB: DrawingBackend> Drawable<DB> for AxisBreak {
    fn draw<I: Iterator<Item = BackendCoord>>(
        &self, mut points: I, backend: &mut DB, _: (u32, u32),
    ) -> Result<(), DrawingErrorKind<DB::ErrorType>> {
        let Some((x, y)) = points.next() else {
            return Ok(());
        };
        // in axis terms: `along` the axis line, `across` it
        let (half_gap, reach, slant) = (4, 8, 4);
        let at = |along: i32, across: i32| {
            if self.vertical {
                (x + across, y - along)
            } else {
                (x + along, y + across)
            }
        };
        let (a, b) = (at(-half_gap, -reach), at(half_gap, reach));
        backend.draw_rect(
            (a.0.min(b.0), a.1.min(b.1)),
            (a.0.max(b.0), a.1.max(b.1)),
            &WHITE.filled(),
            true,
        )?;
        let stroke = BLACK.stroke_width(1);
        for side in [-half_gap, half_gap] {
            backend.draw_line(
                at(side - slant, -reach),
                at(side + slant, reach),
                &stroke,
            )?;
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use plotters::coord::ranged1d::BoldPoints;

    #[test]
    fn an_axis_covers_its_values_and_gives_zero_a_row() {
        let axis = LogAxis::covering([0.0, 4.3e-4, 0.9, 0.02]);
        assert_eq!(
            axis.decade_exponents().collect::<Vec<_>>(),
            [-4, -3, -2, -1]
        );
        assert_eq!(axis.at(0.0), -5.0);
        assert!((axis.at(0.01) + 2.0).abs() < 1e-12);
        assert_eq!(axis.break_at(), Some(-4.5));
        assert_eq!(axis.label(&-5.0), "0");
        assert_eq!(axis.label(&-4.0), "10^{−4}");
        assert_eq!(axis.label(&-4.5), "");
        let range = axis.range();
        assert_eq!(
            range.key_points(BoldPoints(10)),
            [-5.0, -4.0, -3.0, -2.0, -1.0]
        );
        let (lo, hi) = (range.range().start, range.range().end);
        assert!(lo < -5.0 && hi > 0.9f64.log10(), "{lo} .. {hi}");

        let plain = LogAxis::decades(-3, 4);
        assert_eq!(plain.break_at(), None);
        assert_eq!(plain.label(&0.0), "1");
        assert_eq!(plain.label(&1.0), "10");
        assert_eq!(plain.label(&4.0), "10^{4}");
    }

    #[test]
    #[should_panic(expected = "without a row for 0")]
    fn zero_needs_its_row() {
        LogAxis::decades(0, 2).at(0.0);
    }
}
