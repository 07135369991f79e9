//! Chapter 8's lecture figures: every primitive rendered, the lecture's
//! sketch of bounding circles and boxes, and the rays a bound lets through
//! for nothing.
use raystep_figure::palette;
use raystep_figure::{Anchor, DVec2, Figure, Page, Stroke};
use raystep_render::{Progress, RenderOptions};

use ch08::{
    Bound, BoundKind, DVec3, Interval, Primitive, Ray, Torus, TorusSolver,
    Triangle, TriangleTest,
};

use crate::sketch::{sketch_bounds, sketch_shapes};
use crate::torus_figure;

/// Every lecture figure of the chapter.
pub fn all() -> Vec<Figure> {
    let mut figures = vec![
        gallery(),
        bounds_sketch(),
        tightness(),
        torus_figure::torus_roots(),
        crate::instance_figure::instance_idea(),
    ];
    figures.extend(crate::mesh_figures::all());
    figures
}

/// `scenes/primitives.toml`: the fast row above, the slow row below.
pub const PRIMITIVES_SCENE: &str = include_str!("../../scenes/primitives.toml");

/// The gallery: the chapter's scene rendered by chapter 6's tracer.
fn gallery() -> Figure {
    let scene = raystep_scene::parse(PRIMITIVES_SCENE, "primitives.toml")
        .expect("the chapter's scene parses");
    let world =
        ch08::world(&scene, "primitives.toml").expect("the scene builds");
    let options = RenderOptions {
        threads: None,
        progress: Progress::Never,
    };
    let image = ch06_figures::render_exact(&world, &options)
        .expect("the scene renders");
    let (w, h) = (f64::from(image.width()), f64::from(image.height()));
    // a strip above the picture for the fast row's name, one below for
    // the slow row's
    let strip = 30.0;
    let mut page = Page::new(w, h + 2.0 * strip);
    page.image(
        DVec2::new(0.0, strip),
        DVec2::new(w, h + strip),
        image.width(),
        image.height(),
        &image.to_srgb8(),
    );
    page.label_sized(
        DVec2::new(w / 2.0, h + 1.5 * strip),
        "fast: sphere · box · cylinder · ellipsoid · polygon · triangle",
        Anchor::Center,
        16.0,
        palette::BLACK,
    );
    page.label_sized(
        DVec2::new(w / 2.0, 0.5 * strip),
        "slow: torus · monkey saddle · blobby object",
        Anchor::Center,
        16.0,
        palette::BLACK,
    );
    Figure::new(
        "gallery",
        "The chapter's primitives, rendered with chapter 6's tracer (scenes/primitives.toml). Top row, the fast ones: a sphere, a box, a capped cylinder, an ellipsoid, a polygon and a triangle. Bottom row, the slow ones: a torus (a quartic in t), the monkey saddle (a cubic) and a blobby object of three balls (degree-6 pieces).",
        page,
    )
}

/// The lecture's sketch: flat shapes with the circle and box around each,
/// computed by the chapter's bound code on their outlines (z = 0).
fn bounds_sketch() -> Figure {
    let shapes = sketch_shapes();
    let cell = 210.0;
    let mut page = Page::new(cell * shapes.len() as f64 + 30.0, 300.0).view(
        DVec2::new(-0.3, -1.9),
        DVec2::new(0.3 + 2.35 * shapes.len() as f64, 1.6),
    );
    let box_stroke = Stroke::new(palette::BLUE).width(2.0);
    let tight_stroke = Stroke::new(palette::VERMILION).width(2.0);
    let loose_stroke = Stroke::new(palette::GREEN).width(1.5).dashed();
    for (k, (name, points)) in shapes.iter().enumerate() {
        let offset = DVec2::new(1.15 + 2.35 * k as f64, 0.0);
        let at = |p: DVec3| offset + DVec2::new(p.x, p.y) * 0.5;
        let (aabb, tight, loose) = sketch_bounds(points);
        let outline: Vec<DVec2> = points.iter().map(|p| at(*p)).collect();
        page.polygon_alpha(
            &outline,
            Some(palette::GREY.with_alpha(0.35)),
            Some(&Stroke::ink()),
        );
        let corners = [
            DVec3::new(aabb.min.x, aabb.min.y, 0.0),
            DVec3::new(aabb.max.x, aabb.min.y, 0.0),
            DVec3::new(aabb.max.x, aabb.max.y, 0.0),
            DVec3::new(aabb.min.x, aabb.max.y, 0.0),
        ];
        let square: Vec<DVec2> = corners.iter().map(|p| at(*p)).collect();
        page.polygon(&square, None, Some(&box_stroke));
        page.circle(
            at(tight.center),
            0.5 * tight.radius,
            None,
            Some(&tight_stroke),
        );
        page.circle(
            at(loose.center),
            0.5 * loose.radius,
            None,
            Some(&loose_stroke),
        );
        page.label(offset + DVec2::new(0.0, -1.55), name, Anchor::Center);
    }
    page.text_page(
        DVec2::new(15.0, 22.0),
        "box (blue) · tight circle (vermilion) · circle around the box (green, dashed)",
        Anchor::E,
        15.0,
    );
    Figure::new(
        "bounds-sketch",
        "The lecture's sketch: a circle, a square, a thin rotated rectangle and a capsule, each with its bounding box (blue), its tight bounding circle (vermilion, Ritter's algorithm on its outline) and the circle around its box (green, dashed), all computed by the chapter's 3D bound code on points with z = 0. A box fits the square exactly but not the circle; a circle fits the circle but neither long shape.",
        page,
    )
}

