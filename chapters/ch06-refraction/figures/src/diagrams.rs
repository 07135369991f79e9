//! The chapter's lecture figures, drawn from the reference code.
//!
//! Every direction, angle and curve shown comes from the chapter's code:
//! the refracted rays from [`refract`], the critical angles from
//! [`critical_angle`], the reflectance curves from [`fresnel`] and
//! [`schlick`], the renders from [`render`] with the exact Fresnel split,
//! and which pixels of the bubble see total internal reflection from
//! [`Media::cross`] and [`refract`] on the scene's own objects.
use raystep_figure::numbers::fixed;
use raystep_figure::palette::role;
use raystep_figure::{
    Anchor, Color, DVec2, DVec3, Figure, Page, Stroke, camera_pixel, palette,
};
use raystep_render::{Image, RenderOptions};

use crate::measurements::MATERIALS_SCENE;
use ch06::{
    CAMERA_MEDIUM, DEFAULT_STOP, Fresnel, Interval, Media, REFRACTIVE_INDICES,
    Ray, World, critical_angle, refract, render,
};

/// Every figure of this chapter, in the order the lecture shows them.
pub fn all() -> Vec<Figure> {
    vec![snell(), critical_angles(), materials(), bubble()]
}

/// The reflectance curves of the lecture's materials, exact and by
/// Schlick (a chart of computed values; the measured one is
/// [`crate::charts::fresnel_chart`]).
pub fn reflectance_chart() -> Result<Figure, raystep_figure::ChartError> {
    reflectance::chart()
}

/// The bubble scene.
const BUBBLE_SCENE: &str = include_str!("../../scenes/bubble.toml");

const TRANSMIT_COLOR: Color = palette::GREEN;
const TIR_COLOR: Color = palette::ORANGE;
const INTO_BUBBLE_COLOR: Color = palette::BLUE;
/// The denser medium's tint.
const MEDIUM_FILL: Color = Color::rgb(214, 234, 248);
/// An angle in degrees with one decimal.
fn degrees(radians: f64) -> String {
    format!("{}°", fixed(radians.to_degrees(), 1))
}

/// The index of refraction of a material of the lecture's table.
fn index_of(material: &str) -> f64 {
    REFRACTIVE_INDICES
        .iter()
        .find(|(name, _)| *name == material)
        .map(|&(_, n)| n)
        .unwrap_or_else(|| panic!("`{material}` is in the table"))
}

/// The table's materials by index of refraction, lowest first.
fn by_index() -> Vec<(&'static str, f64)> {
    let mut table = REFRACTIVE_INDICES.to_vec();
    table.sort_by(|a, b| a.1.total_cmp(&b.1));
    table
}

/// A direction in the figure's plane as a 3D vector (z = 0), and back.
fn space(v: DVec2) -> DVec3 {
    v.extend(0.0)
}

/// The unit vector at `angle` radians counter-clockwise from `from`.
fn turned(from: DVec2, angle: f64) -> DVec2 {
    DVec2::from_angle(angle).rotate(from)
}

