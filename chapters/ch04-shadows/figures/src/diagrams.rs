//! The chapter's lecture figures, drawn from the reference code.
//!
//! Every verdict and number shown comes from the chapter's code: which
//! shadow ray is blocked from [`occluded`] and [`shadow`] on a real
//! [`World`], where each strategy starts its ray and what it hits from
//! [`shadow_ray`], the lifts of the scale-aware offset from
//! [`offset_scale_aware`], the renders from [`render`], and the fractions
//! of wrong pixels from [`shadow_errors`].
use raystep_figure::numbers::{power, power_text};
use raystep_figure::palette::role;
use raystep_figure::{
    Anchor, Color, DVec2, DVec3, Figure, Page, Stroke, palette,
};
use raystep_render::{Image, RenderOptions};

use ch04::{
    INT_SCALE, Interval, ORIGIN, Offset, TWO_LIGHTS_SCENE, Verdict, World,
    occluded, offset_scale_aware, render, scaled_scene, shadow, shadow_errors,
    shadow_ray, verdict,
};

/// Every figure of this chapter, in the order the lecture shows them.
pub fn all() -> Vec<Figure> {
    vec![shadow_rays(), offsets(), acne(), two_lights()]
}

/// Colours of the chapter's figures (N, lit and blocked shadow rays as in
/// every chapter: `palette::role`).
const ACNE_COLOR: Color = palette::VERMILION;
const LEAK_COLOR: Color = palette::BLUE;
const LIFT_COLOR: Color = palette::PURPLE;

/// The shapes of scene-file text, as the file gives them.
fn shapes_of(text: &str, name: &str) -> Vec<raystep_scene::Shape> {
    let scene =
        raystep_scene::parse(text, name).expect("the figure's scene parses");
    scene.objects.into_iter().map(|o| o.shape).collect()
}

/// A fraction as a percentage with as many decimals as a small one needs.
fn percent(f: f64) -> String {
    let p = 100.0 * f;
    if f == 0.0 {
        "0 %".to_string()
    } else if p >= 10.0 {
        format!("{p:.0} %")
    } else if p >= 1.0 {
        format!("{p:.1} %")
    } else {
        format!("{p:.2} %")
    }
}

/// The side view's scene: a floor, a ball, and two lights, all in the
/// plane z = 0 so that the drawing is exact.
const SIDE_SCENE: &str = r#"
[camera]
look_from = [0, 2, 8]
look_at = [0, 1, 0]

[[lights]]
position = [-2.6, 4.2, 0]
intensity = 1

[[lights]]
position = [3.4, 4.6, 0]
intensity = 1

[materials.any]
kd = 0.5

[[objects]]
sphere = { center = [1.75, 2.25, 0], radius = 0.6 }
material = "any"

[[objects]]
plane = { point = [0, 0, 0], normal = [0, 1, 0] }
material = "any"
"#;

