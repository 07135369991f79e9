//! The chapter's lecture figures, drawn from the reference code.
//!
//! The side views trace the real scene `scenes/spheres.toml` with
//! [`World::closest_hit`]; the reflected direction is [`reflect_light`]'s; the
//! rendered panels come from [`render`] and [`render_with`].
use std::path::Path;

use raystep_figure::palette::role;
use raystep_figure::{
    Anchor, Color, DVec2, DVec3, Figure, Page, SideView, Stroke, palette,
};
use raystep_render::RenderOptions;

use raystep_scene::{Scene, Shape as ShapeSpec};

use ch03::{
    Interval, Ray, ShadingTerms, Terms, World, reflect_light, render,
    render_with, shade,
};

/// Every figure of this chapter, in the order the lecture shows them.
pub fn all() -> Vec<Figure> {
    vec![basic_idea(), vectors(), other_rays(), terms(), exponent()]
}

/// The chapter's scene file, which the side views draw.
fn spheres_scene() -> Scene {
    let path =
        Path::new(env!("CARGO_MANIFEST_DIR")).join("../scenes/spheres.toml");
    raystep_scene::load(&path).expect("the chapter's scene loads")
}

/// The world of the chapter's scene, as `raystep render` builds it.
fn spheres_world(scene: &Scene) -> World {
    ch03::world(scene, "spheres.toml").expect("the chapter's scene builds")
}

/// For each pixel: shoot a ray, find the closest hit, shade it. A side view of the real camera.
fn basic_idea() -> Figure {
    let scene = spheres_scene();
    let world = spheres_world(&scene);
    let camera = world.camera;
    // the middle column of a 10-row image (u = 1/2): its rays lie in the vertical plane of the eye
    let rows = 10;
    let view = SideView::new(camera.eye, camera.forward);
    debug_assert!(
        view.off(camera.pixel_ray(0, 0, 1, rows).direction).abs() < 1e-12
    );
    let eye_at = view.at(camera.eye);

    let mut page = Page::new(900.0, 440.0)
        .margin(16.0)
        .view(DVec2::new(-0.6, -1.9), DVec2::new(9.2, 3.0));
    // the floor and the other planes, and the spheres the plane cuts
    for object in &scene.objects {
        let fill = Color::from_linear(scene.materials[object.material].kd);
        match &object.shape {
            ShapeSpec::Sphere { center, radius } => {
                let d = view.off(*center);
                if d.abs() < *radius {
                    page.circle_alpha(
                        view.at(*center),
                        (radius * radius - d * d).sqrt(),
                        Some(fill.with_alpha(0.35)),
                        Some(&Stroke::new(fill).width(2.0)),
                    );
                }
            }
            ShapeSpec::Plane { point, normal } => {
                let plane = ch02::Plane {
                    normal: *normal,
                    d: -normal.dot(*point),
                };
                // n·P + d = 0 along the view: a line with normal (n·along, n.y)
                let g = view.dir(plane.normal);
                let c = plane.normal.dot(view.point(DVec2::ZERO)) + plane.d;
                let on = -c / g.length_squared() * g;
                page.line(on, g.perp(), &Stroke::new(palette::GREY).width(2.5));
                debug_assert!(
                    (plane.normal.dot(view.point(on)) + plane.d).abs() < 1e-9,
                    "the line lies on the plane"
                );
            }
            _ => {} // the scene has no other shape
        }
    }

    let mut hits = 0;
    for row in 0..rows {
        let ray = camera.pixel_ray(0, row, 1, rows);
        let from = view.at(ray.origin);
        let dir = view.dir(ray.direction);
        match world.closest_hit(&ray, Interval::FORWARD) {
            Some((object, hit)) => {
                hits += 1;
                let at = view.at(hit.point);
                // hits farther along, which the loop does not keep (those on the page)
                let (lo, hi) = (page.world_min(), page.world_max());
                let farther: Vec<f64> = world
                    .objects
                    .iter()
                    .enumerate()
                    .filter(|&(i, _)| i != object)
                    .filter_map(|(_, o)| {
                        o.shape.intersect(&ray, Interval::FORWARD)
                    })
                    .map(|h| h.t)
                    .filter(|&t| {
                        let q = view.at(ray.at(t));
                        q.cmpge(lo).all() && q.cmple(hi).all()
                    })
                    .collect();
                if let Some(t_max) = farther.iter().copied().reduce(f64::max) {
                    page.segment(
                        at,
                        view.at(ray.at(t_max)),
                        &Stroke::new(palette::GREY).width(1.0).dashed(),
                    );
                    for t in farther {
                        page.hollow_point(view.at(ray.at(t)), palette::GREY);
                    }
                }
                page.segment(from, at, &Stroke::new(role::RAY).width(1.5));
                let shade = Color::from_linear(ch03::trace(&world, &ray));
                page.circle(
                    at,
                    5.0 / page.scale(),
                    Some(shade),
                    Some(&Stroke::new(palette::BLACK).width(1.5)),
                );
            }
            None => {
                page.ray(from, dir, &Stroke::new(role::RAY).width(1.5).dashed())
            }
        }
    }
    assert!(0 < hits && hits < rows, "some rays hit, some miss");

    // the image plane, one unit in front of the eye: one cell per pixel row, in its colour
    let centre = view.at(camera.eye + camera.forward);
    let up = view.dir(camera.up) * camera.half_height;
    let depth = view.dir(camera.forward) * 0.14;
    for row in 0..rows {
        let edge =
            |k: u32| centre + (1.0 - 2.0 * f64::from(k) / f64::from(rows)) * up;
        let (top, bottom) = (edge(row), edge(row + 1));
        let pixel = Color::from_linear(ch03::trace(
            &world,
            &camera.pixel_ray(0, row, 1, rows),
        ));
        page.polygon(
            &[top, bottom, bottom + depth, top + depth],
            Some(pixel),
            Some(&Stroke::new(palette::BLACK).width(1.0)),
        );
    }

    page.eye(eye_at, view.dir(camera.forward));
    page.label(eye_at + DVec2::new(0.0, -0.12), "eye", Anchor::S);
    // above left of the plane: the rays there are still below its top
    page.label(centre + up, "image plane", Anchor::NW);
    let x = 2.4;
    page.text_lines(
        DVec2::new(x, -0.5),
        0.3,
        16.0,
        &[(
            "for each pixel on screen: shoot a ray through it",
            palette::BLACK,
        )],
    );
    page.text_lines(
        DVec2::new(x + 0.3, -0.8),
        0.3,
        16.0,
        &[
            ("for each object: does the ray hit it?", palette::BLACK),
            ("keep the closest hit (dot)", palette::BLACK),
            ("shade it: the pixel's colour", palette::BLACK),
        ],
    );
    page.text_lines(
        DVec2::new(x, -1.75),
        0.3,
        16.0,
        &[(
            "blue dashed: a miss;  hollow dot: a farther hit, dropped",
            palette::GREY,
        )],
    );
    Figure::new(
        "basic-idea",
        "The middle column of a 10-row image of the chapter's scene, seen from the side: each ray goes from the eye through a pixel row of the image plane and stops at its closest hit; the green sphere is cut by the plane of the rays, the floor is the grey line.",
        page,
    )
}

