//! Chapter 7's lecture figures, drawn from the chapter's own code.
//!
//! Every verdict and number shown comes from the chapter's code: which
//! pixel centres a triangle covers and who owns a shared edge from
//! [`covers`] and chapter 2's [`edge_function`] and [`owns_boundary`]; the
//! order in which the rasterizer visits pixels, its z tests and its counts
//! from the pieces of [`rasterize`] (checked against [`rasterize`] itself);
//! each ray's tests from the world's polygons (checked against
//! [`raycast`]); the images, depths and ids from [`rasterize`] and
//! [`raycast`], and the differing pixels from [`compare`].
use ch02::{edge_function, owns_boundary};
use raystep_core::Interval;
use raystep_figure::numbers::{fixed, grouped, scientific, signed};
use raystep_figure::{Anchor, Color, DVec2, Figure, Page, Stroke, palette};
use raystep_render::{Image, srgb8};

use ch07::{
    Buffers, DepthBuffer, Mesh, Projection, Stage, barycentric, clip_near,
    compare, covers, perspective_depth, rasterize, raycast, shapes,
};

/// Every figure of chapter 7, in the order the lecture shows them.
pub fn all() -> Vec<Figure> {
    vec![loops(), coverage(), depth(), agreement()]
}

/// One colour per triangle (as chapter 2 colours its polygons).
const TRIANGLE_COLORS: [Color; 3] =
    [palette::SKY_BLUE, palette::ORANGE, palette::GREEN];
/// The ids' colours in the id images (not vermilion: that marks a
/// difference).
const ID_COLORS: [Color; 8] = [
    palette::SKY_BLUE,
    palette::ORANGE,
    palette::GREEN,
    palette::PURPLE,
    palette::YELLOW,
    palette::BLUE,
    palette::GREY,
    Color::rgb(160, 120, 80),
];
/// Rejected by the z test, or differing between the methods.
const REJECT_COLOR: Color = palette::VERMILION;
/// Pixel grid lines.
const GRID_COLOR: Color = Color::rgb(200, 200, 200);

/// A light tint of a colour, for filled cells.
fn tint(c: Color) -> Color {
    c.mix(palette::WHITE, 0.55)
}

/// A darker shade of a colour, for text and outlines.
fn shade(c: Color) -> Color {
    c.mix(palette::BLACK, 0.35)
}

/// The stage of a scene file's text at `width × height`.
fn stage_from(text: &str, name: &str, width: u32, height: u32) -> Stage {
    let mut scene =
        raystep_scene::parse(text, name).expect("the figure's scene parses");
    (scene.width, scene.height) = (width, height);
    Stage::from_scene(&scene, name)
        .expect("the figure's scene has only polygons")
}

/// The projection both methods use for `stage`.
fn projection_of(stage: &Stage) -> Projection {
    Projection {
        camera: stage.world.camera,
        width: stage.world.width,
        height: stage.world.height,
    }
}

/// A pixel grid on the page: pixel (0, 0) at the top left of the world
/// rectangle whose top-left corner is `top_left`, `cell` world units a
/// pixel. Pixel coordinates have y down, the page's world y up.
#[derive(Clone, Copy)]
struct Grid {
    top_left: DVec2,
    cell: f64,
    width: u32,
    height: u32,
}

impl Grid {
    /// The world point of pixel coordinates `p` (y down).
    fn at(&self, p: DVec2) -> DVec2 {
        self.top_left + DVec2::new(p.x, -p.y) * self.cell
    }

    /// The world point of the centre of pixel (column, row).
    fn centre(&self, column: u32, row: u32) -> DVec2 {
        self.at(Projection::pixel_centre(column, row))
    }

    /// Bottom-left and top-right corners of the whole grid.
    fn bounds(&self) -> (DVec2, DVec2) {
        let (w, h) = (f64::from(self.width), f64::from(self.height));
        (self.at(DVec2::new(0.0, h)), self.at(DVec2::new(w, 0.0)))
    }

    /// Every cell filled by `fill` (None: white), with thin grid lines.
    fn draw(&self, page: &mut Page, fill: impl Fn(u32, u32) -> Option<Color>) {
        let (min, max) = self.bounds();
        page.raster(min, max, self.width, self.height, |c, r| {
            fill(c, r).unwrap_or(palette::WHITE)
        });
        let line = Stroke::new(GRID_COLOR).width(1.0);
        for c in 0..=self.width {
            let x = self.at(DVec2::new(f64::from(c), 0.0)).x;
            page.segment(DVec2::new(x, min.y), DVec2::new(x, max.y), &line);
        }
        for r in 0..=self.height {
            let y = self.at(DVec2::new(0.0, f64::from(r))).y;
            page.segment(DVec2::new(min.x, y), DVec2::new(max.x, y), &line);
        }
    }

    /// A frame around the grid.
    fn frame(&self, page: &mut Page) {
        let (min, max) = self.bounds();
        page.polygon(
            &[min, DVec2::new(max.x, min.y), max, DVec2::new(min.x, max.y)],
            None,
            Some(&Stroke::new(palette::GREY).width(1.0)),
        );
    }
}

/// The small scene of the loop figure: three triangles at three depths,
/// drawn in this order: A at the back, B in front, C between them.
const LOOPS_SCENE: &str = r#"
[camera]
look_from = [0, 0, 6]
look_at = [0, 0, 0]
vfov = 40

[ambient]
intensity = 0.2

[[lights]]
position = [2, 3, 6]
intensity = 0.8