/// One surface point, two lights, two shadow rays: one reaches its light,
/// the other is blocked by the ball.
fn shadow_rays() -> Figure {
    let world = ch03::parse(SIDE_SCENE, "side.toml")
        .expect("the figure\'s scene builds");
    let point = DVec3::ZERO;
    let normal = DVec3::Y;
    let hit = ch04::Hit {
        t: 1.0,
        point,
        normal,
    };
    let v2 = |p: DVec3| p.truncate();
    let raystep_scene::Shape::Sphere { center, radius } =
        shapes_of(SIDE_SCENE, "side.toml")[0]
    else {
        panic!("the first object is the ball");
    };
    let (centre, radius) = (v2(center), radius);

    let mut page = Page::new(720.0, 440.0)
        .view(DVec2::new(-4.6, -0.7), DVec2::new(4.9, 5.5));
    // the floor, seen edge-on
    let floor_fill = palette::LIGHT_GREY.mix(palette::WHITE, 0.5);
    page.rect(
        DVec2::new(-6.0, -2.0),
        DVec2::new(7.0, 0.0),
        Some(floor_fill),
        None,
    );
    page.segment(
        DVec2::new(-6.0, 0.0),
        DVec2::new(7.0, 0.0),
        &Stroke::new(palette::BLACK).width(2.0),
    );
    page.label(DVec2::new(-4.4, 0.0), "floor", Anchor::SE);
    // the ball
    page.circle(
        centre,
        radius,
        Some(palette::SKY_BLUE.mix(palette::WHITE, 0.45)),
        Some(&Stroke::new(palette::BLUE).width(2.0)),
    );
    page.label(
        centre + DVec2::new(-radius, radius) * 0.72,
        "ball",
        Anchor::NW,
    );

    let mut lines = Vec::new();
    for (i, light) in world.lights.iter().enumerate() {
        let (ray, interval) =
            shadow_ray(point, normal, light.position, Offset::ScaleAware);
        let blocked = occluded(&world, &ray, interval);
        let s = shadow(&world, &hit, normal, light, Offset::ScaleAware);
        assert_eq!(
            s,
            if blocked { 0.0 } else { 1.0 },
            "Sᵢ is the shadow ray's verdict"
        );
        let to = v2(light.position);
        let label = format!("S_{} = {s}", i + 1);
        if blocked {
            // where it is blocked: the closest blocker on the ray
            let (_, blocker) = world
                .closest_hit(&ray, interval)
                .expect("a blocked ray hits something");
            let at = v2(blocker.point);
            page.segment(v2(point), at, &Stroke::new(role::BLOCKED).width(2.5));
            page.segment(
                at,
                to,
                &Stroke::new(role::BLOCKED).width(2.0).dashed(),
            );
            page.circle(
                at,
                5.5 / page.scale(),
                Some(role::BLOCKED),
                Some(&Stroke::new(palette::BLACK).width(1.0)),
            );
            // under the ball, clear of its outline and of the ray
            page.label(
                DVec2::new(at.x + 0.1, centre.y - radius - 0.05),
                "blocker hit",
                Anchor::SE,
            );
            page.label_sized(
                v2(point) + 0.42 * (at - v2(point)),
                &label,
                Anchor::E,
                18.0,
                role::BLOCKED,
            );
            lines.push((
                format!("light {}: occluded → true, S_{} = {s}", i + 1, i + 1),
                role::BLOCKED,
            ));
        } else {
            page.segment(v2(point), to, &Stroke::new(role::LIT).width(2.5));
            page.label_sized(
                v2(point) + 0.5 * (to - v2(point)),
                &label,
                Anchor::W,
                18.0,
                role::LIT,
            );
            lines.push((
                format!("light {}: occluded → false, S_{} = {s}", i + 1, i + 1),
                role::LIT,
            ));
        }
        page.sun(to);
        let (side, shift) = if to.x < 0.0 {
            (Anchor::E, 0.4)
        } else {
            (Anchor::W, -0.4)
        };
        page.label(
            to + DVec2::new(shift, 0.0),
            &format!("light {}", i + 1),
            side,
        );
    }
    // P and its normal
    page.arrow(v2(point), v2(point + normal), &Stroke::vector(role::NORMAL));
    page.label(v2(point + 0.8 * normal), "N", Anchor::W);
    page.point(v2(point), palette::BLACK);
    page.label(v2(point), "P", Anchor::S);
    // the model, and the verdicts
    let mut block: Vec<(&str, Color)> = vec![(
        "L = k_a·I_a + Σ S_i·I_i·[k_d·(N·L_i) + k_s·(R_i·V)^p]",
        palette::BLACK,
    )];
    block.extend(lines.iter().map(|(line, color)| (line.as_str(), *color)));
    page.text_lines(DVec2::new(-4.5, 5.3), 0.36, 16.0, &block);
    Figure::new(
        "shadow-rays",
        "At a floor point P, one shadow ray per light: the ray to light 1 reaches it (S₁ = 1); the ray to light 2 meets the ball first (S₂ = 0), and occluded stops at that blocker without looking farther.",
        page,
    )
}

/// The acne scene at `scale`, `width × height` (16:9).
fn acne_world(scale: f64, width: u32, height: u32) -> World {
    let mut world = scaled_scene(scale);
    (world.width, world.height) = (width, height);
    world
}

/// The [`verdict`] of `offset` at every pixel, row by row: the per-pixel
/// form of [`shadow_errors`](ch04::shadow_errors) for a one-light scene.
fn error_map(world: &World, offset: Offset) -> Vec<Verdict> {
    assert_eq!(world.lights.len(), 1, "one light: one verdict a pixel");
    let light = world.lights[0].position;
    let mut map = Vec::with_capacity((world.width * world.height) as usize);
    for row in 0..world.height {
        for column in 0..world.width {
            let ray =
                world
                    .camera
                    .pixel_ray(column, row, world.width, world.height);
            map.push(verdict(world, &ray, light, offset));
        }
    }
    map
}

