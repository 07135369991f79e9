//! The chart of chapter 7: the time each method takes to draw the same
//! scene against its number of triangles, on log–log axes, with each
//! method's fitted growth; drawn from `book/src/figures/ch07/scaling.csv`
//! (written by `raystep measure`).
use raystep_figure::decade;
use raystep_figure::plotters::element::DashedPathElement;
use raystep_figure::plotters::prelude::*;
use raystep_figure::plotters::style::text_anchor::{HPos, Pos, VPos};
use raystep_figure::{ChartError, Figure, book_figures, chart, font, measured};

use crate::measurements::{CHART_SIZE, RASTERIZE, RAYCAST, ScalingRow};

/// The scene of the bunny in the CSV: drawn apart, and left out of the fits.
const BUNNY: &str = "bunny";

/// Ray casting and rasterizing (Okabe–Ito, colour-blind safe).
const RAYCAST_COLOUR: RGBColor = RGBColor(213, 94, 0);
const RASTERIZE_COLOUR: RGBColor = RGBColor(0, 114, 178);
const GREY: RGBColor = RGBColor(90, 90, 90);

/// A power law `time ≈ a·Nᵇ`, fitted by least squares to the points'
/// logarithms: a straight line on log–log axes, of slope `b`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PowerFit {
    /// The time at N = 1, in the points' unit.
    pub a: f64,
    /// The growth exponent: N ten times larger, time 10ᵇ times longer.
    pub b: f64,
}

impl PowerFit {
    /// The least-squares line through (ln N, ln t) of `points` (N, t), all
    /// positive; None for fewer than two distinct N.
    pub fn of(points: &[(f64, f64)]) -> Option<PowerFit> {
        let logs: Vec<(f64, f64)> =
            points.iter().map(|&(n, t)| (n.ln(), t.ln())).collect();
        let count = logs.len() as f64;
        let mean_x = logs.iter().map(|p| p.0).sum::<f64>() / count;
        let mean_y = logs.iter().map(|p| p.1).sum::<f64>() / count;
        let sxx: f64 = logs.iter().map(|p| (p.0 - mean_x).powi(2)).sum();
        let sxy: f64 =
            logs.iter().map(|p| (p.0 - mean_x) * (p.1 - mean_y)).sum();
        if sxx <= 0.0 || !sxx.is_finite() {
            return None;
        }
        let b = sxy / sxx;
        Some(PowerFit {
            a: (mean_y - b * mean_x).exp(),
            b,
        })
    }

    /// The fitted time at `n`.
    pub fn at(self, n: f64) -> f64 {
        self.a * n.powf(self.b)
    }
}

/// A fixed cost plus a cost per triangle, `time ≈ fixed + per_triangle·N`,
/// fitted by least squares on the relative error (every point counts the
/// same, whether it took a millisecond or ten seconds). The rasterizer's
/// model: its time is not a power law.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CostFit {
    /// The time at N = 0, in the points' unit.
    pub fixed: f64,
    /// The time each triangle adds.
    pub per_triangle: f64,
}

impl CostFit {
    /// The fit to `points` (N, t), t positive: minimises Σ ((fixed +
    /// per_triangle·N − t) / t)²; None for fewer than two distinct N.
    pub fn of(points: &[(f64, f64)]) -> Option<CostFit> {
        // the normal equations of the weighted problem, weights 1/t²
        let (mut s, mut sn, mut snn, mut st, mut snt) =
            (0.0, 0.0, 0.0, 0.0, 0.0);
        for &(n, t) in points {
            let w = 1.0 / (t * t);
            s += w;
            sn += w * n;
            snn += w * n * n;
            st += w * t;
            snt += w * n * t;
        }
        let det = s * snn - sn * sn;
        if det.abs() <= 1e-12 * s * snn || !det.is_finite() {
            return None;
        }
        Some(CostFit {
            fixed: (st * snn - sn * snt) / det,
            per_triangle: (s * snt - sn * st) / det,
        })
    }

    /// The fitted time at `n`.
    pub fn at(self, n: f64) -> f64 {
        self.fixed + self.per_triangle * n
    }
}

/// What the chart shows of one method: its points and its fit.
pub struct Method<'a> {
    /// The scene alone and with the balls, by triangle count.
    pub balls: Vec<&'a ScalingRow>,
    /// The bunny, if measured.
    pub bunny: Option<&'a ScalingRow>,
    /// The fit over `balls` (the bunny is left out: it checks the fit).
    pub fit: PowerFit,
    /// The fixed-plus-per-triangle fit over `balls` (the chart draws the
    /// rasterizer's, whose time is not a power law).
    pub cost: CostFit,
}