/// Snell's law for water, glass and diamond: the same incoming ray from
/// vacuum, three refracted rays.
fn snell() -> Figure {
    let theta = 45f64.to_radians();
    let materials = ["water", "glass", "diamond"];
    let n_theta = CAMERA_MEDIUM;
    let (panel, gap) = (3.2, 0.4);
    let (top, bottom) = (1.45, -1.95);
    let width_world = 3.0 * panel + 2.0 * gap;
    let mut page = Page::new(900.0, 310.0).margin(10.0).view(
        DVec2::new(-panel / 2.0, bottom),
        DVec2::new(width_world - panel / 2.0, top),
    );
    let thin = Stroke::new(palette::BLACK).width(1.2);
    let len = 1.3;
    for (k, material) in materials.iter().enumerate() {
        let n_phi = index_of(material);
        let p = DVec2::new(k as f64 * (panel + gap), 0.0);
        let (left, right) = (p.x - panel / 2.0, p.x + panel / 2.0);
        // the two media: vacuum above, the material below
        page.rect(
            DVec2::new(left, bottom + 0.62),
            DVec2::new(right, 0.0),
            Some(MEDIUM_FILL),
            None,
        );
        page.segment(
            DVec2::new(left, 0.0),
            DVec2::new(right, 0.0),
            &Stroke::new(palette::GREY).width(1.5),
        );
        // the incoming ray D at θ to N, and T from the chapter's refract
        let n = DVec2::Y;
        let d = turned(-n, theta);
        let t = refract(space(d), space(n), n_theta, n_phi)
            .expect("from vacuum into a denser medium every ray refracts")
            .truncate();
        let phi = t.angle_to(-n).abs();
        let ratio = theta.sin() / phi.sin();
        assert!(
            (ratio - n_phi / n_theta).abs() < 1e-12,
            "Snell's law: sin θ / sin φ = n_φ / n_θ"
        );
        // the normal, both ways, dashed
        // (below the medium's label above)
        page.segment(
            p + 1.05 * n,
            p - 1.25 * n,
            &Stroke::new(role::NORMAL).width(1.5).dashed(),
        );
        page.arrow(p, p + 0.9 * n, &Stroke::vector(role::NORMAL));
        page.label(p + 0.9 * n, "N", Anchor::E);
        // where D would go without bending
        page.segment(
            p,
            p + 1.05 * len * d,
            &Stroke::new(palette::GREY).width(1.2).dashed(),
        );
        page.arrow(p - len * d, p, &Stroke::vector(role::RAY));
        page.label(p - 0.6 * len * d, "D", Anchor::SW);
        page.arrow(p, p + len * t, &Stroke::vector(TRANSMIT_COLOR));
        page.label(p + 0.75 * len * t, "T", Anchor::E);
        page.angle_arc(p, n, -d, 58.0, &thin, Some("θ"));
        page.angle_arc(p, -n, t, 58.0, &thin, Some("φ"));
        // the two angles' values, on the far side of the normal
        page.label_sized(
            p + DVec2::new(0.25, 0.55),
            &format!("θ = {}", degrees(theta)),
            Anchor::E,
            16.0,
            role::RAY,
        );
        page.label_sized(
            p + DVec2::new(-0.25, -0.55),
            &format!("φ = {}", degrees(phi)),
            Anchor::W,
            16.0,
            TRANSMIT_COLOR,
        );
        page.point(p, palette::BLACK);
        // the media and the law with this panel's numbers
        page.label_sized(
            DVec2::new(left + 0.05, top - 0.2),
            &format!("vacuum, n_θ = {n_theta}"),
            Anchor::E,
            16.0,
            palette::BLACK,
        );
        page.text_lines(
            DVec2::new(left + 0.05, bottom + 1.12),
            0.27,
            16.0,
            &[
                (material, palette::BLACK),
                (&format!("n_φ = {n_phi}"), palette::BLACK),
            ],
        );
        page.text_lines(
            DVec2::new(left + 0.05, bottom + 0.4),
            0.27,
            16.0,
            &[
                (
                    &format!("sin {} / sin {}", degrees(theta), degrees(phi)),
                    palette::BLACK,
                ),
                (
                    &format!("= {} = n_φ / n_θ", fixed(ratio, 3)),
                    palette::BLACK,
                ),
            ],
        );
    }
    Figure::new(
        "snell",
        &format!(
            "The same ray D comes from vacuum at θ = {} to the normal N and enters water, glass and diamond; T is the refracted ray from refract, at φ to −N, and the grey dashes show where D would have gone unbent. The denser the material, the more T bends toward the normal: sin θ / sin φ = n_φ / n_θ.",
            degrees(theta)
        ),
        page,
    )
}

