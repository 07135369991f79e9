//! What the chapter's test files share: the bunny, objects, and the
//! DDA's setup to judge exercise 1 by.
#![allow(dead_code)]
pub mod setup;

use ch09::{DVec3, Object};
use raystep_scene::Shape;

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
