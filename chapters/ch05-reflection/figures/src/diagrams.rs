//! The chapter's lecture figures, drawn from the reference code.
//!
//! Every vector and number shown comes from the chapter's code: the
//! reflected direction from [`reflect_ray`], the ray trees from
//! [`pixel_tree`] on the real facing mirrors, the renders, ray counts and
//! errors from [`render`] and [`image_error`].
use raystep_figure::numbers::fixed;
use raystep_figure::palette::role;
use raystep_figure::{
    Anchor, Color, DVec2, DVec3, Figure, Page, Stroke, palette,
};
use raystep_render::{RenderOptions, image_error};

use crate::measurements::{REFERENCE, chart_world};
use ch05::{
    Cut, DEFAULT_STOP, Interval, LoggedRay, Ray, Stop, World, pixel_tree,
    reflect_ray, render,
};

/// Every figure of this chapter, in the order the lecture shows them.
pub fn all() -> Vec<Figure> {
    vec![reflection(), ray_tree(), depths()]
}

/// Colours of the chapter's figures (N, rays, shadow rays and the
/// reflected ray as in every chapter: `palette::role`).
const CUT_COLOR: Color = palette::BLACK;
const MIRROR_COLOR: Color = palette::SKY_BLUE;

/// A 2D vector as `(x, y)` with two decimals.
fn pair(v: DVec2) -> String {
    format!("({}, {})", fixed(v.x, 2), fixed(v.y, 2))
}

/// A mirror seen edge-on: a line from `a` to `b`, hatched on its back
/// (the side `back` points to), except around the points in `gaps`.
fn mirror(page: &mut Page, a: DVec2, b: DVec2, back: DVec2, gaps: &[DVec2]) {
    let along = (b - a).normalize();
    let length = (b - a).length();
    let mut at = 0.05;
    while at < length {
        let p = a + along * at;
        if gaps.iter().all(|g| (p - *g).length() > 0.25) {
            page.segment(
                p,
                p + 0.15 * (back - along),
                &Stroke::new(palette::GREY).width(1.0),
            );
        }
        at += 0.2;
    }
    page.segment(a, b, &Stroke::new(MIRROR_COLOR).width(4.0));
}

/// The angle between two directions, in degrees.
fn degrees_between(a: DVec3, b: DVec3) -> f64 {
    a.angle_between(b).to_degrees()
}