/// Every material of the table, leaving it into vacuum at its critical
/// angle: the refracted ray grazes the surface.
fn critical_angles() -> Figure {
    let (cell, row_height) = (3.0, 2.45);
    let columns = 3;
    let mut page = Page::new(900.0, 738.0).margin(8.0).view(
        DVec2::new(0.0, -3.0 * row_height),
        DVec2::new(columns as f64 * cell, 0.0),
    );
    let thin = Stroke::new(palette::BLACK).width(1.2);
    let (len, margin) = (0.85, 0.08);
    let n_phi = CAMERA_MEDIUM;
    for (k, (material, n_theta)) in by_index().into_iter().enumerate() {
        let corner = DVec2::new(
            (k % columns) as f64 * cell,
            -((k / columns) as f64) * row_height,
        );
        let (left, right) = (corner.x + margin, corner.x + cell - margin);
        let p = DVec2::new(corner.x + cell / 2.0, corner.y - 1.25);
        let floor = corner.y - row_height + margin;
        page.rect(
            DVec2::new(left, floor),
            DVec2::new(right, p.y),
            Some(MEDIUM_FILL),
            None,
        );
        page.segment(
            DVec2::new(left, p.y),
            DVec2::new(right, p.y),
            &Stroke::new(palette::GREY).width(1.5),
        );
        // the ray comes from inside: its side's normal points down
        let n = -DVec2::Y;
        page.segment(
            p - 0.6 * n,
            p + 1.0 * n,
            &Stroke::new(role::NORMAL).width(1.5).dashed(),
        );
        page.label_sized(
            DVec2::new(left + 0.04, corner.y - 0.2),
            material,
            Anchor::E,
            17.0,
            palette::BLACK,
        );
        page.label_sized(
            DVec2::new(left + 0.04, floor + 0.15),
            &format!("n_θ = {n_theta}"),
            Anchor::E,
            16.0,
            palette::BLACK,
        );
        page.label_sized(
            DVec2::new(right - 0.04, p.y + 0.2),
            "vacuum",
            Anchor::W,
            15.0,
            palette::NOTE,
        );
        match critical_angle(n_theta, n_phi) {
            None => {
                // nothing to leave: the ray goes straight on
                let theta = 40f64.to_radians();
                let d = turned(-n, -theta);
                let t = refract(space(d), space(n), n_theta, n_phi)
                    .expect("equal indices always refract")
                    .truncate();
                assert!((t - d).length() < 1e-12, "equal indices do not bend");
                page.arrow(p - len * d, p, &Stroke::vector(role::RAY));
                page.arrow(
                    p,
                    p + 0.75 * len * t,
                    &Stroke::vector(TRANSMIT_COLOR),
                );
                page.label_sized(
                    DVec2::new(right - 0.04, corner.y - 0.2),
                    "no critical angle:",
                    Anchor::W,
                    16.0,
                    palette::BLACK,
                );
                page.label_sized(
                    DVec2::new(right - 0.04, corner.y - 0.45),
                    "n_θ = n_φ, no ray bends",
                    Anchor::W,
                    16.0,
                    palette::NOTE,
                );
            }
            Some(critical) => {
                // just inside θc the ray still gets out, grazing; just
                // past it refract has no answer: total internal reflection
                let nudge = 1e-7;
                let d = turned(-n, -critical);
                let grazing = refract(
                    space(turned(-n, nudge - critical)),
                    space(n),
                    n_theta,
                    n_phi,
                )
                .expect("below the critical angle the ray refracts")
                .truncate();
                assert!(
                    refract(
                        space(turned(-n, -nudge - critical)),
                        space(n),
                        n_theta,
                        n_phi
                    )
                    .is_none(),
                    "past the critical angle: total internal reflection"
                );
                let phi = grazing.angle_to(-n).abs();
                assert!(phi.to_degrees() > 89.9, "the refracted ray grazes");
                // past θc everything reflects: a faint reflected ray
                // (air's would lie on the surface)
                let air = critical.to_degrees() > 80.0;
                if !air {
                    page.arrow(
                        p,
                        p + 0.9 * len * DVec2::new(d.x, -d.y),
                        &Stroke::new(palette::PURPLE).width(1.5).dashed(),
                    );
                }
                page.arrow(p - len * d, p, &Stroke::vector(role::RAY));
                page.arrow(
                    p,
                    p + 1.3 * len * grazing,
                    &Stroke::vector(TRANSMIT_COLOR),
                );
                if air {
                    page.angle_arc(p, -d, n, 34.0, &thin, Some("θ_c"));
                } else {
                    // the label beyond the arc, clear of both rays
                    page.angle_arc(p, -d, n, 34.0, &thin, None);
                    page.label(
                        p + 0.62 * turned(n, -critical / 2.0),
                        "θ_c",
                        Anchor::Center,
                    );
                }
                page.label_sized(
                    DVec2::new(right - 0.04, corner.y - 0.2),
                    &format!(
                        "θ_c = {}{}",
                        degrees(critical),
                        if air { ", nearly 90°" } else { "" }
                    ),
                    Anchor::W,
                    16.0,
                    palette::BLACK,
                );
                page.label_sized(
                    DVec2::new(right - 0.04, corner.y - 0.45),
                    &format!("sin θ_c = {n_phi} / {n_theta}"),
                    Anchor::W,
                    16.0,
                    palette::NOTE,
                );
            }
        }
        page.point(p, palette::BLACK);
    }
    // the last two cells: the key
    let key = DVec2::new(cell + 0.15, -2.0 * row_height - 0.35);
    page.text_lines(
        key,
        0.27,
        16.0,
        &[
            (
                "below: the material, n_θ; above: vacuum, n_φ = 1",
                palette::BLACK,
            ),
            ("blue: the ray inside, at θ_c", role::RAY),
            (
                "green: the refracted ray, from refract just below θ_c:",
                TRANSMIT_COLOR,
            ),
            ("it grazes the surface, φ = 90°", TRANSMIT_COLOR),
            ("dashed: past θ_c refract gives None;", palette::PURPLE),
            ("all light is reflected", palette::PURPLE),
        ],
    );
    let list: Vec<String> = by_index()
        .into_iter()
        .filter_map(|(m, n)| {
            critical_angle(n, n_phi).map(|c| format!("{m} {}", degrees(c)))
        })
        .collect();
    Figure::new(
        "critical-angles",
        &format!(
            "Every material of the table, leaving it into vacuum: the ray inside meets the surface at the material's critical angle θc, sin θc = n_φ / n_θ, and the refracted ray grazes the surface; a ray any steeper is totally reflected (TIR). The angles from critical_angle: {}. Vacuum into vacuum has no critical angle, and air's is nearly 90°: almost every ray gets out.",
            list.join(", ")
        ),
        page,
    )
}

