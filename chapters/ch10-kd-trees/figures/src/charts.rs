//! Chapter 10's charts, drawn from the CSV files `raystep measure`
//! writes: build time against N, and which structure each scene family
//! needs (totals for 1, 10³ and 10⁶ rays; what each costs).
use raystep_figure::plots::{
    BLUE, GREEN, GREY, ORANGE, Series, line_with_dots, log_log, log_range,
    number_label, padded_log_range, series_legend,
};
use raystep_figure::plotters::prelude::*;
use raystep_figure::{
    ChartArea, ChartError, DotRows, Figure, chart, font, measured,
};

use crate::rows::{BuildRow, StructureRow};

/// The builders of the build chart, their names and colours.
const BUILDERS: [Series; 4] = [
    Series::new("median", "median", GREY),
    Series::new("SAH sorting", "SAH, sorting at every node", ORANGE),
    Series::new("SAH events", "SAH, events sorted once", BLUE),
    Series::new("SAH events perfect", "the same, perfect splits", GREEN),
];

/// Build time against triangles, and the time per triangle.
pub fn build_chart() -> Result<Figure, ChartError> {
    let rows: Vec<BuildRow> = measured("ch10", "kd-build.csv")?;
    chart(
        "kd-build",
        "Time to build a kd-tree over N small triangles spread evenly (one thread, medians of the rounds; above, log–log) and the same time per triangle (below, µs, log N across). Sorting every node's candidate planes anew costs O(N log² N), events sorted once at the root and split in order O(N log N): measured, the event build is 1.05–1.5 times faster, the gap widening with N, and its time per triangle climbs less. The median tree looks at no object and is cheapest per node; perfect splits clip every cut triangle again.",
        900,
        700,
        |area| {
            let (top, rest) = area.split_vertically(70);
            let (first, second) = top.split_vertically(35);
            series_legend(&first, &BUILDERS[..2], 150, 330)?;
            series_legend(&second, &BUILDERS[2..], 150, 330)?;
            let (upper, lower) = rest.split_vertically(330);
            let x = log_range(rows.iter().map(|r| r.triangles as f64));
            let y = log_range(rows.iter().map(|r| r.build_ms));
            let mut c = log_log(&upper, x.clone(), y, "", "build, ms")?;
            for Series { key, colour, .. } in BUILDERS {
                let line: Vec<(f64, f64)> = rows
                    .iter()
                    .filter(|r| r.builder == key)
                    .map(|r| (r.triangles as f64, r.build_ms))
                    .collect();
                line_with_dots(&mut c, &line, colour, 5)?;
            }
            let per = |r: &BuildRow| r.build_ms * 1e3 / r.triangles as f64;
            let top_per = rows.iter().map(per).fold(0.0, f64::max) * 1.1;
            let mut c = ChartBuilder::on(&lower)
                .margin(10)
                .margin_right(24)
                .x_label_area_size(48)
                .y_label_area_size(70)
                .build_cartesian_2d(x.log_scale(), 0.0..top_per)?;
            c.configure_mesh()
                .x_desc("triangles N")
                .y_desc("µs per triangle")
                .x_label_formatter(&number_label)
                .label_style(font(14.0))
                .axis_desc_style(font(15.0))
                .light_line_style(WHITE)
                .draw()?;
            for Series { key, colour, .. } in BUILDERS {
                let line: Vec<(f64, f64)> = rows
                    .iter()
                    .filter(|r| r.builder == key)
                    .map(|r| (r.triangles as f64, per(r)))
                    .collect();
                c.draw_series(LineSeries::new(
                    line.clone(),
                    colour.stroke_width(2),
                ))?;
                c.draw_series(
                    line.iter().map(|&p| Circle::new(p, 5, colour.filled())),
                )?;
            }
            Ok(())
        },
    )
}

/// The scene families, in the charts' order, with their names.
pub const FAMILIES: [(&str, &str); 7] = [
    ("handful", "3 spheres and a plane"),
    ("primitives", "chapter 8's 10 primitives"),
    ("spheres-1000", "1 000 small spheres"),
    ("uniform-10000", "10 000 small triangles"),
    ("bunny", "the bunny (3 674)"),
    ("stadium", "bunny in a stadium"),
    ("bunny-235k", "the bunny (235 000)"),
];

