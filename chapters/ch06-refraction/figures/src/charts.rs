//! The chart of chapter 6: how far Schlick's approximation and no Fresnel
//! split at all are from the exact Fresnel split, material by material,
//! against what they cost in render time and per call; drawn from
//! `book/src/figures/ch06/fresnel.csv` (written by `raystep measure`).
use raystep_figure::plots::{accuracy_against_speed, row_label};
use raystep_figure::plotters::prelude::*;
use raystep_figure::{
    AxisBreak, ChartError, Figure, Labels, LogAxis, Spot, chart, font, measured,
};

use crate::measurements::{CHART_MODES, FresnelRow};

/// One colour per mode, in [`CHART_MODES`] order (Okabe–Ito, colour-blind
/// safe): exact black, Schlick orange, off blue.
const COLOURS: [RGBColor; 3] = [
    RGBColor(0, 0, 0),
    RGBColor(230, 159, 0),
    RGBColor(0, 114, 178),
];

/// The legend's names of the modes, in [`CHART_MODES`] order.
const NAMES: [&str; 3] = [
    "Fresnel::Exact (the reference)",
    "Fresnel::Schlick",
    "Fresnel::Off (constant kt)",
];

/// How far apart the modes' lanes in the row of 0 are, in decades.
const LANE: f64 = 0.18;

/// The chart, or an error naming the CSV file if it is missing or bad.
pub fn fresnel_chart() -> Result<Figure, ChartError> {
    let rows: Vec<FresnelRow> = measured("ch06", "fresnel.csv")?;
    chart(
        "fresnel-chart",
        "One ball of each material rendered with the exact Fresnel split, with Schlick's approximation and with no split: top left, the RMSE against the exact image (8-bit levels); top right, the measured time of one call of each reflectance formula; below, the error against the measured render time.",
        900,
        800,
        |area| draw(area, &rows),
    )
}

/// The materials in the CSV, by index of refraction: (name, index).
fn materials(rows: &[FresnelRow]) -> Vec<(String, f64)> {
    let mut found: Vec<(String, f64)> = Vec::new();
    for r in rows {
        if !found.iter().any(|(name, _)| *name == r.material) {
            found.push((r.material.clone(), r.ior));
        }
    }
    found.sort_by(|a, b| a.1.total_cmp(&b.1));
    found
}

/// A material's row on the two panels that list the materials: the lowest
/// index on top.
fn slot(materials: &[(String, f64)], row: &FresnelRow) -> f64 {
    let k = materials
        .iter()
        .position(|(name, _)| *name == row.material)
        .unwrap_or(0);
    (materials.len() - 1 - k) as f64
}

/// Each mode's marker a few px above or below the slot, so that equal
/// values stay visible side by side.
fn nudge(mode: usize) -> i32 {
    5 * (mode as i32 - 1)
}

