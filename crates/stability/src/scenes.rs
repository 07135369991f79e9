//! The meshes the catalogue's cases are made on: the Stanford bunny
//! beside the workspace, and a closed sphere of triangles made here.
use std::path::PathBuf;
use std::sync::OnceLock;

use raystep_core::DVec3;

/// Where the bunny lives: `../shared/meshes/bunny.obj` beside the
/// workspace.
pub fn bunny_path() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../../../shared/meshes/bunny.obj")
}

/// The bunny's triangles (3 674), read once; an error names the file.
pub fn load_bunny() -> Result<&'static [[DVec3; 3]], String> {
    static BUNNY: OnceLock<Result<Vec<[DVec3; 3]>, String>> = OnceLock::new();
    BUNNY
        .get_or_init(|| {
            raystep_bench::load_triangles(&bunny_path()).map_err(|e| {
                format!("{e} (the bunny lives in ../shared/meshes)")
            })
        })
        .as_ref()
        .map(Vec::as_slice)
        .map_err(String::clone)
}

/// The bunny, for the cases: [`catalogue`](crate::run_catalogue) has
/// checked with [`load_bunny`] that it loads.
pub fn bunny() -> &'static [[DVec3; 3]] {
    load_bunny().unwrap_or_else(|e| panic!("{e}"))
}

/// A closed sphere of radius 1 at the origin: chapter 8's icosphere,
/// an icosahedron whose faces are split in four `levels` times (20·4ˡ
/// triangles). Every edge is shared by exactly two triangles, with
/// bit-identical corners (each midpoint is made once).
pub fn icosphere(levels: u32) -> Vec<[DVec3; 3]> {
    let mesh = raystep_scene::Mesh::icosphere(levels);
    (0..mesh.triangles.len())
        .map(|k| mesh.triangle(k))
        .collect()
}
