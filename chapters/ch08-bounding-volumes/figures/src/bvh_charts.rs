//! Part 2's charts, drawn from the `bvh-*.csv` files `raystep measure`
//! writes: builders (build time against trace time, SAH cost against
//! trace time), brute force against the hierarchy as meshes grow, node
//! precision against leaks, and chapter 7's z-buffer against ray casting
//! through a hierarchy.
use raystep_figure::plots::{
    BLUE, GREEN, GREY, ORANGE, dot, label, legend, line_with_dots, log_log,
    log_range, note, padded_log_range, row_label,
};
use raystep_figure::plotters::prelude::*;
use raystep_figure::plotters::style::text_anchor::{HPos, Pos, VPos};
use raystep_figure::{
    ChartError, Figure, Labels, book_figures, chart, font, measured,
};

use crate::bvh_rows::{
    BRUTE, BVH, BuilderRow, PrecisionRow, RASTERIZE, RAYCAST_BRUTE,
    RAYCAST_BVH, ScalingRow, ZbufferRow,
};

/// The meshes of `bvh-builders.csv`, with their colours.
const MESHES: [(&str, RGBColor); 2] = [("bunny", BLUE), ("bunny-235k", ORANGE)];

/// The builder whose tree the SAH chart compares against.
const REFERENCE: &str = "SAH 16 bins";

/// Short builder names for point labels: `SAH 16 bins` → `SAH 16`.
fn short(builder: &str) -> String {
    builder
        .replace(" bins", "")
        .replace(" full sweep", " sweep")
}

/// Build time against trace time, one point per builder and mesh.
pub fn builders_chart() -> Result<Figure, ChartError> {
    let rows: Vec<BuilderRow> = measured("ch08", "bvh-builders.csv")?;
    chart(
        "bvh-builders",
        "Each builder's build time against the time its tree takes per incoherent ray (closest hit, f32 nodes, one thread, log–log; medians of the rounds on this machine), on the bunny (3 674 triangles) and on its 235 136-triangle version. Down is faster tracing, left is faster building.",
        900,
        700,
        |area| {
            let (top, plot) = area.split_vertically(40);
            legend(&top, &MESHES, 300, 220)?;
            let x = log_range(rows.iter().map(|r| r.build_ms));
            // close around the times, so that the crowded points spread
            let y =
                padded_log_range(rows.iter().map(|r| r.incoherent_ns), 1.15);
            let axis = [(x.start, y.start), (x.start, y.end)];
            let mut c = log_log(
                &plot,
                x,
                y,
                "build time, ms",
                "trace time per incoherent ray, ns",
            )?;
            let mut labels = Labels::new();
            // no label across the y axis and its numbers
            labels.avoid_line(&axis.map(|p| c.backend_coord(&p)));
            for r in &rows {
                let at = c.backend_coord(&(r.build_ms, r.incoherent_ns));
                labels.avoid_point(at, 6);
            }
            for (mesh, colour) in MESHES {
                let points = rows.iter().filter(|r| r.mesh == mesh);
                c.draw_series(points.clone().map(|r| {
                    Circle::new(
                        (r.build_ms, r.incoherent_ns),
                        6,
                        colour.filled(),
                    )
                }))?;
                for r in points {
                    let at = (r.build_ms, r.incoherent_ns);
                    label(&mut c, &mut labels, at, &short(&r.builder), &GREY)?;
                }
            }
            Ok(())
        },
    )
}

