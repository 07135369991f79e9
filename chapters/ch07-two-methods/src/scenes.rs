//! The chapter's stages: the scene file's triangles, and meshes added in
//! code.
use raystep_core::DVec3;

use raystep_scene::Mesh;

use crate::Stage;

/// `scenes/shapes.toml`.
pub const SHAPES: &str = include_str!("../scenes/shapes.toml");

/// The shapes scene with a ball of `subdivisions` (an icosphere of
/// 20·4ⁿ triangles) in the middle, at `width × height`.
pub fn shapes(subdivisions: u32, width: u32, height: u32) -> Stage {
    let mut scene = raystep_scene::parse(SHAPES, "shapes.toml")
        .expect("the chapter's scene parses");
    (scene.width, scene.height) = (width, height);
    let mut stage = Stage::from_scene(&scene, "shapes.toml")
        .expect("the chapter's scene builds");
    let ball = stage
        .world
        .materials
        .iter()
        .position(|m| m.name == "ball")
        .expect("shapes.toml has a ball material");
    let mesh =
        Mesh::icosphere(subdivisions).fitted(DVec3::new(0.0, 0.8, 0.2), 1.6);
    stage.add_mesh(&mesh, ball);
    stage
}
