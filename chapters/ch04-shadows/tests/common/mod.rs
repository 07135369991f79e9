//! What the chapter's test files share.
use ch04::World;
use raystep_scene::{Object, Shape};

/// A world of these scene-file shapes, all in the default material (the
/// camera is a placeholder: these tests shoot their own rays).
pub fn world(shapes: Vec<Shape>) -> World {
    let mut scene = raystep_scene::parse(
        "[camera]\nlook_from = [0, 0, 1]\nlook_at = [0, 0, 0]\n",
        "test",
    )
    .expect("the placeholder scene parses");
    scene.objects = shapes
        .into_iter()
        .map(|shape| Object {
            shape,
            material: 0,
            line: 1,
        })
        .collect();
    ch03::world(&scene, "test").expect("spheres and planes build")
}
