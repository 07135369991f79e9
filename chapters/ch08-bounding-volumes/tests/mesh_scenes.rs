//! Scene files with meshes, built into worlds: a `mesh = { … }` object
//! becomes one object per triangle with the object's material, each
//! `[[instances]]` entry one object after the scene's objects, and a
//! fault the scene file cannot see is one line naming the file.
use std::path::{Path, PathBuf};
use std::sync::Arc;

use ch03::BruteForce;
use ch08::{Accelerate, Builder, Bvh, Interval, Ray, world, world_with};
use raystep_core::DVec3;

fn scene_path(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/meshes")
        .join(name)
}

const BRUTE: Accelerate = |_| Arc::new(BruteForce);
const BVH: Accelerate = |objects| {
    Arc::new(Bvh::for_objects(objects, Builder::BinnedSah { bins: 16 }))
};

#[test]
fn a_flattened_mesh_is_one_object_per_triangle() {
    let path = scene_path("flattened.toml");
    let scene = raystep_scene::load(&path).unwrap();
    let world = world(&scene, "flattened.toml").unwrap();
    // the floor, three octaspheres of 32 triangles, a sphere
    assert_eq!(world.objects.len(), 1 + 3 * 32 + 1);
    for (k, object) in world.objects.iter().enumerate() {
        let expected = match k {
            0 => scene.objects[0].material,
            97 => scene.objects[4].material,
            _ => scene.objects[1 + (k - 1) / 32].material,
        };
        assert_eq!(object.material, expected, "object {k}");
    }
}

#[test]
fn each_instance_is_one_object_after_the_scene_objects() {
    let path = scene_path("instanced.toml");
    let scene = raystep_scene::load(&path).unwrap();
    assert_eq!(scene.instances.len(), 5);
    for accelerate in [BRUTE, BVH] {
        let world = world_with(&scene, "instanced.toml", accelerate).unwrap();
        // the floor, a flattened octasphere, five instances
        assert_eq!(world.objects.len(), 1 + 32 + 5);
        for (k, instance) in scene.instances.iter().enumerate() {
            assert_eq!(world.objects[33 + k].material, instance.material);
        }
    }
}

/// The meshes' own structures answer alike, whatever builds them: the
/// brute-force loop or chapter 8's hierarchy.
#[test]
fn an_instance_answers_the_same_through_any_structure() {
    let path = scene_path("instanced.toml");
    let scene = raystep_scene::load(&path).unwrap();
    let brute = world_with(&scene, "instanced.toml", BRUTE).unwrap();
    let bvh = world_with(&scene, "instanced.toml", BVH).unwrap();
    let mut rng = ch08::SplitMix64::new(0x1257);
    let mut hits = 0;
    for _ in 0..3000 {
        let origin = DVec3::new(0.0, 3.0, 8.0) + rng.unit_vector();
        let target = DVec3::new(
            4.0 * rng.next_f64() - 2.0,
            rng.next_f64(),
            3.0 * rng.next_f64() - 2.0,
        );
        let ray = Ray::new(origin, target - origin);
        let interval = Interval::new(0.0, f64::INFINITY);
        for k in 1..brute.objects.len() {
            let a = brute.objects[k].shape.intersect(&ray, interval);
            let b = bvh.objects[k].shape.intersect(&ray, interval);
            assert_eq!(a, b, "object {k}, {ray:?}");
            hits += usize::from(a.is_some());
        }
    }
    assert!(hits > 1000, "{hits}");
}

#[test]
fn an_instance_of_no_mesh_is_one_line_naming_the_file() {
    let path = scene_path("instanced.toml");
    let mut scene = raystep_scene::load(&path).unwrap();
    scene.instances[1].mesh = "teapot".to_string();
    let line = scene.instances[1].line;
    let error = world(&scene, "instanced.toml").unwrap_err().to_string();
    let field = "instances[1].mesh";
    assert_eq!(
        error,
        format!("instanced.toml:{line}:1: {field}: no mesh named \"teapot\"")
    );
}

/// A mesh is many surfaces: asked for one shape, the chapter says how to
/// build it instead.
#[test]
fn a_mesh_is_not_one_shape() {
    let path = scene_path("flattened.toml");
    let scene = raystep_scene::load(&path).unwrap();
    let error = ch08::shape(&scene.objects[1].shape).unwrap_err();
    assert!(error.contains("ch08::world"), "{error}");
}
