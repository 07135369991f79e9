//! `raystep render` from the outside: a PNG for a good scene, one clear
//! error line and no file for a bad one.

use std::fs;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn raystep(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_raystep"))
        .args(args)
        .output()
        .expect("raystep runs")
}

fn scratch(name: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR"))
        .join("raystep-render")
        .join(name);
    let _ = fs::remove_dir_all(&dir);
    fs::create_dir_all(&dir).unwrap();
    dir
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

#[test]
fn renders_a_chapter_scene_at_the_asked_size() {
    let dir = scratch("good");
    let out = dir.join("spheres.png");
    let run = raystep(&[
        "render",
        &scene("ch03-illumination/scenes/spheres.toml"),
        "--out",
        out.to_str().unwrap(),
        "--size",
        "64x36",
        "--threads",
        "2",
    ]);
    assert!(
        run.status.success(),
        "{}",
        String::from_utf8_lossy(&run.stderr)
    );
    assert_eq!(png_size(&fs::read(&out).unwrap()), (64, 36));
    assert!(String::from_utf8_lossy(&run.stdout).contains("ch03 renderer"));
    // chapter 4's scene gets chapter 4's tracer (with shadows)
    let out4 = dir.join("two.png");
    let run = raystep(&[
        "render",
        &scene("ch04-shadows/scenes/two-lights.toml"),
        "--out",
        out4.to_str().unwrap(),
        "--size",
        "32x18",
    ]);
    assert!(run.status.success());
    assert!(String::from_utf8_lossy(&run.stdout).contains("ch04 renderer"));
    // chapters 5 and 06: the recursive tracers, each for its own scenes
    for (file, renderer) in [
        ("ch05-reflection/scenes/mirrors.toml", "ch05 renderer"),
        ("ch06-refraction/scenes/bubble.toml", "ch06 renderer"),
    ] {
        let out = dir.join("recursive.png");
        let run = raystep(&[
            "render",
            &scene(file),
            "--out",
            out.to_str().unwrap(),
            "--size",
            "32x18",
        ]);
        assert!(run.status.success(), "{file}");
        assert!(
            String::from_utf8_lossy(&run.stdout).contains(renderer),
            "{file}"
        );
        assert_eq!(png_size(&fs::read(&out).unwrap()), (32, 18));
    }
}

#[test]
fn a_bad_scene_is_one_error_line_and_no_file() {
    let dir = scratch("bad");
    let bad = dir.join("bad.toml");
    fs::write(&bad, "[camera]\nlook_from = [0, 0, 5]\nlook_at = [0, 0, 0]\n\n[[objects]]\nsphere = { center = [0, 0, 0], radius = -1 }\n").unwrap();
    let out = dir.join("bad.png");
    let run = raystep(&[
        "render",
        bad.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(!run.status.success());
    let stderr = String::from_utf8_lossy(&run.stderr);
    assert_eq!(stderr.lines().count(), 1, "{stderr}");
    assert!(stderr.contains("bad.toml:6:"), "{stderr}");
    assert!(
        stderr.contains("objects[0].sphere.radius: must be positive, got -1"),
        "{stderr}"
    );
    assert!(!out.exists());
    for args in [&["--size", "0x10"][..], &["--threads", "0"]] {
        let mut all = vec!["render", bad.to_str().unwrap()];
        all.extend_from_slice(args);
        let run = raystep(&all);
        assert!(!run.status.success());
        assert_eq!(String::from_utf8_lossy(&run.stderr).lines().count(), 1);
    }
}

/// Chapter 7's scenes are rasterized; a scene with a sphere cannot be,
/// and the error names the file and the object.
#[test]
fn chapter_07_rasterizes_polygons_only() {
    let dir = scratch("ch07");
    let out = dir.join("shapes.png");
    let run = raystep(&[
        "render",
        &scene("ch07-two-methods/scenes/shapes.toml"),
        "--out",
        out.to_str().unwrap(),
        "--size",
        "48x27",
    ]);
    assert!(
        run.status.success(),
        "{}",
        String::from_utf8_lossy(&run.stderr)
    );
    assert!(String::from_utf8_lossy(&run.stdout).contains("ch07 renderer"));
    assert_eq!(png_size(&fs::read(&out).unwrap()), (48, 27));

    let out = dir.join("spheres.png");
    let run = raystep(&[
        "render",
        &scene("ch03-illumination/scenes/spheres.toml"),
        "--chapter",
        "07",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(!run.status.success());
    let stderr = String::from_utf8_lossy(&run.stderr);
    assert_eq!(stderr.lines().count(), 1, "{stderr}");
    assert!(
        stderr.contains("spheres.toml: objects[0] is a sphere"),
        "{stderr}"
    );
    assert!(!out.exists());
}

/// Chapter 8's scene renders with chapter 8's shapes (its folder chooses
/// the renderer); chapter 6's renderer refuses its torus by name, and a
/// spindle torus is refused at its line and column. No image is written
/// for either.
#[test]
fn chapter_08_renders_its_primitives_and_others_refuse_them() {
    let dir = scratch("ch08");
    let primitives = scene("ch08-bounding-volumes/scenes/primitives.toml");
    let out = dir.join("primitives.png");
    let run = raystep(&[
        "render",
        &primitives,
        "--out",
        out.to_str().unwrap(),
        "--size",
        "90x40",
    ]);
    assert!(
        run.status.success(),
        "{}",
        String::from_utf8_lossy(&run.stderr)
    );
    assert!(String::from_utf8_lossy(&run.stdout).contains("ch08 renderer"));
    assert_eq!(png_size(&fs::read(&out).unwrap()), (90, 40));

    let refused = dir.join("refused.png");
    let run = raystep(&[
        "render",
        &primitives,
        "--chapter",
        "06",
        "--out",
        refused.to_str().unwrap(),
    ]);
    assert!(!run.status.success());
    let stderr = String::from_utf8_lossy(&run.stderr);
    assert_eq!(stderr.lines().count(), 1, "{stderr}");
    assert!(
        stderr.contains("objects[2].box: a box is one of chapter 8's"),
        "{stderr}"
    );
    assert!(!refused.exists());

    let spindle = dir.join("spindle.toml");
    fs::write(
        &spindle,
        "[camera]\nlook_from = [0, 1, 5]\nlook_at = [0, 0, 0]\n\n\
         [[objects]]\ntorus = { center = [0, 0, 0], major = 1, minor = 1 }\n",
    )
    .unwrap();
    let run = raystep(&[
        "render",
        spindle.to_str().unwrap(),
        "--chapter",
        "08",
        "--out",
        refused.to_str().unwrap(),
    ]);
    assert!(!run.status.success());
    let stderr = String::from_utf8_lossy(&run.stderr);
    assert!(
        stderr.contains(
            "spindle.toml:6:50: objects[0].torus.minor: must be less than major"
        ),
        "{stderr}"
    );
    assert!(!refused.exists());
}

/// `--accel bvh`, `grid`, `kdtree` and `auto` search with chapter 8's
/// hierarchy, chapter 9's grid, chapter 10's kd-tree and chapter 10's
/// rule, and draw the same bytes as the lecture's loop, for a chapter 6
/// scene, chapter 8's and chapter 9's; an unknown value is refused by
/// name.
#[test]
fn every_accelerator_draws_the_same_image_as_the_loop() {
    let dir = scratch("accel");
    for chapter_scene in [
        "ch06-refraction/scenes/materials.toml",
        "ch08-bounding-volumes/scenes/primitives.toml",
        "ch09-grids/scenes/stadium.toml",
    ] {
        let mut images = Vec::new();
        let accels = ["brute", "bvh", "grid", "kdtree", "auto"];
        for accel in accels {
            let out = dir.join(format!("{accel}.png"));
            let run = raystep(&[
                "render",
                &scene(chapter_scene),
                "--size",
                "64x36",
                "--accel",
                accel,
                "--out",
                out.to_str().unwrap(),
            ]);
            assert!(
                run.status.success(),
                "{}",
                String::from_utf8_lossy(&run.stderr)
            );
            let said = String::from_utf8_lossy(&run.stdout).into_owned();
            assert!(said.contains(&format!("--accel {accel}")), "{said}");
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
    let stderr = String::from_utf8_lossy(&run.stderr);
    assert!(stderr.contains("'octree'"), "{stderr}");
}