/// N, L, R and V at a surface point, with the angles the local model uses.
fn vectors() -> Figure {
    let theta = 40f64.to_radians();
    let alpha = 22f64.to_radians();
    let n = DVec3::Y;
    let l = DVec3::new(-theta.sin(), theta.cos(), 0.0);
    let r = reflect_light(l, n);
    // V: α past R, away from N
    let (rs, rc) = (alpha.sin(), alpha.cos());
    let v = DVec3::new(rc * r.x + rs * r.y, -rs * r.x + rc * r.y, 0.0);
    let flat = |d: DVec3| d.truncate();
    let (n2, l2, r2, v2) = (flat(n), flat(l), flat(r), flat(v));
    assert!((r.dot(n) - l.dot(n)).abs() < 1e-12, "R is at θ to N");

    let mut page = Page::new(640.0, 380.0)
        .view(DVec2::new(-2.4, -0.3), DVec2::new(2.4, 2.5));
    let p = DVec2::ZERO;
    // the surface, hatched below
    page.segment(
        DVec2::new(-2.2, 0.0),
        DVec2::new(2.2, 0.0),
        &Stroke::new(palette::BLACK).width(2.0),
    );
    for k in 0..22 {
        let x = -2.1 + 0.2 * f64::from(k);
        if (-0.1..0.3).contains(&x) {
            continue; // room for P's label
        }
        page.segment(
            DVec2::new(x, 0.0),
            DVec2::new(x - 0.15, -0.15),
            &Stroke::new(palette::GREY).width(1.0),
        );
    }
    let thin = Stroke::new(palette::BLACK).width(1.2);
    page.angle_arc(p, n2, l2, 56.0, &thin, Some("θ"));
    page.angle_arc(p, r2, n2, 56.0, &thin, Some("θ"));
    page.angle_arc(p, v2, r2, 100.0, &thin, Some("α"));
    let len = 1.6;
    page.arrow(p, len * n2, &Stroke::vector(role::NORMAL));
    page.label(len * n2, "N", Anchor::N);
    page.arrow(p, len * l2, &Stroke::vector(role::LIGHT));
    page.label(len * l2, "L", Anchor::pointing(l2));
    page.arrow(p, len * r2, &Stroke::vector(role::REFLECTED));
    page.label(len * r2, "R", Anchor::pointing(r2));
    page.arrow(p, len * v2, &Stroke::vector(palette::GREEN));
    page.label(len * v2, "V", Anchor::pointing(v2));
    page.sun(1.95 * l2);
    page.eye(2.0 * v2, -v2);
    page.point(p, palette::BLACK);
    page.label(p, "P", Anchor::S);

    page.text_lines(
        DVec2::new(-2.35, 2.35),
        0.25,
        16.0,
        &[
            ("k_d·(N·L) + k_s·(R·V)^p", palette::BLACK),
            ("N·L = cos θ,  R·V = cos α", palette::BLACK),
            ("R = 2(N·L)N − L", palette::BLACK),
        ],
    );
    Figure::new(
        "vectors",
        "At a surface point P: the normal N, the direction L to the light, its mirror image R = 2(N·L)N − L at the same angle θ on the other side of N, and the direction V to the eye at angle α from R. Diffuse light goes with N·L = cos θ, the highlight with (R·V)^p = cos^p α.",
        page,
    )
}

