//! `raystep render` from the outside: a PNG for a good scene, one clear
//! error line and no file for a bad one.

use std::fs;
use std::path::{Path, PathBuf};

mod common;
use common::{fails_in_one_line, raystep, succeeds, text};

fn scratch(name: &str) -> PathBuf {
    common::scratch("raystep-render", name)
}

fn scene(chapter_scene: &str) -> String {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../chapters")
        .join(chapter_scene)
        .display()
        .to_string()
}

/// The width and height in a PNG's header.
fn png_size(bytes: &[u8]) -> (u32, u32) {
    assert_eq!(&bytes[..8], b"\x89PNG\r\n\x1a\n");
    let be = |i: usize| u32::from_be_bytes(bytes[i..i + 4].try_into().unwrap());
    (be(16), be(20))
}

/// Renders `scene` into `out` (with `args`), which must succeed and say
/// which chapter's renderer drew it, and returns the image's size.
fn render(
    scene: &str, out: &Path, args: &[&str], renderer: &str,
) -> (u32, u32) {
    let mut all = vec!["render", scene, "--out", out.to_str().unwrap()];
    all.extend_from_slice(args);
    let said = succeeds(&all);
    assert!(said.contains(renderer), "{scene}: {said}");
    png_size(&fs::read(out).unwrap())
}

/// Renders `scene` into `out` (with `args`), which must fail in one line
/// and write nothing; returns that line.
fn refused(scene: &str, out: &Path, args: &[&str]) -> String {
    let mut all = vec!["render", scene, "--out", out.to_str().unwrap()];
    all.extend_from_slice(args);
    let stderr = fails_in_one_line(&all);
    assert!(!out.exists());
    stderr
}

#[test]
fn renders_a_chapter_scene_at_the_asked_size() {
    let dir = scratch("good");
    let size = render(
        &scene("ch03-illumination/scenes/spheres.toml"),
        &dir.join("spheres.png"),
        &["--size", "64x36", "--threads", "2"],
        "ch03 renderer",
    );
    assert_eq!(size, (64, 36));
    // chapter 4's scene gets chapter 4's tracer (with shadows)
    render(
        &scene("ch04-shadows/scenes/two-lights.toml"),
        &dir.join("two.png"),
        &["--size", "32x18"],
        "ch04 renderer",
    );
    // chapters 5 and 06: the recursive tracers, each for its own scenes
    for (file, renderer) in [
        ("ch05-reflection/scenes/mirrors.toml", "ch05 renderer"),
        ("ch06-refraction/scenes/bubble.toml", "ch06 renderer"),
    ] {
        let out = dir.join("recursive.png");
        let size = render(&scene(file), &out, &["--size", "32x18"], renderer);
        assert_eq!(size, (32, 18));
    }
}

#[test]
fn a_bad_scene_is_one_error_line_and_no_file() {
    let dir = scratch("bad");
    let bad = dir.join("bad.toml");
    fs::write(&bad, "[camera]\nlook_from = [0, 0, 5]\nlook_at = [0, 0, 0]\n\n[[objects]]\nsphere = { center = [0, 0, 0], radius = -1 }\n").unwrap();
    let stderr = refused(bad.to_str().unwrap(), &dir.join("bad.png"), &[]);
    assert!(stderr.contains("bad.toml:6:"), "{stderr}");
    assert!(
        stderr.contains("objects[0].sphere.radius: must be positive, got -1"),
        "{stderr}"
    );
    for args in [&["--size", "0x10"][..], &["--threads", "0"]] {
        let mut all = vec!["render", bad.to_str().unwrap()];
        all.extend_from_slice(args);
        fails_in_one_line(&all);
    }
}

/// Bad mesh input, each in one line naming the scene file (or the OBJ's
/// own line), and no image: a missing OBJ, a malformed OBJ line, a NaN in
/// a placement, a zero scale.
#[test]
fn bad_mesh_input_is_one_error_line_and_no_file() {
    let dir = scratch("bad-mesh");
    fs::create_dir_all(dir.join("meshes")).unwrap();
    fs::write(
        dir.join("meshes/bad.obj"),
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n",
    )
    .unwrap();
    fs::write(
        dir.join("meshes/tri.obj"),
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n",
    )
    .unwrap();
    let head = "[camera]\nlook_from = [0, 0, 5]\nlook_at = [0, 0, 0]\n\n";
    let cases = [
        (
            "[[objects]]\nmesh = { obj = \"meshes/gone.obj\" }\n",
            "objects[0].mesh.obj: cannot read meshes/gone.obj",
        ),
        (
            "[[objects]]\nmesh = { obj = \"meshes/bad.obj\" }\n",
            "objects[0].mesh.obj: meshes/bad.obj:4: vertex index 9",
        ),
        (
            "[meshes.tri]\nobj = \"meshes/tri.obj\"\n\n[[instances]]\nmesh = \"tri\"\ntranslate = [0, nan, 0]\n",
            "instances[0].translate[1]: must be a finite number, got nan",
        ),
        (
            "[[objects]]\nmesh = { obj = \"meshes/tri.obj\", scale = [1, 0, 1] }\n",
            "objects[0].mesh.scale: must not be 0, got [1, 0, 1]",
        ),
    ];
    for (k, (body, wanted)) in cases.iter().enumerate() {
        let file = dir.join(format!("scene-{k}.toml"));
        fs::write(&file, format!("{head}{body}")).unwrap();
        let stderr = refused(
            file.to_str().unwrap(),
            &dir.join("out.png"),
            &["--chapter", "ch08"],
        );
        assert!(stderr.contains(&format!("scene-{k}.toml:")), "{stderr}");
        assert!(stderr.contains(wanted), "{wanted}: {stderr}");
    }
}