/// The SAH cost against the work and the time per ray, all relative to
/// the binned SAH's tree (16 bins) on the same mesh.
pub fn sah_chart() -> Result<Figure, ChartError> {
    let rows: Vec<BuilderRow> = measured("ch08", "bvh-builders.csv")?;
    let reference = |mesh: &str| {
        rows.iter()
            .find(|r| r.mesh == mesh && r.builder == REFERENCE)
            .ok_or_else(|| {
                format!(
                    "{}: no `{REFERENCE}` row for {mesh}",
                    book_figures().join("ch08/bvh-builders.csv").display()
                )
            })
    };
    let work = |r: &BuilderRow| r.incoherent_nodes + r.incoherent_triangles;
    // (row, SAH ratio, work ratio, time ratio, colour)
    let mut points: Vec<(&BuilderRow, f64, f64, f64, RGBColor)> = Vec::new();
    for (mesh, colour) in MESHES {
        let base = reference(mesh)?;
        for r in rows.iter().filter(|r| r.mesh == mesh) {
            points.push((
                r,
                r.sah_cost / base.sah_cost,
                work(r) / work(base),
                r.incoherent_ns / base.incoherent_ns,
                colour,
            ));
        }
    }
    chart(
        "bvh-sah",
        "Does a lower SAH cost trace faster? Each builder's tree: its SAH cost (the model's node visits and triangle tests for a ray that hits the root) against what an incoherent ray costs through it, both as ratios to the 16-bin SAH tree on the same mesh. Dots: the node visits and triangle tests counted per ray (the same on every machine); rings: the time measured per ray (one thread, medians; the machine's noise is a few per cent). On the grey diagonal the cost follows the SAH exactly.",
        900,
        620,
        |area| {
            let (top, plot) = area.split_vertically(40);
            legend(&top, &MESHES, 110, 170)?;
            // dots and rings
            top.draw(&Circle::new((500, 20), 6, GREY.filled()))?;
            top.draw(&Text::new("counted", (514, 11), font(16.0)))?;
            top.draw(&Circle::new((630, 20), 6, GREY.stroke_width(2)))?;
            top.draw(&Text::new("timed", (644, 11), font(16.0)))?;
            let all = points.iter().flat_map(|p| [p.1, p.2, p.3]);
            let (lo, hi) = all
                .fold((1.0f64, 1.0f64), |(lo, hi), v| (lo.min(v), hi.max(v)));
            let range = (lo - 0.03)..(hi + 0.03);
            let mut c = ChartBuilder::on(&plot)
                .margin(14)
                .margin_right(30)
                .x_label_area_size(58)
                .y_label_area_size(78)
                .build_cartesian_2d(range.clone(), range.clone())?;
            c.configure_mesh()
                .x_desc("SAH cost ÷ the 16-bin SAH tree's")
                .y_desc("cost per incoherent ray ÷ the 16-bin SAH tree's")
                .x_label_formatter(&|x| format!("{x:.2}"))
                .y_label_formatter(&|y| format!("{y:.2}"))
                .label_style(font(16.0))
                .axis_desc_style(font(16.0))
                .light_line_style(WHITE)
                .draw()?;
            let diagonal = [(range.start, range.start), (range.end, range.end)];
            c.draw_series(LineSeries::new(
                diagonal,
                RGBColor(200, 200, 200).stroke_width(2),
            ))?;
            let mut labels = Labels::new();
            labels.avoid_line(&diagonal.map(|p| c.backend_coord(&p)));
            for p in &points {
                labels.avoid_point(c.backend_coord(&(p.1, p.2)), 6);
                labels.avoid_point(c.backend_coord(&(p.1, p.3)), 6);
            }
            c.draw_series(
                points
                    .iter()
                    .map(|p| Circle::new((p.1, p.3), 6, p.4.stroke_width(2))),
            )?;
            c.draw_series(
                points
                    .iter()
                    .map(|p| Circle::new((p.1, p.2), 6, p.4.filled())),
            )?;
            for p in &points {
                if p.0.builder == REFERENCE {
                    continue; // at (1, 1), named by the axes
                }
                let name = short(&p.0.builder);
                label(&mut c, &mut labels, (p.1, p.2), &name, &p.4)?;
            }
            Ok(())
        },
    )
}

