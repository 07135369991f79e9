//! The rule of "which structure a scene needs", on the chapters' scene
//! families: what the spread test counts, and what the rule picks.
mod common;

use std::path::Path;

use ch10::{Aabb, DVec3, Object, Structure, choose, spread};
use raystep_bench::{SCENE_SEED, stadium, uniform_triangles};
use raystep_check::{Table, num_places};

fn scene_file(path: &str) -> Vec<Aabb> {
    let file = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../..")
        .join(path);
    let scene = raystep_scene::load(&file).expect("a chapter's scene file");
    scene
        .objects
        .iter()
        .map(|o| ch08::shape(&o.shape).expect("a valid shape").bounds())
        .collect()
}

fn triangle_boxes(triangles: &[[DVec3; 3]]) -> Vec<Aabb> {
    triangles
        .iter()
        .map(|t| Aabb::around(t.iter().copied()))
        .collect()
}

#[test]
fn the_rule_on_the_families() {
    let bunny = raystep_bench::bunny();
    let families = [
        (
            "3 spheres and a plane",
            scene_file("chapters/ch03-illumination/scenes/spheres.toml"),
        ),
        (
            "chapter 8's 10 primitives",
            scene_file("chapters/ch08-bounding-volumes/scenes/primitives.toml"),
        ),
        (
            "1 000 small spheres",
            scene_file("chapters/ch09-grids/scenes/uniform-spheres.toml"),
        ),
        (
            "10 000 small triangles",
            triangle_boxes(&uniform_triangles(10_000, SCENE_SEED)),
        ),
        ("the bunny", triangle_boxes(&bunny)),
        ("bunny in a stadium", triangle_boxes(&stadium(&bunny))),
        (
            "triangles in z = 0",
            triangle_boxes(
                &uniform_triangles(1000, 2)
                    .iter()
                    .map(|t| t.map(|v| DVec3::new(v.x, v.y, 0.0)))
                    .collect::<Vec<_>>(),
            ),
        ),
    ];
    let mut table = Table::new(&[
        "scene",
        "objects",
        "cells",
        "empty",
        "fullest/mean",
        "choice",
    ]);
    for (name, boxes) in &families {
        let s = spread(boxes);
        table.row(&[
            name.to_string(),
            s.objects.to_string(),
            s.cells.to_string(),
            s.empty.to_string(),
            num_places(s.fullest_over_mean, 2),
            choose(boxes).name().to_string(),
        ]);
    }
    insta::assert_snapshot!(table.to_string());
}

#[test]
fn a_plane_does_not_count_and_few_objects_go_brute() {
    let plane = Object {
        shape: ch08::shape(&raystep_scene::Shape::Plane {
            point: DVec3::ZERO,
            normal: DVec3::Y,
        })
        .unwrap(),
        material: 0,
    };
    let mut objects = vec![plane; 20];
    assert_eq!(
        choose(&objects.iter().map(|o| o.shape.bounds()).collect::<Vec<_>>()),
        Structure::Brute
    );
    let sphere = |x: f64| Object {
        shape: ch08::shape(&raystep_scene::Shape::Sphere {
            center: DVec3::new(x, 0.0, 0.0),
            radius: 0.1,
        })
        .unwrap(),
        material: 0,
    };
    objects.extend((0..8).map(|k| sphere(k as f64)));
    assert_eq!(
        choose(&objects.iter().map(|o| o.shape.bounds()).collect::<Vec<_>>()),
        Structure::Bvh
    );
    assert_eq!(choose(&[]), Structure::Brute);
}