/// The lecture's reflection: D comes in, R leaves at the same angle to N,
/// and R = D − 2(D·N)N as a sum of vectors.
fn reflection() -> Figure {
    let d = DVec3::new(0.8, -0.6, 0.0);
    let n = DVec3::Y;
    let r = reflect_ray(d, n);
    let dn = d.dot(n);
    let incidence = degrees_between(-d, n);
    let outgoing = degrees_between(r, n);
    assert!(
        (incidence - outgoing).abs() < 1e-9,
        "R leaves at the angle D came in"
    );
    assert!((r.length() - d.length()).abs() < 1e-12, "R has D's length");
    let flat = |v: DVec3| v.truncate();
    let (d2, n2, r2) = (flat(d), flat(n), flat(r));
    let normal_part = flat(dn * n);
    let kept = d2 - normal_part;

    let mut page = Page::new(900.0, 400.0)
        .view(DVec2::new(-2.5, -1.45), DVec2::new(7.7, 2.5));
    let thin = Stroke::new(palette::BLACK).width(1.2);
    let len = 1.8;

    // Left: the angles.
    let p = DVec2::ZERO;
    mirror(
        &mut page,
        DVec2::new(-2.2, 0.0),
        DVec2::new(2.2, 0.0),
        -n2,
        &[p],
    );
    page.angle_arc(p, n2, -d2, 60.0, &thin, Some("θ"));
    page.angle_arc(p, r2, n2, 60.0, &thin, Some("θ"));
    page.arrow(p - len * d2, p, &Stroke::vector(role::RAY));
    page.label(p - 0.55 * len * d2, "D", Anchor::SW);
    page.arrow(p, p + 1.2 * n2, &Stroke::vector(role::NORMAL));
    page.label(p + 1.2 * n2, "N", Anchor::N);
    page.arrow(p, p + len * r2, &Stroke::vector(role::REFLECTED));
    page.label(p + 0.55 * len * r2, "R", Anchor::SE);
    page.point(p, palette::BLACK);
    page.label(p, "P", Anchor::S);
    page.text_lines(
        DVec2::new(-2.4, 2.3),
        0.3,
        16.0,
        &[
            ("angle of incidence = angle of reflection", palette::BLACK),
            (
                &format!("θ = {}° on both sides of N", fixed(incidence, 1)),
                palette::BLACK,
            ),
        ],
    );
    page.label_sized(
        DVec2::new(-1.6, -0.3),
        "mirror",
        Anchor::S,
        14.0,
        palette::GREY,
    );

    // Right: the construction, with D drawn from P:
    // R = D − 2(D·N)N = [D − (D·N)N] − (D·N)N.
    let p = DVec2::new(4.4, 0.0);
    let s = 2.2;
    mirror(
        &mut page,
        p - DVec2::new(1.4, 0.0),
        p + DVec2::new(2.6, 0.0),
        -n2,
        &[0.0, 0.25, 0.5, 0.75, 1.0].map(|f| p + f * s * kept),
    );
    // D's part along the surface is kept...
    page.arrow(
        p,
        p + s * kept,
        &Stroke::new(palette::BLACK).width(2.0).dashed(),
    );
    // under the arrow, where the mirror leaves out its hatching, clear of
    // D and of (D·N)N
    let under = p + DVec2::new(0.6 * s * kept.x, 0.0);
    page.label_sized(under, "D − (D·N)N", Anchor::S, 15.0, palette::BLACK);
    page.label_sized(
        under - DVec2::new(0.0, 0.24),
        "kept",
        Anchor::S,
        15.0,
        palette::BLACK,
    );
    // ...and its part along N, (D·N)N, changes sign.
    page.arrow(
        p + s * kept,
        p + s * d2,
        &Stroke::new(role::NORMAL).width(2.5),
    );
    page.label_sized(
        p + s * (kept + 0.5 * normal_part),
        "(D·N)N",
        Anchor::E,
        15.0,
        role::NORMAL,
    );
    page.arrow(
        p + s * kept,
        p + s * r2,
        &Stroke::new(role::NORMAL).width(2.5).dashed(),
    );
    page.label_sized(
        p + s * (kept - 0.5 * normal_part),
        "−(D·N)N",
        Anchor::E,
        15.0,
        role::NORMAL,
    );
    page.arrow(p, p + s * d2, &Stroke::vector(role::RAY));
    page.label(p + 0.5 * s * d2, "D", Anchor::SW);
    page.arrow(p, p + s * r2, &Stroke::vector(role::REFLECTED));
    page.label(p + 0.5 * s * r2, "R", Anchor::NW);
    page.arrow(p, p + 1.2 * n2, &Stroke::vector(role::NORMAL));
    page.label(p + 1.2 * n2, "N", Anchor::N);
    page.point(p, palette::BLACK);
    page.label(p, "P", Anchor::S);
    page.text_lines(
        DVec2::new(p.x - 1.6, 2.3),
        0.3,
        16.0,
        &[
            (
                &format!("D = {},  N = {}", pair(d2), pair(n2)),
                palette::BLACK,
            ),
            (&format!("D·N = {}", fixed(dn, 2)), palette::BLACK),
            (&format!("R = D − 2(D·N)N = {}", pair(r2)), role::REFLECTED),
        ],
    );
    Figure::new(
        "reflection",
        &format!(
            "Left: the ray D meets a mirror at P and leaves along R, at the same angle θ = {}° to the normal N, on the other side of it. Right: the same R from reflect_ray, taken apart: D's part along the surface, D − (D·N)N, is kept; its part along N, (D·N)N, is taken away twice, so that it points the other way: R = D − 2(D·N)N = [D − (D·N)N] − (D·N)N.",
            fixed(incidence, 1)
        ),
        page,
    )
}

/// The facing mirrors seen from above: the page's right is −z (the way
/// the camera looks), its up is −x, so the view stays right-handed.
fn top(p: DVec3) -> DVec2 {
    DVec2::new(-p.z, -p.x)
}

/// The pixel of the facing mirrors with the longest ray tree: the one that
/// bounces most between the walls (the first of them, row by row).
fn deepest_pixel(world: &World) -> (u32, u32) {
    let mut best = ((0, 0), 0);
    for row in 0..world.height {
        for column in 0..world.width {
            let rays = pixel_tree(world, column, row, &REFERENCE);
            let depth = rays.iter().map(|r| r.path.depth).max().unwrap_or(0);
            if depth > best.1 {
                best = ((column, row), depth);
            }
        }
    }
    best.0
}