/// Time per ray against triangle count: brute force and the hierarchy.
pub fn scaling_chart() -> Result<Figure, ChartError> {
    let rows: Vec<ScalingRow> = measured("ch08", "bvh-scaling.csv")?;
    chart(
        "bvh-scaling",
        "Time per camera ray (closest hit, one thread) against the number of triangles: the bunny, then each triangle cut in four, three times (3 674 → 235 136), log–log. Brute force tests every triangle; the hierarchy (16-bin SAH, f32 nodes) a few boxes and triangles, printed beside each point: node visits + triangle tests per ray.",
        900,
        560,
        |area| {
            let (top, plot) = area.split_vertically(40);
            let entries = [("brute force", ORANGE), ("BVH", BLUE)];
            legend(&top, &entries, 300, 220)?;
            let x = log_range(rows.iter().map(|r| r.triangles as f64));
            let y = log_range(rows.iter().map(|r| r.ns_per_ray / 1e3));
            let mut c = log_log(
                &plot,
                x,
                y,
                "triangles in the mesh",
                "time per ray, µs",
            )?;
            for (method, colour) in [(BRUTE, ORANGE), (BVH, BLUE)] {
                let mut points: Vec<&ScalingRow> =
                    rows.iter().filter(|r| r.method == method).collect();
                points.sort_by_key(|r| r.triangles);
                let at =
                    |r: &ScalingRow| (r.triangles as f64, r.ns_per_ray / 1e3);
                let line: Vec<(f64, f64)> =
                    points.iter().map(|r| at(r)).collect();
                line_with_dots(&mut c, &line, colour, 6)?;
                for r in &points {
                    let work = r.nodes_per_ray + r.triangles_per_ray;
                    let text = if work >= 1000.0 {
                        raystep_figure::numbers::grouped(work.round() as u64)
                    } else {
                        format!("{work:.0}")
                    };
                    let style = font(15.0)
                        .color(&GREY)
                        .pos(Pos::new(HPos::Left, VPos::Top));
                    c.draw_series(std::iter::once(
                        EmptyElement::at(at(r))
                            + Text::new(text, (8, 6), style),
                    ))?;
                }
            }
            Ok(())
        },
    )
}

/// Node precision: speed against rays that leak through shared edges.
pub fn precision_chart() -> Result<Figure, ChartError> {
    let rows: Vec<PrecisionRow> = measured("ch08", "bvh-precision.csv")?;
    let edge_rays = rows.first().map_or(0, |r| r.edge_rays);
    chart(
        "bvh-precision",
        &format!(
            "The three node layouts of the fast walk: time per ray on the 235 136-triangle bunny (one thread; primary and incoherent rays), and, at the right, how many of {} rays aimed exactly at shared edges (of the bunny, the bunny moved far from the origin, and a tiled floor) leak through the surface.",
            raystep_figure::numbers::grouped(edge_rays)
        ),
        900,
        300,
        |area| {
            let (top, plot) = area.split_vertically(40);
            let entries = [("primary rays", BLUE), ("incoherent rays", ORANGE)];
            legend(&top, &entries, 230, 240)?;
            let max = rows
                .iter()
                .map(|r| r.primary_ns.max(r.incoherent_ns))
                .fold(0.0f64, f64::max);
            let n = rows.len() as f64;
            let mut c = ChartBuilder::on(&plot)
                .margin(10)
                .margin_right(230)
                .x_label_area_size(50)
                .y_label_area_size(190)
                .build_cartesian_2d(0.0..max * 1.1, -0.6..(n - 0.4))?;
            let names: Vec<String> = rows
                .iter()
                .map(|r| format!("{} nodes", r.precision))
                .collect();
            c.configure_mesh()
                .x_desc("time per ray, ns")
                .x_labels(6)
                .x_label_formatter(&|x| format!("{x:.0}"))
                .y_labels(rows.len())
                .disable_y_mesh()
                .y_label_formatter(&|y| row_label(&names, *y))
                .label_style(font(16.0))
                .axis_desc_style(font(16.0))
                .light_line_style(WHITE)
                .draw()?;
            for (k, r) in rows.iter().enumerate() {
                let y = n - 1.0 - k as f64;
                for (ns, colour, dy) in
                    [(r.primary_ns, BLUE, -4), (r.incoherent_ns, ORANGE, 4)]
                {
                    dot(&mut c, (ns, y), dy, &colour)?;
                }
                let [bunny, moved, floor] = r.leaks();
                let total = bunny + moved + floor;
                let text =
                    format!("leaks: {total} ({bunny} · {moved} · {floor})");
                note(&mut c, (max * 1.1, y), 14, text, (15.0, &BLACK))?;
            }
            Ok(())
        },
    )
}

