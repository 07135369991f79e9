//! The drawing page: a world window mapped onto page px, and the drawing primitives.
//!
//! World coordinates have y up; page coordinates (SVG user units, "page px") have y down with
//! the origin at the top-left corner. Every primitive appends one SVG element, so later calls
//! draw on top of earlier ones.

use raystep_core::DVec2;

use crate::style::{Color, Fill, Stroke, num, paint_attributes, palette};
use crate::text::{Align, CAP_HEIGHT, text_element};

/// The default space left around the world window by [`Page::view`], in page px.
const DEFAULT_MARGIN: f64 = 24.0;
/// Radius of a [`Page::point`] dot, in page px.
const POINT_RADIUS: f64 = 4.0;
/// Font size of [`Page::label`], in page px.
const LABEL_SIZE: f64 = 16.0;
/// How far [`Page::ray`] and [`Page::axes`] keep their arrow tips inside the page, in page px.
const EDGE_INSET: f64 = 4.0;

/// Where a label sits relative to its point: `Anchor::NE` puts it above and to the right of the
/// point, a few px away; `Anchor::Center` centres it on the point.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Anchor {
    /// Centred on the point.
    Center,
    /// Above.
    N,
    /// Below.
    S,
    /// Right.
    E,
    /// Left.
    W,
    /// Above right.
    NE,
    /// Above left.
    NW,
    /// Below right.
    SE,
    /// Below left.
    SW,
}

impl Anchor {
    /// The anchor that puts a label on the side of a point that `dir` (page coordinates, y down)
    /// points to.
    fn toward(dir: DVec2) -> Anchor {
        let angle = (-dir.y).atan2(dir.x).to_degrees(); // y up, counter-clockwise from east
        let octant = ((angle + 360.0 + 22.5) / 45.0).floor() as i64 % 8;
        match octant {
            0 => Anchor::E,
            1 => Anchor::NE,
            2 => Anchor::N,
            3 => Anchor::NW,
            4 => Anchor::W,
            5 => Anchor::SW,
            6 => Anchor::S,
            _ => Anchor::SE,
        }
    }

    /// The anchor that puts a label on the side of its point that the world direction `dir`
    /// (y up) points to: `Anchor::pointing(n)` labels a normal n beyond its tip.
    pub fn pointing(dir: DVec2) -> Anchor {
        Anchor::toward(DVec2::new(dir.x, -dir.y))
    }
}

/// A figure's drawing surface, `width × height` page px on a white background.
///
/// A new page shows the world window [0, width] × [0, height] at scale 1 (y up); call
/// [`Page::view`] to choose the world window. Then draw with the primitives, whose coordinates
/// are world coordinates unless their documentation says otherwise.
#[derive(Clone, Debug)]
pub struct Page {
    width: f64,
    height: f64,
    margin: f64,
    window: Option<(DVec2, DVec2)>,
    /// Page px per world unit.
    scale: f64,
    /// Where the world origin lands on the page.
    origin: DVec2,
    /// SVG elements in drawing order.
    body: Vec<String>,
}

impl Page {
    /// A blank white page `width × height` page px (SVG user units).
    ///
    /// # Panics
    /// If a side is not a positive finite number.
    pub fn new(width: f64, height: f64) -> Page {
        assert!(
            width.is_finite()
                && height.is_finite()
                && width > 0.0
                && height > 0.0,
            "page size must be positive, got {width} × {height}"
        );
        Page {
            width,
            height,
            margin: DEFAULT_MARGIN,
            window: None,
            scale: 1.0,
            origin: DVec2::new(0.0, height),
            body: Vec::new(),
        }
    }

    /// The space [`Page::view`] leaves around the world window, in page px (default 24).
    pub fn margin(mut self, px: f64) -> Page {
        self.margin = px.max(0.0);
        self.fit();
        self
    }

    /// Maps the world window [`min`, `max`] (y up!) onto the page with a uniform scale, centred,
    /// leaving the margin (default 24 px) around it. The other direction shows more world if
    /// the aspect ratios differ.
    ///
    /// # Panics
    /// If the window is empty or does not fit inside the margins.
    pub fn view(mut self, min: DVec2, max: DVec2) -> Page {
        self.window = Some((min, max));
        self.fit();
        self
    }

