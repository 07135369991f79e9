//! What the two methods draw: a world of polygons cut into triangles, and
//! meshes read from OBJ files.
use std::path::Path;

use ch07::{Mesh, Stage, StageError, shapes};

/// The Stanford bunny beside the workspace: `../shared/meshes/bunny.obj`
/// from the workspace root (this crate is two folders below it).
fn bunny() -> std::path::PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../../shared/meshes/bunny.obj")
}

#[test]
fn the_bunny_has_3674_triangles() {
    let mesh = Mesh::load_obj(&bunny())
        .expect("../shared/meshes/bunny.obj beside the workspace");
    assert_eq!(mesh.triangles.len(), 3674);
    assert!(
        mesh.triangles
            .iter()
            .flatten()
            .all(|&i| i < mesh.vertices.len()),
        "an index beyond the {} vertices",
        mesh.vertices.len()
    );
    // added to a stage, each triangle becomes an object of its own (those
    // of zero area, if any, are left out and counted)
    let mut stage = shapes(0, 16, 9);
    let (objects, triangles) =
        (stage.world.objects.len(), stage.triangles.len());
    let skipped =
        stage.add_mesh(&mesh.fitted(ch07::DVec3::new(0.0, 0.8, 0.2), 1.6), 0);
    assert_eq!(stage.triangles.len() - triangles + skipped, 3674);
    assert_eq!(stage.world.objects.len() - objects + skipped, 3674);
}

/// The shapes scene: 10 polygons of the file (two of them quadrilaterals,
/// cut into two triangles each) and the ball's 20·4ⁿ triangles.
#[test]
fn the_shapes_stage() {
    for n in 0..3 {
        let stage = shapes(n, 16, 9);
        let ball = 20 * 4usize.pow(n);
        assert_eq!(stage.world.objects.len(), 10 + ball);
        assert_eq!(stage.triangles.len(), 12 + ball);
        // in object order, each triangle on its own object's polygon
        assert!(
            stage
                .triangles
                .windows(2)
                .all(|w| w[0].object <= w[1].object)
        );
    }
}

/// A scene with a sphere (or a plane) cannot be rasterized: the error
/// names the file and the object.
#[test]
fn a_sphere_or_a_plane_is_not_a_polygon() {
    let head = "[camera]\nlook_from = [0, 0, 4]\nlook_at = [0, 0, 0]\n\
        [[objects]]\npolygon = { vertices = [[0, 0, 0], [1, 0, 0], [0, 1, 0]] }\n";
    for (object, kind) in [
        ("sphere = { center = [0, 0, -1], radius = 0.5 }", "sphere"),
        (
            "plane = { point = [0, -1, 0], normal = [0, 1, 0] }",
            "plane",
        ),
    ] {
        let text = format!("{head}[[objects]]\n{object}\n");
        let scene = raystep_scene::parse(&text, "mixed.toml")
            .expect("the scene parses");
        let error = Stage::from_scene(&scene, "mixed.toml")
            .expect_err("not all polygons");
        match &error {
            StageError::NotAPolygon {
                file,
                index,
                kind: k,
            } => {
                assert_eq!(
                    (file.as_str(), *index, *k),
                    ("mixed.toml", 1, kind)
                );
            }
            other => panic!("expected NotAPolygon, got {other:?}"),
        }
        let message = error.to_string();
        assert!(
            message.starts_with(&format!("mixed.toml: objects[1] is a {kind}")),
            "{message}"
        );
    }
}