/// Chapter 7's stages: the z-buffer, ray casting, and ray casting through
/// a hierarchy.
pub fn zbuffer_chart() -> Result<Figure, ChartError> {
    let rows: Vec<ZbufferRow> = measured("ch08", "bvh-zbuffer.csv")?;
    chart(
        "bvh-zbuffer",
        "Chapter 7's question answered: the time to draw one 160×90 image of chapter 7's scene (alone, with a ball of 20·4ⁿ triangles, n = 0 … 6, and with the bunny: the triangle markers) against its number of triangles, log–log, one thread. The z-buffer rasterizer; ray casting that tests every object (up to the ball of 5 132 triangles: beyond, chapter 7's chart has it); and ray casting through a hierarchy (16-bin SAH), whose build is timed apart and added in the hollow markers.",
        900,
        600,
        |area| {
            let (top, plot) = area.split_vertically(40);
            let methods = [
                (RASTERIZE, BLUE, "z-buffer"),
                (RAYCAST_BRUTE, ORANGE, "ray casting, every object"),
                (RAYCAST_BVH, GREEN, "ray casting, BVH"),
            ];
            let entries = methods.map(|(_, colour, name)| (name, colour));
            legend(&top, &entries, 90, 260)?;
            let x = log_range(rows.iter().map(|r| r.triangles as f64));
            let y = log_range(
                rows.iter().flat_map(|r| [r.millis, r.millis + r.build_ms]),
            );
            let (x_start, y_end) = (x.start, y.end);
            let mut c = log_log(
                &plot,
                x,
                y,
                "triangles in the scene",
                "time for one 160×90 image, ms",
            )?;
            for (method, colour, _) in methods {
                let mut points: Vec<&ZbufferRow> = rows
                    .iter()
                    .filter(|r| r.method == method && r.scene != "bunny")
                    .collect();
                points.sort_by_key(|r| r.triangles);
                let at = |r: &ZbufferRow| (r.triangles as f64, r.millis);
                let line: Vec<(f64, f64)> =
                    points.iter().map(|r| at(r)).collect();
                line_with_dots(&mut c, &line, colour, 5)?;
                if method == RAYCAST_BVH {
                    c.draw_series(points.iter().map(|r| {
                        Circle::new(
                            (r.triangles as f64, r.millis + r.build_ms),
                            5,
                            colour.stroke_width(2),
                        )
                    }))?;
                }
                if let Some(bunny) = rows
                    .iter()
                    .find(|r| r.method == method && r.scene == "bunny")
                {
                    c.draw_series(std::iter::once(TriangleMarker::new(
                        at(bunny),
                        8,
                        colour.filled(),
                    )))?;
                }
            }
            // the two other markers, explained in the empty upper left
            let key = |row: i32| (x_start * 1.5, y_end / 2f64.powi(row + 1));
            let style = font(15.0)
                .color(&BLACK)
                .pos(Pos::new(HPos::Left, VPos::Center));
            c.draw_series(std::iter::once(
                EmptyElement::at(key(0))
                    + Circle::new((0, 0), 5, GREEN.stroke_width(2))
                    + Text::new("BVH, build included", (14, 0), style.clone()),
            ))?;
            c.draw_series(std::iter::once(
                EmptyElement::at(key(1))
                    + TriangleMarker::new((0, 0), 8, GREY.filled())
                    + Text::new("the bunny", (14, 0), style),
            ))?;
            Ok(())
        },
    )
}