    /// Recomputes the world → page mapping from the window and margin.
    fn fit(&mut self) {
        let Some((min, max)) = self.window else {
            return;
        };
        let size = max - min;
        let scale = ((self.width - 2.0 * self.margin) / size.x)
            .min((self.height - 2.0 * self.margin) / size.y);
        assert!(
            scale.is_finite() && scale > 0.0,
            "world window {min} .. {max} cannot be shown on a {} × {} page with margin {}",
            self.width,
            self.height,
            self.margin
        );
        let centre = (min + max) / 2.0;
        self.scale = scale;
        self.origin = DVec2::new(
            self.width / 2.0 - scale * centre.x,
            self.height / 2.0 + scale * centre.y,
        );
    }

    /// Page width in page px.
    pub fn width(&self) -> f64 {
        self.width
    }

    /// Page height in page px.
    pub fn height(&self) -> f64 {
        self.height
    }

    /// The page point (y down) of world point `p` (y up).
    pub fn to_page(&self, p: DVec2) -> DVec2 {
        DVec2::new(
            self.origin.x + self.scale * p.x,
            self.origin.y - self.scale * p.y,
        )
    }

    /// The world point of page point `q`.
    pub fn to_world(&self, q: DVec2) -> DVec2 {
        DVec2::new(
            (q.x - self.origin.x) / self.scale,
            (self.origin.y - q.y) / self.scale,
        )
    }

    /// Bottom-left corner of the visible world rectangle (the whole page, margins included).
    pub fn world_min(&self) -> DVec2 {
        self.to_world(DVec2::new(0.0, self.height))
    }

    /// Top-right corner of the visible world rectangle (the whole page, margins included).
    pub fn world_max(&self) -> DVec2 {
        self.to_world(DVec2::new(self.width, 0.0))
    }

    /// Page px per world unit.
    pub fn scale(&self) -> f64 {
        self.scale
    }

    /// Appends a raw SVG element (page coordinates). For what the primitives cannot draw.
    pub fn raw_svg(&mut self, element: &str) {
        self.body.push(element.to_string());
    }

    /// Appends an element built by a primitive, unless some coordinate was not finite.
    pub(crate) fn push(&mut self, points: &[DVec2], element: String) {
        if points.iter().all(|p| p.is_finite()) {
            self.body.push(element);
        }
    }

    /// A filled dot of radius 4 px at `p`.
    pub fn point(&mut self, p: DVec2, color: Color) {
        let q = self.to_page(p);
        let el = format!(
            r#"<circle cx="{}" cy="{}" r="{}" fill="{}"/>"#,
            num(q.x),
            num(q.y),
            num(POINT_RADIUS),
            color.hex()
        );
        self.push(&[q], el);
    }

    /// The line segment from `a` to `b`.
    pub fn segment(&mut self, a: DVec2, b: DVec2, stroke: &Stroke) {
        let (qa, qb) = (self.to_page(a), self.to_page(b));
        self.page_segment(qa, qb, stroke);
    }

    /// A segment in page coordinates.
    fn page_segment(&mut self, qa: DVec2, qb: DVec2, stroke: &Stroke) {
        let el = format!(
            r#"<line x1="{}" y1="{}" x2="{}" y2="{}" fill="none" {}/>"#,
            num(qa.x),
            num(qa.y),
            num(qb.x),
            num(qb.y),
            stroke.attributes()
        );
        self.push(&[qa, qb], el);
    }

    /// The open path through `pts`.
    pub fn polyline(&mut self, pts: &[DVec2], stroke: &Stroke) {
        let q: Vec<DVec2> = pts.iter().map(|&p| self.to_page(p)).collect();
        let el = format!(
            r#"<polyline points="{}" fill="none" {}/>"#,
            points_attr(&q),
            stroke.attributes()
        );
        self.push(&q, el);
    }

