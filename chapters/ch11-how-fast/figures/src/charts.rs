//! The appendix's chart, drawn from `fast-steps.csv`: millions of rays
//! per second after each step, for each ray set, the peers as lines.
use raystep_figure::plots::{BLUE, GREEN, GREY, ORANGE, legend};
use raystep_figure::plotters::prelude::*;
use raystep_figure::plotters::style::ShapeStyle;
use raystep_figure::plotters::style::text_anchor::{HPos, Pos, VPos};
use raystep_figure::{ChartError, Figure, chart, font, measured};

use crate::rows::StepRow;

/// Embree's colour (Okabe and Ito's reddish purple), and a darker one
/// for its robust mode.
const PURPLE: RGBColor = RGBColor(204, 121, 167);
const DARK_PURPLE: RGBColor = RGBColor(120, 50, 100);

/// A peer's colour, by the start of its name.
fn peer_colour(name: &str) -> RGBColor {
    if name.starts_with("obvhs Bvh2") {
        ORANGE
    } else if name.starts_with("obvhs CwBvh") {
        GREEN
    } else if name.starts_with("Embree") && name.ends_with("robust") {
        DARK_PURPLE
    } else if name.starts_with("Embree") {
        PURPLE
    } else {
        GREY
    }
}

/// The three ray sets, as the panels name them.
const SETS: [&str; 3] = [
    "primary (1024² = 1 048 576 camera rays)",
    "shadow (442 061 rays, any hit)",
    "incoherent (2²⁰ = 1 048 576 rays)",
];

/// Mrays/s per step and ray set on one thread; the peers as horizontal
/// lines.
pub fn steps_chart() -> Result<Figure, ChartError> {
    let rows: Vec<StepRow> = measured("ch11", "fast-steps.csv")?;
    let one: Vec<&StepRow> = rows.iter().filter(|r| r.threads == 1).collect();
    let ours: Vec<&StepRow> =
        one.iter().copied().filter(|r| r.kind == "ours").collect();
    let peers: Vec<&StepRow> =
        one.iter().copied().filter(|r| r.kind == "peer").collect();
    if ours.is_empty() {
        return Err("fast-steps.csv has no step on one thread".into());
    }
    let numbers: Vec<String> = ours
        .iter()
        .map(|r| r.method.split(' ').next().unwrap_or("").to_string())
        .collect();
    let caption = caption(&ours, &peers);
    chart("fast-steps", &caption, 900, 940, |area| {
        let (top, rest) = area.split_vertically(80);
        let mut entries: Vec<(&str, RGBColor)> = vec![("our steps", BLUE)];
        entries.extend(
            peers
                .iter()
                .map(|p| (p.method.as_str(), peer_colour(&p.method))),
        );
        legend(
            &top.split_vertically(40).0,
            &entries[..entries.len().min(3)],
            40,
            280,
        )?;
        if entries.len() > 3 {
            legend(&top.split_vertically(40).1, &entries[3..], 40, 280)?;
        }
        let panels = rest.split_evenly((3, 1));
        for (k, panel) in panels.iter().enumerate() {
            let top_y = ours
                .iter()
                .chain(&peers)
                .map(|r| r.mrays()[k])
                .fold(0.0, f64::max)
                * 1.15;
            let n = ours.len() as f64;
            let last = k == 2;
            let mut c = ChartBuilder::on(panel)
                .margin(10)
                .margin_right(24)
                .caption(SETS[k], font(16.0))
                .x_label_area_size(if last { 48 } else { 28 })
                .y_label_area_size(70)
                .build_cartesian_2d(-0.5..(n - 0.5), 0.0..top_y)?;
            let labels = numbers.clone();
            c.configure_mesh()
                .x_labels(ours.len())
                .x_label_formatter(&|x| {
                    let i = x.round();
                    if (x - i).abs() > 1e-6 || i < 0.0 {
                        return String::new();
                    }
                    labels.get(i as usize).cloned().unwrap_or_default()
                })
                .x_desc(if last { "step" } else { "" })
                .y_desc("Mrays/s")
                .y_labels(5)
                .disable_x_mesh()
                .label_style(font(14.0))
                .axis_desc_style(font(15.0))
                .light_line_style(WHITE)
                .draw()?;
            for peer in &peers {
                let colour = peer_colour(&peer.method);
                let y = peer.mrays()[k];
                c.draw_series(DashedLineSeries::new(
                    [(-0.5, y), (n - 0.5, y)],
                    8,
                    5,
                    ShapeStyle::from(&colour).stroke_width(2),
                ))?;
            }
            let points: Vec<(f64, f64)> = ours
                .iter()
                .enumerate()
                .map(|(i, r)| (i as f64, r.mrays()[k]))
                .collect();
            c.draw_series(LineSeries::new(
                points.iter().copied(),
                BLUE.mix(0.6).stroke_width(2),
            ))?;
            c.draw_series(
                points.iter().map(|&p| Circle::new(p, 6, BLUE.filled())),
            )?;
            // Each value above its point, but below it where the point
            // before is labelled above at nearly the same height (the two
            // labels would touch).
            let close = 0.08 * top_y;
            let mut above = Vec::with_capacity(points.len());
            for (i, &(_, y)) in points.iter().enumerate() {
                let crowded = i > 0
                    && above[i - 1]
                    && (y - points[i - 1].1).abs() < close;
                above.push(!crowded);
            }
            c.draw_series(points.iter().zip(&above).map(|(&(x, y), &up)| {
                let (dy, v) = if up {
                    (-9, VPos::Bottom)
                } else {
                    (9, VPos::Top)
                };
                EmptyElement::at((x, y))
                    + Text::new(
                        format!("{y:.2}"),
                        (0, dy),
                        font(13.0).color(&BLACK).pos(Pos::new(HPos::Center, v)),
                    )
            }))?;
        }
        Ok(())
    })
}

/// The chart's caption: what each step is, and the last step's ratio to
/// each peer.
fn caption(ours: &[&StepRow], peers: &[&StepRow]) -> String {
    let steps: Vec<String> = ours.iter().map(|r| r.method.clone()).collect();
    let last = ours[ours.len() - 1];
    let best = ours
        .iter()
        .max_by(|a, b| a.mrays()[0].total_cmp(&b.mrays()[0]))
        .unwrap_or(&last);
    let ratios: Vec<String> = peers
        .iter()
        .map(|p| {
            format!(
                "{} {:.2}× / {:.2}× / {:.2}×",
                p.method,
                best.mrays()[0] / p.mrays()[0],
                best.mrays()[1] / p.mrays()[1],
                best.mrays()[2] / p.mrays()[2]
            )
        })
        .collect();
    format!(
        "Millions of rays per second on the 235 000-triangle bunny, one thread, \
         medians of the rounds (raystep measure; fast-steps.csv), after each step: {}. \
         Dashed: the peers in the same run. Step {} against each peer (primary / shadow / \
         incoherent): {}.",
        steps.join(", "),
        best.method,
        ratios.join("; ")
    )
}