[materials.a]
kd = [0.3, 0.6, 0.9]

[materials.b]
kd = [0.9, 0.6, 0.2]

[materials.c]
kd = [0.2, 0.7, 0.5]

# A, at the back
[[objects]]
polygon = { vertices = [[-4.0, -2.6, -2], [0.8, -2.6, -2], [-1.8, 2.6, -2]] }
material = "a"

# B, in front
[[objects]]
polygon = { vertices = [[-1.2, -1.5, 1], [1.5, 1.2, 1], [-1.1, 1.5, 1]] }
material = "b"

# C, between A and B
[[objects]]
polygon = { vertices = [[-0.9, -1.9, 0], [2.7, -1.5, 0], [0.5, 1.9, 0]] }
material = "c"
"#;

/// One covered pixel centre in the rasterizer's loop.
struct Visit {
    /// The triangle being drawn (an index into the stage's triangles).
    triangle: usize,
    column: u32,
    row: u32,
    /// Passed the z test and was shaded.
    shaded: bool,
}

/// The rasterizer's loop taken apart: every covered pixel centre in the
/// order [`rasterize`] visits them, with the verdict of the z test, and
/// the number of pixel centres tested. Built from the same pieces, and
/// checked against [`rasterize`] itself.
fn raster_visits(stage: &Stage) -> (Vec<Visit>, u64) {
    let projection = projection_of(stage);
    let (width, height) = (stage.world.width, stage.world.height);
    let mut depth = DepthBuffer::new(width, height);
    let mut visits = Vec::new();
    let mut tested = 0;
    for (k, triangle) in stage.triangles.iter().enumerate() {
        let view = clip_near(triangle.corners.map(|p| projection.view(p)));
        for j in 1..view.len().saturating_sub(1) {
            let corners = [view[0], view[j], view[j + 1]];
            let screen = corners.map(|v| projection.to_pixels(v));
            let z = corners.map(|v| v.z);
            let lo = screen[0].min(screen[1]).min(screen[2]);
            let hi = screen[0].max(screen[1]).max(screen[2]);
            for row in 0..height {
                for column in 0..width {
                    let p = Projection::pixel_centre(column, row);
                    if p.cmplt(lo).any() || p.cmpgt(hi).any() {
                        continue;
                    }
                    tested += 1;
                    if !covers(&screen, p) {
                        continue;
                    }
                    let lambda = barycentric(&screen, p)
                        .expect("a covering triangle has an area");
                    let shaded = depth.test_and_set(
                        column,
                        row,
                        perspective_depth(lambda, z),
                    );
                    visits.push(Visit {
                        triangle: k,
                        column,
                        row,
                        shaded,
                    });
                }
            }
        }
    }
    // the same loop as rasterize's: the same counts and the same ids
    let (buffers, counts) = rasterize(stage);
    assert_eq!(counts.tested, tested, "pixel centres tested");
    assert_eq!(counts.covered, visits.len() as u64, "covered");
    let shaded = visits.iter().filter(|v| v.shaded).count() as u64;
    assert_eq!(counts.shaded, shaded, "shaded");
    let mut ids = vec![None; buffers.id.len()];
    for v in visits.iter().filter(|v| v.shaded) {
        ids[v.row as usize * width as usize + v.column as usize] =
            Some(stage.triangles[v.triangle].object);
    }
    assert_eq!(ids, buffers.id, "the visits give rasterize's ids");
    (visits, tested)
}

/// Each pixel's ray against each object: the distance of its hit, if any.
/// The closest is what [`raycast`] keeps (checked).
fn ray_tests(stage: &Stage) -> Vec<Vec<Option<f64>>> {
    let world = &stage.world;
    let (width, height) = (world.width, world.height);
    let mut tests = Vec::new();
    let mut ids = Vec::new();
    for row in 0..height {
        for column in 0..width {
            let ray = world.camera.pixel_ray(column, row, width, height);
            let hits: Vec<Option<f64>> = world
                .objects
                .iter()
                .map(|o| {
                    o.shape.intersect(&ray, Interval::FORWARD).map(|h| h.t)
                })
                .collect();
            ids.push(closest(&hits));
            tests.push(hits);
        }
    }
    assert_eq!(ids, raycast(stage).id, "the closest hits are raycast's ids");
    tests
}

/// The index of the closest hit (the first of equals, as closest_hit keeps it).
fn closest(hits: &[Option<f64>]) -> Option<usize> {
    let mut best: Option<(usize, f64)> = None;
    for (i, t) in hits.iter().enumerate() {
        match (*t, best) {
            (Some(t), Some((_, b))) if t >= b => {}
            (Some(t), _) => best = Some((i, t)),
            (None, _) => {}
        }
    }
    best.map(|(i, _)| i)
}

/// The projected outline of each triangle of the stage on `grid`.
fn outlines(page: &mut Page, stage: &Stage, grid: &Grid) {
    let projection = projection_of(stage);
    for triangle in &stage.triangles {
        let view = clip_near(triangle.corners.map(|p| projection.view(p)));
        let pts: Vec<DVec2> = view
            .iter()
            .map(|&v| grid.at(projection.to_pixels(v)))
            .collect();
        page.polygon(
            &pts,
            None,
            Some(
                &Stroke::new(shade(TRIANGLE_COLORS[triangle.object % 3]))
                    .width(1.5),
            ),
        );
    }
}