/// The structures with their names and colours.
const METHODS: [Series; 4] = [
    Series::new("brute", "brute force", GREY),
    Series::new("bvh", "BVH", BLUE),
    Series::new("grid", "grid", ORANGE),
    Series::new("kdtree", "kd-tree", GREEN),
];

/// An axis label that keeps small numbers: 0.0001, 0.01, 3, 12 000.
fn small_label(x: &f64) -> String {
    if *x > 0.0 && *x < 0.01 {
        let places = (-x.log10()).ceil() as usize;
        format!("{x:.places$}")
    } else {
        number_label(x)
    }
}

/// A number read off a row.
type Value = dyn Fn(&StructureRow) -> f64;

/// One panel: a row per family, a dot per structure on a log axis; a
/// ring around the rule's choice.
fn dot_panel(
    panel: &ChartArea, rows: &[StructureRow], desc: &str, value: &Value,
    names: bool,
) -> Result<(), ChartError> {
    let dots = DotRows {
        names: &FAMILIES.map(|(_, name)| name),
        names_width: 200,
        colours: &METHODS.map(|s| s.colour),
        spacing: 8,
        x_labels: 4,
        x_label: &small_label,
    };
    let x = padded_log_range(rows.iter().map(value).filter(|v| *v > 0.0), 3.0);
    dots.panel(panel, desc, x, names, &|k, m| {
        let (scene, method) = (FAMILIES[k].0, METHODS[m].key);
        let r = rows
            .iter()
            .find(|r| r.scene == scene && r.method == method)?;
        Some((value(r), r.chosen))
    })
}

fn method_legend(top: &ChartArea) -> Result<(), ChartError> {
    series_legend(top, &METHODS, 120, 150)?;
    top.draw(&Circle::new((735, 20), 11, BLACK.stroke_width(2)))?;
    top.draw(&Text::new("the rule's choice", (752, 11), font(16.0)))?;
    Ok(())
}

/// Which structure each family needs: the total time to build it and
/// trace 1, 10³ and 10⁶ rays.
pub fn which_chart() -> Result<Figure, ChartError> {
    let rows: Vec<StructureRow> = measured("ch10", "which-structure.csv")?;
    chart(
        "which-structure",
        "Which structure a scene needs: the time to build it and then trace 1, 1 000 and 1 000 000 rays (closest hits, half camera rays, half incoherent; one thread, log scales), for brute force (grey), chapter 8's BVH (16-bin SAH; blue), chapter 9's grid (orange) and the kd-tree (SAH, events; green), on the tracers' own path (objects, double precision). For one ray nothing pays its build but brute force; for a million, every structure beats brute force above a handful of objects. The black ring marks the structure chapter 10's rule picks.",
        900,
        560,
        |area| {
            let (top, rest) = area.split_vertically(40);
            method_legend(&top)?;
            let panels = rest.split_horizontally(440);
            let (first, others) = panels;
            let others = others.split_evenly((1, 2));
            let specs: [(&str, &Value); 3] = [
                ("1 ray: ms", &|r| r.total_ms(1.0)),
                ("1 000 rays: ms", &|r| r.total_ms(1e3)),
                ("10⁶ rays: s", &|r| r.total_ms(1e6) / 1e3),
            ];
            dot_panel(&first, &rows, specs[0].0, specs[0].1, true)?;
            for (panel, (desc, value)) in others.iter().zip(&specs[1..]) {
                dot_panel(panel, &rows, desc, *value, false)?;
            }
            Ok(())
        },
    )
}

/// What each structure costs on each family: trace times, build, memory.
pub fn costs_chart() -> Result<Figure, ChartError> {
    let rows: Vec<StructureRow> = measured("ch10", "which-structure.csv")?;
    chart(
        "structure-costs",
        "The measurements behind the totals: time per camera ray and per incoherent ray (µs, closest hit, one thread), time to build (ms) and the structure's memory (MB, without the objects), log scales. Brute force builds nothing and keeps nothing; the black ring marks the rule's choice.",
        900,
        640,
        |area| {
            let (top, rest) = area.split_vertically(40);
            method_legend(&top)?;
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
