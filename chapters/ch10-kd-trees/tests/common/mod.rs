//! What the chapter's test files share: the bunny.
#![allow(dead_code)]
use std::path::Path;

use ch10::DVec3;
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