/// The refracted direction of unit `d` entering a medium of index `n` through a surface with
/// unit normal `normal` (against `d`), by Snell's law; `None` for total internal reflection.
/// Chapter 6 teaches it.
fn refract(d: DVec3, normal: DVec3, n: f64) -> Option<DVec3> {
    let eta = 1.0 / n;
    let cos_i = -d.dot(normal);
    let k = 1.0 - eta * eta * (1.0 - cos_i * cos_i);
    (k >= 0.0).then(|| eta * d + (eta * cos_i - k.sqrt()) * normal)
}

/// At one primary hit of the scene: the shadow rays, the reflected ray and the refracted ray.
fn other_rays() -> Figure {
    let scene = spheres_scene();
    let world = spheres_world(&scene);
    // a pixel that sees the floor where one light is blocked
    let ray = world.camera.pixel_ray(155, 115, world.width, world.height);
    let (object, hit) = world
        .closest_hit(&ray, Interval::FORWARD)
        .expect("the pixel sees the floor");
    assert!(
        matches!(scene.objects[object].shape, ShapeSpec::Plane { .. }),
        "the pixel sees the floor"
    );
    let n = hit.normal;

    // Left: the plane of the primary ray and N, which holds the reflected and refracted rays.
    let view = SideView::new(hit.point, ray.direction);
    let left = DVec2::new(7.0, 0.0); // where P is drawn
    let at = |q: DVec3| left + view.at(q) - DVec2::new(0.0, hit.point.y);
    let p = at(hit.point);
    let mut page = Page::new(900.0, 390.0)
        .margin(12.0)
        .view(DVec2::new(0.0, -2.4), DVec2::new(23.0, 6.8));
    let floor = Stroke::new(palette::GREY).width(2.5);
    page.segment(DVec2::new(0.0, 0.0), DVec2::new(10.4, 0.0), &floor);
    page.label(
        DVec2::new(5.2, 6.4),
        "in the plane of the primary ray and N",
        Anchor::Center,
    );
    let eye_at = at(ray.origin);
    page.segment(eye_at, p, &Stroke::new(role::RAY).width(2.0));
    page.arrow(
        eye_at,
        eye_at + 0.5 * (p - eye_at),
        &Stroke::new(role::RAY).width(2.0),
    );
    page.eye(eye_at, p - eye_at);
    page.label(
        eye_at + 0.45 * (p - eye_at) + DVec2::new(0.0, 0.3),
        "primary ray",
        Anchor::N,
    );
    let reflected = reflect_light(-ray.direction, n);
    let refracted =
        refract(ray.direction, n, 1.5).expect("entering glass refracts");
    let len = 2.4;
    let tip = p + len * view.dir(reflected);
    page.arrow(p, tip, &Stroke::vector(role::REFLECTED));
    page.label(tip, "reflected", Anchor::N);
    let tip = p + len * view.dir(refracted);
    page.arrow(p, tip, &Stroke::vector(role::REFRACTED));
    page.label(tip, "refracted, n = 1.5", Anchor::S);
    page.arrow(p, p + 1.4 * view.dir(n), &Stroke::vector(role::NORMAL));
    page.label(p + 1.4 * view.dir(n), "N", Anchor::N);
    page.point(p, palette::BLACK);
    page.label(p, "P", Anchor::SW);

    // Right: each shadow ray in the vertical plane through it, turned about N into the page,
    // lights to the camera's left on the left.
    let q = DVec2::new(17.0, 0.0); // where P is drawn
    page.segment(DVec2::new(11.2, 0.0), DVec2::new(23.0, 0.0), &floor);
    page.segment(
        DVec2::new(10.8, -2.2),
        DVec2::new(10.8, 6.6),
        &Stroke::new(palette::LIGHT_GREY).width(1.5),
    );
    // right of light 1's label
    page.label(
        DVec2::new(17.6, 6.4),
        "shadow rays, each in its vertical plane",
        Anchor::Center,
    );
    let mut blocked_lights = 0;
    for (i, light) in world.lights.iter().enumerate() {
        let to_light = light.position - hit.point;
        let distance = to_light.length();
        let shadow = Ray::new(hit.point, to_light / distance);
        let side = if to_light.dot(world.camera.right) < 0.0 {
            -1.0
        } else {
            1.0
        };
        let plane = SideView::new(hit.point, to_light);
        let at = |x: DVec3| {
            q + DVec2::new(side, 1.0)
                * (plane.at(x) - DVec2::new(0.0, hit.point.y))
        };
        let at_light = at(light.position);
        match world
            .closest_hit(&shadow, Interval::new(1e-9 * distance, distance))
        {
            None => {
                page.segment(q, at_light, &Stroke::new(role::LIGHT).width(2.0));
                page.label(
                    q + 0.5 * (at_light - q),
                    "S = 1",
                    Anchor::pointing(DVec2::new(side, 0.0)),
                );
            }
            Some((by, block)) => {
                blocked_lights += 1;
                let at_block = at(block.point);
                if let ShapeSpec::Sphere { center, radius } =
                    &scene.objects[by].shape
                {
                    // the blocker where the vertical plane cuts it
                    let off = plane.off(*center);
                    let fill = Color::from_linear(world.material_of(by).kd);
                    page.circle_alpha(
                        at(*center - off * plane.across),
                        (radius * radius - off * off).sqrt(),
                        Some(fill.with_alpha(0.35)),
                        Some(&Stroke::new(fill).width(2.0)),
                    );
                }
                page.segment(q, at_block, &Stroke::new(role::LIGHT).width(2.0));
                page.segment(
                    at_block,
                    at_light,
                    &Stroke::new(role::LIGHT).width(1.5).dashed(),
                );
                page.cross(at_block);
                page.label(
                    at_block + 0.5 * (at_light - at_block),
                    "S = 0",
                    Anchor::pointing(DVec2::new(side, -1.0)),
                );
                let name = &world.material_of(by).name;
                page.text_lines(
                    DVec2::new(at_block.x - 0.3, -0.5),
                    0.45,
                    16.0,
                    &[
                        ("blocked by", palette::BLACK),
                        (&format!("the {name} sphere"), palette::BLACK),
                    ],
                );
            }
        }
        page.sun(at_light);
        page.label(
            at_light - DVec2::new(side * 0.35, 0.0),
            &format!("light {}", i + 1),
            Anchor::pointing(DVec2::new(-side, 0.0)),
        );
    }
    assert_eq!(blocked_lights, 1, "one light is blocked, one is not");
    page.arrow(q, q + 1.4 * DVec2::Y, &Stroke::vector(role::NORMAL));
    page.label(q + 1.4 * DVec2::Y, "N", Anchor::N);
    page.point(q, palette::BLACK);
    page.label(q, "P", Anchor::S);

    Figure::new(
        "other-rays",
        "The other rays at one point P where a primary ray of the chapter's scene meets the floor. Left: the reflected ray (chapter 5) and the ray refracted into glass of n = 1.5 (chapter 6) lie in the plane of the primary ray and N. Right: a shadow ray to each light (chapter 4), each drawn in its own vertical plane; the blue sphere blocks the second.",
        page,
    )
}

