//! Scenes that hold triangle meshes: an object's `mesh = { … }`,
//! `[meshes.NAME]` and their `[[instances]]`; the path rule; placements;
//! vertex normals; and each bad mesh input with its exact message.
use std::fs;
use std::path::{Path, PathBuf};
use std::sync::Arc;

use raystep_core::{DAffine3, DVec3};
use raystep_scene::{Placement, Scene, Shape, load, parse};
use tempfile::TempDir;

const CAMERA: &str = "[camera]\nlook_from = [0, 1, 5]\nlook_at = [0, 0, 0]\n";

/// A unit square of two triangles, no normals.
const SQUARE: &str = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3\nf 1 3 4\n";

fn v(x: f64, y: f64, z: f64) -> DVec3 {
    DVec3::new(x, y, z)
}

/// A temporary folder holding `files` (path, text); the folder, and its
/// canonical path (as the errors show it).
fn folder(files: &[(&str, &str)]) -> (TempDir, PathBuf) {
    let dir = tempfile::tempdir().unwrap();
    for (path, text) in files {
        let path = dir.path().join(path);
        fs::create_dir_all(path.parent().unwrap()).unwrap();
        fs::write(path, text).unwrap();
    }
    let canonical = dir.path().canonicalize().unwrap();
    (dir, canonical)
}

/// The scene `CAMERA + body` written to `dir/name` and loaded.
fn scene(dir: &Path, name: &str, body: &str) -> Result<Scene, String> {
    let path = dir.join(name);
    fs::create_dir_all(path.parent().unwrap()).unwrap();
    fs::write(&path, format!("{CAMERA}{body}")).unwrap();
    load(&path).map_err(|e| e.to_string())
}

#[test]
fn a_mesh_object_and_instances_of_a_named_mesh_read_back() {
    let (_dir, root) = folder(&[("meshes/square.obj", SQUARE)]);
    let body = "[materials.clay]\nkd = 0.6\n\
        [meshes.square]\nobj = \"meshes/square.obj\"\n\
        [meshes.again]\nobj = \"meshes/../meshes/square.obj\"\n\
        [[objects]]\n\
        mesh = { obj = \"meshes/square.obj\", scale = 1.5, rotate = [0, 90, 0], translate = [0, 0.5, 0] }\n\
        material = \"clay\"\n\
        [[instances]]\nmesh = \"square\"\nscale = [1, 2, 3]\n\
        rotate = [10, 20, 30]\ntranslate = [-1, 0, 4]\nmaterial = \"clay\"\n\
        [[instances]]\nmesh = \"again\"\n";
    let scene = scene(&root, "scene.toml", body).unwrap();

    let [object] = &scene.objects[..] else {
        panic!("one object")
    };
    let Shape::Mesh { mesh, placement } = &object.shape else {
        panic!("a mesh: {:?}", object.shape)
    };
    assert_eq!(object.shape.kind(), "mesh");
    assert_eq!((object.material, object.line), (1, 10));
    assert_eq!(
        *placement,
        Placement {
            scale: DVec3::splat(1.5),
            rotate: v(0.0, 90.0, 0.0),
            translate: v(0.0, 0.5, 0.0),
        }
    );
    assert_eq!(mesh.vertices.len(), 4);
    assert_eq!(mesh.triangles, vec![[0, 1, 2], [0, 2, 3]]);
    assert!(mesh.normals.is_empty(), "the OBJ has no vn");

    let [first, second] = &scene.instances[..] else {
        panic!("two instances")
    };
    assert_eq!(
        (first.mesh.as_str(), first.material, first.line),
        ("square", 1, 13)
    );
    assert_eq!(
        first.placement,
        Placement {
            scale: v(1.0, 2.0, 3.0),
            rotate: v(10.0, 20.0, 30.0),
            translate: v(-1.0, 0.0, 4.0),
        }
    );
    // every default: scale 1, rotate 0, translate 0, material "default"
    assert_eq!(
        (second.mesh.as_str(), second.material, second.line),
        ("again", 0, 19)
    );
    assert_eq!(second.placement, Placement::IDENTITY);

    // the file is read once: both names, and the object, share its mesh
    let square = &scene.meshes[&first.mesh];
    let again = &scene.meshes[&second.mesh];
    assert!(Arc::ptr_eq(square, again));
    assert!(Arc::ptr_eq(square, mesh));
    assert_eq!(scene.meshes.len(), 2);
}

