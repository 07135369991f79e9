//! What the appendix's test files share: the bunny, the one comparison
//! of answers, and a tree deeper than the walks' fixed stacks.
#![allow(dead_code)]
use std::path::Path;

use ch08::MeshHit;
use raystep_core::DVec3;
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

/// Both miss, or both hit at the same `t`.
pub fn agree(a: Option<MeshHit>, b: Option<MeshHit>) -> bool {
    match (a, b) {
        (None, None) => true,
        (Some(a), Some(b)) => a.t == b.t,
        _ => false,
    }
}

/// 300 slivers, each 0.9 times the last, along x: the SAH peels them
/// off one by one, a tree about 300 deep.
pub fn slivers() -> Vec<[DVec3; 3]> {
    (0..300)
        .map(|k| {
            let x = 0.9f64.powi(k);
            [
                DVec3::new(x, -1.0, 0.0),
                DVec3::new(x, 1.0, -1.0),
                DVec3::new(x, 1.0, 1.0),
            ]
        })
        .collect()
}