    /// A right-angle mark at `corner` between the unit directions `u` and `v`: a thin square
    /// corner `size` world units on a side.
    pub fn right_angle(
        &mut self, corner: DVec2, u: DVec2, v: DVec2, size: f64,
    ) {
        let mark = [
            corner + size * u,
            corner + size * (u + v),
            corner + size * v,
        ];
        self.polyline(&mark, &Stroke::new(palette::BLACK).thin());
    }

    /// The infinite line through `p` along `dir`, clipped to the visible world rectangle.
    /// Draws nothing if the line misses the page or `dir` is zero.
    pub fn line(&mut self, p: DVec2, dir: DVec2, stroke: &Stroke) {
        let (min, max) = (self.world_min(), self.world_max());
        if let Some((t0, t1)) =
            clip_line(p, dir, min, max, f64::NEG_INFINITY, f64::INFINITY)
        {
            self.segment(p + t0 * dir, p + t1 * dir, stroke);
        }
    }

    /// An arrow from `from` to `to` with its head at `to`; the head grows with the stroke width.
    pub fn arrow(&mut self, from: DVec2, to: DVec2, stroke: &Stroke) {
        let (qa, qb) = (self.to_page(from), self.to_page(to));
        self.page_arrow(qa, qb, stroke);
    }

    /// An arrow in page coordinates: the shaft stops inside the head so its cap never pokes out.
    fn page_arrow(&mut self, from: DVec2, tip: DVec2, stroke: &Stroke) {
        let Some(u) = (tip - from).try_normalize() else {
            return;
        };
        let n = u.perp();
        let len = 5.0 + 2.5 * stroke.width;
        let half = 0.4 * len;
        let back = tip - u * len;
        let head =
            [tip, back + n * half, tip - u * (0.8 * len), back - n * half];
        if (tip - from).length() > 0.7 * len {
            self.page_segment(from, tip - u * (0.7 * len), stroke);
        }
        let el = format!(
            r#"<polygon points="{}" fill="{}"/>"#,
            points_attr(&head),
            stroke.color.hex()
        );
        self.push(&head, el);
    }

    /// A ray from `origin` along `dir` to where it leaves the visible rectangle, with an
    /// arrowhead there (kept a few px inside the page so it is not cut off). Draws nothing if
    /// the origin is off the page or `dir` is zero.
    pub fn ray(&mut self, origin: DVec2, dir: DVec2, stroke: &Stroke) {
        let inset = DVec2::splat(EDGE_INSET / self.scale);
        let (min, max) = (self.world_min() + inset, self.world_max() - inset);
        // t0 > 0 would mean the origin itself is off the page
        if let Some((0.0, t1)) =
            clip_line(origin, dir, min, max, 0.0, f64::INFINITY)
        {
            self.arrow(origin, origin + t1 * dir, stroke);
        }
    }

    /// A circle of world radius `r` about `c`, optionally filled and/or stroked.
    pub fn circle(
        &mut self, c: DVec2, r: f64, fill: Option<Color>,
        stroke: Option<&Stroke>,
    ) {
        self.circle_alpha(c, r, fill.map(Fill::from), stroke);
    }

    /// [`Page::circle`] with a possibly translucent fill, e.g. `Some(palette::ORANGE.with_alpha(0.3))`.
    pub fn circle_alpha(
        &mut self, c: DVec2, r: f64, fill: Option<Fill>,
        stroke: Option<&Stroke>,
    ) {
        let q = self.to_page(c);
        let rq = DVec2::splat(r * self.scale);
        let el = format!(
            r#"<circle cx="{}" cy="{}" r="{}" {}/>"#,
            num(q.x),
            num(q.y),
            num(rq.x),
            paint_attributes(fill, stroke)
        );
        self.push(&[q, rq], el);
    }

    /// The closed polygon through `pts`, optionally filled (opaque) and/or stroked.
    /// For a translucent fill use [`Page::polygon_alpha`].
    pub fn polygon(
        &mut self, pts: &[DVec2], fill: Option<Color>, stroke: Option<&Stroke>,
    ) {
        self.polygon_alpha(pts, fill.map(Fill::from), stroke);
    }

