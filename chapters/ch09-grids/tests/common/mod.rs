//! What the chapter's test files share: the bunny, scenes of objects, and
//! the comparison with brute force.
#![allow(dead_code)]
use std::path::Path;
use std::sync::Arc;

use ch03::{BruteForce, Sphere};
use ch09::{Accelerator, DVec3, Interval, Object, Ray};
use raystep_scene::Mesh;

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

/// Triangles as objects (chapter 8's watertight triangle); zero-area
/// ones left out.
pub fn triangle_objects(triangles: &[[DVec3; 3]]) -> Vec<Object> {
    triangles
        .iter()
        .filter_map(|&t| ch08::mesh_triangle(t))
        .map(|t| Object {
            shape: Arc::new(t),
            material: 0,
        })
        .collect()
}

/// Chapter 3's spheres as objects.
pub fn sphere_objects(spheres: &[(DVec3, f64)]) -> Vec<Object> {
    spheres
        .iter()
        .map(|&(c, r)| Object {
            shape: Arc::new(Sphere::new(c, r)),
            material: 0,
        })
        .collect()
}

/// A plane (no finite box) as an object.
pub fn plane_object(point: DVec3, normal: DVec3) -> Object {
    let shape = ch08::shape(&raystep_scene::Shape::Plane { point, normal })
        .expect("a plane");
    Object { shape, material: 0 }
}

/// How many of `rays` `accelerator` answers differently from brute force:
/// a closest hit at another t (or a hit against a miss), or another
/// any-hit answer (within the forward interval, and within t ≤ 1).
pub fn disagreements(
    accelerator: &dyn Accelerator,
    objects: &[Object],
    rays: &[Ray],
) -> usize {
    rays.iter()
        .filter(|ray| {
            let closest = |a: &dyn Accelerator| {
                a.closest_hit(objects, ray, Interval::FORWARD)
                    .map(|(_, hit)| hit.t)
            };
            let short = Interval::new(0.0, 1.0);
            closest(accelerator) != closest(&BruteForce)
                || accelerator.any_hit(objects, ray, Interval::FORWARD)
                    != BruteForce.any_hit(objects, ray, Interval::FORWARD)
                || accelerator.any_hit(objects, ray, short)
                    != BruteForce.any_hit(objects, ray, short)
        })
        .count()
}