/// The reflectance chart: exact Fresnel and Schlick against the angle.
mod reflectance {
    use raystep_figure::plotters::prelude::*;
    use raystep_figure::{ChartError, Figure, Ticked, font};

    use ch06::{CAMERA_MEDIUM, critical_angle, fresnel, schlick};

    /// The materials drawn, their colours (Okabe–Ito) and how the legend
    /// names them; air is left out, its curves lie on vacuum's. Ice and
    /// water lie close together, so they get colours far apart: reddish
    /// purple and blue, not two blues.
    const CURVES: [(&str, RGBColor); 6] = [
        ("vacuum", RGBColor(136, 136, 136)),
        ("ice", RGBColor(204, 121, 167)),
        ("water", RGBColor(0, 114, 178)),
        ("glass", RGBColor(0, 158, 115)),
        ("quartz", RGBColor(230, 159, 0)),
        ("diamond", RGBColor(213, 94, 0)),
    ];

    /// The angles sampled, in degrees: every tenth of a degree below 90°
    /// (at 90° itself a ray only grazes the surface), up to the critical
    /// angle if there is one, and close below it, where the exact curve
    /// rises steeply. Past it R = 1.
    fn angles(critical: Option<f64>) -> Vec<f64> {
        let end = critical.map_or(90.0, f64::to_degrees);
        let mut theta: Vec<f64> = (0..900)
            .map(|k| f64::from(k) / 10.0)
            .filter(|&t| t < end)
            .collect();
        if let Some(c) = critical {
            let c = c.to_degrees();
            theta.extend(
                [0.05, 0.02, 0.01, 0.005, 0.002, 0.001, 0.0].map(|d| c - d),
            );
        }
        theta.sort_by(f64::total_cmp);
        theta
    }

    /// The chart: both panels and the legend.
    pub fn chart() -> Result<Figure, ChartError> {
        raystep_figure::chart(
            "reflectance",
            "The fraction R of light reflected at the surface of each material against the angle of incidence θ, by the exact Fresnel equations (solid, fresnel) and by Schlick's approximation (dashed, schlick). Left: entering the material from vacuum; R rises from R₀ at normal incidence to 1 at grazing incidence. Right: leaving it into vacuum; R reaches 1 at the critical angle, and past it all light is reflected. Vacuum's exact R is 0 at every angle, but Schlick's rises to 1 at grazing angles. Air (n = 1.0003) is left out: its curves lie on vacuum's except in the last 1.4° before 90°.",
            900,
            550,
            draw,
        )
    }

