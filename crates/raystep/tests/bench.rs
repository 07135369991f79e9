//! `raystep bench` from the outside: a tiny run writes its JSON report and
//! its hit file; bad input gives one clear line naming the file or the
//! argument, a failing exit status, and no output file at all.

use std::fs;
use std::path::{Path, PathBuf};

mod common;
use common::{raystep, read_json, succeeds, text};

/// A unit square in the plane z = 0, as two triangles: 0 below the
/// diagonal x = y, 1 above it.
const SQUARE: &str = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3\nf 1 3 4\n";

/// A ray file: per ray six little-endian f32.
fn ray_file(rays: &[[f32; 6]]) -> Vec<u8> {
    rays.iter()
        .flatten()
        .flat_map(|x| x.to_le_bytes())
        .collect()
}

/// A fresh scratch folder for one test holding [`SQUARE`] as
/// `square.obj`: (the folder, the mesh).
fn with_square(name: &str) -> (PathBuf, PathBuf) {
    let dir = common::scratch("raystep-bench", name);
    let obj = dir.join("square.obj");
    fs::write(&obj, SQUARE).unwrap();
    (dir, obj)
}

/// The methods of a JSON report, by name.
fn methods(report: &serde_json::Value) -> Vec<&str> {
    report["methods"]
        .as_array()
        .unwrap()
        .iter()
        .map(|m| m["method"].as_str().unwrap())
        .collect()
}

/// Every method of a JSON report agrees with the first on every set.
fn assert_agree(report: &serde_json::Value) {
    for method in report["methods"].as_array().unwrap() {
        for set in method["sets"].as_array().unwrap() {
            assert_eq!(set["disagreements"], 0, "{method}");
        }
    }
}

/// Runs `raystep bench <obj> --rounds 1 <args>`, which must succeed;
/// returns its table.
fn bench(obj: &Path, args: &[&str]) -> String {
    let mut all = vec!["bench", obj.to_str().unwrap(), "--rounds", "1"];
    all.extend_from_slice(args);
    succeeds(&all)
}

#[test]
fn a_ray_file_run_writes_the_report_and_every_hit() {
    let (dir, obj) = with_square("good");
    let rays = dir.join("rays.bin");
    let (json, hits) = (dir.join("report.json"), dir.join("hits.bin"));
    // Down the z axis from z = 2: onto triangle 0, onto triangle 1, and
    // beside the square.
    fs::write(
        &rays,
        ray_file(&[
            [0.75, 0.25, 2.0, 0.0, 0.0, -1.0],
            [0.25, 0.75, 2.0, 0.0, 0.0, -1.0],
            [3.0, 3.0, 2.0, 0.0, 0.0, -1.0],
        ]),
    )
    .unwrap();
    let table = bench(
        &obj,
        &[
            "--rays",
            rays.to_str().unwrap(),
            "--builders",
            "median,sah4",
            "--json",
            json.to_str().unwrap(),
            "--write-hits",
            hits.to_str().unwrap(),
        ],
    );
    // The table names every method and counts no disagreement.
    for method in ["median, f32", "median, f64", "SAH, 4 bins, f32"] {
        assert!(table.contains(method), "{method} missing:\n{table}");
    }
    assert!(table.contains("3 (Closest hit)"), "{table}");
    assert!(table.contains("0 disagreements"), "{table}");
    // The JSON report: the mesh, the set, four methods.
    let report = read_json(&json);
    assert_eq!(report["triangles"], 2);
    assert_eq!(report["sets"][0]["rays"], 3);
    assert_eq!(report["sets"][0]["brute_force_disagreements"], 0);
    assert_eq!(report["methods"].as_array().unwrap().len(), 4);
    // The hit file: 8 bytes a ray, t then the triangle; a miss is
    // (+inf, u32::MAX).
    let bytes = fs::read(&hits).unwrap();
    assert_eq!(bytes.len(), 3 * 8);
    let record = |k: usize| {
        let r = &bytes[8 * k..8 * k + 8];
        (
            f32::from_le_bytes(r[..4].try_into().unwrap()),
            u32::from_le_bytes(r[4..].try_into().unwrap()),
        )
    };
    assert_eq!(record(0), (2.0, 0));
    assert_eq!(record(1), (2.0, 1));
    assert_eq!(record(2), (f32::INFINITY, u32::MAX));
}

#[test]
fn generated_ray_sets_are_reported_by_name() {
    let (_, obj) = with_square("generated");
    let table = bench(
        &obj,
        &["--size", "8", "--incoherent", "100", "--precision", "f32"],
    );
    for set in ["primary rays: 64", "shadow rays:", "incoherent rays: 100"] {
        assert!(table.contains(set), "{set} missing:\n{table}");
    }
}

/// The arguments of a run on small generated sets in `f64`, beside
/// chapter 8's hierarchy (`--accel bvh,<accel>`), its report to `json`.
fn beside_the_hierarchy<'a>(accel: &'a str, json: &'a Path) -> Vec<&'a str> {
    vec![
        "--size",
        "16",
        "--incoherent",
        "200",
        "--precision",
        "f64",
        "--accel",
        accel,
        "--json",
        json.to_str().unwrap(),
    ]
}

