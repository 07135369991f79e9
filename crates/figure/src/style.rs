//! Colours, fills and strokes, and the colour-blind-safe palette.

/// An opaque sRGB colour.
///
/// For a translucent fill use [`Color::with_alpha`], which gives a [`Fill`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Color {
    /// Red, 0–255.
    pub r: u8,
    /// Green, 0–255.
    pub g: u8,
    /// Blue, 0–255.
    pub b: u8,
}

impl Color {
    /// The colour with these red, green and blue components.
    pub const fn rgb(r: u8, g: u8, b: u8) -> Color {
        Color { r, g, b }
    }

    /// This colour as a fill of the given opacity (0 = invisible, 1 = opaque; clamped).
    pub fn with_alpha(self, alpha: f64) -> Fill {
        Fill {
            color: self,
            opacity: alpha.clamp(0.0, 1.0),
        }
    }

    /// The colour a fraction `t` (0–1) of the way from `self` to `other`.
    pub fn mix(self, other: Color, t: f64) -> Color {
        let t = t.clamp(0.0, 1.0);
        let lerp = |a: u8, b: u8| {
            (f64::from(a) + (f64::from(b) - f64::from(a)) * t).round() as u8
        };
        Color::rgb(
            lerp(self.r, other.r),
            lerp(self.g, other.g),
            lerp(self.b, other.b),
        )
    }

    /// The colour a linear-RGB render colour is stored as (its 8-bit sRGB
    /// levels), e.g. a material's kd drawn in a diagram.
    pub fn from_linear(c: raystep_core::DVec3) -> Color {
        let [r, g, b] = raystep_render::srgb8(c);
        Color::rgb(r, g, b)
    }

    /// The linear-RGB colour whose stored sRGB levels are this colour's,
    /// e.g. a diagram colour painted into a render.
    pub fn to_linear(self) -> raystep_core::DVec3 {
        raystep_render::linear_from_srgb8([self.r, self.g, self.b])
    }

    /// The colour as an SVG `#rrggbb` string.
    pub(crate) fn hex(self) -> String {
        format!("#{:02x}{:02x}{:02x}", self.r, self.g, self.b)
    }
}

/// A possibly translucent fill: a colour and an opacity in 0–1.
///
/// Made with [`Color::with_alpha`]; a plain [`Color`] converts into an opaque fill.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Fill {
    /// The colour.
    pub color: Color,
    /// 0 = invisible, 1 = opaque.
    pub opacity: f64,
}

impl From<Color> for Fill {
    fn from(color: Color) -> Fill {
        Fill {
            color,
            opacity: 1.0,
        }
    }
}

/// The Okabe–Ito colours, which stay distinguishable for the common kinds of colour blindness,
/// plus greys.
pub mod palette {
    use super::Color;

    /// Black: the default for strokes and labels.
    pub const BLACK: Color = Color::rgb(0, 0, 0);
    /// Orange.
    pub const ORANGE: Color = Color::rgb(230, 159, 0);
    /// Sky blue.
    pub const SKY_BLUE: Color = Color::rgb(86, 180, 233);
    /// Bluish green.
    pub const GREEN: Color = Color::rgb(0, 158, 115);
    /// Yellow.
    pub const YELLOW: Color = Color::rgb(240, 228, 66);
    /// Blue.
    pub const BLUE: Color = Color::rgb(0, 114, 178);
    /// Vermilion (a red that reads as red to most readers).
    pub const VERMILION: Color = Color::rgb(213, 94, 0);
    /// Reddish purple.
    pub const PURPLE: Color = Color::rgb(204, 121, 167);
    /// Mid grey, for secondary lines.
    pub const GREY: Color = Color::rgb(136, 136, 136);
    /// Light grey, for grids and backgrounds.
    pub const LIGHT_GREY: Color = Color::rgb(221, 221, 221);
    /// White.
    pub const WHITE: Color = Color::rgb(255, 255, 255);
    /// Dark grey, for notes and secondary text.
    pub const NOTE: Color = Color::rgb(85, 85, 85);

    /// What the colours mean in every chapter's figures, so that a normal
    /// or a shadow ray looks the same from chapter 1 to chapter 10.
    pub mod role {
        use super::*;

