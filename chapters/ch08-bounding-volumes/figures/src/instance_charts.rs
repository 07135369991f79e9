//! The instances chart, drawn from `instances.csv` (written by `raystep
//! measure`): a field of bunnies flattened into one hierarchy against
//! instanced through two levels, as the field grows.
use raystep_figure::plots::{BLUE, ORANGE, legend, number_label};
use raystep_figure::plotters::prelude::*;
use raystep_figure::plotters::style::text_anchor::{HPos, Pos, VPos};
use raystep_figure::{ChartError, Figure, chart, font, measured};

use crate::instance_rows::{FLATTENED, INSTANCED, InstanceRow};

/// The two ways, with their colours and legend names.
const WAYS: [(&str, RGBColor, &str); 2] = [
    (FLATTENED, ORANGE, "flattened: one BVH over every triangle"),
    (INSTANCED, BLUE, "instanced: one bunny's BVH, shared"),
];

/// What each panel shows: its title and the value of a row.
type Panel = (&'static str, fn(&InstanceRow) -> f64);

/// The three panels: build time, memory, trace time.
const PANELS: [Panel; 3] = [
    ("build, ms", |r| r.build_ms),
    ("memory, MB", |r| r.bytes() as f64 / 1e6),
    ("trace, ns per ray", |r| r.trace_ns),
];

/// A value as its point's label: 3 significant digits at most.
fn value_label(v: f64) -> String {
    if v >= 100.0 {
        raystep_figure::numbers::grouped(v.round() as u64)
    } else if v >= 10.0 {
        format!("{v:.0}")
    } else if v >= 1.0 {
        format!("{v:.1}")
    } else {
        format!("{v:.2}")
    }
}

/// Build time, memory and trace time against the number of bunnies, both
/// ways, log–log.
pub fn instances_chart() -> Result<Figure, ChartError> {
    let rows: Vec<InstanceRow> = measured("ch08", "instances.csv")?;
    let rays = rows.first().map_or(0, |r| r.rays);
    // the share of the rays that hit a bunny, in the smallest and the
    // largest field
    let hit_share = |pick: fn(u64, u64) -> bool| {
        rows.iter()
            .reduce(|a, b| if pick(b.bunnies, a.bunnies) { b } else { a })
            .map_or(0.0, |r| 100.0 * r.hits as f64 / r.rays as f64)
    };
    let (fewest, most) = (hit_share(|b, a| b < a), hit_share(|b, a| b > a));
    chart(
        "instances-chart",
        &format!(
            "A field of 1 to 1 000 bunnies (3 674 triangles each), built two ways with the 16-bin SAH hierarchy: flattened, every bunny's triangles placed in the world under one BVH, or instanced, one BVH over the bunny's triangles shared by every bunny and a top BVH over the bunnies. Left to right, log–log: the build (from the scene in memory to the world ready), the memory of the objects and the hierarchies (counted from their sizes), and the time per camera ray (closest hit, {} rays of the scene's camera; as the field fills the view more rays hit a bunny, {fewest:.1} % for one, {most:.0} % for 1 000, and the time per ray grows with them). One thread, medians of the rounds (instances.csv).",
            raystep_figure::numbers::grouped(rays)
        ),
        900,
        440,
        |area| {
            let (top, rest) = area.split_vertically(40);
            let entries = WAYS.map(|(_, colour, name)| (name, colour));
            legend(&top, &entries, 40, 420)?;
            let panels = rest.split_evenly((1, 3));
            let bunnies = 0.5..2_000.0;
            for ((title, value), panel) in PANELS.iter().zip(panels.iter()) {
                let y = raystep_figure::plots::padded_log_range(
                    rows.iter().map(value),
                    2.5,
                );
                let mut c = ChartBuilder::on(panel)
                    .margin(10)
                    .margin_right(16)
                    .caption(*title, font(16.0))
                    .x_label_area_size(50)
                    .y_label_area_size(54)
                    .build_cartesian_2d(
                        bunnies.clone().log_scale(),
                        y.log_scale(),
                    )?;
                c.configure_mesh()
                    .x_desc("bunnies")
                    .x_label_formatter(&number_label)
                    .y_label_formatter(&number_label)
                    .label_style(font(14.0))
                    .axis_desc_style(font(15.0))
                    .light_line_style(WHITE)
                    .draw()?;
                for (k, (way, colour, _)) in WAYS.iter().enumerate() {
                    let mut points: Vec<(f64, f64)> = rows
                        .iter()
                        .filter(|r| r.way == *way)
                        .map(|r| (r.bunnies as f64, value(r)))
                        .collect();
                    points.sort_by(|a, b| a.0.total_cmp(&b.0));
                    c.draw_series(LineSeries::new(
                        points.iter().copied(),
                        colour.mix(0.6).stroke_width(2),
                    ))?;
                    c.draw_series(
                        points
                            .iter()
                            .map(|&p| Circle::new(p, 5, colour.filled())),
                    )?;
                    // each point's value, above (flattened) or below
                    let (dy, v) = if k == 0 {
                        (-8, VPos::Bottom)
                    } else {
                        (8, VPos::Top)
                    };
                    let style =
                        font(13.0).color(colour).pos(Pos::new(HPos::Center, v));
                    c.draw_series(points.iter().map(|&(x, y)| {
                        EmptyElement::at((x, y))
                            + Text::new(value_label(y), (0, dy), style.clone())
                    }))?;
                }
            }
            Ok(())
        },
    )
}