impl<'a> Method<'a> {
    /// The rows of `method`; an error if fewer than two stages of
    /// different sizes were measured.
    pub fn of(
        rows: &'a [ScalingRow], method: &str,
    ) -> Result<Method<'a>, String> {
        let mut balls: Vec<&ScalingRow> = rows
            .iter()
            .filter(|r| r.method == method && r.scene != BUNNY)
            .collect();
        balls.sort_by_key(|r| r.triangles);
        let bunny =
            rows.iter().find(|r| r.method == method && r.scene == BUNNY);
        let points: Vec<(f64, f64)> = balls.iter().map(|r| at(r)).collect();
        let too_few = || format!("{method}: fewer than two scene sizes to fit");
        let fit = PowerFit::of(&points).ok_or_else(too_few)?;
        let cost = CostFit::of(&points).ok_or_else(too_few)?;
        Ok(Method {
            balls,
            bunny,
            fit,
            cost,
        })
    }
}

/// A row's point: (triangles, ms).
fn at(row: &ScalingRow) -> (f64, f64) {
    (row.triangles as f64, row.millis)
}

/// The chart, or an error naming the CSV file if it is missing or bad.
pub fn scaling_chart() -> Result<Figure, ChartError> {
    let rows: Vec<ScalingRow> = measured("ch07", "scaling.csv")?;
    let path = book_figures().join("ch07").join("scaling.csv");
    let cast = Method::of(&rows, RAYCAST)
        .map_err(|e| format!("{}: {e}", path.display()))?;
    let raster = Method::of(&rows, RASTERIZE)
        .map_err(|e| format!("{}: {e}", path.display()))?;
    chart(
        "scaling-chart",
        "Time to draw one image of shapes.toml (160×90, one thread) against its number of triangles N: the scene alone (12 triangles), with a ball of 20·4ⁿ triangles (n = 0 … 6), and with the Stanford bunny in the ball's place. Pale lines: the least-squares power law through the ball points; the bunny is left out of the fit and lands on it. Dashed: the rasterizer's time as a fixed cost plus a cost per triangle, fitted to the same points. Grey brackets: how many times longer ray casting takes than rasterizing, at the smallest and the largest N.",
        900,
        600,
        |area| draw(area, &cast, &raster),
    )
}

/// An axis label (label markup): powers of ten from 10⁴ on as `10^{4}`.
fn power_label(x: &f64) -> String {
    let exponent = x.log10().round();
    if exponent >= 4.0 && (x / 10f64.powf(exponent) - 1.0).abs() < 1e-9 {
        decade(exponent as i32)
    } else if *x >= 1.0 {
        format!("{x:.0}")
    } else {
        format!("{x}")
    }
}