/// The same scene with each strategy at the scale where it fails, and the
/// pixels each gets wrong.
fn acne() -> Figure {
    let (w, h) = (192, 108);
    // the fixed offsets and scales of tests/acne.rs where they fail
    let (large, small) = (1e-4, 1e-12);
    let (tiny, huge) = (1e-3, 1e4);
    let large_name = format!("AlongNormal({})", power(large));
    let small_name = format!("AlongNormal({})", power(small));
    let panels = [
        ("TMin(0)", "no protection", Offset::TMin(0.0), 1.0),
        (
            large_name.as_str(),
            "ε too large",
            Offset::AlongNormal(large),
            tiny,
        ),
        (
            small_name.as_str(),
            "ε too small",
            Offset::AlongNormal(small),
            huge,
        ),
        ("ScaleAware", "", Offset::ScaleAware, huge),
    ];
    let (pw, ph) = (f64::from(w), f64::from(h));
    let (gap, side) = (30.0, 14.0);
    let (top, mid, bottom) = (62.0, 34.0, 82.0);
    let width = 4.0 * pw + 3.0 * gap + 2.0 * side;
    let height = top + ph + mid + ph + bottom;
    let mut page = Page::new(width, height);
    let map_y = bottom; // bottom of the error maps
    let render_y = bottom + ph + mid; // bottom of the renders
    for (k, &(name, why, offset, scale)) in panels.iter().enumerate() {
        let world = acne_world(scale, w, h);
        let image = render(&world, offset, &RenderOptions::QUIET)
            .expect("a small render");
        let map = error_map(&world, offset);
        let errors = shadow_errors(&world, offset);
        let x = side + k as f64 * (pw + gap);
        let centre = x + pw / 2.0;
        page.image(
            DVec2::new(x, render_y),
            DVec2::new(x + pw, render_y + ph),
            w,
            h,
            &image.to_srgb8(),
        );
        // the wrong pixels over a faded copy of the render
        let faded = Image::from_fn(w, h, |column, row| {
            let i = (row * w + column) as usize;
            match map[i] {
                Verdict::Acne => ACNE_COLOR.to_linear(),
                Verdict::Leak => LEAK_COLOR.to_linear(),
                Verdict::Right | Verdict::Unjudged => {
                    let c = image.get(column, row);
                    let grey = (c.x + c.y + c.z) / 3.0;
                    DVec3::splat(0.55 + 0.45 * grey.min(1.0))
                }
            }
        });
        page.image(
            DVec2::new(x, map_y),
            DVec2::new(x + pw, map_y + ph),
            w,
            h,
            &faded.to_srgb8(),
        );
        // headings: the strategy, then the scale and why it fails there
        page.label_sized(
            DVec2::new(centre, render_y + ph + 32.0),
            name,
            Anchor::N,
            17.0,
            palette::BLACK,
        );
        let scale_line = if offset == Offset::ScaleAware {
            format!("any scale {} … {}", power(tiny), power(huge))
        } else if scale == 1.0 {
            format!("scale 1: {why}")
        } else {
            format!("scale {}: {why}", power(scale))
        };
        page.label_sized(
            DVec2::new(centre, render_y + ph + 8.0),
            &scale_line,
            Anchor::N,
            16.0,
            palette::BLACK.mix(palette::GREY, 0.5),
        );
        // the verdict under the map, measured at this size
        let wrong = errors.acne + errors.leaks;
        if offset == Offset::ScaleAware {
            // every scale of the test, at the figure's size
            let all_clean = [tiny, 1.0, huge].iter().all(|&s| {
                let e = shadow_errors(&acne_world(s, w, h), offset);
                e.acne + e.leaks == 0
            });
            assert!(
                all_clean,
                "the scale-aware offset is right at every scale"
            );
            let scales =
                format!("scales {}, 1 and {}", power(tiny), power(huge));
            page.text_lines(
                DVec2::new(x, map_y - 16.0),
                20.0,
                16.0,
                &[
                    ("0 pixels wrong at", palette::BLACK),
                    (&scales, palette::BLACK),
                ],
            );
        } else {
            let acne_line = format!("acne {}", percent(errors.acne_fraction()));
            let leak_line =
                format!("leaks {}", percent(errors.leak_fraction()));
            let mut lines = vec![
                (acne_line.as_str(), ACNE_COLOR),
                (leak_line.as_str(), LEAK_COLOR),
            ];
            // a handful of pixels does not show in the render: say so
            let hidden = (wrong as f64) < 0.01 * errors.pixels as f64;
            if hidden {
                lines.push(("too few to see above", palette::BLACK));
            }
            page.text_lines(DVec2::new(x, map_y - 16.0), 20.0, 16.0, &lines);
        }
    }
    page.label_sized(
        DVec2::new(side, map_y + ph + mid / 2.0),
        "below: the pixels each strategy gets wrong (orange: acne, blue: leaks), as shadow\\_errors counts them",
        Anchor::E,
        15.0,
        palette::BLACK,
    );
    Figure::new(
        "acne",
        &format!(
            "The acne scene rendered with each strategy where it fails, and below, the pixels it gets wrong against the true shadows: no protection speckles every lit surface; a fixed normal offset of {} in a scene shrunk to {} errs only in thin slivers at the contact shadows, too few to see in the render; {} in a scene grown to {} is below the rounding error and speckles again; the scale-aware offset is right at every scale. Fractions measured at this {w} × {h} size.",
            power_text(large),
            power_text(tiny),
            power_text(small),
            power_text(huge),
        ),
        page,
    )
}

