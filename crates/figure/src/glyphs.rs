//! Small glyphs the lecture's figures share: a rejected hit, a light, a
//! block of text lines.
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

    /// Lines of text, each in its own colour, left-aligned at `top_left`
    /// and `step` world units apart, `size_px` high.
    pub fn text_lines(
        &mut self,
        top_left: DVec2,
        step: f64,
        size_px: f64,
        lines: &[(&str, Color)],
    ) {
        for (k, (text, color)) in lines.iter().enumerate() {
            let at = top_left - DVec2::new(0.0, step * k as f64);
            self.label_sized(at, text, Anchor::E, size_px, *color);
        }
    }
}