/// The two loop orders on a 12 × 8 image of three triangles.
fn loops() -> Figure {
    let (w, h) = (12, 8);
    let stage = stage_from(LOOPS_SCENE, "loops.toml", w, h);
    let names = ["A", "B", "C"];
    let n = stage.triangles.len();
    assert_eq!(n, 3, "three triangles, one object each");
    let (visits, tested) = raster_visits(&stage);
    let tests = ray_tests(&stage);
    let (raster, _) = rasterize(&stage);

    // the two loops one above the other, each grid with its counts on
    // its right
    let cell = 50.0;
    let (gw, gh) = (f64::from(w) * cell, f64::from(h) * cell);
    let (side, top, below) = (20.0, 48.0, 30.0);
    let panel = top + gh + below;
    let (width, height) = (900.0, 2.0 * panel);
    let mut page = Page::new(width, height);
    let left = Grid {
        top_left: DVec2::new(side, height - top),
        cell,
        width: w,
        height: h,
    };
    let right = Grid {
        top_left: DVec2::new(side, height - panel - top),
        ..left
    };
    let notes_x = side + gw + 24.0;
    let final_color = |c: u32, r: u32| {
        raster.id_at(c, r).map(|i| tint(TRIANGLE_COLORS[i % 3]))
    };

    // Top: object order.
    page.label_sized(
        DVec2::new(side, height - 22.0),
        "rasterization: for each triangle, for each pixel it covers",
        Anchor::E,
        17.0,
        palette::BLACK,
    );
    left.draw(&mut page, final_color);
    outlines(&mut page, &stage, &left);
    // the visits of each pixel, in order: the step number, struck out if
    // a later triangle drew over it, × if the z test rejected it
    let mut per_pixel: Vec<Vec<(usize, &Visit)>> =
        vec![Vec::new(); (w * h) as usize];
    for (step, v) in visits.iter().enumerate() {
        per_pixel[(v.row * w + v.column) as usize].push((step + 1, v));
    }
    let mut overdrawn = 0;
    for row in 0..h {
        for column in 0..w {
            let list = &per_pixel[(row * w + column) as usize];
            let last_shaded = list.iter().rposition(|(_, v)| v.shaded);
            let centre = left.centre(column, row);
            let lines = list.len() as f64;
            let (step_y, size) = if list.len() > 2 {
                (14.0, 13.0)
            } else {
                (17.0, 15.0)
            };
            for (k, (step, v)) in list.iter().enumerate() {
                let y =
                    centre.y + (lines - 1.0) * step_y / 2.0 - step_y * k as f64;
                let at = DVec2::new(centre.x, y);
                let text = format!("{}{step}", names[v.triangle]);
                if !v.shaded {
                    page.label_sized(
                        at,
                        &format!("×{text}"),
                        Anchor::Center,
                        size - 1.0,
                        shade(REJECT_COLOR),
                    );
                } else if Some(k) == last_shaded {
                    page.label_sized(
                        at,
                        &text,
                        Anchor::Center,
                        size,
                        palette::BLACK,
                    );
                } else {
                    overdrawn += 1;
                    page.label_sized(
                        at,
                        &text,
                        Anchor::Center,
                        size - 1.0,
                        palette::NOTE,
                    );
                    page.segment(
                        at - DVec2::new(14.0, 0.0),
                        at + DVec2::new(14.0, 0.0),
                        &Stroke::new(palette::NOTE).width(1.2),
                    );
                }
            }
        }
    }
    left.frame(&mut page);

    // Bottom: image order.
    page.label_sized(
        DVec2::new(side, height - panel - 22.0),
        "ray casting: for each pixel, for each triangle",
        Anchor::E,
        17.0,
        palette::BLACK,
    );
    let ids: Vec<Option<usize>> =
        tests.iter().map(|hits| closest(hits)).collect();
    assert_eq!(
        ids, raster.id,
        "both loops show the same triangle everywhere"
    );
    right.draw(&mut page, |c, r| {
        ids[(r * w + c) as usize].map(|i| tint(TRIANGLE_COLORS[i % 3]))
    });
    outlines(&mut page, &stage, &right);
    let mut hits = 0;
    for row in 0..h {
        for column in 0..w {
            let i = (row * w + column) as usize;
            let centre = right.centre(column, row);
            page.label_sized(
                centre + DVec2::new(0.0, 9.0),
                &(i + 1).to_string(),
                Anchor::Center,
                14.0,
                palette::NOTE,
            );
            // one box per triangle tested: filled if the ray hits it,
            // framed in black if it is the closest
            for (k, t) in tests[i].iter().enumerate() {
                let x = centre.x + (k as f64 - 1.0) * 13.0;
                let (lo, hi) = (
                    DVec2::new(x - 5.0, centre.y - 17.0),
                    DVec2::new(x + 5.0, centre.y - 7.0),
                );
                let square =
                    [lo, DVec2::new(hi.x, lo.y), hi, DVec2::new(lo.x, hi.y)];
                let kept = ids[i] == Some(k);
                hits += usize::from(t.is_some());
                page.polygon(
                    &square,
                    Some(if t.is_some() {
                        TRIANGLE_COLORS[k]
                    } else {
                        palette::WHITE
                    }),
                    Some(&if kept {
                        Stroke::new(palette::BLACK).width(1.6)
                    } else {
                        Stroke::new(palette::GREY).width(0.8)
                    }),
                );
            }
        }
    }
    right.frame(&mut page);

    // What each loop did, counted.
    let covered = visits.len();
    let shaded = visits.iter().filter(|v| v.shaded).count();
    let rejected = covered - shaded;
    let shown = raster.id.iter().filter(|i| i.is_some()).count();
    let pixels = (w * h) as usize;
    let ranges: Vec<String> = (0..n)
        .map(|k| {
            let steps: Vec<usize> = visits
                .iter()
                .enumerate()
                .filter(|(_, v)| v.triangle == k)
                .map(|(s, _)| s + 1)
                .collect();
            format!(
                "{} {}–{}",
                names[k],
                steps.first().expect("each triangle covers a pixel"),
                steps.last().expect("each triangle covers a pixel")
            )
        })
        .collect();
    let lines = |page: &mut Page, y: f64, lines: &[String]| {
        let lines: Vec<(&str, Color)> =
            lines.iter().map(|l| (l.as_str(), palette::BLACK)).collect();
        page.text_lines(DVec2::new(notes_x, y), 21.0, 15.0, &lines);
    };
    lines(
        &mut page,
        left.top_left.y - 10.0,
        &[
            "steps in drawing order:".to_string(),
            ranges.join(", "),
            String::new(),
            format!("tested: {tested} pixel centres,"),
            "those in the triangles' boxes".to_string(),
            format!("covered: {covered}"),
            format!("shaded: {shaded}"),
            format!("× rejected by the z test: {rejected}"),
            format!("struck out, drawn over: {overdrawn}"),
            format!("pixels shown: {shown}"),
        ],
    );
    lines(
        &mut page,
        right.top_left.y - 10.0,
        &[
            format!("pixels in image order 1–{pixels}"),
            String::new(),
            "boxes: each ray's tests".to_string(),
            "of A, B and C".to_string(),
            "filled: a hit".to_string(),
            "framed in black: the closest,".to_string(),
            "kept".to_string(),
            String::new(),
            format!("{pixels} rays × {n} triangles"),
            format!("= {} ray–triangle tests", pixels * n),
            format!("{hits} hits"),
            format!("{shown} pixels shown, each"),
            "shaded once".to_string(),
        ],
    );
    Figure::new(
        "loops",
        &format!(
            "The lecture's two loops on the same three triangles at {w} × {h} pixels (A at the back, B in front, C between them; outlines: the triangles on screen). Top, rasterization in object order: triangle by triangle, the rasterizer tests the pixel centres of its bounding box, and numbers the ones it covers in the order it visits them; the z test rejects the pixels of C that B hides (×), and B and C draw over A (struck out). Below, ray casting in image order: pixel by pixel, the ray is tested against every triangle and the closest hit is kept. Both end with the same image: {shown} pixels of the {pixels} show a triangle."
        ),
        page,
    )
}