        /// A surface normal N.
        pub const NORMAL: Color = VERMILION;
        /// A primary ray, or a ray's direction D.
        pub const RAY: Color = BLUE;
        /// A light, and the rays that reach it.
        pub const LIGHT: Color = ORANGE;
        /// A reflected ray R.
        pub const REFLECTED: Color = PURPLE;
        /// A refracted (transmitted) ray T.
        pub const REFRACTED: Color = SKY_BLUE;
        /// A shadow ray that reaches its light (Sᵢ = 1).
        pub const LIT: Color = GREEN;
        /// A shadow ray that is blocked (Sᵢ = 0).
        pub const BLOCKED: Color = VERMILION;
    }
}

/// How a line is drawn. Width and dash lengths are in page px, whatever the world scale.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Stroke {
    /// Line colour.
    pub color: Color,
    /// Line width in page px.
    pub width: f64,
    /// Dash and gap lengths in page px; `None` for a solid line.
    pub dash: Option<(f64, f64)>,
}

impl Stroke {
    /// A solid line of width 2 px.
    pub fn new(color: Color) -> Stroke {
        Stroke {
            color,
            width: 2.0,
            dash: None,
        }
    }

    /// Construction lines: 1.5 px black.
    pub fn ink() -> Stroke {
        Stroke::new(palette::BLACK).width(1.5)
    }

    /// A vector arrow's stroke: 2.5 px in `color`.
    pub fn vector(color: Color) -> Stroke {
        Stroke::new(color).width(2.5)
    }

    /// The same stroke with width `w` px.
    pub fn width(self, w: f64) -> Stroke {
        Stroke { width: w, ..self }
    }

    /// The same stroke dashed: dashes of 3 widths + 3 px with gaps of 2 widths + 2 px.
    pub fn dashed(self) -> Stroke {
        let w = self.width;
        Stroke {
            dash: Some((3.0 * w + 3.0, 2.0 * w + 2.0)),
            ..self
        }
    }

    /// The same stroke 1 px wide (dashes, if any, keep their length).
    pub fn thin(self) -> Stroke {
        Stroke { width: 1.0, ..self }
    }

    /// The SVG presentation attributes of this stroke (with `fill="none"` unless `fill` is set).
    pub(crate) fn attributes(&self) -> String {
        let mut s = format!(
            r#"stroke="{}" stroke-width="{}""#,
            self.color.hex(),
            num(self.width)
        );
        match self.dash {
            Some((on, off)) => {
                s.push_str(&format!(
                    r#" stroke-dasharray="{} {}" stroke-linecap="butt" stroke-linejoin="round""#,
                    num(on),
                    num(off)
                ));
            }
            None => {
                s.push_str(r#" stroke-linecap="round" stroke-linejoin="round""#)
            }
        }
        s
    }
}

/// SVG attributes for an optional fill and an optional stroke.
pub(crate) fn paint_attributes(
    fill: Option<Fill>, stroke: Option<&Stroke>,
) -> String {
    let mut s = match fill {
        Some(f) if f.opacity < 1.0 => {
            format!(
                r#"fill="{}" fill-opacity="{}""#,
                f.color.hex(),
                num(f.opacity)
            )
        }
        Some(f) => format!(r#"fill="{}""#, f.color.hex()),
        None => r#"fill="none""#.to_string(),
    };
    if let Some(stroke) = stroke {
        s.push(' ');
        s.push_str(&stroke.attributes());
    }
    s
}

/// A number with two decimals, never `-0.00`: every number in the SVG source goes through this,
/// so the source is the same on every machine.
pub(crate) fn num(x: f64) -> String {
    let s = format!("{x:.2}");
    if s == "-0.00" { "0.00".to_string() } else { s }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_have_two_decimals_and_no_negative_zero() {
        assert_eq!(num(1.0), "1.00");
        assert_eq!(num(-0.001), "0.00");
        assert_eq!(num(2.345_6), "2.35");
    }

    #[test]
    fn colours_are_hex() {
        assert_eq!(palette::ORANGE.hex(), "#e69f00");
        assert_eq!(
            palette::BLACK.mix(palette::WHITE, 0.5),
            Color::rgb(128, 128, 128)
        );
    }
}