    fn draw(area: &raystep_figure::ChartArea) -> Result<(), ChartError> {
        // the legend: the materials on one line, the two formulas below,
        // then what the dots mark
        let (legend, panels) = area.split_vertically(94);
        for (k, (name, colour)) in CURVES.iter().enumerate() {
            let x = 20 + 120 * k as i32;
            legend.draw(&Rectangle::new(
                [(x, 14), (x + 24, 19)],
                colour.filled(),
            ))?;
            legend.draw(&Text::new(*name, (x + 30, 7), font(16.0)))?;
        }
        let x = 20;
        legend.draw(&PathElement::new(
            [(x, 46), (x + 28, 46)],
            BLACK.stroke_width(2),
        ))?;
        legend.draw(&Text::new("exact (fresnel)", (x + 36, 37), font(16.0)))?;
        let x = 240;
        for dash in 0..3 {
            let x0 = x + 11 * dash;
            legend.draw(&PathElement::new(
                [(x0, 46), (x0 + 6, 46)],
                BLACK.stroke_width(2),
            ))?;
        }
        legend.draw(&Text::new(
            "Schlick's approximation (schlick)",
            (x + 36, 37),
            font(16.0),
        ))?;
        legend.draw(&Text::new(
            "● right: the critical angle θ_c; past it R = 1 for both, total internal reflection",
            (20, 67),
            font(16.0),
        ))?;

        let panels = panels.split_evenly((1, 2));
        let sides = [
            ("entering: vacuum → material", true),
            ("leaving: material → vacuum", false),
        ];
        for (panel, (title, entering)) in panels.iter().zip(sides) {
            let mut c = ChartBuilder::on(panel)
                .caption(title, font(17.0))
                .margin(12)
                .margin_right(22)
                .x_label_area_size(52)
                .y_label_area_size(60)
                .build_cartesian_2d(
                    Ticked::new(
                        0.0..90.0,
                        (0..=6).map(|k| 15.0 * f64::from(k)).collect(),
                    ),
                    0f64..1.02f64,
                )?;
            c.configure_mesh()
                .x_desc("θ, angle of incidence")
                .y_desc("R, reflected fraction")
                .y_labels(6)
                .x_label_formatter(&|x| format!("{x:.0}°"))
                .y_label_formatter(&|y| format!("{y:.1}"))
                .label_style(font(16.0))
                .axis_desc_style(font(15.0))
                .light_line_style(WHITE)
                .draw()?;
            for (name, colour) in CURVES {
                let n = crate::diagrams::index_of(name);
                let (n_theta, n_phi) = if entering {
                    (CAMERA_MEDIUM, n)
                } else {
                    (n, CAMERA_MEDIUM)
                };
                let critical = critical_angle(n_theta, n_phi);
                let theta = angles(critical);
                let curve = |f: fn(f64, f64, f64) -> f64| -> Vec<(f64, f64)> {
                    theta
                        .iter()
                        .map(|&t| (t, f(t.to_radians().cos(), n_theta, n_phi)))
                        .collect()
                };
                c.draw_series(LineSeries::new(
                    curve(fresnel),
                    colour.stroke_width(2),
                ))?;
                c.draw_series(DashedLineSeries::new(
                    curve(schlick),
                    7,
                    5,
                    colour.stroke_width(2),
                ))?;
                // the critical angle: from here on R = 1
                if let Some(angle) = critical {
                    c.draw_series(std::iter::once(Circle::new(
                        (angle.to_degrees(), 1.0),
                        4,
                        colour.filled(),
                    )))?;
                }
            }
        }
        Ok(())
    }
}

