//! The chapter's generated scene file (`scenes/bunnies.toml`) is what
//! its generator writes, and it loads as a world of instances.
use std::path::Path;

use ch08_figures::{STEM_BUNNIES, bunnies_toml};

fn committed(stem: &str) -> (String, std::path::PathBuf) {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../scenes")
        .join(format!("{stem}.toml"));
    let text = std::fs::read_to_string(&path)
        .unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    (text, path)
}

#[test]
fn the_scene_file_is_generated() {
    assert!(
        committed(STEM_BUNNIES).0 == bunnies_toml(1000),
        "scenes/{STEM_BUNNIES}.toml differs from bunnies_toml(1000)"
    );
}

/// A thousand instances of one mesh: one object each beside the floor,
/// all sharing one structure (needs ../shared beside the workspace).
#[test]
fn the_bunnies_load_as_instances_of_one_mesh() {
    let (_, path) = committed(STEM_BUNNIES);
    let scene = raystep_scene::load(&path).unwrap();
    assert_eq!((scene.meshes.len(), scene.instances.len()), (1, 1000));
    let world = ch08::world(&scene, STEM_BUNNIES).unwrap();
    assert_eq!(world.objects.len(), 1001);
}
