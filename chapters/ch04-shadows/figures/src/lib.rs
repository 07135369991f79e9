//! Chapter 4 — shadows: the lecture's figures, charts and measurements, drawn
//! from the chapter's public API, and the chapter's entry in the command
//! line ([`CHAPTER`]).
mod charts;
mod diagrams;
pub mod measurements;
mod questions;

use raystep_figure::{Chapter, measurement, render_world};

/// What chapter 4 hands `raystep figures`, `measure`, `render` and `check`.
pub const CHAPTER: Chapter =
    Chapter::new("ch04-shadows", "Shadows", &["shadow", "normal_offset"])
        .stars(&[2, 2])
        .questions(questions::all)
        .figures(diagrams::all)
        .charts(&[charts::acne_chart])
        .measurements(&[measurement!(
            "ch04 acne",
            "acne.csv",
            |_| {
                (measurements::CHART_STRATEGIES.len()
                    * measurements::CHART_SCALES.len()) as u64
            },
            measurements::measure_acne
        )])
        // `raystep render` with chapter 4's tracer: shadow rays, with the
        // scale-aware offset against acne
        .renderer(|scene, file, options, accelerate| {
            render_world(
                ch03::world(scene, file),
                accelerate,
                options,
                |world| ch04::render(world, ch04::Offset::ScaleAware, options),
            )
        });