    /// [`Page::polygon`] with a possibly translucent fill, e.g. `Some(palette::SKY_BLUE.with_alpha(0.3))`.
    pub fn polygon_alpha(
        &mut self, pts: &[DVec2], fill: Option<Fill>, stroke: Option<&Stroke>,
    ) {
        let q: Vec<DVec2> = pts.iter().map(|&p| self.to_page(p)).collect();
        let el = format!(
            r#"<polygon points="{}" {}/>"#,
            points_attr(&q),
            paint_attributes(fill, stroke)
        );
        self.push(&q, el);
    }

    /// An arc of `radius_px` page px about `centre`, counter-clockwise (world, y up) from
    /// direction `from_dir` to direction `to_dir`, with an optional label just outside the
    /// middle of the arc.
    pub fn angle_arc(
        &mut self, centre: DVec2, from_dir: DVec2, to_dir: DVec2,
        radius_px: f64, stroke: &Stroke, label: Option<&str>,
    ) {
        let a0 = from_dir.y.atan2(from_dir.x);
        let sweep =
            (to_dir.y.atan2(to_dir.x) - a0).rem_euclid(std::f64::consts::TAU);
        if from_dir == DVec2::ZERO || to_dir == DVec2::ZERO || sweep < 1e-9 {
            return;
        }
        let c = self.to_page(centre);
        // page direction (y down) of world angle a
        let dir = |a: f64| DVec2::new(a.cos(), -a.sin());
        let start = c + radius_px * dir(a0);
        let end = c + radius_px * dir(a0 + sweep);
        let large = u8::from(sweep > std::f64::consts::PI);
        // sweep-flag 0: counter-clockwise as seen on the page
        let el = format!(
            r#"<path d="M {} {} A {r} {r} 0 {large} 0 {} {}" fill="none" {}/>"#,
            num(start.x),
            num(start.y),
            num(end.x),
            num(end.y),
            stroke.attributes(),
            r = num(radius_px),
        );
        self.push(&[start, end], el);
        if let Some(text) = label {
            let mid = dir(a0 + sweep / 2.0);
            let at = c + (radius_px + 2.0) * mid;
            self.page_label(
                at,
                text,
                Anchor::toward(mid),
                LABEL_SIZE,
                palette::BLACK,
            );
        }
    }

    /// Thin grid lines at every multiple of `step` (world units) across the visible rectangle.
    pub fn grid(&mut self, step: f64, color: Color) {
        let (min, max) = (self.world_min(), self.world_max());
        if !(step.is_finite() && step > 0.0)
            || (max - min).max_element() / step > 10_000.0
        {
            return;
        }
        let mut d = String::new();
        let mut k = (min.x / step).ceil();
        while k * step <= max.x {
            let x = self.to_page(DVec2::new(k * step, 0.0)).x;
            d.push_str(&format!("M {} 0 V {} ", num(x), num(self.height)));
            k += 1.0;
        }
        let mut k = (min.y / step).ceil();
        while k * step <= max.y {
            let y = self.to_page(DVec2::new(0.0, k * step)).y;
            d.push_str(&format!("M 0 {} H {} ", num(y), num(self.width)));
            k += 1.0;
        }
        if !d.is_empty() {
            let el = format!(
                r#"<path d="{}" fill="none" stroke="{}" stroke-width="1.00"/>"#,
                d.trim_end(),
                color.hex()
            );
            self.body.push(el);
        }
    }

    /// The x and y axes through the world origin across the page, with arrowheads, labelled
    /// "x" and "y". An axis whose line is off the page is left out.
    pub fn axes(&mut self, color: Color) {
        let stroke = Stroke::new(color).width(1.5);
        let o = self.to_page(DVec2::ZERO);
        let e = EDGE_INSET;
        if (0.0..=self.height).contains(&o.y) {
            let tip = DVec2::new(self.width - e, o.y);
            self.page_arrow(DVec2::new(e, o.y), tip, &stroke);
            self.page_label(
                tip - DVec2::new(6.0, -2.0),
                "x",
                Anchor::SW,
                LABEL_SIZE,
                color,
            );
        }
        if (0.0..=self.width).contains(&o.x) {
            let tip = DVec2::new(o.x, e);
            self.page_arrow(DVec2::new(o.x, self.height - e), tip, &stroke);
            self.page_label(
                tip + DVec2::new(2.0, 6.0),
                "y",
                Anchor::SE,
                LABEL_SIZE,
                color,
            );
        }
    }