/// One panel of the tightness figure: an object and a kind of bound.
struct Panel {
    title: &'static str,
    object: Box<dyn Primitive>,
    kind: BoundKind,
}

/// Pixels per panel side in the tightness figure.
const PANEL_PX: u32 = 180;

/// Parallel rays along −z through a grid over each object and its bound,
/// one per pixel: green where the ray hits the object, vermilion where it
/// hits the bound but misses the object (a wasted object test), light
/// grey where the bound turns it away after one cheap test.
fn tightness() -> Figure {
    let tilted = DVec3::new(0.5, 0.75, 0.43).normalize();
    let torus = || -> Box<dyn Primitive> {
        Box::new(
            Torus::new(DVec3::ZERO, tilted, 1.0, 0.3, TorusSolver::Bracketed)
                .expect("a ring torus"),
        )
    };
    let triangle = || -> Box<dyn Primitive> {
        Box::new(
            Triangle::new(
                [
                    DVec3::new(-1.2, -0.6, 0.4),
                    DVec3::new(1.25, -0.1, -0.3),
                    DVec3::new(-0.7, 0.35, 0.0),
                ],
                TriangleTest::Watertight,
            )
            .expect("a triangle"),
        )
    };
    let panels = [
        Panel {
            title: "torus, its box",
            object: torus(),
            kind: BoundKind::Box,
        },
        Panel {
            title: "torus, its sphere",
            object: torus(),
            kind: BoundKind::Sphere,
        },
        Panel {
            title: "thin triangle, its box",
            object: triangle(),
            kind: BoundKind::Box,
        },
        Panel {
            title: "thin triangle, its sphere",
            object: triangle(),
            kind: BoundKind::Sphere,
        },
    ];
    let (gap, top, bottom) = (35.0, 40.0, 36.0);
    let side = f64::from(PANEL_PX);
    let width = 4.0 * side + 5.0 * gap;
    let mut page = Page::new(width, side + top + bottom);
    for (k, panel) in panels.iter().enumerate() {
        let bound = panel.kind.around(panel.object.as_ref());
        let (rgb, [hit, wasted, _]) =
            view_along_z(panel.object.as_ref(), &bound);
        let x = gap + k as f64 * (side + gap);
        page.image(
            DVec2::new(x, bottom),
            DVec2::new(x + side, bottom + side),
            PANEL_PX,
            PANEL_PX,
            &rgb,
        );
        page.label_sized(
            DVec2::new(x + side / 2.0, bottom + side + 16.0),
            panel.title,
            Anchor::Center,
            15.0,
            palette::BLACK,
        );
        let of_bound = f64::from(wasted) / f64::from(hit + wasted);
        page.label_sized(
            DVec2::new(x + side / 2.0, bottom - 16.0),
            &format!("{:.0} % of its hits wasted", 100.0 * of_bound),
            Anchor::Center,
            13.0,
            palette::BLACK,
        );
    }
    Figure::new(
        "tightness",
        "Each object seen along parallel rays, one per pixel (180 × 180 rays over a 3.3 × 3.3 square): green rays hit the object; vermilion rays hit the bound but miss the object, so they paid for the bound test and the object test for nothing; grey rays are turned away by the bound after one cheap test. Seen from this side the tilted torus fills more of its box than of its sphere, and the thin triangle little of either; the chart at the end of the chapter counts random lines from every direction instead, where the torus's sphere is the tighter bound.",
        page,
    )
}

/// The picture of `object` and `bound` seen along −z over [−1.65, 1.65]²,
/// and the counts of (hit, wasted, turned away) rays.
fn view_along_z(object: &dyn Primitive, bound: &Bound) -> (Vec<u8>, [u32; 3]) {
    let mut rgb = Vec::with_capacity((PANEL_PX * PANEL_PX * 3) as usize);
    let mut counts = [0u32; 3];
    let colours = [palette::GREEN, palette::VERMILION, palette::LIGHT_GREY];
    for row in 0..PANEL_PX {
        for column in 0..PANEL_PX {
            let at = |i: u32| {
                -1.65 + 3.3 * (f64::from(i) + 0.5) / f64::from(PANEL_PX)
            };
            let origin = DVec3::new(at(column), -at(row), 10.0);
            let ray = Ray::new(origin, DVec3::NEG_Z);
            let on_bound = bound.hit(&ray, Interval::FORWARD).is_some();
            let on_object = object.intersect(&ray, Interval::FORWARD).is_some();
            let k = match (on_bound, on_object) {
                (_, true) => 0,
                (true, false) => 1,
                (false, false) => 2,
            };
            counts[k] += 1;
            let c = colours[k];
            rgb.extend_from_slice(&[c.r, c.g, c.b]);
        }
    }
    (rgb, counts)
}
