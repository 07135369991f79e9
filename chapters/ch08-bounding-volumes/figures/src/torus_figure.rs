//! The torus's quartic along one grazing ray from far away: f(t) near the
//! torus, and the roots each solver finds.
use raystep_figure::plotters::prelude::*;
use raystep_figure::{Figure, chart, font};

use ch08::{DVec3, Ray, Torus, TorusSolver};

/// The torus of the figure: R = 1, r = 0.35, around the y axis.
const MAJOR: f64 = 1.0;
const MINOR: f64 = 0.35;
/// How far the ray starts from the torus's centre.
pub const DISTANCE: f64 = 1.0e4;
/// How far inside the outer rim the ray passes: two roots 2·√(2(R+r)ε)
/// apart, almost a double root.
pub const GRAZE: f64 = 1.0e-4;

/// The grazing ray: along x, in the torus's equator plane, `GRAZE` inside
/// its outer rim, starting `DISTANCE` away.
pub fn grazing_ray() -> Ray {
    Ray::new(DVec3::new(-DISTANCE, 0.0, MAJOR + MINOR - GRAZE), DVec3::X)
}

/// The torus's implicit function at `p` (torus frame), evaluated at the
/// point itself: accurate near the torus, wherever the ray started.
fn implicit(p: DVec3) -> f64 {
    let q = p.length_squared() + MAJOR * MAJOR - MINOR * MINOR;
    q * q - 4.0 * MAJOR * MAJOR * (p.x * p.x + p.z * p.z)
}

/// The figure.
pub fn torus_roots() -> Figure {
    let ray = grazing_ray();
    let torus = |solver| {
        Torus::new(DVec3::ZERO, DVec3::Y, MAJOR, MINOR, solver)
            .expect("a ring torus")
    };
    let closed = torus(TorusSolver::ClosedForm).roots(&ray);
    let bracketed = torus(TorusSolver::Bracketed).roots(&ray);
    // the two true roots, where the ray crosses the rim: x = ±√(…)
    let rim = MAJOR + MINOR;
    let z = rim - GRAZE;
    let half = (rim * rim - z * z).sqrt();
    let exact = [DISTANCE - half, DISTANCE + half];
    let caption = format!(
        "The torus's quartic f(t) along one ray that grazes the outer rim ({GRAZE:e} inside it) from {DISTANCE:e} away: f is evaluated at each point of the ray, its two roots are {:.6} apart. Ferrari's closed form, solving the quartic written from the far origin, finds {} root(s); the bracketed method, which moves the origin to the torus's box first, finds {}. Left: the whole stretch of the ray inside the box; right: around the two roots.",
        exact[1] - exact[0],
        closed.len(),
        bracketed.len(),
    );
    chart("torus-roots", &caption, 900, 400, |area| {
        let (legend, plots) = area.split_vertically(34);
        legend.draw(&Circle::new(
            (250, 17),
            7,
            RGBColor(0, 114, 178).stroke_width(2),
        ))?;
        legend.draw(&Text::new("bracketed roots", (264, 8), font(15.0)))?;
        legend.draw(&Cross::new(
            (470, 17),
            6,
            RGBColor(213, 94, 0).stroke_width(2),
        ))?;
        let closed_label = if closed.is_empty() {
            "closed-form roots (it finds none)".to_string()
        } else {
            format!("closed-form roots ({} found)", closed.len())
        };
        legend.draw(&Text::new(closed_label, (484, 8), font(15.0)))?;
        let (left, right) = plots.split_horizontally(450);
        let panels = [
            (&left, MAJOR + MINOR, "the ray across the torus's box"),
            (&right, 2.5 * half, "around the rim: two close roots"),
        ];
        for (panel, reach, title) in panels {
            let (t0, t1) = (DISTANCE - reach, DISTANCE + reach);
            let samples: Vec<(f64, f64)> = (0..=400)
                .map(|k| {
                    let t = t0 + (t1 - t0) * f64::from(k) / 400.0;
                    // the point itself, not ray.at(t): at t ≈ 10⁴ the
                    // product would round the point by ~10⁻¹²
                    let s = t - DISTANCE;
                    (s, implicit(DVec3::new(s, 0.0, ray.origin.z)))
                })
                .collect();
            let (lo, hi) =
                samples.iter().fold((0.0f64, 0.0f64), |(lo, hi), (_, f)| {
                    (lo.min(*f), hi.max(*f))
                });
            let pad = 0.08 * (hi - lo).max(1e-300);
            let mut c = ChartBuilder::on(panel)
                .caption(title, font(16.0))
                .margin(12)
                .margin_right(24)
                .x_label_area_size(48)
                .y_label_area_size(76)
                .build_cartesian_2d(-reach..reach, (lo - pad)..(hi + pad))?;
            c.configure_mesh()
                .x_desc("t − 10 000 (the ray starts 10 000 away)")
                .y_desc("f(t)")
                .x_labels(5)
                .y_labels(5)
                .x_label_formatter(&|x| axis_number(*x))
                .y_label_formatter(&|y| axis_number(*y))
                .label_style(font(13.0))
                .axis_desc_style(font(14.0))
                .light_line_style(WHITE)
                .draw()?;
            c.draw_series(LineSeries::new(
                [(-reach, 0.0), (reach, 0.0)],
                RGBColor(150, 150, 150).stroke_width(1),
            ))?;
            c.draw_series(LineSeries::new(
                samples,
                RGBColor(0, 0, 0).stroke_width(2),
            ))?;
            // the roots in the panel, in its coordinate t − DISTANCE
            let shown = |roots: &[f64]| -> Vec<f64> {
                roots
                    .iter()
                    .map(|t| t - DISTANCE)
                    .filter(|s| s.abs() <= reach * 1.001)
                    .collect()
            };
            let blue = RGBColor(0, 114, 178).stroke_width(2);
            let vermilion = RGBColor(213, 94, 0).stroke_width(2);
            c.draw_series(
                shown(&bracketed)
                    .into_iter()
                    .map(|s| Circle::new((s, 0.0), 7, blue)),
            )?;
            c.draw_series(
                shown(&closed)
                    .into_iter()
                    .map(|s| Cross::new((s, 0.0), 6, vermilion)),
            )?;
        }
        Ok(())
    })
    .expect("the torus figure draws")
}

/// A tick label: `0` for rounding noise, else three significant digits.
fn axis_number(v: f64) -> String {
    if v.abs() < 1e-12 {
        "0".to_string()
    } else if (0.01..1000.0).contains(&v.abs()) {
        let digits = (2 - v.abs().log10().floor() as i32).max(0) as usize;
        let text = format!("{v:.digits$}");
        if text.contains('.') {
            text.trim_end_matches('0').trim_end_matches('.').to_string()
        } else {
            text
        }
    } else {
        let exponent = v.abs().log10().floor() as i32;
        format!("{:.1}e{exponent}", v / 10f64.powi(exponent))
    }
}
