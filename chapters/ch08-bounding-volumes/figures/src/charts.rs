//! Chapter 8's two charts, drawn from `book/src/figures/ch08/costs.csv` and
//! `bounding.csv` (written by `raystep measure`): what one ray–primitive
//! test costs against the sphere's, and what a bound saves.
use raystep_figure::plots::{dot, legend, note, row_label, row_of};
use raystep_figure::plotters::coord::types::RangedCoordf64;
use raystep_figure::plotters::prelude::*;
use raystep_figure::plotters::style::text_anchor::{HPos, Pos, VPos};
use raystep_figure::{ChartError, Figure, chart, font, measured};

use crate::rows::{BoundingRow, CostRow};

/// Hits and misses; the bound kinds (Okabe–Ito, colour-blind safe).
const HIT: RGBColor = RGBColor(213, 94, 0);
const MISS: RGBColor = RGBColor(0, 114, 178);
const GREY: RGBColor = RGBColor(120, 120, 120);

/// The bound kinds of `bounding.csv` on the chart, with their colours and
/// legend names.
pub const BOUND_KINDS: [(&str, RGBColor, &str); 3] = [
    ("box", RGBColor(0, 114, 178), "its box"),
    ("sphere", RGBColor(213, 94, 0), "its own bounding sphere"),
    (
        "box's sphere",
        RGBColor(0, 158, 115),
        "the sphere around its box",
    ),
];

/// The ratios the axes label, where they fall inside the range.
const TICKS: [f64; 11] =
    [0.1, 0.2, 0.25, 0.5, 1.0, 2.0, 5.0, 10.0, 20.0, 50.0, 100.0];

/// Ratios on a log axis drawn by hand: plotters' own log axis leaves the
/// decade below 1 unlabelled. The chart's x coordinate is log₁₀ of the
/// ratio; this draws a grid line and a label at each of [`TICKS`] in
/// range, on `root` (the whole figure, in its own pixels).
fn draw_log_ticks(
    root: &raystep_figure::ChartArea,
    c: &mut ChartContext<
        '_,
        SVGBackend<'_>,
        Cartesian2d<RangedCoordf64, RangedCoordf64>,
    >,
    x: &std::ops::Range<f64>, y: &std::ops::Range<f64>,
) -> Result<(), ChartError> {
    for v in TICKS.iter().filter(|v| x.contains(&v.log10())) {
        let at = v.log10();
        c.draw_series(LineSeries::new(
            [(at, y.start), (at, y.end)],
            RGBColor(225, 225, 225).stroke_width(1),
        ))?;
        let (px, py) = c.backend_coord(&(at, y.start));
        let style = font(16.0)
            .color(&BLACK)
            .pos(Pos::new(HPos::Center, VPos::Top));
        root.draw(&Text::new(ratio_label(*v), (px, py + 8), style))?;
    }
    Ok(())
}

/// A ratio as the axis shows it: `0.25`, `2`, `50`.
fn ratio_label(v: f64) -> String {
    let text = format!("{v:.2}");
    text.trim_end_matches('0').trim_end_matches('.').to_string()
}

/// The names in `rows`, in file order, without repeats.
fn names<'a>(rows: impl Iterator<Item = &'a str>) -> Vec<&'a str> {
    let mut found: Vec<&str> = Vec::new();
    for name in rows {
        if !found.contains(&name) {
            found.push(name);
        }
    }
    found
}

/// The axis over `values` (positive ratios), padded, at least 0.5 … 2.
fn ratio_range(values: impl Iterator<Item = f64>) -> std::ops::Range<f64> {
    let (lo, hi) = values
        .filter(|v| *v > 0.0 && v.is_finite())
        .fold((0.5f64, 2.0f64), |(lo, hi), v| (lo.min(v), hi.max(v)));
    (lo.log10() - 0.08)..(hi.log10() + 0.08)
}

/// The chart both figures share: one row per name (the first on top),
/// the x axis log₁₀ of a ratio over `x`, labelled by [`draw_log_ticks`].
fn named_rows<'a, 'b>(
    plot: &'a raystep_figure::ChartArea<'b>, root: &raystep_figure::ChartArea,
    names: &[&str], x: std::ops::Range<f64>, margin_right: u32,
    description: &str,
) -> Result<Chart<'a, 'b>, ChartError> {
    let n = names.len() as f64;
    let y = -0.6..(n - 0.4);
    let mut c = ChartBuilder::on(plot)
        .margin(10)
        .margin_right(margin_right)
        .x_label_area_size(50)
        .y_label_area_size(250)
        .build_cartesian_2d(x.clone(), y.clone())?;
    c.configure_mesh()
        .x_desc(description)
        .y_labels(names.len())
        .x_labels(0)
        .disable_x_mesh()
        .y_label_formatter(&|y| row_label(names, *y))
        .label_style(font(16.0))
        .axis_desc_style(font(15.0))
        .light_line_style(WHITE)
        .draw()?;
    draw_log_ticks(root, &mut c, &x, &y)?;
    // ratio 1: as costly as the sphere, or no gain from the bound
    c.draw_series(LineSeries::new(
        [(0.0, y.start), (0.0, y.end)],
        GREY.stroke_width(1),
    ))?;
    Ok(c)
}

/// The charts' plotting context: log₁₀ ratio across, rows down.
type Chart<'a, 'b> = ChartContext<
    'a,
    SVGBackend<'b>,
    Cartesian2d<RangedCoordf64, RangedCoordf64>,