/// `scenes/materials.toml` rendered with the exact Fresnel split, each ball
/// labelled with its material under it.
fn materials() -> Figure {
    let mut world = ch03::parse(MATERIALS_SCENE, "materials.toml")
        .expect("the figure\'s scene builds");
    let zoom = 4;
    (world.width, world.height) = (world.width * zoom, world.height * zoom);
    let (w, h) = (world.width, world.height);
    let (image, counts) =
        render(&world, &DEFAULT_STOP, Fresnel::Exact, &RenderOptions::QUIET)
            .expect("a small render");
    let (pw, ph) = (f64::from(w), f64::from(h));
    let (side, top, bottom) = (2.0, 12.0, 52.0);
    let mut page = Page::new(pw + 2.0 * side, ph + top + bottom);
    page.image(
        DVec2::new(side, bottom),
        DVec2::new(side + pw, bottom + ph),
        w,
        h,
        &image.to_srgb8(),
    );
    let scene = raystep_scene::parse(MATERIALS_SCENE, "materials.toml")
        .expect("it parses");
    for object in &scene.objects {
        let raystep_scene::Shape::Sphere { center, .. } = object.shape else {
            continue;
        };
        let material = &world.materials[object.material];
        let at = camera_pixel(&world.camera, center, w, h);
        page.label_sized(
            DVec2::new(side + at.x, bottom - 2.0),
            &material.name,
            Anchor::S,
            16.0,
            palette::BLACK,
        );
        page.label_sized(
            DVec2::new(side + at.x, bottom - 22.0),
            &format!("n = {}", material.ior),
            Anchor::S,
            14.0,
            palette::NOTE,
        );
    }
    assert_eq!(counts.medium_mismatches, 0, "every crossing fits the stack");
    // a chord meets a sphere at the same angle at both ends: a ray that
    // got into a ball always gets out again
    assert_eq!(
        counts.total_internal_reflections, 0,
        "no TIR in a lone ball"
    );
    Figure::new(
        "materials",
        &format!(
            "scenes/materials.toml at {w} × {h}, rendered with the exact Fresnel split: one ball of each material of the table, all with kt = 1 and no diffuse colour. The vacuum ball shows only its highlight, and the air ball is all but invisible too; the denser the ball, the more it bends the checks behind it (turned upside down, as by a lens) and the brighter the reflection at its rim. Every ball casts a black shadow, the vacuum ball too: shadow rays stop at any object, transparent or not."
        ),
        page,
    )
}

/// What the eye sees of the bubble, pixel by pixel, on its first way in.
#[derive(Clone, Copy, PartialEq, Eq)]
enum BubbleView {
    /// The pixel does not see the bubble through the water.
    Elsewhere,
    /// The ray meets the bubble past the critical angle: all reflected.
    Reflected,
    /// The ray enters the bubble.
    Entered,
}

/// For each pixel of `world` (the bubble scene): the primary ray enters
/// the water ball, bends by [`refract`], and meets the bubble either past
/// the critical angle or not. The indices come from [`Media::cross`],
/// as in the tracer.
fn bubble_views(world: &World) -> Vec<BubbleView> {
    let (w, h) = (world.width, world.height);
    let index = |name: &str| {
        world
            .objects
            .iter()
            .position(|o| world.materials[o.material].name == name)
            .expect("the bubble scene has water and air")
    };
    let (water, air) = (index("water"), index("air"));
    let ior =
        |object: usize| world.materials[world.objects[object].material].ior;
    let hit_of = |ray: &Ray| {
        world
            .closest_hit(ray, Interval::FORWARD)
            .map(|(object, hit)| (hit, object))
    };
    let mut views = Vec::with_capacity((w * h) as usize);
    for row in 0..h {
        for column in 0..w {
            let ray = world.camera.pixel_ray(column, row, w, h);
            let mut view = BubbleView::Elsewhere;
            if let Some((hit, k)) = hit_of(&ray)
                && k == water
            {
                let d = ray.direction.normalize();
                let into_water =
                    Media::new(CAMERA_MEDIUM).cross(water, ior(water), true);
                let normal = hit.facing(d);
                if let Some(t) =
                    refract(d, normal, into_water.n_theta, into_water.n_phi)
                {
                    let inside = Ray::new(
                        ch04::offset_scale_aware(hit.point, -normal),
                        t,
                    );
                    if let Some((hit, k)) = hit_of(&inside)
                        && k == air
                    {
                        let into_air =
                            into_water.beyond.cross(air, ior(air), true);
                        view = match refract(
                            t,
                            hit.facing(t),
                            into_air.n_theta,
                            into_air.n_phi,
                        ) {
                            None => BubbleView::Reflected,
                            Some(_) => BubbleView::Entered,
                        };
                    }
                }
            }
            views.push(view);
        }
    }
    views
}

