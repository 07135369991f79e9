//! Charts of named rows, a dot per series in each row, on a log axis:
//! chapters 9 and 10 compare structures on scenes this way, a panel per
//! quantity.
use std::ops::Range;

use plotters::prelude::*;

use crate::plots::{dot, row_label};
use crate::{ChartArea, ChartError, font};

/// How the panels of one chart look: the rows, the series and the axis.
pub struct DotRows<'a> {
    /// The rows' names, the first on top.
    pub names: &'a [&'a str],
    /// The width of the names at the left, in px.
    pub names_width: u32,
    /// The series' colours; in a row the dots of the series stand one
    /// above the other, in this order from the top.
    pub colours: &'a [RGBColor],
    /// Pixels between two dots of a row.
    pub spacing: i32,
    /// How many labels the log axis has...
    pub x_labels: usize,
    /// ... and how they read.
    pub x_label: &'a dyn Fn(&f64) -> String,
}

impl DotRows<'_> {
    /// One panel on `panel`: the log axis over `x`, named `desc`; the
    /// rows' names at the left if `names` (else no room for them); in row
    /// `k` the dot of series `m` at the value `value(k, m)` gives, ringed if
    /// it says so (none where it gives none or a value that is not
    /// positive).
    pub fn panel(
        &self, panel: &ChartArea, desc: &str, x: Range<f64>, names: bool,
        value: &dyn Fn(usize, usize) -> Option<(f64, bool)>,
    ) -> Result<(), ChartError> {
        let n = self.names.len() as f64;
        let mut c = ChartBuilder::on(panel)
            .margin(10)
            .margin_right(24)
            .x_label_area_size(48)
            .y_label_area_size(if names { self.names_width } else { 10 })
            .build_cartesian_2d(x.log_scale(), -0.6..(n - 0.4))?;
        let labels: Vec<&str> = self
            .names
            .iter()
            .map(|name| if names { *name } else { "" })
            .collect();
        c.configure_mesh()
            .x_desc(desc)
            .x_labels(self.x_labels)
            .x_label_formatter(self.x_label)
            .y_labels(self.names.len())
            .disable_y_mesh()
            .y_label_formatter(&|y| row_label(&labels, *y))
            .label_style(font(14.0))
            .axis_desc_style(font(15.0))
            .light_line_style(WHITE)
            .draw()?;
        let last = self.colours.len() as i32 - 1;
        for k in 0..self.names.len() {
            let y = n - 1.0 - k as f64;
            for (m, colour) in self.colours.iter().enumerate() {
                let Some((v, ringed)) = value(k, m) else {
                    continue;
                };
                if v.is_nan() || v <= 0.0 {
                    continue; // brute force builds nothing
                }
                let dy = self.spacing / 2 * (2 * m as i32 - last);
                dot(&mut c, (v, y), dy, colour)?;
                if ringed {
                    c.draw_series(std::iter::once(
                        EmptyElement::at((v, y))
                            + Circle::new((0, dy), 11, BLACK.stroke_width(2)),
                    ))?;
                }
            }
        }
        Ok(())
    }
}