>;

/// "Fast vs slow": each primitive's test against the sphere's.
pub fn costs_chart() -> Result<Figure, ChartError> {
    let rows: Vec<CostRow> = measured("ch08", "costs.csv")?;
    let sphere = |rays: &str| {
        rows.iter()
            .find(|r| r.primitive == "sphere" && r.rays == rays)
            .map(|r| r.nanos)
            .ok_or_else(|| format!("costs.csv: no sphere row for {rays}"))
    };
    let (hit, miss) = (sphere("hit")?, sphere("miss")?);
    let primitives = names(rows.iter().map(|r| r.primitive.as_str()));
    let height = 120 + 30 * primitives.len() as u32;
    chart(
        "costs-chart",
        "One ray–primitive test, relative to the sphere's (log scale; hits against the sphere's hits, misses against its misses). The hits are random lines that hit the object; the misses are near misses, random lines through its bounding sphere (grown by a quarter) that miss it: the misses a bound cannot turn away. Medians of 7 rounds on this machine, one thread; the numbers at the right are nanoseconds per test (hit / miss).",
        900,
        height,
        |area| draw_costs(area, &rows, &primitives, hit, miss),
    )
}

fn draw_costs(
    area: &raystep_figure::ChartArea, rows: &[CostRow], primitives: &[&str],
    sphere_hit: f64, sphere_miss: f64,
) -> Result<(), ChartError> {
    let (top, plot) = area.split_vertically(40);
    let entries = [("rays that hit it", HIT), ("rays that miss it", MISS)];
    legend(&top, &entries, 230, 260)?;
    let ratio = |r: &CostRow| {
        r.nanos
            / if r.rays == "hit" {
                sphere_hit
            } else {
                sphere_miss
            }
    };
    let x_range = ratio_range(rows.iter().map(ratio));
    let slot = |name: &str| row_of(primitives, name);
    let mut c = named_rows(
        &plot,
        area,
        primitives,
        x_range.clone(),
        150,
        "cost of one test ÷ the sphere's (log scale)",
    )?;
    for r in rows {
        let colour = if r.rays == "hit" { HIT } else { MISS };
        let dy = if r.rays == "hit" { -4 } else { 4 };
        dot(&mut c, (ratio(r).log10(), slot(&r.primitive)), dy, &colour)?;
    }
    // ns per test at the right
    let right = x_range.end;
    for name in primitives {
        let ns = |rays: &str| {
            rows.iter()
                .find(|r| r.primitive == *name && r.rays == rays)
                .map_or("–".to_string(), |r| format!("{:.0}", r.nanos))
        };
        let text = format!("{} / {} ns", ns("hit"), ns("miss"));
        note(&mut c, (right, slot(name)), 12, text, (15.0, &BLACK))?;
    }
    Ok(())
}

/// The speed-up from bounding: time per ray without a bound ÷ with it.
pub fn bounding_chart() -> Result<Figure, ChartError> {
    let rows: Vec<BoundingRow> = measured("ch08", "bounding.csv")?;
    let objects = names(rows.iter().map(|r| r.object.as_str()));
    let height = 130 + 34 * objects.len() as u32;
    chart(
        "bounding-chart",
        "What a bound saves: the time per ray of each object tested alone, divided by its time behind a bound (log scale; right of 1 the bound pays, left of 1 it costs). The same seeded random lines for every object and bound; the percentages at the right are the box's hits that miss the object.",
        900,
        height,
        |area| draw_bounding(area, &rows, &objects),
    )
}

fn draw_bounding(
    area: &raystep_figure::ChartArea, rows: &[BoundingRow], objects: &[&str],
) -> Result<(), ChartError> {
    let (top, plot) = area.split_vertically(40);
    let entries = BOUND_KINDS.map(|(_, colour, name)| (name, colour));
    legend(&top, &entries, 60, 270)?;
    let unbounded = |object: &str| {
        rows.iter()
            .find(|r| r.object == object && r.bound == "none")
            .map(|r| r.nanos)
    };
    let speed_ups: Vec<(&BoundingRow, f64)> = rows
        .iter()
        .filter(|r| r.bound != "none")
        .filter_map(|r| Some((r, unbounded(&r.object)? / r.nanos)))
        .collect();
    let x_range = ratio_range(speed_ups.iter().map(|(_, s)| *s));
    let slot = |name: &str| row_of(objects, name);
    let mut c = named_rows(
        &plot,
        area,
        objects,
        x_range.clone(),
        190,
        "speed-up: time per ray alone ÷ behind the bound (log scale)",
    )?;
    for (k, (kind, colour, _)) in BOUND_KINDS.iter().enumerate() {
        let dy = 6 * (k as i32 - 1);
        c.draw_series(speed_ups.iter().filter(|(r, _)| r.bound == *kind).map(
            |(r, s)| {
                EmptyElement::at((s.log10(), slot(&r.object)))
                    + Circle::new((0, dy), 6, colour.filled())
            },
        ))?;
    }
    let right = x_range.end;
    for name in objects {
        let Some(boxed) =
            rows.iter().find(|r| r.object == *name && r.bound == "box")
        else {
            continue;
        };
        let wasted = 100.0 * boxed.wasted_of_bound_hits();
        let text = format!("box: {wasted:.0} % wasted");
        note(&mut c, (right, slot(name)), 12, text, (15.0, &BLACK))?;
    }
    Ok(())
}