/// `scenes/two-lights.toml` rendered with shadows, each light's shadow of
/// the big sphere labelled.
fn two_lights() -> Figure {
    let mut world = ch03::parse(TWO_LIGHTS_SCENE, "two-lights.toml")
        .expect("the figure\'s scene builds");
    (world.width, world.height) = (480, 270);
    let (w, h) = (world.width, world.height);
    let image = render(&world, Offset::ScaleAware, &RenderOptions::QUIET)
        .expect("a small render");
    assert_eq!(world.lights.len(), 2, "two lights");
    let red = &world.objects[0];
    let shapes = shapes_of(TWO_LIGHTS_SCENE, "two-lights.toml");

    // Sort the floor pixels by which lights reach them, keeping those the
    // big red sphere shadows (the blue one casts shadows of its own).
    let mut groups: [Vec<DVec2>; 3] = [Vec::new(), Vec::new(), Vec::new()];
    for row in 0..h {
        for column in 0..w {
            let ray = world.camera.pixel_ray(column, row, w, h);
            let Some((object, hit)) =
                world.closest_hit(&ray, Interval::FORWARD)
            else {
                continue;
            };
            if !matches!(shapes[object], raystep_scene::Shape::Plane { .. }) {
                continue;
            }
            let normal = hit.normal * -hit.normal.dot(ray.direction).signum();
            let by_red = |light: &ch04::Light| {
                let (ray, interval) = shadow_ray(
                    hit.point,
                    normal,
                    light.position,
                    Offset::ScaleAware,
                );
                red.shape.intersect(&ray, interval).is_some()
            };
            let s: Vec<f64> = world
                .lights
                .iter()
                .map(|light| {
                    shadow(&world, &hit, normal, light, Offset::ScaleAware)
                })
                .collect();
            let red_blocks: Vec<bool> =
                world.lights.iter().map(by_red).collect();
            let at = DVec2::new(f64::from(column) + 0.5, f64::from(row) + 0.5);
            let lit = [s[0] == 1.0, s[1] == 1.0];
            match lit {
                [false, true] if red_blocks[0] => groups[0].push(at),
                [true, false] if red_blocks[1] => groups[1].push(at),
                [false, false] if red_blocks[0] && red_blocks[1] => {
                    groups[2].push(at)
                }
                _ => {}
            }
        }
    }
    // each group's pixel nearest its centre (a pixel of the group itself)
    let centre_of = |group: &[DVec2]| {
        assert!(!group.is_empty(), "every kind of shadow shows");
        let mean = group.iter().copied().sum::<DVec2>() / group.len() as f64;
        group
            .iter()
            .copied()
            .min_by(|a, b| {
                (*a - mean).length().total_cmp(&(*b - mean).length())
            })
            .expect("not empty")
    };

    let (pw, ph) = (f64::from(w), f64::from(h));
    let (left, right, top, bottom) = (200.0, 200.0, 40.0, 16.0);
    let mut page = Page::new(left + pw + right, bottom + ph + top);
    page.image(
        DVec2::new(left, bottom),
        DVec2::new(left + pw, bottom + ph),
        w,
        h,
        &image.to_srgb8(),
    );
    // image pixel → page point
    let on_page = |p: DVec2| DVec2::new(left + p.x, bottom + ph - p.y);
    let tones: Vec<Color> = world
        .lights
        .iter()
        .map(|l| Color::from_linear(l.intensity).mix(palette::BLACK, 0.5))
        .collect();
    let ink = Stroke::new(palette::BLACK).width(2.0);
    let note = |page: &mut Page,
                target: DVec2,
                at: DVec2,
                anchor: Anchor,
                lines: [(String, Color); 2]| {
        page.arrow(at, target, &ink);
        // a white ring keeps the tip visible on a dark shadow
        page.circle(target, 3.0, Some(palette::WHITE), Some(&ink.thin()));
        page.label_sized(
            at + DVec2::new(0.0, 10.0),
            &lines[0].0,
            anchor,
            16.0,
            lines[0].1,
        );
        page.label_sized(
            at - DVec2::new(0.0, 10.0),
            &lines[1].0,
            anchor,
            16.0,
            lines[1].1,
        );
    };
    // each light's shadow falls on the far side of the sphere from it
    for (i, group) in groups.iter().enumerate().take(2) {
        let target = on_page(centre_of(group));
        let other = 1 - i;
        let right = target.x > left + pw / 2.0;
        let at = DVec2::new(
            if right { left + pw + 14.0 } else { left - 14.0 },
            bottom + ph * 0.45,
        );
        note(
            &mut page,
            target,
            at,
            if right { Anchor::E } else { Anchor::W },
            [
                (format!("light {}'s shadow", i + 1), palette::BLACK),
                (format!("lit by light {} only", other + 1), tones[other]),
            ],
        );
    }
    let target = on_page(centre_of(&groups[2]));
    note(
        &mut page,
        target,
        DVec2::new(left - 14.0, bottom + ph * 0.12),
        Anchor::W,
        [
            ("in both shadows".to_string(), palette::BLACK),
            ("ambient light only".to_string(), palette::BLACK),
        ],
    );
    // which light is where
    let coordinate = |x: f64| format!("{x}").replace('-', "−");
    for (i, light) in world.lights.iter().enumerate() {
        let p = light.position;
        let left_side = p.x < 0.0;
        page.label_sized(
            DVec2::new(
                if left_side { left } else { left + pw },
                bottom + ph + 8.0,
            ),
            &format!(
                "light {} at ({}, {}, {})",
                i + 1,
                coordinate(p.x),
                coordinate(p.y),
                coordinate(p.z)
            ),
            if left_side { Anchor::NE } else { Anchor::NW },
            16.0,
            tones[i],
        );
    }
    Figure::new(
        "two-lights",
        "scenes/two-lights.toml with the scale-aware offset: the red sphere casts one shadow away from each light; each shadow is lit only by the other light and takes its colour, and where both overlap, under the sphere, only the ambient term remains.",
        page,
    )
}