#[test]
fn to_world_scales_then_rotates_about_x_then_y_then_z_then_translates() {
    let place = |scale: DVec3, rotate: DVec3, translate: DVec3, p: DVec3| {
        Placement {
            scale,
            rotate,
            translate,
        }
        .to_world()
        .transform_point3(p)
    };
    assert_eq!(Placement::IDENTITY.to_world(), DAffine3::IDENTITY);
    assert_eq!(Placement::default(), Placement::IDENTITY);
    // scale (2, 3, 4): (1, 1, 1) → (2, 3, 4); 90° about x takes y to z:
    // (2, −4, 3); then + (1, 2, 3). Multiples of 90° are exact.
    let p = place(
        v(2.0, 3.0, 4.0),
        v(90.0, 0.0, 0.0),
        v(1.0, 2.0, 3.0),
        DVec3::ONE,
    );
    assert_eq!(p, v(3.0, -2.0, 6.0));
    // right-handed: about y, z goes to x; about z, x goes to y
    assert_eq!(
        place(DVec3::ONE, v(0.0, 90.0, 0.0), DVec3::ZERO, DVec3::Z),
        DVec3::X
    );
    assert_eq!(
        place(DVec3::ONE, v(0.0, 0.0, 90.0), DVec3::ZERO, DVec3::X),
        DVec3::Y
    );
    // x first, then y, then z: y → z (about x) → x (about y) → y (about z);
    // the other order would give −y
    let about = |r: DVec3| place(DVec3::ONE, r, DVec3::ZERO, DVec3::Y);
    assert_eq!(about(v(90.0, 90.0, 0.0)), DVec3::X);
    assert_eq!(about(v(90.0, 90.0, 90.0)), DVec3::Y);
    // scale before rotating: [2, 1, 1] stretches the mesh's own x, which
    // 90° about z then turns into y
    let stretched = place(
        v(2.0, 1.0, 1.0),
        v(0.0, 0.0, 90.0),
        DVec3::ZERO,
        v(1.0, 1.0, 0.0),
    );
    assert_eq!(stretched, v(-1.0, 2.0, 0.0));
    // −90° is 270°, and any angle rotates (30° about z, after scale 2)
    assert_eq!(about(v(-90.0, 0.0, 0.0)), DVec3::NEG_Z);
    let p = place(DVec3::splat(2.0), v(0.0, 0.0, 30.0), DVec3::ZERO, DVec3::X);
    assert!((p - v(3f64.sqrt(), 1.0, 0.0)).length() < 1e-15, "{p}");
    // a tiny negative angle (rem_euclid rounds it up to 360) is no turn
    assert_eq!(about(v(-1e-20, 0.0, 0.0)), DVec3::Y);
}

#[test]
fn a_mesh_file_is_found_in_the_scenes_folder_or_the_nearest_above_it() {
    let one_triangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    let (_dir, root) = folder(&[
        ("shared/meshes/far.obj", SQUARE),
        ("shared/meshes/near.obj", SQUARE),
        ("a/shared/meshes/near.obj", one_triangle),
    ]);
    let body = "[meshes.far]\nobj = \"shared/meshes/far.obj\"\n\
                [meshes.near]\nobj = \"shared/meshes/near.obj\"\n";
    let scene = scene(&root, "a/b/scenes/scene.toml", body).unwrap();
    assert_eq!(
        scene.meshes["far"].triangles.len(),
        2,
        "found two folders up"
    );
    assert_eq!(scene.meshes["near"].triangles.len(), 1, "the nearest wins");
    // parse: the folder of its file name, which need not exist as a file
    let source = format!("{CAMERA}{body}");
    let name = root.join("a/b/scenes/not-written.toml");
    let parsed = parse(&source, name.to_str().unwrap()).unwrap();
    assert_eq!(parsed, scene);
    // an absolute path is taken as it is
    let absolute = root.join("shared/meshes/far.obj");
    let body = format!(
        "[[objects]]\nmesh = {{ obj = {:?} }}\n",
        absolute.display().to_string()
    );
    let scene = scene_in_elsewhere(&body);
    let Shape::Mesh { mesh, .. } = &scene.objects[0].shape else {
        panic!("a mesh")
    };
    assert_eq!(mesh.triangles.len(), 2);
}

/// A scene in a folder of its own, away from the mesh files.
fn scene_in_elsewhere(body: &str) -> Scene {
    let (_dir, root) = folder(&[]);
    scene(&root, "scene.toml", body).unwrap()
}