/// The coverage figure's two triangles on a 14 × 10 pixel grid, in pixel
/// coordinates (y down): they share the edge S → E, which passes exactly
/// through six pixel centres (every coordinate is a multiple of ¼, so
/// every edge function here is exact).
const SHARED_S: DVec2 = DVec2::new(1.0, 8.75);
const SHARED_E: DVec2 = DVec2::new(12.0, 3.25);
const A_CORNER: DVec2 = DVec2::new(3.25, 0.75);
const B_CORNER: DVec2 = DVec2::new(12.75, 9.5);

/// The edges of a triangle as [`covers`] walks them: inside on their
/// positive side (every edge function positive inside).
fn inner_edges(corners: &[DVec2; 3]) -> [(DVec2, DVec2); 3] {
    let [a, b, c] = *corners;
    if edge_function(a, b, c) > 0.0 {
        [(a, b), (b, c), (c, a)]
    } else {
        [(a, c), (c, b), (b, a)]
    }
}

/// Two triangles sharing an edge through pixel centres: which centres each
/// covers, and who owns the centres on the shared edge.
fn coverage() -> Figure {
    let (w, h) = (14, 10);
    let a = [SHARED_S, SHARED_E, A_CORNER];
    let b = [SHARED_S, B_CORNER, SHARED_E];
    // the grid, centred, and under it what it shows in two columns
    let cell = 48.0;
    let (gw, gh) = (f64::from(w) * cell, f64::from(h) * cell);
    let (top, legend) = (16.0, 236.0);
    let width = 900.0;
    let height = top + gh + legend;
    let mut page = Page::new(width, height);
    let grid = Grid {
        top_left: DVec2::new((width - gw) / 2.0, height - top),
        cell,
        width: w,
        height: h,
    };
    grid.draw(&mut page, |_, _| None);
    let (ca, cb) = (TRIANGLE_COLORS[0], TRIANGLE_COLORS[1]);
    for (t, color) in [(&a, ca), (&b, cb)] {
        let pts: Vec<DVec2> = t.iter().map(|&p| grid.at(p)).collect();
        page.polygon_alpha(
            &pts,
            Some(color.with_alpha(0.22)),
            Some(&Stroke::new(shade(color)).width(1.5)),
        );
    }
    page.segment(
        grid.at(SHARED_S),
        grid.at(SHARED_E),
        &Stroke::new(palette::BLACK).width(2.5),
    );

    // B's edges as covers walks them, each with its inward normal: the
    // side where its edge function is positive
    let b_edges = inner_edges(&b);
    let is_shared = |from: DVec2, to: DVec2| {
        [from, to].contains(&SHARED_S) && [from, to].contains(&SHARED_E)
    };
    for (k, &(from, to)) in b_edges.iter().enumerate() {
        // on the shared edge, clear of A's arrow
        let mid = if is_shared(from, to) {
            SHARED_S + 0.72 * (SHARED_E - SHARED_S)
        } else {
            (from + to) / 2.0
        };
        let n = (to - from).perp().normalize();
        let tip = mid + 1.1 * n;
        page.arrow(
            grid.at(mid),
            grid.at(tip),
            &Stroke::new(shade(cb)).width(2.0),
        );
        page.label_sized(
            grid.at(tip),
            &format!("f_{}", k + 1),
            Anchor::pointing(DVec2::new(n.x, -n.y)),
            17.0,
            shade(cb),
        );
    }
    // A's normal on the shared edge points the other way
    let (a_from, a_to) = *inner_edges(&a)
        .iter()
        .find(|&&(f, t)| is_shared(f, t))
        .expect("A has the shared edge");
    let mid = SHARED_S + 0.3 * (SHARED_E - SHARED_S);
    let na = (a_to - a_from).perp().normalize();
    page.arrow(
        grid.at(mid),
        grid.at(mid + 1.1 * na),
        &Stroke::new(shade(ca)).width(2.0),
    );
    page.label_sized(
        grid.at(mid + 1.1 * na),
        "f_A",
        Anchor::pointing(DVec2::new(na.x, -na.y)),
        17.0,
        shade(ca),
    );

    // every pixel centre: whom it belongs to
    let (mut on_edge, mut by_a, mut by_b) = (Vec::new(), 0, 0);
    for row in 0..h {
        for column in 0..w {
            let p = Projection::pixel_centre(column, row);
            let (in_a, in_b) = (covers(&a, p), covers(&b, p));
            assert!(!(in_a && in_b), "no centre is covered twice: {p}");
            by_a += usize::from(in_a);
            by_b += usize::from(in_b);
            let at = grid.centre(column, row);
            let on = edge_function(SHARED_S, SHARED_E, p) == 0.0
                && (SHARED_S.x..=SHARED_E.x).contains(&p.x);
            if on {
                assert!(
                    in_a || in_b,
                    "no centre on the shared edge is left out: {p}"
                );
                on_edge.push((p, in_b));
                page.circle(
                    at,
                    7.0,
                    Some(if in_b { cb } else { ca }),
                    Some(&Stroke::new(palette::BLACK).width(2.0)),
                );
            } else if in_a || in_b {
                page.circle(
                    at,
                    4.0,
                    Some(shade(if in_b { cb } else { ca })),
                    None,
                );
            } else {
                page.circle(at, 2.0, Some(palette::GREY), None);
            }
        }
    }
    grid.frame(&mut page);
    page.label_sized(grid.at(SHARED_S), "S", Anchor::SW, 16.0, palette::BLACK);
    page.label_sized(grid.at(SHARED_E), "E", Anchor::NE, 16.0, palette::BLACK);
    page.label_sized(
        grid.at(DVec2::new(4.0, 3.0)), // a cell corner: no centre hidden
        "A",
        Anchor::Center,
        22.0,
        shade(ca),
    );
    page.label_sized(
        grid.at(DVec2::new(10.0, 7.0)),
        "B",
        Anchor::Center,
        22.0,
        shade(cb),
    );

    // a centre inside B and its three edge functions
    let q = DVec2::new(8.5, 7.5);
    let fq: Vec<f64> = b_edges
        .iter()
        .map(|&(f, t)| edge_function(f, t, q))
        .collect();
    assert!(covers(&b, q) && fq.iter().all(|&f| f > 0.0));
    page.circle(
        grid.at(q),
        9.0,
        None,
        Some(&Stroke::new(palette::BLACK).width(1.5)),
    );
    page.label_sized(grid.at(q), "Q", Anchor::SE, 16.0, palette::BLACK);

    // the owners of the shared edge, from owns_boundary
    let (b_from, b_to) = *b_edges
        .iter()
        .find(|&&(f, t)| is_shared(f, t))
        .expect("B has the shared edge");
    let nb = (b_to - b_from).perp();
    let na = (a_to - a_from).perp();
    let (a_owns, b_owns) =
        (owns_boundary(a_from, a_to), owns_boundary(b_from, b_to));
    assert!(b_owns && !a_owns, "B owns the shared edge");
    assert!(on_edge.iter().all(|&(_, b)| b), "B draws the shared edge");
    let pair = |v: DVec2| format!("({}, {})", signed(v.x, 6), signed(v.y, 6));

    let black = |t: &str| (t.to_string(), palette::BLACK);
    let left: Vec<(String, Color)> = vec![
        black("edge functions of B (pixel coordinates,"),
        black("y down): each positive on its arrow's side"),
        (
            format!(
                "at Q: f_1 = {}, f_2 = {}, f_3 = {}",
                signed(fq[0], 6),
                signed(fq[1], 6),
                signed(fq[2], 6)
            ),
            shade(cb),
        ),
        ("all > 0: B covers Q".to_string(), shade(cb)),
        black(""),
        black(&format!(
            "{} centres lie on the shared edge S–E:",
            on_edge.len()
        )),
        black("f = 0 there for A and for B, exactly"),
        black("(large dots, in the colour of the"),
        black("triangle that draws them)"),
    ];
    let right: Vec<(String, Color)> = vec![
        black("owns\\_boundary: the inward normal"),
        (format!("A: n = {}, n.x < 0:", pair(na)), shade(ca)),
        ("A does not own it".to_string(), shade(ca)),
        (
            format!("B: n = {}, n.x > 0: B owns it", pair(nb)),
            shade(cb),
        ),
        black(""),
        black(&format!("covered: A {by_a}, B {by_b}")),
        black(&format!("(B with the {} on the edge)", on_edge.len())),
        black("no centre twice, none left out"),
    ];
    for (x, lines) in [(20.0, left), (480.0, right)] {
        let lines: Vec<(&str, Color)> =
            lines.iter().map(|(t, c)| (t.as_str(), *c)).collect();
        page.text_lines(DVec2::new(x, legend - 24.0), 22.0, 16.0, &lines);
    }
    Figure::new(
        "coverage",
        &format!(
            "Two triangles on a {w} × {h} pixel grid share the edge S–E, which passes exactly through {} pixel centres. covers tests each centre against a triangle's three edge functions (the arrows point to their positive sides); a centre exactly on an edge (f = 0) is drawn only by the triangle that owns that edge, chapter 2's owns_boundary: B, whose inward normal there points to +x. Large dots: the centres on the shared edge, all drawn by B; small dots: the other covered centres, in their triangle's colour.",
            on_edge.len()
        ),
        page,
    )
}