    /// A 16 px black label at `p` (label markup: `"P_0"`, `"E_{12}"`, `"θ"`; see the crate docs).
    pub fn label(&mut self, p: DVec2, text: &str, anchor: Anchor) {
        self.label_sized(p, text, anchor, LABEL_SIZE, palette::BLACK);
    }

    /// A label at `p` with its size in page px and colour.
    pub fn label_sized(
        &mut self, p: DVec2, text: &str, anchor: Anchor, size_px: f64,
        color: Color,
    ) {
        let q = self.to_page(p);
        self.page_label(q, text, anchor, size_px, color);
    }

    /// Black text at page point `p_page` (y down), for titles and captions.
    pub fn text_page(
        &mut self, p_page: DVec2, text: &str, anchor: Anchor, size_px: f64,
    ) {
        self.page_label(p_page, text, anchor, size_px, palette::BLACK);
    }

    /// A label at a page point.
    fn page_label(
        &mut self, q: DVec2, text: &str, anchor: Anchor, size: f64,
        color: Color,
    ) {
        let (align, x, y) = label_position(q, anchor, size);
        let el = text_element(x, y, text, align, size, color);
        self.push(&[q], el);
    }

    /// The SVG document drawn so far, before usvg: text is still `<text>` in "DejaVu Sans".
    pub fn to_svg_source(&self) -> String {
        let (w, h) = (num(self.width), num(self.height));
        let mut s = format!(
            "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{w}\" height=\"{h}\" \
             viewBox=\"0 0 {w} {h}\" font-family=\"DejaVu Sans\">\n\
             <rect x=\"0\" y=\"0\" width=\"{w}\" height=\"{h}\" fill=\"#ffffff\"/>\n"
        );
        for el in &self.body {
            s.push_str(el);
            s.push('\n');
        }
        s.push_str("</svg>\n");
        s
    }
}

/// Where a label's text goes for a page point `q`: its alignment and the start of its baseline.
fn label_position(q: DVec2, anchor: Anchor, size: f64) -> (Align, f64, f64) {
    let gap = 0.35 * size; // between a cardinal label and its point
    let diag = 0.25 * size; // in x and in y for a diagonal one
    let (align, x) = match anchor {
        Anchor::Center | Anchor::N | Anchor::S => (Align::Middle, q.x),
        Anchor::E => (Align::Start, q.x + gap),
        Anchor::NE | Anchor::SE => (Align::Start, q.x + diag),
        Anchor::W => (Align::End, q.x - gap),
        Anchor::NW | Anchor::SW => (Align::End, q.x - diag),
    };
    let y = match anchor {
        Anchor::Center | Anchor::E | Anchor::W => q.y + CAP_HEIGHT * size / 2.0,
        Anchor::N => q.y - gap,
        Anchor::NE | Anchor::NW => q.y - diag,
        Anchor::S => q.y + gap + CAP_HEIGHT * size,
        Anchor::SE | Anchor::SW => q.y + diag + CAP_HEIGHT * size,
    };
    (align, x, y)
}

/// The SVG `points` list of page points.
fn points_attr(q: &[DVec2]) -> String {
    q.iter()
        .map(|p| format!("{},{}", num(p.x), num(p.y)))
        .collect::<Vec<_>>()
        .join(" ")
}

