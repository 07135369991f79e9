//! Chapter 9's charts, drawn from the `grid-*.csv` files `raystep
//! measure` writes: the resolution sweep, the grid beside the hierarchy
//! and brute force, and mailboxing.
use raystep_figure::plots::{
    BLUE, GREEN, GREY, ORANGE, Series, legend, line_with_dots, log_log,
    log_range, note, number_label, row_label, series_legend,
};
use raystep_figure::plotters::prelude::*;
use raystep_figure::{
    ChartArea, ChartError, DotRows, Figure, chart, font, measured,
};

use crate::rows::{BRUTE, BVH, CompareRow, GRID, MailboxRow, ResolutionRow};

/// The scene families, their names in the charts and their colours.
const FAMILIES: [Series; 3] = [
    Series::new("uniform-10000", "10 000 small triangles", BLUE),
    Series::new("bunny", "the bunny", GREEN),
    Series::new("stadium", "the bunny in a stadium", ORANGE),
];

/// Trace time and memory against the cells along the longest axis.
pub fn resolution_chart() -> Result<Figure, ChartError> {
    let rows: Vec<ResolutionRow> = measured("ch09", "grid-resolution.csv")?;
    chart(
        "grid-resolution",
        "Time per camera ray (closest hit, one thread; above) and the grid's memory with the triangles (below) against the cells along the scene's longest axis, log–log, for the three scene families; the ring marks the rule's choice, 3·∛N. Too few cells and every ray tests long lists; too many and it walks empty cells and the memory grows as the cube. For the bunny in its stadium no resolution helps much: the stadium is 200 times the bunny's size, and even 256 cells along it leave the bunny in a few cells.",
        900,
        720,
        |area| {
            let (top, rest) = area.split_vertically(40);
            series_legend(&top, &FAMILIES, 120, 250)?;
            let (upper, lower) = rest.split_vertically(370);
            let x = log_range(rows.iter().map(|r| r.longest as f64));
            let draw = |panel: &ChartArea,
                        y_desc: &str,
                        x_desc: &str,
                        value: &dyn Fn(&ResolutionRow) -> f64|
             -> Result<(), ChartError> {
                let y = log_range(rows.iter().map(value));
                let mut c = log_log(panel, x.clone(), y, x_desc, y_desc)?;
                for Series { key, colour, .. } in FAMILIES {
                    let mut points: Vec<&ResolutionRow> =
                        rows.iter().filter(|r| r.scene == key).collect();
                    points.sort_by_key(|r| r.longest);
                    let line: Vec<(f64, f64)> = points
                        .iter()
                        .map(|r| (r.longest as f64, value(r)))
                        .collect();
                    line_with_dots(&mut c, &line, colour, 5)?;
                    for r in points.iter().filter(|r| r.rule) {
                        let at = (r.longest as f64, value(r));
                        c.draw_series(std::iter::once(Circle::new(
                            at,
                            11,
                            colour.stroke_width(2),
                        )))?;
                    }
                }
                Ok(())
            };
            draw(&upper, "time per ray, ns", "", &|r| r.primary_ns)?;
            draw(&lower, "memory, MB", "cells along the longest axis", &|r| {
                r.bytes as f64 / 1e6
            })?;
            Ok(())
        },
    )
}

/// The scenes of the comparison, in the chart's order, with their names.
const SCENES: [(&str, &str); 5] = [
    ("uniform-1000", "1 000 small triangles"),
    ("uniform-10000", "10 000 small triangles"),
    ("uniform-100000", "100 000 small triangles"),
    ("bunny", "the bunny"),
    ("stadium", "the bunny in a stadium"),
];

/// The methods of the comparison with their colours.
const METHODS: [(&str, RGBColor); 3] =
    [(BRUTE, GREY), (BVH, BLUE), (GRID, ORANGE)];

/// Brute force, the BVH and the grid on every scene: trace times, build
/// time, memory.
pub fn compare_chart() -> Result<Figure, ChartError> {
    let rows: Vec<CompareRow> = measured("ch09", "grid-vs-bvh.csv")?;
    chart(
        "grid-vs-bvh",
        "Brute force (grey), the BVH of chapter 8 (16-bin SAH, f32 nodes; blue) and the grid (the rule, exact fill; orange) on the chapter's scenes, one thread, log scales: time per camera ray and per incoherent ray, time to build, and memory (the structure with the triangles it reads). Small triangles spread evenly are the grid's case: it matches or beats the BVH there. In the stadium the camera looks at the bunny: the grid walks into the cells that hold the whole bunny and tests hundreds of triangles per ray.",
        900,
        640,
        |area| {
            let (top, rest) = area.split_vertically(40);
            legend(&top, &METHODS, 200, 200)?;
            let panels = rest.split_evenly((2, 2));
            let specs: [(&str, &Value); 4] = [
                ("camera rays: µs per ray", &|r| r.primary_ns / 1e3),
                ("incoherent rays: µs per ray", &|r| r.incoherent_ns / 1e3),
                ("build, ms", &|r| r.build_ms),
                ("memory, MB", &|r| r.bytes as f64 / 1e6),
            ];
            for (k, (panel, (desc, value))) in
                panels.iter().zip(specs).enumerate()
            {
                dot_panel(panel, &rows, desc, value, k % 2 == 0)?;
            }
            Ok(())
        },
    )
}

