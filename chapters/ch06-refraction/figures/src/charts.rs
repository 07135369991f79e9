//! The chart of chapter 06: how far Schlick's approximation and no Fresnel
//! split at all are from the exact Fresnel split, material by material,
//! against what they cost in render time and per call; drawn from
//! `book/src/figures/ch06/fresnel.csv` (written by `raystep measure`).
use raystep_figure::numbers::floored;
use raystep_figure::plotters::prelude::*;
use raystep_figure::{ChartError, Figure, chart, measured};

use crate::measurements::{CHART_MODES, FresnelRow};

/// Errors below this are drawn at the chart's floor (log axes have no 0).
const FLOOR: f64 = 0.01;

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

/// The chart, or an error naming the CSV file if it is missing or bad.
pub fn fresnel_chart() -> Result<Figure, ChartError> {
    let rows: Vec<FresnelRow> = measured("ch06", "fresnel.csv")?;
    chart(
        "fresnel-chart",
        "One ball of each material rendered with the exact Fresnel split, with Schlick's approximation and with no split: left, the RMSE against the exact image (8-bit levels); middle, that error against the measured render time; right, the measured time of one call of each reflectance formula.",
        1000,
        420,
        |area| draw(area, &rows),
    )
}

/// The RMSE as drawn: 0 sits on the floor.
fn rmse(row: &FresnelRow) -> f64 {
    row.rmse.max(FLOOR)
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

/// The name and index of the material on `slot`, or nothing between slots.
fn material_label(materials: &[(String, f64)], y: f64) -> String {
    let k = materials.len() as f64 - 1.0 - y.round();
    if (y - y.round()).abs() > 1e-6 || k < 0.0 || k >= materials.len() as f64 {
        return String::new();
    }
    let (name, ior) = &materials[k as usize];
    format!("{name} {ior}")
}

/// Each mode's marker a few px above or below the slot, so that equal
/// values stay visible side by side.
fn nudge(mode: usize) -> i32 {
    4 * (mode as i32 - 1)
}

fn draw(
    area: &raystep_figure::ChartArea,
    rows: &[FresnelRow],
) -> Result<(), ChartError> {
    // a legend strip across the top, then three panels
    let (legend, panels) = area.split_vertically(34);
    for (i, (name, colour)) in NAMES.iter().zip(COLOURS).enumerate() {
        let x = 90 + 300 * i as i32;
        legend.draw(&Circle::new((x + 12, 20), 5, colour.filled()))?;
        legend.draw(&Text::new(*name, (x + 26, 12), ("sans-serif", 15)))?;
    }
    let materials = materials(rows);
    let slots = -0.5..(materials.len() as f64 - 0.5);
    let labels = materials.len();
    let panels = panels.split_evenly((1, 3));
    let label_style = ("sans-serif", 14);
    let max_rmse = rows.iter().map(|r| r.rmse).fold(1.0, f64::max) * 2.0;
    let of_mode = |k: usize| {
        let name = CHART_MODES[k].0;
        rows.iter().filter(move |r| r.mode == name)
    };

    // Left: the error of each mode, material by material.
    let mut c = ChartBuilder::on(&panels[0])
        .caption("error against Fresnel::Exact", ("sans-serif", 17))
        .margin(10)
        .x_label_area_size(34)
        .y_label_area_size(96)
        .build_cartesian_2d((FLOOR..max_rmse).log_scale(), slots.clone())?;
    c.configure_mesh()
        .x_desc("RMSE, 8-bit levels (0 at the left)")
        .y_labels(labels)
        .x_label_formatter(&|y: &f64| floored(*y, FLOOR))
        .y_label_formatter(&|y| material_label(&materials, *y))
        .label_style(label_style)
        .light_line_style(WHITE)
        .draw()?;
    for (k, colour) in COLOURS.iter().enumerate() {
        c.draw_series(of_mode(k).map(|r| {
            EmptyElement::at((rmse(r), slot(&materials, r)))
                + Circle::new((0, nudge(k)), 4, colour.filled())
        }))?;
    }

    // Middle: every (material, mode) as a point: render time against error.
    let max_ms = rows.iter().map(|r| r.millis).fold(0.0, f64::max) * 1.1;
    let min_ms =
        rows.iter().map(|r| r.millis).fold(f64::INFINITY, f64::min) * 0.9;
    let mut c = ChartBuilder::on(&panels[1])
        .caption("accuracy against speed", ("sans-serif", 17))
        .margin(10)
        .x_label_area_size(34)
        .y_label_area_size(52)
        .build_cartesian_2d(min_ms..max_ms, (FLOOR..max_rmse).log_scale())?;
    c.configure_mesh()
        .x_desc("render time, ms (160×90, one thread)")
        .y_desc("RMSE, 8-bit levels (0 at the bottom)")
        .x_labels(5)
        .y_label_formatter(&|y: &f64| floored(*y, FLOOR))
        .label_style(label_style)
        .light_line_style(WHITE)
        .draw()?;
    for (k, colour) in COLOURS.iter().enumerate() {
        c.draw_series(
            of_mode(k)
                .map(|r| Circle::new((r.millis, rmse(r)), 4, colour.filled())),
        )?;
    }

    // Right: one call of each formula, material by material.
    let max_ns =
        rows.iter().map(|r| r.nanos_per_call).fold(0.0, f64::max) * 1.15;
    let mut c = ChartBuilder::on(&panels[2])
        .caption("one call of the reflectance", ("sans-serif", 17))
        .margin(10)
        .x_label_area_size(34)
        .y_label_area_size(96)
        .build_cartesian_2d(0f64..max_ns, slots)?;
    c.configure_mesh()
        .x_desc("ns per call (median of batches)")
        .x_labels(5)
        .y_labels(labels)
        .y_label_formatter(&|y| material_label(&materials, *y))
        .label_style(label_style)
        .light_line_style(WHITE)
        .draw()?;
    for (k, colour) in COLOURS.iter().enumerate() {
        c.draw_series(of_mode(k).map(|r| {
            EmptyElement::at((r.nanos_per_call, slot(&materials, r)))
                + Circle::new((0, nudge(k)), 4, colour.filled())
        }))?;
    }
    Ok(())
}
