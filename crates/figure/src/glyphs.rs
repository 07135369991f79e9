//! Small glyphs the lecture's figures share: a rejected hit, a light, an
//! eye, a cut, a rectangle, a block of text lines.
use raystep_core::DVec2;

use crate::{Anchor, Color, Page, Stroke, palette};

impl Page {
    /// A hollow dot of radius 4.5 px: a hit that is not kept (behind the
    /// origin, farther than the closest, skipped).
    pub fn hollow_point(&mut self, p: DVec2, color: Color) {
        let r = 4.5 / self.scale();
        self.circle(
            p,
            r,
            Some(palette::WHITE),
            Some(&Stroke::new(color).width(2.0)),
        );
    }

    /// A small sun at `p`: a point light.
    pub fn sun(&mut self, p: DVec2) {
        let r = 7.0 / self.scale();
        let rays = Stroke::new(palette::ORANGE).width(2.0);
        for k in 0..8 {
            let a = f64::from(k) * std::f64::consts::FRAC_PI_4;
            let d = DVec2::new(a.cos(), a.sin());
            self.segment(p + 1.4 * r * d, p + 2.1 * r * d, &rays);
        }
        self.circle(p, r, Some(palette::YELLOW), Some(&rays));
    }

    /// A small eye at `p`: an almond with a pupil, looking along `dir`.
    pub fn eye(&mut self, p: DVec2, dir: DVec2) {
        let s = 9.0 / self.scale();
        let (u, v) = (dir.normalize(), dir.normalize().perp());
        let almond: Vec<DVec2> = (0..=24)
            .map(|k| {
                let a = f64::from(k) / 24.0 * std::f64::consts::TAU;
                p + s
                    * (1.3 * a.cos() * u
                        + 0.6 * a.sin() * a.cos().abs().mul_add(-0.5, 1.0) * v)
            })
            .collect();
        self.polygon(
            &almond,
            Some(palette::WHITE),
            Some(&Stroke::new(palette::BLACK).width(1.5)),
        );
        self.circle(p + 0.35 * s * u, 0.42 * s, Some(palette::GREEN), None);
        self.circle(p + 0.35 * s * u, 0.18 * s, Some(palette::BLACK), None);
    }

    /// A black X at `p`: where a ray was blocked or cut.
    pub fn cross(&mut self, p: DVec2) {
        let x = 6.0 / self.scale();
        for d in [DVec2::new(x, x), DVec2::new(x, -x)] {
            self.segment(p - d, p + d, &Stroke::new(palette::BLACK).width(3.0));
        }
    }

    /// The axis-aligned rectangle from `min` to `max`.
    pub fn rect(
        &mut self, min: DVec2, max: DVec2, fill: Option<Color>,
        stroke: Option<&Stroke>,
    ) {
        self.polygon(
            &[min, DVec2::new(max.x, min.y), max, DVec2::new(min.x, max.y)],
            fill,
            stroke,
        );
    }

    /// Lines of text, each in its own colour, left-aligned at `top_left`
    /// and `step` world units apart, `size_px` high.
    pub fn text_lines(
        &mut self, top_left: DVec2, step: f64, size_px: f64,
        lines: &[(&str, Color)],
    ) {
        for (k, (text, color)) in lines.iter().enumerate() {
            let at = top_left - DVec2::new(0.0, step * k as f64);
            self.label_sized(at, text, Anchor::E, size_px, *color);
        }
    }
}
