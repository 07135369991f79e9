//! Point labels on a chart that cover no line, marker or other label.
//!
//! [`Labels`] works in the chart's pixels (`ChartContext::backend_coord`):
//! it is told what to keep clear, then tries spots around each point in the
//! order asked and takes the first that is clear.

use plotters::style::text_anchor::{HPos, Pos, VPos};

use crate::text::{Run, parse_markup};

/// A spot around a point: where its label goes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Spot {
    /// Right of the point.
    E,
    /// Left.
    W,
    /// Above.
    N,
    /// Below.
    S,
    /// Above right.
    NE,
    /// Above left.
    NW,
    /// Below right.
    SE,
    /// Below left.
    SW,
}

impl Spot {
    /// Every spot, the sides first.
    pub const ALL: [Spot; 8] = [
        Spot::E,
        Spot::W,
        Spot::N,
        Spot::S,
        Spot::NE,
        Spot::NW,
        Spot::SE,
        Spot::SW,
    ];

    /// The text's offset from the point (pixels, y down) and its anchor.
    fn anchor(self, gap: i32) -> ((i32, i32), Pos) {
        let d = gap * 7 / 10; // along each axis for a diagonal spot
        let (x, h) = match self {
            Spot::E => (gap, HPos::Left),
            Spot::W => (-gap, HPos::Right),
            Spot::N | Spot::S => (0, HPos::Center),
            Spot::NE | Spot::SE => (d, HPos::Left),
            Spot::NW | Spot::SW => (-d, HPos::Right),
        };
        let (y, v) = match self {
            Spot::E | Spot::W => (0, VPos::Center),
            Spot::N => (-gap, VPos::Bottom),
            Spot::S => (gap, VPos::Top),
            Spot::NE | Spot::NW => (-d, VPos::Bottom),
            Spot::SE | Spot::SW => (d, VPos::Top),
        };
        ((x, y), Pos::new(h, v))
    }
}

/// A box in pixels: left, top, right, bottom.
type Area = (f64, f64, f64, f64);

/// The labels of one chart, and what they must keep clear of.
#[derive(Clone, Debug, Default)]
pub struct Labels {
    segments: Vec<((f64, f64), (f64, f64))>,
    taken: Vec<Area>,
}

/// How far a label stays from its point, in pixels.
const GAP: i32 = 8;

impl Labels {
    /// Nothing to keep clear of yet.
    pub fn new() -> Labels {
        Labels::default()
    }

    /// Keep clear of the polyline through `points`.
    pub fn avoid_line(&mut self, points: &[(i32, i32)]) {
        let f = |(x, y): (i32, i32)| (f64::from(x), f64::from(y));
        for pair in points.windows(2) {
            self.segments.push((f(pair[0]), f(pair[1])));
        }
    }

    /// Keep clear of a marker of `radius` pixels at `at`.
    pub fn avoid_point(&mut self, at: (i32, i32), radius: i32) {
        let (x, y, r) = (f64::from(at.0), f64::from(at.1), f64::from(radius));
        self.taken.push((x - r, y - r, x + r, y + r));
    }

    /// A spot for the label `text` (label markup) of `size` px beside the
    /// point `at`: the first of `spots` where it covers nothing kept clear,
    /// now taken. Gives the text's offset from the point and its anchor
    /// (for `Text::new(text, offset, style.pos(anchor))`), or `None` if no
    /// spot is clear.
    pub fn place(
        &mut self, at: (i32, i32), text: &str, size: f64, spots: &[Spot],
    ) -> Option<((i32, i32), Pos)> {
        let (width, height) = (text_width(text, size), size);
        for spot in spots {
            let (offset, pos) = spot.anchor(GAP);
            let x = f64::from(at.0 + offset.0);
            let y = f64::from(at.1 + offset.1);
            let left = match pos.h_pos {
                HPos::Left => x,
                HPos::Center => x - width / 2.0,
                HPos::Right => x - width,
            };
            let top = match pos.v_pos {
                VPos::Top => y,
                VPos::Center => y - height / 2.0,
                VPos::Bottom => y - height,
            };
            let area = (left, top, left + width, top + height);
            let clear = !self.taken.iter().any(|t| overlap(area, *t))
                && !self.segments.iter().any(|&(a, b)| crosses(area, a, b));
            if clear {
                self.taken.push(area);
                return Some((offset, pos));
            }
        }
        None
    }
}

/// The width of label markup `text` at `size` px, estimated: DejaVu Sans
/// averages about 0.6 em a character (its digits are 0.64 em), scripts at
/// 0.7 of that.
fn text_width(text: &str, size: f64) -> f64 {
    let chars = |s: &str| s.chars().count() as f64;
    let ems: f64 = parse_markup(text)
        .iter()
        .map(|run| match run {
            Run::Normal(s) => 0.62 * chars(s),
            Run::Sub(s) | Run::Super(s) => 0.7 * 0.62 * chars(s),
        })
        .sum();
    ems * size
}

fn overlap(a: Area, b: Area) -> bool {
    a.0 < b.2 && b.0 < a.2 && a.1 < b.3 && b.1 < a.3
}

/// Whether the segment from `a` to `b` enters the box (Liang–Barsky).
fn crosses(area: Area, a: (f64, f64), b: (f64, f64)) -> bool {
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    let (mut lo, mut hi) = (0.0f64, 1.0f64);
    for (p, q) in [
        (-dx, a.0 - area.0),
        (dx, area.2 - a.0),
        (-dy, a.1 - area.1),
        (dy, area.3 - a.1),
    ] {
        if p == 0.0 {
            if q < 0.0 {
                return false;
            }
        } else {
            let t = q / p;
            if p < 0.0 {
                lo = lo.max(t);
            } else {
                hi = hi.min(t);
            }
        }
    }
    lo <= hi
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The offset and the anchor as (h, v) letters, for comparing.
    fn spot(
        placed: Option<((i32, i32), Pos)>,
    ) -> Option<((i32, i32), &'static str)> {
        placed.map(|(offset, pos)| {
            let h = match pos.h_pos {
                HPos::Left => "l",
                HPos::Center => "c",
                HPos::Right => "r",
            };
            let anchor = match (h, pos.v_pos) {
                ("r", VPos::Center) => "rc",
                ("c", VPos::Top) => "ct",
                _ => "other",
            };
            (offset, anchor)
        })
    }

    #[test]
    fn a_label_takes_the_first_clear_spot() {
        let mut labels = Labels::new();
        // a line leaving the point to the right: E is covered, W is clear
        labels.avoid_line(&[(100, 100), (200, 100)]);
        let placed = labels.place((100, 100), "18", 16.0, &[Spot::E, Spot::W]);
        assert_eq!(spot(placed), Some(((-GAP, 0), "rc")));
        // the same spot again is taken by the first label
        assert!(labels.place((100, 100), "18", 16.0, &[Spot::W]).is_none());
        // below is clear
        let placed = labels.place((100, 100), "3", 16.0, &[Spot::S]);
        assert_eq!(spot(placed), Some(((0, GAP), "ct")));
    }

    #[test]
    fn widths_count_scripts_smaller() {
        assert!((text_width("10", 10.0) - 12.4).abs() < 1e-9);
        assert!(text_width("10^{−2}", 10.0) < text_width("10−2", 10.0));
    }
}
