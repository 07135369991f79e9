//! Draws a sample lecture figure with most primitives and writes it to
//! `/tmp/figkit-demo.svg` and `/tmp/figkit-demo.png` (or into the directory given as argument).
//!
//! `cargo run -p raystep-figure --example demo [DIR]`

use std::path::PathBuf;
use std::process::ExitCode;

use raystep_figure::{
    Anchor, DVec2, DVec3, Figure, Format, Page, Projection, Stroke, palette,
    write_all,
};

fn line_sign() -> Figure {
    let mut page = Page::new(640.0, 420.0)
        .view(DVec2::new(-3.0, -2.0), DVec2::new(4.0, 3.0));
    let n = DVec2::new(1.0, 2.0).normalize();
    let p0 = DVec2::new(0.5, 0.5);
    let f = move |p: DVec2| n.dot(p - p0);

    page.scalar_field(f, 2.0, 4.0);
    page.grid(1.0, palette::LIGHT_GREY);
    page.axes(palette::GREY);

    let ink = Stroke::new(palette::BLACK);
    page.line(p0, n.perp(), &ink);
    page.arrow(p0, p0 + 1.2 * n, &Stroke::new(palette::VERMILION));
    page.label(p0 + 1.2 * n, "n", Anchor::NE);
    page.point(p0, palette::BLACK);
    page.label(p0, "P_0", Anchor::S);

    let p = DVec2::new(2.5, 1.5);
    page.segment(p0, p, &ink.thin().dashed());
    page.point(p, palette::BLUE);
    page.label(p, "P, f(P) > 0", Anchor::E);
    page.angle_arc(p0, p - p0, n, 36.0, &ink.thin(), Some("θ"));

    let q = DVec2::new(-2.0, -1.2);
    page.point(q, palette::BLUE);
    page.label(q, "Q, f(Q) < 0", Anchor::N);
    page.ray(
        q,
        DVec2::new(1.0, -0.25),
        &Stroke::new(palette::GREEN).width(1.5),
    );

    page.polygon_alpha(
        &[
            DVec2::new(2.5, -1.0),
            DVec2::new(3.6, -1.5),
            DVec2::new(3.2, -0.3),
        ],
        Some(palette::PURPLE.with_alpha(0.35)),
        Some(&Stroke::new(palette::PURPLE).thin()),
    );
    page.circle(DVec2::new(-2.0, 2.0), 0.5, None, Some(&ink.thin()));
    page.label(DVec2::new(-2.0, 2.0), "E_{12}, x^2", Anchor::Center);

    page.raster(
        DVec2::new(2.4, 1.9),
        DVec2::new(3.6, 2.9),
        12,
        10,
        |x, y| {
            if (x / 3 + y / 3) % 2 == 0 {
                palette::SKY_BLUE
            } else {
                palette::WHITE
            }
        },
    );
    // a small RGB image (a render, say), stretched over a world rectangle
    let (w, h) = (16u32, 8u32);
    let rgb: Vec<u8> = (0..w * h)
        .flat_map(|i| {
            [
                (i % w * 255 / (w - 1)) as u8,
                (i / w * 255 / (h - 1)) as u8,
                160,
            ]
        })
        .collect();
    page.image(DVec2::new(0.6, 2.05), DVec2::new(2.2, 2.65), w, h, &rgb);
    page.text_page(
        DVec2::new(450.0, 20.0),
        "the sign of f(x, y) = n · (p − P_0)",
        Anchor::Center,
        16.0,
    );
    Figure::new("figkit-demo", "Which side of a line a point lies on.", page)
}

fn cube() -> Figure {
    let proj = Projection::perspective(
        DVec3::new(3.0, 2.5, 4.0),
        DVec3::ZERO,
        DVec3::Y,
        40.0,
    );
    let t = proj.tan_half_fov();
    let mut page = Page::new(360.0, 300.0)
        .view(DVec2::new(-1.2 * t, -t), DVec2::new(1.2 * t, t));
    let corner = |i: u32| {
        DVec3::new(
            if i & 1 == 0 { -1.0 } else { 1.0 },
            if i & 2 == 0 { -1.0 } else { 1.0 },
            if i & 4 == 0 { -1.0 } else { 1.0 },
        )
    };
    let ink = Stroke::new(palette::BLACK).width(1.5);
    for i in 0..8u32 {
        for bit in [1, 2, 4] {
            if i & bit == 0 {
                page.segment(
                    proj.project(corner(i)),
                    proj.project(corner(i | bit)),
                    &ink,
                );
            }
        }
    }
    page.label(proj.project(corner(7)), "(1, 1, 1)", Anchor::NE);
    Figure::new("figkit-demo-cube", "A cube in perspective.", page)
}

fn main() -> ExitCode {
    let dir = std::env::args()
        .nth(1)
        .map_or_else(std::env::temp_dir, PathBuf::from);
    match write_all(&[line_sign(), cube()], &dir, Format::Both) {
        Ok(paths) => {
            for p in paths {
                println!("{}", p.display());
            }
            ExitCode::SUCCESS
        }
        Err(e) => {
            eprintln!("demo: {e}");
            ExitCode::FAILURE
        }
    }
}