/// A number read off a row.
type Value = dyn Fn(&CompareRow) -> f64;

/// One panel of the comparison: a row per scene, a dot per method, the
/// value on a log axis.
fn dot_panel(
    panel: &ChartArea, rows: &[CompareRow], desc: &str, value: &Value,
    names: bool,
) -> Result<(), ChartError> {
    let dots = DotRows {
        names: &SCENES.map(|(_, name)| name),
        names_width: 175,
        colours: &METHODS.map(|(_, colour)| colour),
        spacing: 6,
        x_labels: 5,
        x_label: &number_label,
    };
    let x = log_range(rows.iter().map(value));
    dots.panel(panel, desc, x, names, &|k, m| {
        let (scene, method) = (SCENES[k].0, METHODS[m].0);
        let r = rows
            .iter()
            .find(|r| r.scene == scene && r.method == method)?;
        Some((value(r), false))
    })
}

/// The rows of the mailbox chart: scene and fill.
fn mailbox_name(r: &MailboxRow) -> String {
    let scene = Series::name_of(&FAMILIES, &r.scene);
    format!("{scene}, {} fill", r.fill)
}

/// Triangle tests per ray with the mailbox off and on, and the time.
pub fn mailbox_chart() -> Result<Figure, ChartError> {
    let rows: Vec<MailboxRow> = measured("ch09", "grid-mailbox.csv")?;
    chart(
        "grid-mailbox",
        "Triangle tests per incoherent ray (closest hit) through the grid at the rule's resolution, without a mailbox (orange) and with the hashed mailbox of 32 slots (blue); the pale end of each bar counts the tests of a triangle the ray had already tested. At the right, the time per ray without → with the mailbox (one thread). The mailbox removes nearly every repeat, but a repeated test of a small triangle is cheap: the time changes far less than the count. Filling cells exactly (the triangle–box test) lists each triangle in fewer cells, so there are fewer repeats to begin with.",
        900,
        380,
        |area| {
            let (top, plot) = area.split_vertically(40);
            let entries = [("mailbox off", ORANGE), ("mailbox on", BLUE)];
            legend(&top, &entries, 330, 200)?;
            let n = rows.len() as f64;
            let max = rows.iter().map(|r| r.tests_off).fold(0.0f64, f64::max);
            let mut c = ChartBuilder::on(&plot)
                .margin(10)
                .margin_right(190)
                .x_label_area_size(48)
                .y_label_area_size(330)
                .build_cartesian_2d(0.0..max * 1.08, -0.6..(n - 0.4))?;
            let names: Vec<String> = rows.iter().map(mailbox_name).collect();
            c.configure_mesh()
                .x_desc("triangle tests per ray")
                .x_labels(6)
                .x_label_formatter(&|x| format!("{x:.0}"))
                .y_labels(rows.len())
                .disable_y_mesh()
                .y_label_formatter(&|y| row_label(&names, *y))
                .label_style(font(15.0))
                .axis_desc_style(font(15.0))
                .light_line_style(WHITE)
                .draw()?;
            for (k, r) in rows.iter().enumerate() {
                let y = n - 1.0 - k as f64;
                for (tests, repeats, colour, dy) in [
                    (r.tests_off, r.repeats_off, ORANGE, 0.17),
                    (r.tests_on, r.repeats_on, BLUE, -0.17),
                ] {
                    let first = tests - repeats;
                    c.draw_series(std::iter::once(Rectangle::new(
                        [(0.0, y + dy - 0.13), (first, y + dy + 0.13)],
                        colour.filled(),
                    )))?;
                    c.draw_series(std::iter::once(Rectangle::new(
                        [(first, y + dy - 0.13), (tests, y + dy + 0.13)],
                        colour.mix(0.35).filled(),
                    )))?;
                }
                let text = format!("{:.0} → {:.0} ns", r.ns_off, r.ns_on);
                note(&mut c, (max * 1.08, y), 12, text, (14.0, &GREY))?;
            }
            Ok(())
        },
    )
}
