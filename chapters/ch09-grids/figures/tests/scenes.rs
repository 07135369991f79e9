//! The chapter's scene files (`chapters/ch09-grids/scenes/`) are what
//! the generators write, and they load as worlds.
use std::path::Path;

use ch09_figures::{
    STEM_SPHERES, STEM_STADIUM, stadium_toml, uniform_spheres_toml,
};

fn committed(stem: &str) -> String {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../scenes")
        .join(format!("{stem}.toml"));
    std::fs::read_to_string(&path)
        .unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

#[test]
fn the_scene_files_are_generated() {
    assert!(
        committed(STEM_SPHERES) == uniform_spheres_toml(1000),
        "scenes/{STEM_SPHERES}.toml differs from uniform_spheres_toml(1000)"
    );
    assert!(
        committed(STEM_STADIUM) == stadium_toml(&raystep_bench::bunny()),
        "scenes/{STEM_STADIUM}.toml differs from stadium_toml(bunny)"
    );
}

/// Both scenes load and build into worlds: 1000 spheres; five boxes and
/// the bunny's triangles (those of zero area left out) for the stadium,
/// which reads ../shared/meshes/bunny.obj (found from the scene's folder
/// upwards).
#[test]
fn the_scene_files_load() {
    let triangles = ch08::TriangleMesh::new(
        &raystep_scene::Mesh::load_obj(&raystep_bench::shared_mesh(
            "bunny.obj",
        ))
        .unwrap(),
    )
    .triangles()
    .len();
    for (stem, objects) in [(STEM_SPHERES, 1000), (STEM_STADIUM, 5 + triangles)]
    {
        let path = Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("../scenes")
            .join(format!("{stem}.toml"));
        let scene = raystep_scene::load(&path).unwrap();
        let world = ch08::world(&scene, stem).unwrap();
        assert_eq!(world.objects.len(), objects, "{stem}");
    }
}