/// Clips the line `p + t·dir`, `t` in [`t_min`, `t_max`], to the rectangle [`min`, `max`]
/// (Liang–Barsky). Returns the parameter range inside, or `None` if the line misses it or `dir`
/// is zero.
pub fn clip_line(
    p: DVec2, dir: DVec2, min: DVec2, max: DVec2, t_min: f64, t_max: f64,
) -> Option<(f64, f64)> {
    if dir == DVec2::ZERO {
        return None;
    }
    let (mut lo, mut hi) = (t_min, t_max);
    for (p, d, min, max) in
        [(p.x, dir.x, min.x, max.x), (p.y, dir.y, min.y, max.y)]
    {
        if d == 0.0 {
            if p < min || p > max {
                return None;
            }
        } else {
            let (a, b) = ((min - p) / d, (max - p) / d);
            lo = lo.max(a.min(b));
            hi = hi.min(a.max(b));
        }
    }
    (lo <= hi && lo.is_finite() && hi.is_finite()).then_some((lo, hi))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn close(a: DVec2, b: DVec2) -> bool {
        (a - b).length() < 1e-9
    }

    #[test]
    fn view_maps_window_centred_with_margin() {
        let page = Page::new(400.0, 200.0)
            .view(DVec2::new(-1.0, -1.0), DVec2::new(1.0, 1.0));
        assert!((page.scale() - 76.0).abs() < 1e-12); // (200 - 2·24) / 2
        assert!(close(page.to_page(DVec2::ZERO), DVec2::new(200.0, 100.0)));
        assert!(close(
            page.to_page(DVec2::new(1.0, 1.0)),
            DVec2::new(276.0, 24.0)
        ));
        assert!(close(
            page.to_page(page.world_min()),
            DVec2::new(0.0, 200.0)
        ));
        assert!(close(
            page.to_page(page.world_max()),
            DVec2::new(400.0, 0.0)
        ));
    }

    #[test]
    fn clipped_line_ends_on_the_border() {
        let (min, max) = (DVec2::new(-2.0, -1.0), DVec2::new(2.0, 1.0));
        let (p, d) = (DVec2::new(0.5, 0.0), DVec2::new(1.0, 1.0));
        let (t0, t1) =
            clip_line(p, d, min, max, f64::NEG_INFINITY, f64::INFINITY)
                .unwrap();
        assert!(close(p + t0 * d, DVec2::new(-0.5, -1.0)));
        assert!(close(p + t1 * d, DVec2::new(1.5, 1.0)));
        // a ray only goes forward
        let (t0, _) = clip_line(p, d, min, max, 0.0, f64::INFINITY).unwrap();
        assert_eq!(t0, 0.0);
        // misses
        assert!(
            clip_line(DVec2::new(0.0, 5.0), DVec2::X, min, max, -1e9, 1e9)
                .is_none()
        );
        assert!(clip_line(p, DVec2::ZERO, min, max, -1e9, 1e9).is_none());
    }

    #[test]
    fn line_through_the_view_reaches_the_page_border() {
        let mut page =
            Page::new(300.0, 200.0).view(DVec2::splat(-1.0), DVec2::splat(1.0));
        page.line(
            DVec2::ZERO,
            DVec2::new(1.0, 0.3),
            &Stroke::new(palette::BLACK),
        );
        let svg = page.to_svg_source();
        // the line y = 0.3 x leaves through the left and right page edges
        assert!(svg.contains(r#"<line x1="0.00""#), "{svg}");
        assert!(svg.contains(r#"x2="300.00""#), "{svg}");
    }

    #[test]
    fn labels_use_subscript_tspans_and_escape() {
        let mut page = Page::new(100.0, 100.0);
        page.label(DVec2::new(10.0, 10.0), "P_0", Anchor::NE);
        page.label(DVec2::new(10.0, 10.0), "E_{12}", Anchor::SW);
        page.label(DVec2::new(10.0, 10.0), "f(x, y) < 0", Anchor::Center);
        let svg = page.to_svg_source();
        assert!(svg.contains(r#"baseline-shift="-3.20">0</tspan>"#), "{svg}");
        assert!(
            svg.contains(r#"baseline-shift="-3.20">12</tspan>"#),
            "{svg}"
        );
        assert!(svg.contains("f(x, y) &lt; 0"), "{svg}");
        assert!(!svg.contains("y) < 0"), "{svg}");
    }

    #[test]
    fn anchors_point_away_from_a_direction() {
        assert_eq!(Anchor::toward(DVec2::new(1.0, 0.0)), Anchor::E);
        assert_eq!(Anchor::toward(DVec2::new(1.0, -1.0)), Anchor::NE); // page y down
        assert_eq!(Anchor::toward(DVec2::new(0.0, 1.0)), Anchor::S);
        assert_eq!(Anchor::toward(DVec2::new(-1.0, 0.1)), Anchor::W);
    }
}