/// Chapter 7's scenes are rasterized; a scene with a sphere cannot be,
/// and the error names the file and the object.
#[test]
fn chapter_07_rasterizes_polygons_only() {
    let dir = scratch("ch07");
    let size = render(
        &scene("ch07-two-methods/scenes/shapes.toml"),
        &dir.join("shapes.png"),
        &["--size", "48x27"],
        "ch07 renderer",
    );
    assert_eq!(size, (48, 27));

    let stderr = refused(
        &scene("ch03-illumination/scenes/spheres.toml"),
        &dir.join("spheres.png"),
        &["--chapter", "07"],
    );
    assert!(
        stderr.contains("spheres.toml: objects[0] is a sphere"),
        "{stderr}"
    );
}

/// Chapter 8's scene renders with chapter 8's shapes (its folder chooses
/// the renderer); chapter 6's renderer refuses its torus by name, and a
/// spindle torus is refused at its line and column. No image is written
/// for either.
#[test]
fn chapter_08_renders_its_primitives_and_others_refuse_them() {
    let dir = scratch("ch08");
    let primitives = scene("ch08-bounding-volumes/scenes/primitives.toml");
    let size = render(
        &primitives,
        &dir.join("primitives.png"),
        &["--size", "90x40"],
        "ch08 renderer",
    );
    assert_eq!(size, (90, 40));

    let not_drawn = dir.join("refused.png");
    let stderr = refused(&primitives, &not_drawn, &["--chapter", "06"]);
    assert!(
        stderr.contains("objects[2].box: a box is one of chapter 8's"),
        "{stderr}"
    );

    let spindle = dir.join("spindle.toml");
    fs::write(
        &spindle,
        "[camera]\nlook_from = [0, 1, 5]\nlook_at = [0, 0, 0]\n\n\
         [[objects]]\ntorus = { center = [0, 0, 0], major = 1, minor = 1 }\n",
    )
    .unwrap();
    let stderr =
        refused(spindle.to_str().unwrap(), &not_drawn, &["--chapter", "08"]);
    assert!(
        stderr.contains(
            "spindle.toml:6:50: objects[0].torus.minor: must be less than major"
        ),
        "{stderr}"
    );
}

/// `--accel bvh`, `grid`, `kdtree` and `auto` search with chapter 8's
/// hierarchy, chapter 9's grid, chapter 10's kd-tree and chapter 10's
/// rule, and draw the same bytes as the lecture's loop, for a chapter 6
/// scene, chapter 8's and chapter 9's (the bunny mesh in its stadium);
/// an unknown value is refused by name.
#[test]
fn every_accelerator_draws_the_same_image_as_the_loop() {
    let dir = scratch("accel");
    for chapter_scene in [
        "ch06-refraction/scenes/materials.toml",
        "ch08-bounding-volumes/scenes/primitives.toml",
        "ch09-grids/scenes/teapot-in-stadium.toml",
    ] {
        let mut images = Vec::new();
        let accels = ["brute", "bvh", "grid", "kdtree", "auto"];
        for accel in accels {
            let out = dir.join(format!("{accel}.png"));
            let args = ["--size", "64x36", "--accel", accel];
            render(
                &scene(chapter_scene),
                &out,
                &args,
                &format!("--accel {accel}"),
            );
            images.push(fs::read(&out).unwrap());
        }
        for (accel, image) in accels.iter().zip(&images).skip(1) {
            assert!(images[0] == *image, "{chapter_scene}: {accel}'s differs");
        }
    }
    let run = raystep(&[
        "render",
        &scene("ch03-illumination/scenes/spheres.toml"),
        "--accel",
        "octree",
    ]);
    assert!(!run.status.success());
    let stderr = text(&run.stderr);
    assert!(stderr.contains("'octree'"), "{stderr}");
}