/// One pixel's ray tree in the facing mirrors under two rules, from above.
fn ray_tree() -> Figure {
    let world = chart_world("facing-mirrors");
    let (column, row) = deepest_pixel(&world);
    let threshold = 0.1;
    let rules = [Stop::depth(2), Stop::contribution(threshold)];
    let titles = ["Stop::depth(2)", "Stop::contribution(0.1)"];
    // the corridor: walls at x = ±2 from z = −8 (beyond the page's right
    // edge) to z = 3
    let (z_near, z_far) = (3.0, -8.0);
    let panel_height = 6.5;
    let (min, max) = (
        DVec2::new(-3.9, -2.55 - panel_height),
        DVec2::new(6.6, 3.75),
    );
    let width = 900.0;
    let height = width * (max.y - min.y) / (max.x - min.x);
    let mut page = Page::new(width, height).margin(0.0).view(min, max);
    let light = world.lights[0].position;
    for (k, (stop, title)) in rules.iter().zip(titles).enumerate() {
        let shift = DVec2::new(0.0, -panel_height * k as f64);
        let at = |p: DVec3| top(p) + shift;
        let rays = pixel_tree(&world, column, row, stop);
        // the walls, their mirror sides facing each other, and the ball
        for x in [-2.0, 2.0] {
            mirror(
                &mut page,
                at(DVec3::new(x, 0.0, z_near)),
                at(DVec3::new(x, 0.0, z_far)),
                DVec2::new(0.0, -x.signum()),
                &[],
            );
        }
        page.label_sized(
            at(DVec3::new(1.9, 0.0, -5.3)),
            "mirror walls, seen from above",
            Anchor::N,
            14.0,
            palette::GREY,
        );
        page.circle(
            at(DVec3::ZERO),
            0.7,
            Some(palette::LIGHT_GREY.mix(palette::WHITE, 0.4)),
            None,
        );
        page.label_sized(
            at(DVec3::ZERO),
            "ball",
            Anchor::Center,
            14.0,
            palette::GREY,
        );
        // the shadow rays: thin branches toward the light (the caption
        // says they all reach it)
        assert!(
            rays.iter().all(|r| !r.blocked),
            "no shadow ray of this pixel is blocked"
        );
        for ray in rays.iter().filter(|r| r.shadow) {
            let t = ray.t.expect("a shadow ray ends at its light");
            let blocker = ray.blocked.then(|| {
                world
                    .closest_hit(
                        &Ray::new(ray.origin, ray.direction),
                        Interval::new(0.0, t),
                    )
                    .expect("a blocked shadow ray hits something")
                    .1
                    .point
            });
            match blocker {
                Some(b) => page.segment(
                    at(ray.origin),
                    at(b),
                    &Stroke::new(role::BLOCKED).width(1.0),
                ),
                None => page.segment(
                    at(ray.origin),
                    at(ray.origin + t * ray.direction),
                    &Stroke::new(role::LIT).width(0.8),
                ),
            }
        }
        page.sun(at(light));
        page.label(at(light) + DVec2::new(0.0, 0.25), "light", Anchor::N);
        // the traced rays, each ending at its hit (or leaving the corridor)
        draw_rays(&mut page, &rays, stop, &at);
        let eye_at = at(world.camera.eye);
        page.eye(eye_at, top(rays[0].direction));
        page.label(eye_at - DVec2::new(0.2, 0.0), "eye", Anchor::W);
        // what this rule did, from the log
        let summary = summarise(&rays);
        let mut lines: Vec<(&str, Color)> = vec![(title, palette::BLACK)];
        lines.extend(summary.iter().map(|(t, c)| (t.as_str(), *c)));
        page.text_lines(
            DVec2::new(min.x + 0.1, max.y - 0.3) + shift,
            0.36,
            15.0,
            &lines,
        );
    }
    // the caption's numbers, from the log and the scene
    let cut = pixel_tree(&world, column, row, &rules[1])
        .into_iter()
        .find(|r| r.cut == Some(Cut::Contribution))
        .expect("rule 2 cuts this pixel's tree");
    let kr = world.materials[world.objects[0].material].kr;
    let kr = format!("({}, {}, {})", kr.x, kr.y, kr.z);
    let (depth, weight) = (cut.path.depth, fixed(cut.path.contribution(), 3));
    Figure::new(
        "ray-tree",
        &format!(
            "The ray tree of pixel ({column}, {row}) of scenes/facing-mirrors.toml (160 × 90), seen from above, as pixel_tree logs it: the primary ray (blue) and the reflected rays (purple) bounce between the two mirror walls; each number is the depth of the ray that ends there. The thin green lines are the shadow rays each hit sends to the light. Top: Stop::depth(2) does not shoot the ray at depth 3. Bottom: Stop::contribution(0.1) goes on until the ray's weight, the walls' kr = {kr} multiplied along the path, has its largest channel below 0.1: {weight} at depth {depth}."
        ),
        page,
    )
}

