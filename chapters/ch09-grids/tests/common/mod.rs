//! What the chapter's test files share: the bunny, objects, and the
//! DDA's setup to judge exercise 1 by.
#![allow(dead_code)]
use std::path::Path;

pub mod setup;

use ch09::{DVec3, Object};
use raystep_scene::{Mesh, Shape};

/// The Stanford bunny beside the workspace: `../shared/meshes/bunny.obj`.
pub fn bunny() -> Vec<[DVec3; 3]> {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../../shared/meshes/bunny.obj");
    let mesh = Mesh::load_obj(&path).unwrap_or_else(|e| {
        panic!("{e} (the bunny lives in ../shared/meshes beside the workspace)")
    });
    (0..mesh.triangles.len())
        .map(|k| mesh.triangle(k))
        .collect()
}

/// A shape of a scene file as an object (chapter 8's shapes).
pub fn object(spec: Shape) -> Object {
    Object {
        shape: ch08::shape(&spec).expect("a valid shape"),
        material: 0,
    }
}

/// Spheres as objects.
pub fn sphere_objects(spheres: &[(DVec3, f64)]) -> Vec<Object> {
    spheres
        .iter()
        .map(|&(center, radius)| object(Shape::Sphere { center, radius }))
        .collect()
}

/// A plane (no finite box) as an object.
pub fn plane_object(point: DVec3, normal: DVec3) -> Object {
    object(Shape::Plane { point, normal })
}