/// The background in a depth image: no depth at all.
const NO_DEPTH: Color = Color::rgb(255, 214, 170);

/// A grey for a depth: black at `near`, white at `far`.
fn depth_grey(z: f64, near: f64, far: f64) -> Color {
    if !z.is_finite() {
        return NO_DEPTH;
    }
    let g = ((z - near) / (far - near)).clamp(0.0, 1.0);
    palette::BLACK.mix(palette::WHITE, g)
}

/// The 8-bit RGB bytes of a `width × height` image of colours.
fn rgb8(width: u32, height: u32, pixel: impl Fn(u32, u32) -> Color) -> Vec<u8> {
    let mut bytes = Vec::with_capacity((width * height * 3) as usize);
    for row in 0..height {
        for column in 0..width {
            let c = pixel(column, row);
            bytes.extend([c.r, c.g, c.b]);
        }
    }
    bytes
}

/// The z-buffer of the shapes scene as a depth image, beside the colours.
fn depth() -> Figure {
    let (w, h) = (320, 180);
    let subdivisions = 2;
    let stage = shapes(subdivisions, w, h);
    let (buffers, counts) = rasterize(&stage);
    let finite: Vec<f64> = buffers
        .depth
        .iter()
        .copied()
        .filter(|z| z.is_finite())
        .collect();
    let near = finite.iter().copied().fold(f64::INFINITY, f64::min);
    let far = finite.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    let background = buffers.depth.len() - finite.len();
    let (pw, ph) = (f64::from(w), f64::from(h));
    let (side, gap, top, bottom) = (16.0, 16.0, 36.0, 116.0);
    let width = 2.0 * side + 2.0 * pw + gap;
    let height = top + ph + bottom;
    let mut page = Page::new(width, height);
    let y0 = bottom;
    page.image(
        DVec2::new(side, y0),
        DVec2::new(side + pw, y0 + ph),
        w,
        h,
        &buffers.color.to_srgb8(),
    );
    let x1 = side + pw + gap;
    page.image(
        DVec2::new(x1, y0),
        DVec2::new(x1 + pw, y0 + ph),
        w,
        h,
        &rgb8(w, h, |c, r| depth_grey(buffers.depth_at(c, r), near, far)),
    );
    page.label_sized(
        DVec2::new(side + pw / 2.0, y0 + ph + 10.0),
        "colour buffer",
        Anchor::N,
        16.0,
        palette::BLACK,
    );
    page.label_sized(
        DVec2::new(x1 + pw / 2.0, y0 + ph + 10.0),
        "depth buffer: the view depth z",
        Anchor::N,
        16.0,
        palette::BLACK,
    );
    // the grey scale under the depth image, and the background's colour
    let (bar_lo, bar_hi) = (DVec2::new(x1, 84.0), DVec2::new(x1 + pw, 98.0));
    let steps = 320;
    page.image(
        bar_lo,
        bar_hi,
        steps,
        1,
        &rgb8(steps, 1, |c, _| {
            let z =
                near + (far - near) * (f64::from(c) + 0.5) / f64::from(steps);
            depth_grey(z, near, far)
        }),
    );
    let frame = Stroke::new(palette::GREY).width(1.0);
    page.polygon(
        &[
            bar_lo,
            DVec2::new(bar_hi.x, bar_lo.y),
            bar_hi,
            DVec2::new(bar_lo.x, bar_hi.y),
        ],
        None,
        Some(&frame),
    );
    page.label_sized(
        DVec2::new(bar_lo.x, bar_lo.y - 4.0),
        &format!("z = {}, nearest", fixed(near, 2)),
        Anchor::SE,
        15.0,
        palette::BLACK,
    );
    page.label_sized(
        DVec2::new(bar_hi.x, bar_lo.y - 4.0),
        &format!("z = {}, farthest", fixed(far, 2)),
        Anchor::SW,
        15.0,
        palette::BLACK,
    );
    let sw = DVec2::new(x1, 16.0);
    page.polygon(
        &[
            sw,
            sw + DVec2::new(14.0, 0.0),
            sw + DVec2::new(14.0, 14.0),
            sw + DVec2::new(0.0, 14.0),
        ],
        Some(NO_DEPTH),
        Some(&frame),
    );
    page.label_sized(
        sw + DVec2::new(14.0, 7.0),
        "+∞: nothing drawn, the background",
        Anchor::E,
        15.0,
        palette::BLACK,
    );
    let lines = [
        format!(
            "{} triangles: {} pixel tests,",
            counts.triangles,
            grouped(counts.tested)
        ),
        format!(
            "{} covered, {} passed",
            grouped(counts.covered),
            grouped(counts.shaded)
        ),
        "the z test and were shaded;".to_string(),
        format!(
            "{} of {} pixels show",
            grouped(background as u64),
            grouped(u64::from(w * h))
        ),
        "the background".to_string(),
    ];
    let lines: Vec<(&str, Color)> =
        lines.iter().map(|l| (l.as_str(), palette::NOTE)).collect();
    page.text_lines(DVec2::new(side, bottom - 16.0), 20.0, 15.0, &lines);
    Figure::new(
        "depth",
        &format!(
            "The shapes scene (with a ball of {} triangles) rasterized at {w} × {h}: left the colour buffer, right the depth buffer it was drawn with, the view depth z of what each pixel shows in grey from black (z = {}) to white (z = {}); where nothing is drawn the buffer keeps its +∞.",
            Mesh::icosphere(subdivisions).triangles.len(),
            fixed(near, 2),
            fixed(far, 2)
        ),
        page,
    )
}