#[test]
fn vertex_normals_line_up_with_the_vertices_and_smooth_false_drops_them() {
    // a roof: two triangles on one edge, each with its own normal at its
    // corners, so the edge's two vertices are split, one per normal
    let roof = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n\
                vn 0 0 2\nvn 0 1 1\n\
                f 1//1 2//1 3//1\nf 1//2 3//2 4//2\n";
    let (_dir, root) = folder(&[("roof.obj", roof)]);
    let body = "[meshes.smooth]\nobj = \"roof.obj\"\n\
                [meshes.flat]\nobj = \"roof.obj\"\nsmooth = false\n";
    let scene = scene(&root, "scene.toml", body).unwrap();
    let mesh = &scene.meshes["smooth"];
    assert_eq!(mesh.vertices.len(), 6);
    assert_eq!(mesh.normals.len(), mesh.vertices.len());
    let corners = [
        v(0.0, 0.0, 0.0),
        v(1.0, 0.0, 0.0),
        v(1.0, 1.0, 0.0),
        v(0.0, 1.0, 0.0),
    ];
    let faces = [
        ([0, 1, 2], DVec3::Z),
        ([0, 2, 3], v(0.0, 1.0, 1.0).normalize()),
    ];
    for (t, (corner, normal)) in mesh.triangles.iter().zip(faces) {
        for k in 0..3 {
            assert_eq!(mesh.vertices[t[k]], corners[corner[k]]);
            assert_eq!(mesh.normals[t[k]], normal, "normalised");
        }
    }
    let flat = &scene.meshes["flat"];
    assert!(flat.normals.is_empty());
    assert_eq!(
        (&flat.vertices, &flat.triangles),
        (&mesh.vertices, &mesh.triangles)
    );
}

/// The error of `body` in a scene `scene.toml` beside `files`, with
/// `ROOT` in the expected text standing for the folder's canonical path.
fn error(files: &[(&str, &str)], body: &str) -> (String, String) {
    let (dir, root) = folder(files);
    let message = scene(dir.path(), "scene.toml", body).unwrap_err();
    let file = dir.path().join("scene.toml").display().to_string();
    (
        message
            .replace(&file, "scene.toml")
            .replace(&root.display().to_string(), "ROOT"),
        root.display().to_string(),
    )
}

#[test]
fn a_missing_mesh_file_names_where_it_was_looked_for() {
    let (message, _) = error(
        &[],
        "[[objects]]\nsphere = { center = [0, 0, 0], radius = 1 }\n[[objects]]\nmesh = { obj = \"meshes/x.obj\" }\n",
    );
    assert_eq!(
        message,
        "scene.toml:7:16: objects[1].mesh.obj: cannot read meshes/x.obj (looked in ROOT and every folder above it): No such file or directory"
    );
    let (message, _) = error(
        &[("meshes/x.obj/keep", "")],
        "[meshes.x]\nobj = \"meshes/x.obj\"\n",
    );
    assert_eq!(
        message,
        "scene.toml:5:7: meshes.x.obj: cannot read meshes/x.obj (looked in ROOT and every folder above it): a folder, not a file"
    );
    let (message, _) = error(&[], "[meshes.x]\nobj = \"/nonexistent/x.obj\"\n");
    assert_eq!(
        message,
        "scene.toml:5:7: meshes.x.obj: cannot read /nonexistent/x.obj: No such file or directory"
    );
}

#[test]
fn a_bad_obj_file_is_named_with_its_own_line() {
    let cases: [(&str, &str, &str); 6] = [
        (
            "v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 9\n",
            "meshes/bad.obj:4: vertex index 9 is not one of the 3 before it: f 1 2 9",
            "a face beyond the vertices",
        ),
        (
            "v 0 0 0\nv 1 0 0\nv 1 1 0\n",
            "meshes/bad.obj: no faces",
            "no faces",
        ),
        (
            "v 0 0 0\nv 1 0 0\nv 1 1 0\nvn 0 0 0\nf 1//1 2//1 3//1\n",
            "meshes/bad.obj:4: normal 1 has no direction (it is zero), and the face on line 5 uses it: vn 0 0 0",
            "a zero normal",
        ),
        (
            "v 0 0 0\nv 1 0 0\nv 1 1 0\nvn 0 nan 1\nf 1//1 2//1 3//1\n",
            "meshes/bad.obj:4: normal 1 is not finite, and the face on line 5 uses it: vn 0 nan 1",
            "a NaN normal",
        ),
        (
            "v 0 0 0\nv 1 0 0\nv 1 1 0\nvn 0 0 1\nf 1//1 2//1 3//1\nf 1 3 2\n",
            "meshes/bad.obj:6: normals on some face corners only: f 1 3 2",
            "normals on some corners",
        ),
        (
            "v 0 0 0\nv 1 0\nv 1 1 0\nf 1 2 3\n",
            "meshes/bad.obj:2: a vertex is 3 numbers (or x y z w, or x y z r g b): v 1 0",
            "a short vertex",
        ),
    ];
    for (obj, expected, what) in cases {
        let (message, _) = error(
            &[("meshes/bad.obj", obj)],
            "[meshes.bunny]\nobj = \"meshes/bad.obj\"\n",
        );
        assert_eq!(
            message,
            format!("scene.toml:5:7: meshes.bunny.obj: {expected}"),
            "{what}"
        );
    }
    // not UTF-8
    let (dir, _) = folder(&[]);
    fs::create_dir_all(dir.path().join("meshes")).unwrap();
    fs::write(dir.path().join("meshes/bin.obj"), b"v 0 0 0\nv \xff 0 0\n")
        .unwrap();
    let message = scene(
        dir.path(),
        "scene.toml",
        "[[objects]]\nmesh = { obj = \"meshes/bin.obj\" }\n",
    )
    .unwrap_err();
    assert!(message.ends_with("scene.toml:5:16: objects[0].mesh.obj: meshes/bin.obj:2: not UTF-8 text"), "{message}");
}