/// The traced rays of a pixel's tree under `stop` (not the shadow rays),
/// each numbered by its depth where it ends, and the cut ray with an X.
fn draw_rays(
    page: &mut Page, rays: &[LoggedRay], stop: &Stop,
    at: &dyn Fn(DVec3) -> DVec2,
) {
    for ray in rays.iter().filter(|r| !r.shadow) {
        let colour = if ray.is_primary() {
            role::RAY
        } else {
            role::REFLECTED
        };
        let from = at(ray.origin);
        let direction = top(ray.direction).normalize();
        match (ray.t, ray.cut) {
            (_, Some(cut)) => {
                // the ray that was not shot: a short dashed stub and an X
                let to = from + 0.9 * direction;
                page.segment(
                    from,
                    to,
                    &Stroke::new(colour).width(2.0).dashed(),
                );
                page.cross(to);
                let why = match cut {
                    Cut::Depth => vec![
                        format!(
                            "depth {} > {}:",
                            ray.path.depth, stop.max_depth
                        ),
                        "cut by rule 1".to_string(),
                    ],
                    Cut::Contribution => vec![
                        format!("depth {},", ray.path.depth),
                        format!(
                            "weight {} < {}:",
                            fixed(ray.path.contribution(), 3),
                            stop.min_contribution
                        ),
                        "cut by rule 2".to_string(),
                    ],
                };
                let lines: Vec<(&str, Color)> =
                    why.iter().map(|t| (t.as_str(), CUT_COLOR)).collect();
                page.text_lines(to + DVec2::new(0.2, 0.1), 0.22, 14.0, &lines);
            }
            (Some(t), None) => {
                let to = at(ray.origin + t * ray.direction);
                page.arrow(from, to, &Stroke::new(colour).width(2.0));
                // the depth of the ray that ends here, outside the wall
                let outside = DVec2::new(0.0, 0.3 * (to.y - from.y).signum());
                page.label_sized(
                    to + outside,
                    &ray.path.depth.to_string(),
                    Anchor::Center,
                    14.0,
                    colour,
                );
            }
            (None, None) => {
                // a miss: out over the walls to the sky
                page.arrow(
                    from,
                    from + 1.2 * direction,
                    &Stroke::new(colour).width(2.0),
                );
                page.label_sized(
                    from + 1.2 * direction,
                    "to the sky",
                    Anchor::pointing(direction),
                    14.0,
                    colour,
                );
            }
        }
    }
}

/// A rule's ray counts for one pixel, as lines of text.
fn summarise(rays: &[LoggedRay]) -> Vec<(String, Color)> {
    let count = |kind: fn(&LoggedRay) -> bool| {
        rays.iter().filter(|r| kind(r) && r.cut.is_none()).count()
    };
    let cut = rays.iter().find(|r| r.cut.is_some());
    let mut lines = vec![(
        format!(
            "{} primary + {} reflected rays, {} shadow rays",
            count(LoggedRay::is_primary),
            count(|r| !r.shadow && !r.is_primary()),
            count(|r| r.shadow)
        ),
        palette::BLACK,
    )];
    if let Some(cut) = cut {
        let weight = cut.path.weight;
        lines.push((
            format!(
                "not shot: the ray at depth {}, weight ({}, {}, {})",
                cut.path.depth,
                fixed(weight.x, 3),
                fixed(weight.y, 3),
                fixed(weight.z, 3)
            ),
            CUT_COLOR,
        ));
    }
    lines
}