/// The fan of the agreement figure: eight triangles around a pixel centre
/// in the plane z = 0, facing a camera that puts the point (x, y, 0) at
/// pixel coordinates (16 + 2x, 8 − 2y) exactly; every corner is a pixel
/// centre and every edge runs through pixel centres.
fn fan_stage() -> Stage {
    let mut text = String::from(
        "[camera]\nlook_from = [0, 0, 4]\nlook_at = [0, 0, 0]\nvfov = 53\n\
         [ambient]\nintensity = 0.2\n\
         [[lights]]\nposition = [1, 2, 5]\nintensity = 0.8\n\
         [materials.light]\nkd = 0.8\n\
         [materials.dark]\nkd = 0.4\n",
    );
    // from pixel coordinates to the plane z = 0
    let at = |px: f64, py: f64| [(px - 16.0) / 2.0, (8.0 - py) / 2.0, 0.0];
    let hub = (16.5, 8.5);
    let rim = [
        (12.0, 0.0),
        (6.0, -6.0),
        (0.0, -6.0),
        (-6.0, -6.0),
        (-12.0, 0.0),
        (-6.0, 6.0),
        (0.0, 6.0),
        (6.0, 6.0),
    ];
    for k in 0..rim.len() {
        let (p, q) = (rim[k], rim[(k + 1) % rim.len()]);
        let corners = [
            at(hub.0, hub.1),
            at(hub.0 + p.0, hub.1 + p.1),
            at(hub.0 + q.0, hub.1 + q.1),
        ];
        let list: Vec<String> = corners
            .iter()
            .map(|[x, y, z]| format!("[{x}, {y}, {z}]"))
            .collect();
        let material = if k % 2 == 0 { "light" } else { "dark" };
        text.push_str(&format!(
            "\n[[objects]]\npolygon = {{ vertices = [{}] }}\nmaterial = \"{material}\"\n",
            list.join(", ")
        ));
    }
    let mut stage = stage_from(&text, "fan.toml", 32, 16);
    stage.world.camera.half_height = 1.0;
    stage
}