#[test]
fn a_placement_beyond_the_finite_numbers_is_refused() {
    let (message, _) = error(
        &[("big.obj", "v 0 0 0\nv 1e30 0 0\nv 0 1 0\nf 1 2 3\n")],
        "[meshes.big]\nobj = \"big.obj\"\n[[instances]]\nmesh = \"big\"\nscale = 1e300\n",
    );
    assert_eq!(
        message,
        "scene.toml:6:1: instances[0]: scale, rotate and translate take the mesh beyond the finite numbers: its corner [1.0000000150474662e30, 0, 0] goes to [inf, 0, 0]"
    );
}

#[test]
fn scaling_a_placed_mesh_scales_where_its_points_go() {
    let mesh = Arc::new(raystep_scene::Mesh::icosphere(0));
    let placement = Placement {
        scale: v(1.0, 2.0, 3.0),
        rotate: v(10.0, 20.0, 30.0),
        translate: v(-1.0, 0.5, 4.0),
    };
    let mut shape = Shape::Mesh { mesh, placement };
    shape.scale(2.5);
    let Shape::Mesh {
        placement: scaled, ..
    } = shape
    else {
        panic!("still a mesh")
    };
    for &p in &[DVec3::ZERO, DVec3::ONE, v(-0.3, 0.7, 2.0)] {
        let expected = 2.5 * placement.to_world().transform_point3(p);
        let got = scaled.to_world().transform_point3(p);
        assert!(
            (got - expected).length() < 1e-13,
            "{p}: {got} vs {expected}"
        );
    }
}

#[test]
fn normals_stay_lined_up_across_an_objs_objects_and_quads() {
    // a cube in two objects (`o`), quads with texture coordinates and
    // one normal per face (crates/stability's seed)
    let cube = "o front\n\
        v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n\
        v 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n\
        vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n\
        vn 0 0 -1\nvn 0 0 1\nvn 0 -1 0\nvn 0 1 0\nvn -1 0 0\nvn 1 0 0\n\
        f 1/1/1 4/4/1 3/3/1 2/2/1\nf 5/1/2 6/2/2 7/3/2 8/4/2\n\
        f 1/1/3 2/2/3 6/3/3 5/4/3\no back\n\
        f 4/1/4 8/4/4 7/3/4 3/2/4\nf 1/1/5 5/2/5 8/3/5 4/4/5\n\
        f 2/1/6 3/2/6 7/3/6 6/4/6\n";
    let (_dir, root) = folder(&[("cube.obj", cube)]);
    let scene =
        scene(&root, "scene.toml", "[meshes.cube]\nobj = \"cube.obj\"\n")
            .unwrap();
    let mesh = &scene.meshes["cube"];
    assert_eq!(mesh.triangles.len(), 12);
    assert_eq!(mesh.normals.len(), mesh.vertices.len());
    // every face's corners carry the normal of that face: the axis on
    // which its three corners agree, pointing out of the unit cube
    for t in &mesh.triangles {
        let [a, b, c] = t.map(|i| mesh.vertices[i]);
        let n = mesh.normals[t[0]];
        assert!(t.iter().all(|&i| mesh.normals[i] == n));
        let centre = DVec3::splat(0.5);
        assert_eq!(n.length(), 1.0);
        for corner in [a, b, c] {
            assert_eq!((corner - centre).dot(n), 0.5, "{t:?}");
        }
    }
}
