//! The grid against brute force: the same closest hit (the same t) and
//! the same any-hit answer for every ray, on every kind of scene and
//! every kind of dangerous ray, with and without mailboxing. The
//! disagreements are counted, and must be 0. Uses both exercises.
mod common;

use ch08::{Ray32, TraceCounts};
use ch09::{
    DVec3, Fill, Grid, MeshGrid, Resolution, adversarial_rays, disagreements,
    stability_scenes, uniform_spheres,
};
use raystep_check::Table;

use common::{bunny, sphere_objects};

/// Every scene × every kind of dangerous ray: 0 disagreements, with the
/// mailbox on and off.
#[test]
fn stability_catalogue() {
    let mut table = Table::new(&["scene", "rays", "mailbox on", "mailbox off"]);
    let mut wrong = 0;
    for scene in stability_scenes(&bunny()) {
        let (name, objects) = (scene.name, &scene.objects);
        let mut grid = Grid::for_objects(objects, scene.resolution);
        for case in adversarial_rays(&grid.lattice, 60, 7) {
            let mut row = Vec::new();
            for mailboxing in [true, false] {
                grid.mailboxing = mailboxing;
                let n = disagreements(&grid, objects, &case.rays);
                wrong += n;
                row.push(n.to_string());
            }
            table.row(&[
                format!("{name}: {}", case.name),
                case.rays.len().to_string(),
                row[0].clone(),
                row[1].clone(),
            ]);
        }
    }
    insta::assert_snapshot!(table.to_string());
    assert_eq!(wrong, 0, "{table}");
}

/// Rays no tracer should trace: NaN or infinite numbers, a zero
/// direction. The grid answers them as brute force does, and returns.
#[test]
fn broken_rays_end_the_walk() {
    let objects = sphere_objects(&uniform_spheres(50, 4));
    let grid = Grid::for_objects(&objects, Resolution::Rule);
    let rays = [
        ch09::Ray::new(DVec3::NAN, DVec3::X),
        ch09::Ray::new(DVec3::ZERO, DVec3::new(f64::NAN, 1.0, 0.0)),
        ch09::Ray::new(DVec3::ZERO, DVec3::ZERO),
        ch09::Ray::new(DVec3::ZERO, DVec3::new(f64::INFINITY, 1.0, 0.0)),
        ch09::Ray::new(DVec3::splat(f64::INFINITY), DVec3::X),
    ];
    assert_eq!(disagreements(&grid, &objects, &rays), 0);
}

/// The triangle grid of the benchmark (single-precision rays, chapter 8's
/// watertight test), filled both ways, with the mailbox on and off:
/// the same hits as brute force on the bunny, and the counts that the
/// exact fill and the mailbox exist for.
#[test]
fn the_bunny_grid_agrees_and_what_it_costs() {
    let triangles = bunny();
    let brute = |ray: &Ray32| {
        let mut best: Option<f64> = None;
        let prepared = ch08::PreparedRay::new(ray);
        for t in &triangles {
            let interval =
                ch09::Interval::new(0.0, best.unwrap_or(f64::INFINITY));
            if let Some(t) = prepared.triangle(t, interval) {
                best = Some(t);
            }
        }
        best
    };
    let mut table = Table::new(&[
        "fill",
        "mailbox",
        "entries",
        "wrong",
        "cells/ray",
        "tests/ray",
        "tested twice",
    ]);
    let probe = MeshGrid::new(&triangles, Resolution::Rule, Fill::Boxes);
    let rays: Vec<Ray32> = adversarial_rays(&probe.grid.lattice, 40, 11)
        .iter()
        .flat_map(|case| case.rays.iter().map(Ray32::rounded))
        .collect();
    let expected: Vec<Option<f64>> = rays.iter().map(brute).collect();
    for fill in [Fill::Boxes, Fill::Exact] {
        let mut grid = MeshGrid::new(&triangles, Resolution::Rule, fill);
        for mailboxing in [true, false] {
            grid.grid.mailboxing = mailboxing;
            let mut counts = TraceCounts::default();
            let (mut wrong, mut twice) = (0, 0);
            for (ray, want) in rays.iter().zip(&expected) {
                let mut seen = Vec::new();
                let hit = grid.closest_recorded(
                    ray,
                    ch09::Interval::FORWARD,
                    &mut counts,
                    |k| seen.push(k),
                );
                wrong += usize::from(hit.map(|h| h.t) != *want);
                let tests = seen.len();
                seen.sort_unstable();
                seen.dedup();
                twice += tests - seen.len();
            }
            let per_ray =
                |n: u64| format!("{:.1}", n as f64 / rays.len() as f64);
            table.row(&[
                fill.name().to_string(),
                if mailboxing { "on" } else { "off" }.to_string(),
                grid.grid.stats().entries.to_string(),
                wrong.to_string(),
                per_ray(counts.nodes),
                per_ray(counts.triangles),
                twice.to_string(),
            ]);
        }
    }
    insta::assert_snapshot!(table.to_string());
}