/// The colour of pixel (column, row) of an id image: a tint per object,
/// white for the background.
fn id_pixels(buffers: &Buffers, column: u32, row: u32) -> Color {
    match buffers.id_at(column, row) {
        Some(i) => tint(ID_COLORS[i % ID_COLORS.len()]),
        None => palette::WHITE,
    }
}

/// The two methods' images side by side with their differences.
fn agreement() -> Figure {
    // Row 1: the shapes scene, whose edges pass no pixel centre.
    let (w, h) = (160, 90);
    let stage = shapes(2, w, h);
    let (raster, _) = rasterize(&stage);
    let cast = raycast(&stage);
    let shapes_agree = compare(&stage, &raster, &cast);
    assert!(
        shapes_agree.elsewhere.is_empty(),
        "ids differ only on edges"
    );
    // the colour differences, in linear units and in 8-bit sRGB
    let mut largest: f64 = 0.0;
    let mut bytes_differ = 0;
    for row in 0..h {
        for column in 0..w {
            let (a, b) =
                (raster.color.get(column, row), cast.color.get(column, row));
            largest = largest.max((a - b).abs().max_element());
            bytes_differ += usize::from(srgb8(a) != srgb8(b));
        }
    }
    let magnify = if largest > 0.0 { 1.0 / largest } else { 1.0 };
    let difference = rgb8(w, h, |c, r| {
        let d = (raster.color.get(c, r) - cast.color.get(c, r))
            .abs()
            .max_element();
        palette::WHITE.mix(palette::BLACK, d * magnify)
    });

    // Row 2: a fan whose every edge runs through pixel centres.
    let fan = fan_stage();
    let (fw, fh) = (fan.world.width, fan.world.height);
    let (fan_raster, _) = rasterize(&fan);
    let fan_cast = raycast(&fan);
    let fan_agree = compare(&fan, &fan_raster, &fan_cast);
    assert!(fan_agree.elsewhere.is_empty(), "ids differ only on edges");
    assert!(fan_agree.differing() > 0, "the fan shows differing pixels");
    let differs =
        |c: u32, r: u32| fan_raster.id_at(c, r) != fan_cast.id_at(c, r);

    let scale = 1.5;
    let (pw, ph) = (f64::from(w) * scale, f64::from(h) * scale);
    let fan_cell = pw / f64::from(fw);
    let fph = f64::from(fh) * fan_cell;
    let (side, gap, heading, foot) = (16.0, 48.0, 32.0, 56.0);
    let width = 2.0 * side + 3.0 * pw + 2.0 * gap;
    let height = heading + ph + foot + heading + fph + foot;
    let mut page = Page::new(width, height);
    let columns: Vec<f64> =
        (0..3).map(|k| side + f64::from(k) * (pw + gap)).collect();
    let title = |page: &mut Page, x: f64, y: f64, text: &str| {
        page.label_sized(
            DVec2::new(x + pw / 2.0, y + 8.0),
            text,
            Anchor::N,
            16.0,
            palette::BLACK,
        );
    };
    // a note of one or two lines under a picture
    let note = |page: &mut Page, x: f64, y: f64, lines: &[&str]| {
        for (k, line) in lines.iter().enumerate() {
            page.label_sized(
                DVec2::new(x + pw / 2.0, y - 6.0 - 20.0 * k as f64),
                line,
                Anchor::S,
                16.0,
                palette::NOTE,
            );
        }
    };

    // row 1
    let y1 = foot + fph + heading + foot;
    let images: [(&Image, &str); 2] =
        [(&raster.color, "rasterized"), (&cast.color, "ray-cast")];
    for (k, (image, name)) in images.iter().enumerate() {
        page.image(
            DVec2::new(columns[k], y1),
            DVec2::new(columns[k] + pw, y1 + ph),
            w,
            h,
            &image.to_srgb8(),
        );
        title(&mut page, columns[k], y1 + ph, name);
    }
    page.image(
        DVec2::new(columns[2], y1),
        DVec2::new(columns[2] + pw, y1 + ph),
        w,
        h,
        &difference,
    );
    let frame = |page: &mut Page, x: f64, y: f64, fw: f64, fh: f64| {
        page.polygon(
            &[
                DVec2::new(x, y),
                DVec2::new(x + fw, y),
                DVec2::new(x + fw, y + fh),
                DVec2::new(x, y + fh),
            ],
            None,
            Some(&Stroke::new(palette::GREY).width(1.0)),
        );
    };
    frame(&mut page, columns[2], y1, pw, ph);
    title(
        &mut page,
        columns[2],
        y1 + ph,
        "|difference|, black = largest",
    );
    note(
        &mut page,
        columns[0],
        y1,
        &[
            &format!("ids differ at {} of", shapes_agree.differing()),
            &format!("{} pixels", grouped(u64::from(w * h))),
        ],
    );
    note(
        &mut page,
        columns[1],
        y1,
        &[&format!("{bytes_differ} pixels differ"), "in 8-bit colour"],
    );
    note(
        &mut page,
        columns[2],
        y1,
        &["largest difference", &scientific(largest, true)],
    );

    // row 2
    let y2 = foot;
    let fan_pixels =
        |page: &mut Page, x: f64, pixel: &dyn Fn(u32, u32) -> Color| {
            let grid = Grid {
                top_left: DVec2::new(x, y2 + fph),
                cell: fan_cell,
                width: fw,
                height: fh,
            };
            grid.draw(page, |c, r| Some(pixel(c, r)));
            grid
        };
    fan_pixels(&mut page, columns[0], &|c, r| id_pixels(&fan_raster, c, r));
    title(&mut page, columns[0], y2 + fph, "rasterized ids");
    fan_pixels(&mut page, columns[1], &|c, r| id_pixels(&fan_cast, c, r));
    title(&mut page, columns[1], y2 + fph, "ray-cast ids");
    let grid = fan_pixels(&mut page, columns[2], &|c, r| {
        if differs(c, r) {
            REJECT_COLOR
        } else {
            id_pixels(&fan_raster, c, r).mix(palette::WHITE, 0.6)
        }
    });
    // the fan's edges over the differences
    let projection = projection_of(&fan);
    for t in &fan.triangles {
        let pts: Vec<DVec2> = t
            .corners
            .iter()
            .map(|&p| grid.at(projection.to_pixels(projection.view(p))))
            .collect();
        page.polygon(&pts, None, Some(&Stroke::new(palette::BLACK).width(1.0)));
    }
    title(&mut page, columns[2], y2 + fph, "where the ids differ");
    note(
        &mut page,
        columns[0],
        y2,
        &[
            &format!("{} triangles, corners", fan.triangles.len()),
            "on pixel centres",
        ],
    );
    note(&mut page, columns[1], y2, &[&format!("{fw} × {fh} pixels")]);
    note(
        &mut page,
        columns[2],
        y2,
        &[
            &format!("{} of {} differ,", fan_agree.differing(), fw * fh),
            "all on edges",
        ],
    );
    Figure::new(
        "agreement",
        &format!(
            "Top: the shapes scene at {w} × {h}, rasterized and ray-cast. The id buffers agree on all {} pixels ({} differ), and the colours differ by at most {} (linear units: rounding), which changes no 8-bit pixel ({bytes_differ} differ); the difference image is magnified so that the largest difference is black. Bottom: a fan of {} triangles at {fw} × {fh} whose every edge runs exactly through pixel centres: there the two sampling rules meet, and {} of the {} pixels differ (red), every one within {} pixel of an edge: the rasterizer decides a centre on an edge with its fill rule on the screen, the ray caster with chapter 2's rule in the triangle's own plane, after rounding.",
            grouped(u64::from(w * h)),
            shapes_agree.differing(),
            scientific(largest, false),
            fan.triangles.len(),
            fan_agree.differing(),
            fw * fh,
            scientific(ch07::ON_EDGE, false)
        ),
        page,
    )
}