/// `--accel bvh,grid`: chapter 9's grid runs beside the hierarchy, each
/// fill asked for at the rule's resolution or at `--grid-cells`, on the
/// same rays, with the same answers.
#[test]
fn the_grid_runs_beside_the_hierarchy() {
    let (dir, obj) = with_square("grid");
    let json = dir.join("report.json");
    for (cells, name) in [(None, "rule"), (Some("7"), "7 cells")] {
        let mut args = beside_the_hierarchy("bvh,grid", &json);
        args.extend(["--grid-fill", "boxes,exact"]);
        if let Some(n) = cells {
            args.extend(["--grid-cells", n]);
        }
        bench(&obj, &args);
        let report = read_json(&json);
        assert_eq!(
            methods(&report),
            [
                "ours: SAH, 16 bins, f64".to_string(),
                format!("grid: {name}, boxes"),
                format!("grid: {name}, exact"),
            ]
        );
        assert_agree(&report);
    }
    fs::remove_file(&json).unwrap();
    // only the grid; a structure we do not have is refused by name
    let table = bench(&obj, &["--size", "4", "--accel", "grid"]);
    assert!(!table.contains("SAH"), "{table}");
    refused(
        &dir,
        &[obj.to_str().unwrap(), "--accel", "octree"],
        "octree",
    );
    refused(
        &dir,
        &[obj.to_str().unwrap(), "--grid-cells", "0"],
        "--grid-cells",
    );
}

/// `--accel bvh,kdtree`: chapter 10's kd-tree runs beside the hierarchy,
/// each `--kd-clip` its own method, on the same rays, with the same
/// answers.
#[test]
fn the_kd_tree_runs_beside_the_hierarchy() {
    let (dir, obj) = with_square("kdtree");
    let json = dir.join("report.json");
    let mut args = beside_the_hierarchy("bvh,kdtree", &json);
    args.extend(["--kd-clip", "boxes,triangles"]);
    bench(&obj, &args);
    let report = read_json(&json);
    assert_eq!(
        methods(&report),
        [
            "ours: SAH, 16 bins, f64",
            "kd-tree: SAH, events, boxes",
            "kd-tree: SAH, events, perfect splits",
        ]
    );
    for method in report["methods"].as_array().unwrap() {
        assert_eq!(method["ours"], true, "{method}");
    }
    assert_agree(&report);
    fs::remove_file(&json).unwrap();
    // only the kd-tree, clipped by boxes unless asked; a clip we do not
    // have is refused by name
    let table = bench(&obj, &["--size", "4", "--accel", "kdtree"]);
    assert!(table.contains("kd-tree: SAH, events, boxes"), "{table}");
    assert!(!table.contains("ours:"), "{table}");
    assert!(!table.contains("perfect splits"), "{table}");
    refused(
        &dir,
        &[
            obj.to_str().unwrap(),
            "--accel",
            "kdtree",
            "--kd-clip",
            "perfect",
        ],
        "--kd-clip",
    );
}

/// Bad input: the exit status is not 0, stderr is one line naming
/// `names`, and neither output file exists.
fn refused(dir: &Path, args: &[&str], names: &str) {
    let (json, hits) = (dir.join("report.json"), dir.join("hits.bin"));
    let mut all = vec!["bench"];
    all.extend_from_slice(args);
    all.extend([
        "--rounds",
        "1",
        "--json",
        json.to_str().unwrap(),
        "--write-hits",
        hits.to_str().unwrap(),
    ]);
    let run = raystep(&all);
    let stderr = text(&run.stderr);
    assert!(!run.status.success(), "{args:?} was accepted");
    assert_eq!(stderr.trim_end().lines().count(), 1, "{stderr}");
    assert!(stderr.contains(names), "{names} not named in: {stderr}");
    assert!(!json.exists() && !hits.exists(), "{args:?} left a file");
    let leftovers: Vec<_> = fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name())
        .filter(|name| name != "square.obj" && name != "bad.obj")
        .filter(|name| name != "rays.bin")
        .collect();
    assert!(leftovers.is_empty(), "{args:?} left {leftovers:?}");
}

#[test]
fn bad_input_is_refused_by_name_and_writes_nothing() {
    let (dir, obj) = with_square("bad");
    let obj = obj.to_str().unwrap();
    // A mesh that is not there, and one that does not parse.
    let missing = dir.join("missing.obj");
    refused(&dir, &[missing.to_str().unwrap()], "missing.obj");
    let bad = dir.join("bad.obj");
    fs::write(&bad, "v 0 0 0\nv 1 0 0\nv 1 1 zero\nf 1 2 3\n").unwrap();
    refused(&dir, &[bad.to_str().unwrap()], "bad.obj");
    // A ray file of 25 bytes: not a whole number of 24-byte rays.
    let rays = dir.join("rays.bin");
    fs::write(&rays, [0u8; 25]).unwrap();
    refused(&dir, &[obj, "--rays", rays.to_str().unwrap()], "rays.bin");
    // Threads: none, not a number.
    refused(&dir, &[obj, "--threads", "0"], "--threads");
    refused(&dir, &[obj, "--threads", "abc"], "--threads");
    // Embree kept to an instruction set: only beside the peers, and only
    // one it knows.
    refused(&dir, &[obj, "--embree-isa", "avx2"], "--peers");
    refused(&dir, &[obj, "--peers", "--embree-isa", "neon"], "neon");
    refused(&dir, &[obj, "--embree-alone"], "--peers");
    // An output folder that does not exist: refused before any work.
    let nowhere = dir.join("no/such/folder/report.json");
    let run = raystep(&[
        "bench",
        obj,
        "--json",
        nowhere.to_str().unwrap(),
        "--size",
        "4",
    ]);
    assert!(!run.status.success());
    assert!(text(&run.stderr).contains("report.json"));
    assert!(!text(&run.stdout).contains("method"), "it ran first");
}