/// How far the blocker of the offsets figure lies above the surface.
const GAP: f64 = 1e-5;

/// The offsets figure's surface y = 1 and a blocker `GAP` above it: a
/// sheet of paper on a table.
fn sheet_world() -> World {
    let text = format!(
        "[camera]\nlook_from = [0, 3, 3]\nlook_at = [0, 1, 0]\n\
         [materials.any]\nkd = 0.5\n\
         [[objects]]\nplane = {{ point = [0, 1, 0], normal = [0, 1, 0] }}\nmaterial = \"any\"\n\
         [[objects]]\nplane = {{ point = [0, {}, 0], normal = [0, 1, 0] }}\nmaterial = \"any\"\n",
        1.0 + GAP
    );
    ch03::parse(&text, "sheet.toml").expect("the figure\'s scene builds")
}

/// The three strategies at one rounded hit point, magnified, and the ulps
/// the scale-aware offset counts.
fn offsets() -> Figure {
    let world = sheet_world();
    let (surface, blocker) = (&world.objects[0].shape, &world.objects[1].shape);
    // A real hit point that rounded below its surface: primary rays from
    // an eye toward the plane until one lands below y = 1.
    let eye = DVec3::new(0.3, 3.7, 2.9);
    let point = (0..1000)
        .find_map(|k| {
            let k = f64::from(k);
            let target = DVec3::new(0.1 + 0.0137 * k, 1.0, -0.3 - 0.0071 * k);
            let ray = ch04::Ray::new(eye, (target - eye).normalize());
            let hit = surface.intersect(&ray, Interval::FORWARD)?;
            (hit.point.y < 1.0).then_some(hit.point)
        })
        .expect("some hit point rounds below the surface");
    let below = 1.0 - point.y;
    let normal = DVec3::Y;
    let light = point + DVec3::new(2.5, 5.0, 0.0);
    let epsilon = 1e-4;
    let strategies = [
        ("no offset: TMin(0)", Offset::TMin(0.0)),
        ("TMin(ε), ε = 10^{−4}", Offset::TMin(epsilon)),
        ("AlongNormal(ε)", Offset::AlongNormal(epsilon)),
        ("ScaleAware", Offset::ScaleAware),
    ];

    // two rows of two panels, then the number line of the ulps
    let mut page = Page::new(900.0, 990.0)
        .view(DVec2::new(0.0, -1.3), DVec2::new(18.0, 18.6));
    // the magnified drawing: surface at 0, blocker at 1, P 0.4 below
    let (drawn_blocker, drawn_p) = (1.0, -0.55);
    let dir = DVec2::new(0.42, 1.0).normalize();
    let top = 3.0;
    let px = -0.2; // where P is drawn in each panel
    let half = 4.0; // half the width of a panel's drawing
    let bases = [14.6, 7.3]; // where each row's surface is drawn
    for (k, &(name, offset)) in strategies.iter().enumerate() {
        let (cx, base) = (4.5 + 9.0 * (k % 2) as f64, bases[k / 2]);
        let at = |x: f64, y: f64| DVec2::new(cx + x, base + y);
        // the real shadow ray and what it meets
        let (ray, interval) = shadow_ray(point, normal, light, offset);
        let re_hit = surface.intersect(&ray, interval);
        let found = blocker.intersect(&ray, interval).is_some();
        // where the ray meets the blocker, if anywhere ahead of its origin
        let blocker_t =
            blocker.intersect(&ray, Interval::FORWARD).map(|hit| hit.t);
        let lift = ray.origin.y - 1.0; // height of the origin above the surface

        // a line between the panels of a row, and under each row
        let rule = Stroke::new(palette::LIGHT_GREY).width(1.5);
        if k % 2 == 1 {
            page.segment(at(-4.5, -3.1), at(-4.5, top + 0.9), &rule);
            page.segment(
                DVec2::new(0.2, base - 3.4),
                DVec2::new(17.8, base - 3.4),
                &rule,
            );
        }
        page.label_sized(
            at(0.0, top + 0.75),
            name,
            Anchor::Center,
            17.0,
            palette::BLACK,
        );
        // blocker and surface
        page.segment(
            at(-half, drawn_blocker),
            at(half, drawn_blocker),
            &Stroke::new(palette::GREY).width(4.0),
        );
        page.segment(
            at(-half, 0.0),
            at(half, 0.0),
            &Stroke::new(palette::BLACK).width(2.0),
        );
        let p = at(px, drawn_p);
        // the drawn origin: where the real one is, relative to surface and blocker
        let origin_y = if ray.origin.y >= 1.0 + GAP {
            drawn_blocker + 0.6
        } else if ray.origin.y > 1.0 {
            0.35
        } else {
            drawn_p
        };
        let o = at(px, origin_y);
        let cross = |y: f64| o + (y - origin_y) / dir.y * dir;
        let end = cross(top);
        let ray_stroke = Stroke::new(palette::BLUE).width(2.0);
        match offset {
            Offset::TMin(eps) if eps > 0.0 => {
                // the ignored first ε of the ray
                let skip = cross(drawn_blocker + 0.55);
                page.segment(
                    o,
                    skip,
                    &Stroke::new(palette::LIGHT_GREY).width(9.0),
                );
                page.segment(o, skip, &ray_stroke.dashed());
                page.arrow(skip, end, &ray_stroke);
                page.hollow_point(cross(0.0), palette::BLACK);
                page.hollow_point(cross(drawn_blocker), LEAK_COLOR);
                page.label_sized(
                    skip - DVec2::new(0.15, 0.0),
                    "t < ε: ignored",
                    Anchor::W,
                    16.0,
                    palette::BLACK,
                );
            }
            _ => {
                let first = if re_hit.is_some() {
                    Some((cross(0.0), ACNE_COLOR))
                } else if found {
                    Some((cross(drawn_blocker), palette::BLACK))
                } else {
                    None
                };
                match first {
                    Some((stop, color)) => {
                        page.segment(o, stop, &ray_stroke);
                        page.arrow(stop, end, &ray_stroke.dashed());
                        page.circle(
                            stop,
                            5.5 / page.scale(),
                            Some(color),
                            Some(&Stroke::new(palette::BLACK).width(1.0)),
                        );
                    }
                    None => page.arrow(o, end, &ray_stroke),
                }
            }
        }
        if origin_y != drawn_p {
            // the lift, and for the scale-aware offset its ulp steps
            page.arrow(p, o, &Stroke::new(LIFT_COLOR).width(2.0));
            if offset == Offset::ScaleAware {
                for step in 1..7 {
                    let y =
                        drawn_p + f64::from(step) * (origin_y - drawn_p) / 7.0;
                    page.segment(
                        at(px - 0.1, y),
                        at(px + 0.1, y),
                        &Stroke::new(LIFT_COLOR).width(1.0),
                    );
                }
                page.label_sized(
                    at(px + 0.15, -0.3),
                    &format!("{INT_SCALE} ulps"),
                    Anchor::E,
                    16.0,
                    LIFT_COLOR,
                );
            } else {
                page.label_sized(
                    at(px, 0.7),
                    "ε·N",
                    Anchor::W,
                    16.0,
                    LIFT_COLOR,
                );
            }
        }
        page.point(p, palette::BLACK);
        page.label(p, "P", Anchor::SW);

        // what the real ray does, in numbers
        let mut lines: Vec<(String, Color)> = vec![(
            match offset {
                Offset::TMin(0.0) => "starts at P, counts t ≥ 0".to_string(),
                Offset::TMin(eps) => {
                    format!("starts at P, skips t < {}", power(eps))
                }
                _ => format!("starts {} above", power(lift)),
            },
            palette::BLACK,
        )];
        match re_hit {
            Some(hit) => {
                lines.push(("hits its own surface at".to_string(), ACNE_COLOR));
                lines.push((format!("t = {}: acne", power(hit.t)), ACNE_COLOR));
            }
            None => lines
                .push(("misses its own surface".to_string(), palette::BLACK)),
        }
        match (found, blocker_t) {
            (true, _) => lines
                .push(("finds the blocker: S = 0".to_string(), palette::BLACK)),
            (false, Some(t)) => {
                lines.push(("skips the blocker at".to_string(), LEAK_COLOR));
                lines.push((format!("t = {} < ε: leak", power(t)), LEAK_COLOR));
            }
            (false, None) => {
                lines.push((
                    "starts above the blocker:".to_string(),
                    LEAK_COLOR,
                ));
                lines.push(("leak".to_string(), LEAK_COLOR));
            }
        }
        let lines: Vec<(&str, Color)> =
            lines.iter().map(|(t, c)| (t.as_str(), *c)).collect();
        page.text_lines(at(-half, -1.3), 0.45, 16.0, &lines);
        if k == 0 {
            page.label_sized(
                at(-half, 0.0),
                "surface y = 1",
                Anchor::NE,
                16.0,
                palette::BLACK,
            );
            page.label_sized(
                at(-half, drawn_blocker),
                &format!("blocker {} above", power(GAP)),
                Anchor::NE,
                16.0,
                palette::GREY,
            );
            page.label_sized(
                p + DVec2::new(0.25, 0.0),
                &format!("{} below", power(below)),
                Anchor::E,
                16.0,
                palette::BLACK,
            );
        }
    }

    // The ulps: the numbers of a toy format (3 bits after the point), whose
    // spacing doubles at every power of two.
    let axis_y = 1.3;
    let x0 = 0.7;
    let unit = 2.0; // drawing units per toy unit
    let ax = |x: f64| DVec2::new(x0 + unit * x, axis_y);
    let up = |h: f64| DVec2::new(0.0, h);
    let toy_origin = 0.5;
    let toy_ulp = |x: f64| 2f64.powi(x.log2().floor() as i32) / 8.0;
    page.text_lines(
        DVec2::new(x0 - 0.3, axis_y + 2.35),
        0.45,
        16.0,
        &[
            (
                "ScaleAware moves each coordinate by ulps, the gaps between",
                palette::BLACK,
            ),
            (
                "neighbouring numbers; they double at every power of 2",
                palette::BLACK,
            ),
        ],
    );
    page.rect(
        ax(0.0) - up(0.35),
        ax(toy_origin) + up(1.1),
        Some(LIFT_COLOR.mix(palette::WHITE, 0.8)),
        None,
    );
    page.arrow(ax(-0.15), ax(8.4), &Stroke::new(palette::BLACK).width(1.5));
    page.label(ax(8.4), "x", Anchor::S);
    let tick = |page: &mut Page, x: f64, h: f64| {
        page.segment(
            ax(x) - up(h),
            ax(x) + up(h),
            &Stroke::new(palette::BLACK).width(1.0),
        );
    };
    tick(&mut page, 0.0, 0.25);
    // every number of the format from 1/4 to 8 (closer to 0 they crowd
    // ever closer: that is where the fixed step takes over)
    for e in -2..=2 {
        let octave = 2f64.powi(e);
        for m in 0..8 {
            let x = octave * (1.0 + f64::from(m) / 8.0);
            tick(&mut page, x, if m == 0 { 0.25 } else { 0.13 });
        }
    }
    tick(&mut page, 8.0, 0.25);
    for x in [0.0, 0.5, 1.0, 2.0, 4.0, 8.0] {
        let text = if x == 0.5 {
            "½".to_string()
        } else {
            format!("{x}")
        };
        page.label_sized(
            ax(x) - up(0.25),
            &text,
            Anchor::S,
            16.0,
            palette::BLACK,
        );
    }
    // a lift of 2 ulps from a few points, and the fixed step near 0
    for x in [1.25, 2.5, 5.0] {
        let to = x + 2.0 * toy_ulp(x);
        page.arrow(
            ax(x) + up(0.4),
            ax(to) + up(0.4),
            &Stroke::new(LIFT_COLOR).width(2.5),
        );
        page.label_sized(
            ax((x + to) / 2.0) + up(0.45),
            "2 ulps",
            Anchor::N,
            16.0,
            LIFT_COLOR,
        );
    }
    let fixed = 2.0 * toy_ulp(toy_origin);
    page.arrow(
        ax(0.1) + up(0.4),
        ax(0.1 + fixed) + up(0.4),
        &Stroke::new(LIFT_COLOR).width(2.5),
    );
    page.label_sized(
        ax(0.0) + up(1.35),
        "near 0: a fixed step",
        Anchor::E,
        16.0,
        LIFT_COLOR,
    );
    // the real f64 lifts, from offset_scale_aware (only x moves: N = +x)
    let lift =
        |x: f64| offset_scale_aware(DVec3::new(x, 0.5, 0.5), DVec3::X).x - x;
    let lines = [
        "drawn: 3 bits after the point and a lift of 2 ulps;".to_string(),
        format!(
            "f64 has 52 bits and lifts INT\\_SCALE = {INT_SCALE} ulps: x = 1.25 moves {},",
            power(lift(1.25)),
        ),
        format!(
            "x = 5·10^6 moves {}, |x| < ORIGIN = 1/{} a fixed {}",
            power(lift(5e6)),
            1.0 / ORIGIN,
            power(lift(0.01))
        ),
    ];
    let lines: Vec<(&str, Color)> =
        lines.iter().map(|l| (l.as_str(), palette::BLACK)).collect();
    page.text_lines(DVec2::new(x0 - 0.3, axis_y - 1.1), 0.45, 16.0, &lines);
    Figure::new(
        "offsets",
        &format!(
            "Top: one real hit point P that rounded {} below the surface y = 1, with a blocker {} above it, and the shadow ray of each strategy (heights not to scale; the verdicts are the real rays'). Bottom: the numbers of a toy format, whose gaps (ulps) double at every power of 2: a lift of a fixed number of ulps grows with |x|, and near 0 a fixed step takes over.",
            power_text(below),
            power_text(GAP)
        ),
        page,
    )
}
