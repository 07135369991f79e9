//! Chapters 9's grid and 10's kd-trees against brute force, on the rays
//! and scenes where each can go wrong (a few rays of each kind here;
//! `raystep measure` asks over a million): the same closest hit (the same
//! t) and the same any-hit answer for every ray, with and without
//! mailboxing. The disagreements are counted, and must be 0.
use ch08::{Ray32, TraceCounts};
use ch09::{Fill, Grid, MeshGrid};
use ch10::{Accelerator, KdBuilder, KdCosts, KdTree};
use raystep_check::Table;
use raystep_stability::scenes::bunny;
use raystep_stability::{
    adversarial_rays, disagreements, kd_disagreements, kd_rays, kd_scenes,
    stability_scenes,
};

/// Every scene × every kind of dangerous ray: 0 disagreements, with the
/// mailbox on and off.
#[test]
fn stability_catalogue() {
    let mut table = Table::new(&["scene", "rays", "mailbox on", "mailbox off"]);
    let mut wrong = 0;
    for scene in stability_scenes(bunny()) {
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

/// The triangle grid of the benchmark (single-precision rays, chapter 8's
/// watertight test), filled both ways, with the mailbox on and off:
/// the same hits as brute force on the bunny, and the counts that the
/// exact fill and the mailbox exist for.
#[test]
fn the_bunny_grid_agrees_and_what_it_costs() {
    let triangles = bunny().to_vec();
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
    let probe = MeshGrid::new(&triangles, ch09::Resolution::Rule, Fill::Boxes);
    let rays: Vec<Ray32> = adversarial_rays(&probe.grid.lattice, 40, 11)
        .iter()
        .flat_map(|case| case.rays.iter().map(Ray32::rounded))
        .collect();
    let expected: Vec<Option<f64>> = rays.iter().map(brute).collect();
    for fill in [Fill::Boxes, Fill::Exact] {
        let mut grid = MeshGrid::new(&triangles, ch09::Resolution::Rule, fill);
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

/// Rays of each kind per scene and tree.
const PER_CASE: usize = 40;

#[test]
fn every_tree_agrees_with_brute_force_on_the_catalogue() {
    let mut table = String::from(
        "scene | rays | SAH | SAH, no mailbox | median | SAH, pbrt's costs\n",
    );
    let mut total = 0;
    for scene in kd_scenes(bunny()) {
        let sah = KdTree::for_objects(
            &scene.objects,
            KdBuilder::SahEvents,
            KdCosts::CHOSEN,
        );
        let mut plain = sah.clone();
        plain.mailboxing = false;
        let median = KdTree::for_objects(
            &scene.objects,
            KdBuilder::Median,
            KdCosts::CHOSEN,
        );
        // the same four trees as `raystep measure`'s catalogue
        let pbrt = KdTree::for_objects(
            &scene.objects,
            KdBuilder::SahEvents,
            KdCosts::PBRT_V3,
        );
        let trees: [&dyn Accelerator; 4] = [&sah, &plain, &median, &pbrt];
        let mut wrong = vec![0; trees.len()];
        let mut rays = 0;
        for (seed, tree) in [&sah, &median, &pbrt].into_iter().enumerate() {
            for case in kd_rays(tree, PER_CASE, seed as u64) {
                rays += case.rays.len();
                for (w, d) in wrong.iter_mut().zip(kd_disagreements(
                    &trees,
                    &scene.objects,
                    &case.rays,
                )) {
                    *w += d;
                }
            }
        }
        total += wrong.iter().sum::<usize>();
        table += &format!(
            "{} | {rays} | {}\n",
            scene.name,
            wrong
                .iter()
                .map(|w| w.to_string())
                .collect::<Vec<_>>()
                .join(" | ")
        );
    }
    println!("{table}");
    assert_eq!(total, 0, "disagreements with brute force:\n{table}");
}