fn draw(
    area: &raystep_figure::ChartArea, rows: &[FresnelRow],
) -> Result<(), ChartError> {
    // a legend strip across the top, two panels by material, and the
    // accuracy against speed below them
    let (legend, panels) = area.split_vertically(64);
    for (i, (name, colour)) in NAMES.iter().zip(COLOURS).enumerate() {
        let x = [20, 330, 560][i];
        legend.draw(&Circle::new((x + 8, 18), 5, colour.filled()))?;
        legend.draw(&Text::new(*name, (x + 22, 9), font(16.0)))?;
    }
    legend.draw(&Text::new(
        "0: no error at all (Fresnel::Exact is the reference); in the lower chart each mode has a line of its own at 0",
        (20, 40),
        font(15.0),
    ))?;
    let (top, bottom) = panels.split_vertically(380);
    let (left, right) = top.split_horizontally(450);
    let materials = materials(rows);
    let slots = -0.5..(materials.len() as f64 - 0.5);
    let labels = materials.len();
    // the name and index of the material on each slot
    let names: Vec<String> = materials
        .iter()
        .map(|(name, ior)| format!("{name} {ior}"))
        .collect();
    let errors = LogAxis::covering(rows.iter().map(|r| r.rmse));
    let of_mode = |k: usize| {
        let name = CHART_MODES[k].0;
        rows.iter().filter(move |r| r.mode == name)
    };

    // Left: the error of each mode, material by material.
    let mut c = ChartBuilder::on(&left)
        .caption("error against Fresnel::Exact", font(17.0))
        .margin(10)
        .x_label_area_size(52)
        .y_label_area_size(136)
        .build_cartesian_2d(errors.range(), slots.clone())?;
    c.configure_mesh()
        .x_desc("RMSE, 8-bit levels")
        .y_labels(labels)
        .x_label_formatter(&|x| errors.label(x))
        .y_label_formatter(&|y| row_label(&names, *y))
        .label_style(font(16.0))
        .axis_desc_style(font(15.0))
        .light_line_style(WHITE)
        .draw()?;
    if let Some(at) = errors.break_at() {
        c.draw_series([AxisBreak::x((at, slots.start))])?;
    }
    for (k, colour) in COLOURS.iter().enumerate() {
        c.draw_series(of_mode(k).map(|r| {
            EmptyElement::at((errors.at(r.rmse), slot(&materials, r)))
                + Circle::new((0, nudge(k)), 5, colour.filled())
        }))?;
    }

    // Right: one call of each formula, material by material.
    let max_ns =
        rows.iter().map(|r| r.nanos_per_call).fold(0.0, f64::max) * 1.15;
    let mut c = ChartBuilder::on(&right)
        .caption("one call of the reflectance", font(17.0))
        .margin(10)
        .margin_right(24)
        .x_label_area_size(52)
        .y_label_area_size(136)
        .build_cartesian_2d(0f64..max_ns, slots)?;
    c.configure_mesh()
        .x_desc("ns per call (median of batches)")
        .x_labels(5)
        .y_labels(labels)
        .x_label_formatter(&|x| format!("{x:.0}"))
        .y_label_formatter(&|y| row_label(&names, *y))
        .label_style(font(16.0))
        .axis_desc_style(font(15.0))
        .light_line_style(WHITE)
        .draw()?;
    for (k, colour) in COLOURS.iter().enumerate() {
        c.draw_series(of_mode(k).map(|r| {
            EmptyElement::at((r.nanos_per_call, slot(&materials, r)))
                + Circle::new((0, nudge(k)), 5, colour.filled())
        }))?;
    }

    // Below: every (material, mode) as a point: render time against error,
    // the zeros of each mode on a lane of their own.
    let millis = rows.iter().map(|r| r.millis);
    let mut c =
        accuracy_against_speed(&bottom, millis, &errors, "RMSE, 8-bit levels")?;
    let at = |k: usize, r: &FresnelRow| {
        let y = if r.rmse == 0.0 {
            errors.zero_row() + LANE * (1.0 - k as f64)
        } else {
            errors.at(r.rmse)
        };
        (r.millis, y)
    };
    let mut placed = Labels::new();
    for k in 0..COLOURS.len() {
        for r in of_mode(k) {
            placed.avoid_point(c.backend_coord(&at(k, r)), 6);
        }
    }
    for (k, colour) in COLOURS.iter().enumerate() {
        c.draw_series(
            of_mode(k).map(|r| Circle::new(at(k, r), 5, colour.filled())),
        )?;
    }
    // Each point named by its material, where a name fits beside it.
    let size = 13.0;
    for (k, colour) in COLOURS.iter().enumerate() {
        for r in of_mode(k) {
            let point = at(k, r);
            let spots =
                [Spot::E, Spot::W, Spot::N, Spot::S, Spot::NE, Spot::SE];
            let Some((offset, pos)) = placed.place(
                c.backend_coord(&point),
                &r.material,
                size,
                &spots,
            ) else {
                continue;
            };
            let style = font(size).color(colour).pos(pos);
            c.draw_series(std::iter::once(
                EmptyElement::at(point)
                    + Text::new(r.material.clone(), offset, style),
            ))?;
        }
    }
    Ok(())
}