fn draw(
    area: &raystep_figure::ChartArea, cast: &Method, raster: &Method,
) -> Result<(), ChartError> {
    let (width, height) = CHART_SIZE;
    let mut c = ChartBuilder::on(area)
        .margin(14)
        .margin_right(24)
        .x_label_area_size(58)
        .y_label_area_size(64)
        .build_cartesian_2d(
            (3f64..3e5).log_scale(),
            (0.5f64..4e4).log_scale(),
        )?;
    c.configure_mesh()
        .x_desc("N, triangles in the scene")
        .y_desc(format!(
            "time for one {width}×{height} image, ms (one thread, this machine)"
        ))
        .x_label_formatter(&power_label)
        .y_label_formatter(&power_label)
        .label_style(font(16.0))
        .axis_desc_style(font(16.0))
        .light_line_style(WHITE)
        .draw()?;

    // the rasterizer's cost model, dashed, under everything else: a curve
    // on these axes, through 65 points spaced evenly in log N
    let (first, last) = (
        at(raster.balls[0]).0,
        at(raster.balls[raster.balls.len() - 1]).0,
    );
    let curve = (0..=64).map(|i| {
        let n = first * (last / first).powf(f64::from(i) / 64.0);
        (n, raster.cost.at(n))
    });
    c.draw_series(DashedLineSeries::new(
        curve,
        7,
        5,
        RASTERIZE_COLOUR.stroke_width(2),
    ))?;

    for (method, colour) in [(cast, RAYCAST_COLOUR), (raster, RASTERIZE_COLOUR)]
    {
        // the fit, a pale line, over the points it was fitted to (a straight
        // line on these axes: its two ends)
        let (first, last) = (
            at(method.balls[0]).0,
            at(method.balls[method.balls.len() - 1]).0,
        );
        let fitted = [first, last].map(|n| (n, method.fit.at(n)));
        c.draw_series(LineSeries::new(
            fitted,
            colour.mix(0.55).stroke_width(3),
        ))?;
        // the points: the balls as dots, the bunny as a triangle
        c.draw_series(
            method
                .balls
                .iter()
                .map(|r| Circle::new(at(r), 5, colour.filled())),
        )?;
        if let Some(bunny) = method.bunny {
            c.draw_series(std::iter::once(TriangleMarker::new(
                at(bunny),
                8,
                colour.filled(),
            )))?;
        }
    }

    // which stage each column of points is: n above the ray-cast dots
    let small = font(15.0).color(&GREY);
    for (k, row) in cast.balls.iter().enumerate() {
        let text = if k == 0 {
            "alone".to_string()
        } else {
            format!("n = {}", k - 1)
        };
        c.draw_series(std::iter::once(
            EmptyElement::at(at(row))
                + Text::new(
                    text,
                    (0, -12),
                    small.clone().pos(Pos::new(HPos::Center, VPos::Bottom)),
                ),
        ))?;
    }
    // the bunny's label to the left of its marker, clear of n = 4's
    if let Some(bunny) = cast.bunny {
        c.draw_series(std::iter::once(
            EmptyElement::at(at(bunny))
                + Text::new(
                    "bunny",
                    (-12, 0),
                    small.clone().pos(Pos::new(HPos::Right, VPos::Center)),
                ),
        ))?;
    }

    // how many times longer ray casting takes, at the smallest and the
    // largest N: a bracket beside the two methods' points, left of the
    // first pair and right of the last
    let last = cast.balls.len() - 1;
    for (k, side) in [(0, -1), (last, 1)] {
        let (n, slow) = at(cast.balls[k]);
        let fast = raster
            .balls
            .iter()
            .find(|r| r.triangles == cast.balls[k].triangles)
            .map(|r| r.millis);
        let Some(fast) = fast else { continue };
        let x = n * 1.4f64.powi(side);
        let tick = 1.06f64.powi(-side);
        c.draw_series(std::iter::once(PathElement::new(
            vec![(x * tick, fast), (x, fast), (x, slow), (x * tick, slow)],
            GREY.stroke_width(1),
        )))?;
        let ratio = slow / fast;
        let text = if ratio < 10.0 {
            format!("×{ratio:.1}")
        } else {
            format!("×{ratio:.0}")
        };
        let h = if side < 0 { HPos::Right } else { HPos::Left };
        c.draw_series(std::iter::once(
            EmptyElement::at((x, (fast * slow).sqrt()))
                + Text::new(
                    text,
                    (6 * side, 0),
                    font(16.0).color(&GREY).pos(Pos::new(h, VPos::Center)),
                ),
        ))?;
    }

    legend(area, cast, raster)
}