/// The scene with each term of the local model on its own, and their sum.
fn terms() -> Figure {
    let mut world = spheres_world(&spheres_scene());
    (world.width, world.height) = (192, 108);
    let term = |pick: fn(&ShadingTerms) -> DVec3| {
        render_with(&world, &RenderOptions::QUIET, |ray| {
            shade(&world, ray).map_or(DVec3::ZERO, |t| pick(&t))
        })
        .expect("a small render")
    };
    let ambient = render(&world, Terms::Ambient, &RenderOptions::QUIET)
        .expect("a small render");
    let diffuse = term(|t| t.diffuse);
    let specular = term(|t| t.specular);
    let sum = render(&world, Terms::All, &RenderOptions::QUIET)
        .expect("a small render");
    for (i, &l) in sum.pixels().iter().enumerate() {
        let parts =
            ambient.pixels()[i] + diffuse.pixels()[i] + specular.pixels()[i];
        assert!(
            (parts - l).abs().max_element() < 1e-12,
            "L is the sum of its terms"
        );
    }
    let panels = [
        (&ambient, "ambient", "k_a·I_a"),
        (&diffuse, "diffuse", "Σ I_i·k_d·(N·L_i)"),
        (&specular, "specular", "Σ I_i·k_s·(R_i·V)^p"),
        (&sum, "their sum", "L"),
    ];
    let (pw, ph) = (f64::from(world.width), f64::from(world.height));
    let (gap, side, bottom) = (32.0, 12.0, 56.0);
    let mut page =
        Page::new(4.0 * pw + 3.0 * gap + 2.0 * side, ph + bottom + 12.0);
    for (k, (image, name, formula)) in panels.iter().enumerate() {
        let x = side + k as f64 * (pw + gap);
        let (min, max) =
            (DVec2::new(x, bottom), DVec2::new(x + pw, bottom + ph));
        page.image(min, max, image.width(), image.height(), &image.to_srgb8());
        page.label(DVec2::new(x + pw / 2.0, bottom), name, Anchor::S);
        page.label(DVec2::new(x + pw / 2.0, bottom - 22.0), formula, Anchor::S);
        if k > 0 {
            let sign = if k == panels.len() - 1 { "=" } else { "+" };
            page.label_sized(
                DVec2::new(x - gap / 2.0, bottom + ph / 2.0),
                sign,
                Anchor::Center,
                24.0,
                palette::BLACK,
            );
        }
    }
    Figure::new(
        "terms",
        "The chapter's scene term by term: the ambient term, the diffuse term and the specular term each on its own, and their sum L, the local model.",
        page,
    )
}