/// `scenes/bubble.toml` rendered, beside a map of where the eye's rays
/// meet the bubble past the critical angle.
fn bubble() -> Figure {
    let mut world = ch03::parse(BUBBLE_SCENE, "bubble.toml")
        .expect("the figure\'s scene builds");
    (world.width, world.height) = (432, 243);
    let (w, h) = (world.width, world.height);
    let (image, counts) =
        render(&world, &DEFAULT_STOP, Fresnel::Exact, &RenderOptions::QUIET)
            .expect("a small render");
    assert_eq!(counts.medium_mismatches, 0, "every crossing fits the stack");
    let views = bubble_views(&world);
    let count = |v: BubbleView| views.iter().filter(|&&x| x == v).count();
    let (reflected, entered) =
        (count(BubbleView::Reflected), count(BubbleView::Entered));
    assert!(reflected > 0 && entered > 0, "the bubble shows both");
    // the render tinted by what each pixel's ray does, faded elsewhere
    let map = Image::from_fn(w, h, |column, row| {
        let c = image.get(column, row).min(DVec3::ONE);
        match views[(row * w + column) as usize] {
            BubbleView::Reflected => c.lerp(TIR_COLOR.to_linear(), 0.6),
            BubbleView::Entered => c.lerp(INTO_BUBBLE_COLOR.to_linear(), 0.6),
            BubbleView::Elsewhere => {
                let grey = (c.x + c.y + c.z) / 3.0;
                DVec3::splat(0.55 + 0.45 * grey)
            }
        }
    });
    let (pw, ph) = (f64::from(w), f64::from(h));
    let (side, gap, top, bottom) = (6.0, 16.0, 34.0, 62.0);
    let mut page = Page::new(2.0 * pw + gap + 2.0 * side, ph + top + bottom);
    for (k, (picture, title)) in [
        (&image, "bubble.toml, exact Fresnel split"),
        (&map, "where the eye's rays meet the bubble"),
    ]
    .into_iter()
    .enumerate()
    {
        let x = side + k as f64 * (pw + gap);
        page.image(
            DVec2::new(x, bottom),
            DVec2::new(x + pw, bottom + ph),
            w,
            h,
            &picture.to_srgb8(),
        );
        page.label_sized(
            DVec2::new(x + pw / 2.0, bottom + ph + 8.0),
            title,
            Anchor::N,
            16.0,
            palette::BLACK,
        );
    }
    let critical = critical_angle(index_of("water"), index_of("air"))
        .expect("water is denser than air");
    let percent = |n: usize| 100.0 * n as f64 / (entered + reflected) as f64;
    page.text_lines(
        DVec2::new(side, bottom - 16.0),
        21.0,
        15.0,
        &[
            (
                &format!(
                    "orange: past the critical angle {} of water to air, all light is reflected ({} % of the bubble)",
                    degrees(critical),
                    fixed(percent(reflected), 0)
                ),
                TIR_COLOR.mix(palette::BLACK, 0.25),
            ),
            (
                &format!(
                    "blue: the ray enters the bubble and shows the checks behind, shrunk ({} %)",
                    fixed(percent(entered), 0)
                ),
                INTO_BUBBLE_COLOR,
            ),
        ],
    );
    Figure::new(
        "bubble",
        &format!(
            "Left: scenes/bubble.toml at {w} × {h}, an air bubble in a ball of water, rendered with the exact Fresnel split. Right: for each pixel, the eye's ray refracted into the water (by refract) and followed to the bubble: orange where it meets the bubble past the critical angle of water to air, {} — total internal reflection turns the bubble's rim into a bright mirror ring —, blue where it gets into the bubble, which acts as a diverging lens. The whole render counted {} total internal reflections.",
            degrees(critical),
            counts.total_internal_reflections
        ),
        page,
    )
}