/// The legend, in the empty upper left: each method, its fit's exponent
/// as a superscript, and the bunny's marker.
fn legend(
    area: &raystep_figure::ChartArea, cast: &Method, raster: &Method,
) -> Result<(), ChartError> {
    let (x, y) = (110, 34);
    let style = font(16.0).color(&BLACK);
    let entries = [
        (
            "ray casting: each pixel × each object",
            cast,
            RAYCAST_COLOUR,
        ),
        (
            "rasterizing: each triangle × its pixels",
            raster,
            RASTERIZE_COLOUR,
        ),
    ];
    for (i, (name, method, colour)) in entries.iter().enumerate() {
        let row = y + 28 * i as i32;
        area.draw(&PathElement::new(
            vec![(x, row), (x + 30, row)],
            colour.mix(0.55).stroke_width(3),
        ))?;
        area.draw(&Circle::new((x + 15, row), 5, colour.filled()))?;
        area.draw(&Text::new(
            *name,
            (x + 42, row),
            style.pos(Pos::new(HPos::Left, VPos::Center)),
        ))?;
        // the fit's exponent raised (label markup)
        area.draw(&Text::new(
            format!("fit: time ∝ N^{{{:.2}}}", method.fit.b),
            (x + 400, row),
            style.pos(Pos::new(HPos::Left, VPos::Center)),
        ))?;
    }
    let row = y + 56;
    area.draw(&DashedPathElement::new(
        vec![(x, row), (x + 30, row)],
        7,
        5,
        RASTERIZE_COLOUR.stroke_width(2),
    ))?;
    area.draw(&Text::new(
        format!(
            "rasterizing, fixed + per triangle: {:.2} ms + {:.0} ns·N",
            raster.cost.fixed,
            raster.cost.per_triangle * 1e6
        ),
        (x + 42, row),
        style.pos(Pos::new(HPos::Left, VPos::Center)),
    ))?;
    let row = y + 84;
    area.draw(&TriangleMarker::new((x + 15, row), 8, GREY.filled()))?;
    area.draw(&Text::new(
        "the Stanford bunny (not in the fits)",
        (x + 42, row),
        style.pos(Pos::new(HPos::Left, VPos::Center)),
    ))?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_power_law_is_fitted_exactly() {
        // t = 3·N² at N = 10, 100, 1000
        let points = [(10.0, 300.0), (100.0, 30_000.0), (1000.0, 3e6)];
        let fit = PowerFit::of(&points).unwrap();
        assert!((fit.b - 2.0).abs() < 1e-12, "{fit:?}");
        assert!((fit.a - 3.0).abs() < 1e-9, "{fit:?}");
        assert!((fit.at(50.0) - 7500.0).abs() < 1e-6);
        // the least-squares slope of log t: here (1, 1), (10, 1), (100, 100)
        // in logs (0, 0), (1, 0), (2, 2) → slope 1
        let fit =
            PowerFit::of(&[(1.0, 1.0), (10.0, 1.0), (100.0, 100.0)]).unwrap();
        assert!((fit.b - 1.0).abs() < 1e-12, "{fit:?}");
        assert_eq!(PowerFit::of(&[(5.0, 1.0), (5.0, 2.0)]), None);
        assert_eq!(PowerFit::of(&[]), None);
    }

    #[test]
    fn a_fixed_cost_plus_a_cost_per_triangle_is_fitted_exactly() {
        // t = 1.5 + 0.002·N
        let points = [(12.0, 1.524), (1000.0, 3.5), (80_000.0, 161.5)];
        let fit = CostFit::of(&points).unwrap();
        assert!((fit.fixed - 1.5).abs() < 1e-9, "{fit:?}");
        assert!((fit.per_triangle - 0.002).abs() < 1e-12, "{fit:?}");
        assert!((fit.at(500.0) - 2.5).abs() < 1e-9);
        // the relative error is what is minimised: about 2 ms + 10 µs·N,
        // measured with noise; every point within 2.5 % (a plain least
        // squares fit follows the 98 ms point and misses the 2 ms one by 8 %)
        let points =
            [(10.0, 2.0), (100.0, 2.9), (1000.0, 12.0), (10_000.0, 98.0)];
        let fit = CostFit::of(&points).unwrap();
        for (n, t) in points {
            assert!((fit.at(n) / t - 1.0).abs() < 0.025, "{fit:?} at {n}");
        }
        assert_eq!(CostFit::of(&[(5.0, 1.0), (5.0, 2.0)]), None);
        assert_eq!(CostFit::of(&[]), None);
    }

    #[test]
    fn axis_labels_are_numbers_then_powers_of_ten() {
        assert_eq!(power_label(&0.5), "0.5");
        assert_eq!(power_label(&10.0), "10");
        assert_eq!(power_label(&1000.0), "1000");
        assert_eq!(power_label(&1e4), "10^{4}");
        assert_eq!(power_label(&1e5), "10^{5}");
        assert_eq!(power_label(&20_000.0), "20000");
    }

    /// The committed CSV draws: every stage of both methods is in it, and
    /// the chart comes out (the `figures` command draws the same).
    #[test]
    fn the_chart_draws_from_the_committed_csv() {
        let rows: Vec<ScalingRow> =
            measured("ch07", "scaling.csv").expect("the committed scaling.csv");
        let scenes = crate::measurements::chart_scenes();
        assert_eq!(rows.len(), 2 * scenes.len());
        for (pair, scene) in rows.chunks(2).zip(&scenes) {
            assert_eq!(pair[0].scene, scene.name());
            assert_eq!(
                (pair[0].method.as_str(), pair[1].method.as_str()),
                (RASTERIZE, RAYCAST)
            );
            assert_eq!(pair[0].triangles, pair[1].triangles);
        }
        let figure = scaling_chart().expect("the chart draws");
        assert_eq!(figure.name, "scaling-chart");
    }
}