/// A scene with one shiny sphere, for the exponent sweep.
const SHINY: &str = r#"
# ANCHOR: shiny
# One shiny sphere, lit from the upper left.
[image]
width = 150
height = 150

[camera]
look_from = [0, 0, 4]
look_at = [0, 0, 0]
vfov = 34

[ambient]
intensity = 0.1

[[lights]]
position = [-3, 4, 5]
intensity = 1

[materials.shiny]
kd = [0.15, 0.3, 0.65]
ks = 0.6
p = 32

[[objects]]
sphere = { center = [0, 0, 0], radius = 1 }
material = "shiny"
# ANCHOR_END: shiny
"#;

/// The highlight of one sphere as the Phong exponent p grows.
fn exponent() -> Figure {
    let scene = raystep_scene::parse(SHINY, "shiny.toml")
        .expect("the sweep's scene parses");
    let world =
        ch03::world(&scene, "shiny.toml").expect("the sweep's scene builds");
    let exponents = [2.0, 8.0, 32.0, 128.0, 512.0];
    let (w, h) = (world.width, world.height);
    let gap = 16.0;
    let (pw, ph) = (f64::from(w), f64::from(h));
    let width = 5.0 * pw + 4.0 * gap + 2.0 * 12.0;
    let mut page = Page::new(width, ph + 48.0);
    for (k, &p) in exponents.iter().enumerate() {
        let mut world = world.clone();
        for m in &mut world.materials {
            m.p = p;
        }
        let image = render(&world, Terms::All, &RenderOptions::QUIET)
            .expect("a small render");
        let x = 12.0 + k as f64 * (pw + gap);
        page.image(
            DVec2::new(x, 36.0),
            DVec2::new(x + pw, 36.0 + ph),
            w,
            h,
            &image.to_srgb8(),
        );
        page.label(
            DVec2::new(x + pw / 2.0, 36.0),
            &format!("p = {p}"),
            Anchor::S,
        );
    }
    Figure::new(
        "exponent",
        "One sphere with ks = 0.6 and the Phong exponent p from 2 to 512: the larger p, the smaller and sharper the highlight, from a dull plastic to a polished one.",
        page,
    )
}