/// scenes/mirrors.toml rendered with rule 1 at depths 0, 1, 2, 3 and 5,
/// each with its error against the whole tree.
fn depths() -> Figure {
    let mut world = chart_world("mirrors");
    (world.width, world.height) = (240, 135);
    let (w, h) = (world.width, world.height);
    let (reference, whole) = render(&world, &REFERENCE, &RenderOptions::QUIET)
        .expect("a small render");
    let shown = [0, 1, 2, 3, 5];
    let table_depths = [0, 1, 2, 3, 4, 5];
    let (pw, ph) = (f64::from(w), f64::from(h));
    let (gap, side, heading, bottom) = (16.0, 12.0, 46.0, 12.0);
    let width = 3.0 * pw + 2.0 * gap + 2.0 * side;
    let height = 2.0 * (heading + ph) + gap + bottom;
    let mut page = Page::new(width, height);
    let mut table = Vec::new();
    for depth in table_depths {
        let stop = Stop::depth(depth);
        let (image, counts) = render(&world, &stop, &RenderOptions::QUIET)
            .expect("a small render");
        let error = image_error(&image, &reference);
        table.push((depth, counts, error));
        let Some(k) = shown.iter().position(|&d| d == depth) else {
            continue;
        };
        let (col, line) = (k % 3, k / 3);
        let x = side + col as f64 * (pw + gap);
        let y =
            height - (line as f64 + 1.0) * (heading + ph) - line as f64 * gap;
        page.image(
            DVec2::new(x, y),
            DVec2::new(x + pw, y + ph),
            w,
            h,
            &image.to_srgb8(),
        );
        let centre = x + pw / 2.0;
        page.label_sized(
            DVec2::new(centre, y + ph + 26.0),
            &format!("Stop::depth({depth})"),
            Anchor::N,
            16.0,
            palette::BLACK,
        );
        let note = match depth {
            0 => "no reflected rays: chapter 4".to_string(),
            _ if error.max == 0.0 => "the same as the whole tree".to_string(),
            _ => format!(
                "RMSE {}, max {} levels",
                fixed(error.rmse, 2),
                error.max
            ),
        };
        page.label_sized(
            DVec2::new(centre, y + ph + 6.0),
            &note,
            Anchor::N,
            14.0,
            palette::BLACK.mix(palette::GREY, 0.5),
        );
    }
    // the sixth cell: every depth's rays and error, in numbers
    let x = side + 2.0 * (pw + gap);
    let y = bottom + ph + heading - 8.0;
    let columns = [x, x + 48.0, x + 130.0, x + 190.0];
    let header = ["depth", "reflected", "RMSE", "max"];
    for (c, text) in columns.iter().zip(header) {
        page.label_sized(
            DVec2::new(*c, y),
            text,
            Anchor::E,
            14.0,
            palette::BLACK,
        );
    }
    for (i, (depth, counts, error)) in table.iter().enumerate() {
        let row_y = y - 22.0 * (i as f64 + 1.0);
        let cells = [
            depth.to_string(),
            counts.secondary.to_string(),
            fixed(error.rmse, 2),
            format!("{}", error.max),
        ];
        for (c, text) in columns.iter().zip(&cells) {
            page.label_sized(
                DVec2::new(*c, row_y),
                text,
                Anchor::E,
                14.0,
                palette::BLACK.mix(palette::GREY, 0.3),
            );
        }
    }
    page.label_sized(
        DVec2::new(x, y - 22.0 * (table.len() as f64 + 1.0)),
        &format!("whole tree: {} reflected rays", whole.secondary),
        Anchor::E,
        14.0,
        palette::BLACK,
    );
    // the first depth that cuts nothing: the longest path in the scene
    let (longest, ..) = table
        .iter()
        .find(|(_, counts, _)| counts.cut_by_depth == 0)
        .expect("some depth of the table cuts nothing");
    // the default rule cuts nothing here either
    let (_, default_counts) =
        render(&world, &DEFAULT_STOP, &RenderOptions::QUIET)
            .expect("a small render");
    assert_eq!(default_counts, whole, "the default rule cuts no ray here");
    Figure::new(
        "depths",
        &format!(
            "scenes/mirrors.toml at {w} × {h} with rule 1 at depths 0, 1, 2, 3 and 5, and the error of each against the whole ray tree in 8-bit sRGB levels (RMSE over every channel of every pixel, and the largest difference). Each level shows the reflections one bounce deeper: at depth 1 the mirrors show the scene as depth 0 drew it, so the mirror ball seen in the wall is still black; at depth 2 it shows the sky. From depth {longest} on nothing changes: no ray here bounces more than {longest} times."
        ),
        page,
    )
}
