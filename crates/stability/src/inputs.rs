//! Malformed input files: valid seeds mutated by [`crate::mutate`], each
//! written to a temporary file and read by the scene parser, the OBJ
//! loader, the bench's ray-file reader, or the whole of `raystep render`.
//! A trial fails if the reader panics, if its error does not name the
//! file (and the line or field, where the file has them), if it accepts
//! what the format refuses, or if an output file is left behind.
//!
//! Only `raystep render` writes a file from a scene; it is run here as
//! the command runs it. `raystep bench --rays FILE` reads its ray file
//! before it writes anything (`--json` and `--hits` are written whole,
//! after the run), so a bad ray file cannot leave one.
use std::fs;
use std::panic::{self, AssertUnwindSafe, PanicHookInfo};
use std::path::{Path, PathBuf};
use std::sync::{Arc, Mutex};

use raystep_bench::RAY_BYTES;
use raystep_scene::{Mesh, MeshError, SceneError};
use raystep_world::Accelerate;

use crate::mutate::{Mutator, SCENES, obj_seeds, ray_seed};
use crate::{Budget, Case, Count, Expect};

/// What one trial showed: `Err` says why it failed.
type Verdict = Result<(), String>;

/// A scene mutation: the new bytes, and whether the parser must refuse
/// them.
type SceneMutation = fn(&mut Mutator, &str) -> (Vec<u8>, bool);

/// This group's cases.
pub fn cases() -> Vec<Case> {
    let case = |name, what, run| Case {
        group: "inputs",
        name,
        what,
        run,
    };
    vec![
        case(
            "scene TOML: truncated",
            "a scene cut at a random character: an error names FILE:LINE, \
             never a panic",
            |b| scene_case(b, 1, Expect::Never, |m, t| text(m.truncated(t))),
        ),
        case(
            "scene TOML: lines deleted, duplicated, swapped",
            "1–3 line edits: an error names FILE:LINE (and the field), \
             never a panic",
            |b| scene_case(b, 2, Expect::Never, |m, t| text(m.lines_edited(t))),
        ),
        case(
            "scene TOML: bad numbers",
            "a number made NaN, ∞, 1e309, 10²⁰, −0, empty, garbage: \
             NaN/∞ refused at FILE:LINE: FIELD",
            |b| scene_case(b, 3, Expect::Never, |m, t| bytes(m.bad_number(t))),
        ),
        case(
            "scene TOML: wrong keys and types",
            "a key renamed, a string/bool/table for a number, [x, y], \
             [x, y, z, w]: refused at FILE:LINE",
            |b| {
                scene_case(b, 4, Expect::Never, |m, t| {
                    bytes(m.wrong_key_or_type(t))
                })
            },
        ),
        case(
            "scene TOML: invalid UTF-8",
            "bytes that are not UTF-8 put in: refused, the error naming \
             FILE:LINE",
            // (The reader named no line until the catalogue found it.)
            |b| {
                scene_case(b, 5, Expect::Never, |m, t| {
                    m.invalid_utf8(t.as_bytes())
                })
            },
        ),
        case(
            "scene TOML: overlong lines, deep nesting",
            "lines of 10⁵ characters, values nested 10⁴ deep: refused at \
             FILE:LINE, no stack overflow",
            |b| scene_case(b, 6, Expect::Never, |m, t| bytes(m.overlong(t))),
        ),
        case(
            "OBJ: bad face indices",
            "an index 0, past the end, negative, past u32/i64, not a \
             number: refused at FILE: line N",
            |b| obj_case(b, 7, |m, t| bytes(m.bad_index(t))),
        ),
        case(
            "OBJ: bad numbers",
            "a coordinate NaN, ∞, past f32, garbage, missing or extra: \
             refused at FILE: line N, no NaN kept",
            |b| obj_case(b, 8, |m, t| bytes(m.bad_vertex(t))),
        ),
        case(
            "OBJ: truncated, stray lines, garbage",
            "cut, lines edited, stray lines, not UTF-8, 10⁵-character \
             lines: errors name FILE: line N",
            |b| obj_case(b, 9, Mutator::obj_garbage),
        ),
        case(
            "ray file: wrong length",
            "a ray file cut, lengthened by 1–23 bytes or emptied: refused \
             naming the file, else read exactly",
            |b| ray_case(b, 10, Mutator::ray_length, true),
        ),
        case(
            "ray file: NaN and ∞",
            "floats made NaN, ±∞, ±MAX, subnormal or −0, zero directions: \
             no panic, read bit for bit",
            |b| ray_case(b, 11, Mutator::ray_special, false),
        ),
        case(
            "render: bad scene leaves no image",
            "raystep render of a mutated scene (each --accel): an error \
             names the file and writes no file",
            render_case,
        ),
    ]
}

/// A mutated text that the reader may take.
fn text(input: String) -> (Vec<u8>, bool) {
    (input.into_bytes(), false)
}

/// A mutated text, and whether the reader must refuse it.
fn bytes((input, reject): (String, bool)) -> (Vec<u8>, bool) {
    (input.into_bytes(), reject)
}

/// The small mesh the scene format's example names (`meshes/tetra.obj`).
const TETRA: &str = include_str!("../../scene/meshes/tetra.obj");

/// Mutated scenes, read by `raystep_scene::load`.
fn scene_case(
    budget: &Budget, seed: u64, expect: Expect, mutate: SceneMutation,
) -> Vec<(Count, Expect)> {
    trials("scene parser", expect, budget, seed, "toml", |m, path| {
        // Step 1: a seed, mutated, in a file (beside the small mesh the
        // format's example names, so a scene that may be taken can be).
        let seed = m.pick(&SCENES);
        let (input, reject) = mutate(m, seed);
        fs::write(path, &input).map_err(|e| e.to_string())?;
        let meshes = path.with_file_name("meshes");
        if !meshes.join("tetra.obj").exists() {
            fs::create_dir_all(&meshes).map_err(|e| e.to_string())?;
            fs::write(meshes.join("tetra.obj"), TETRA)
                .map_err(|e| e.to_string())?;
        }
        // Step 2: read it, a panic caught.
        match guarded(|| raystep_scene::load(path))? {
            Ok(_) if reject => Err("accepted".to_owned()),
            Ok(_) => Ok(()),
            Err(error) => scene_error_located(&error, path, &input),
        }
    })
}

/// `Ok` if `error` reads `FILE:LINE:COLUMN: …` with a line of `input`,
/// and a field unless it is a TOML syntax error.
fn scene_error_located(
    error: &SceneError, path: &Path, input: &[u8],
) -> Verdict {
    let message = error.to_string();
    let lines = input.split(|&b| b == b'\n').count();
    let (line, field) = match error {
        SceneError::Read { .. } => return Err(format!("no line: {message}")),
        SceneError::Syntax { line, .. } => (*line, "syntax"),
        SceneError::Invalid { line, field, .. } => (*line, field.as_str()),
    };
    if !message.starts_with(&format!("{}:", path.display())) {
        Err(format!("no file: {message}"))
    } else if line == 0 || line > lines || field.is_empty() {
        Err(format!("no line or field: {message}"))
    } else if message.contains('\n') {
        Err(format!("more than one line: {message}"))
    } else {
        Ok(())
    }
}

/// Mutated OBJ files, read by `Mesh::load_obj`; a mesh it returns must
/// have every index in range and every vertex finite.
fn obj_case(
    budget: &Budget, seed: u64,
    mutate: fn(&mut Mutator, &str) -> (Vec<u8>, bool),
) -> Vec<(Count, Expect)> {
    // (Until the catalogue found it, what only the OBJ reader (tobj)
    // checked was refused without a line, and in debug builds tobj's
    // index arithmetic overflowed on a `vt`/`vn` index far below the
    // first; the loader now checks every line first.)
    let seeds = obj_seeds();
    trials(
        "OBJ loader",
        Expect::Never,
        budget,
        seed,
        "obj",
        |m, path| {
            // Step 1: a seed, mutated, in a file.
            let seed = &seeds[m.below(seeds.len())];
            let (input, reject) = mutate(m, seed);
            fs::write(path, &input).map_err(|e| e.to_string())?;
            // Step 2: read it, a panic caught.
            match guarded(|| Mesh::load_obj(path))? {
                Ok(_) if reject => Err("accepted".to_owned()),
                Ok(mesh) => {
                    let n = mesh.vertices.len();
                    let indices = mesh.triangles.iter().flatten();
                    if indices.into_iter().any(|&i| i >= n) {
                        Err("an index out of range".to_owned())
                    } else if mesh.vertices.iter().any(|v| !v.is_finite()) {
                        Err("a vertex not finite".to_owned())
                    } else {
                        Ok(())
                    }
                }
                Err(error) => mesh_error_located(&error, path, &input),
            }
        },
    )
}

/// `Ok` if `error` names the file and a line of `input`, the file's own
/// vertex number of a vertex that is not finite, or no faces.
fn mesh_error_located(error: &MeshError, path: &Path, input: &[u8]) -> Verdict {
    let message = error.to_string();
    let Some(rest) = message.strip_prefix(&format!("{}: ", path.display()))
    else {
        return Err(format!("no file: {message}"));
    };
    let number = |prefix: &str| {
        let digits = rest.strip_prefix(prefix)?.split([':', ' ']).next()?;
        digits.parse::<usize>().ok().filter(|&n| n >= 1)
    };
    let text = String::from_utf8_lossy(input);
    if matches!(error, MeshError::Empty { .. }) {
        Ok(())
    } else if let Some(n) = number("line ") {
        match n <= text.lines().count() {
            true => Ok(()),
            false => Err(format!("no such line: {message}")),
        }
    } else if let Some(k) = number("vertex ") {
        // the file's k-th `v` line must be the one that is not finite
        let line = text.lines().filter(|l| l.starts_with("v ")).nth(k - 1);
        let finite = line.is_some_and(|line| {
            let mut words = line.split_whitespace().skip(1);
            let xyz: Vec<f32> =
                words.by_ref().take(3).flat_map(str::parse).collect();
            let w = words
                .next()
                .and_then(|w| w.parse::<f32>().ok())
                .unwrap_or(1.0);
            xyz.iter().all(|x| (x / w).is_finite())
        });
        match finite {
            false => Ok(()),
            true => Err(format!("names the wrong vertex: {message}")),
        }
    } else {
        Err(format!("no line: {message}"))
    }
}

/// Mutated ray files, read by `raystep_bench::read_rays`: a length that
/// is not a positive multiple of 24 must be refused (if `lengths`), and
/// what is read must be the file's floats, bit for bit.
fn ray_case(
    budget: &Budget, seed: u64, mutate: fn(&mut Mutator, &[u8]) -> Vec<u8>,
    lengths: bool,
) -> Vec<(Count, Expect)> {
    trials(
        "ray file reader",
        Expect::Never,
        budget,
        seed,
        "rays",
        |m, path| {
            // Step 1: 1–8 seeded rays, mutated, in a file.
            let count = 1 + m.below(8);
            let seed = ray_seed(m, count);
            let input = mutate(m, &seed);
            let whole = input.len().is_multiple_of(RAY_BYTES);
            let reject = lengths && (input.is_empty() || !whole);
            fs::write(path, &input).map_err(|e| e.to_string())?;
            // Step 2: read it, a panic caught.
            match guarded(|| raystep_bench::read_rays(path))? {
                Ok(_) if reject => Err("accepted".to_owned()),
                Ok(set) => {
                    let read = raystep_bench::ray_bytes(&set.rays);
                    match read == input {
                        true => Ok(()),
                        false => Err("rays not read bit for bit".to_owned()),
                    }
                }
                Err(error) => {
                    let message = error.to_string();
                    match message.starts_with(&format!("{}: ", path.display()))
                    {
                        true => Ok(()),
                        false => Err(format!("no file: {message}")),
                    }
                }
            }
        },
    )
}

/// The accelerators of `raystep render --accel`, as it builds them.
const ACCELERATORS: [Accelerate; 5] = [
    |_| Arc::new(ch03::BruteForce),
    |objects| {
        let builder = ch08::Builder::BinnedSah { bins: 16 };
        Arc::new(ch08::Bvh::for_objects(objects, builder))
    },
    |objects| {
        Arc::new(ch09::Grid::for_objects(objects, ch09::Resolution::Rule))
    },
    |objects| {
        Arc::new(ch10::KdTree::for_objects(
            objects,
            ch10::KdBuilder::SahEvents,
            ch10::KdCosts::CHOSEN,
        ))
    },
    ch10::auto,
];

/// The scenes of chapters 3–7, mutated by any of the scene cases'
/// mutations (but the overlong lines) or given a finite extreme number
/// (1e308, 5e-324, −0), rendered as `raystep render SCENE
/// -o OUT --size 8x6` does.
fn render_case(budget: &Budget) -> Vec<(Count, Expect)> {
    let mutations: [SceneMutation; 6] = [
        |m, t| text(m.extreme_number(t)),
        |m, t| text(m.truncated(t)),
        |m, t| text(m.lines_edited(t)),
        |m, t| bytes(m.bad_number(t)),
        |m, t| bytes(m.wrong_key_or_type(t)),
        |m, t| m.invalid_utf8(t.as_bytes()),
    ];
    trials("render", Expect::Never, budget, 12, "toml", |m, scene| {
        // Step 1: a mutated scene in a file, an empty folder for the image.
        let (mutate, seed) = (m.pick(&mutations), m.pick(&SCENES[1..6]));
        let (input, _) = mutate(m, seed);
        fs::write(scene, &input).map_err(|e| e.to_string())?;
        let folder = scene.with_file_name("out");
        fs::create_dir_all(&folder).map_err(|e| e.to_string())?;
        let out = folder.join("scene.png");
        // Step 2: render it, a panic caught.
        let accelerate = m.pick(&ACCELERATORS);
        let result = guarded(|| render(scene, &out, accelerate));
        // Step 3: what is in the folder now, then empty it again.
        let left: Vec<PathBuf> = fs::read_dir(&folder)
            .map_err(|e| e.to_string())?
            .map(|entry| entry.map(|e| e.path()))
            .collect::<Result<_, _>>()
            .map_err(|e| e.to_string())?;
        for file in &left {
            fs::remove_file(file).map_err(|e| e.to_string())?;
        }
        match result? {
            Ok(()) if left == [out] => Ok(()),
            Ok(()) => Err(format!("wrote {left:?}")),
            Err(_) if !left.is_empty() => Err(format!("left {left:?}")),
            Err(message) => {
                match message.starts_with(&format!("{}:", scene.display())) {
                    true => Ok(()),
                    false => Err(format!("no file: {message}")),
                }
            }
        }
    })
}

/// `raystep render` (crates/raystep/src/render.rs) with chapter 6's
/// renderer (its default outside a chapter folder), at 8×6 pixels.
fn render(
    scene: &Path, out: &Path, accelerate: Accelerate,
) -> Result<(), String> {
    let file = scene.display().to_string();
    // Step 1: read the scene; nothing is written before this succeeds.
    let mut parsed = raystep_scene::load(scene).map_err(|e| e.to_string())?;
    (parsed.width, parsed.height) = (8, 6);
    // Step 2: its world and image, as ch06-figures' renderer makes them.
    let world = ch03::world(&parsed, &file)
        .map_err(|e| e.to_string())?
        .accelerated(accelerate);
    let stop = ch06::DEFAULT_STOP;
    let fresnel = ch06::Fresnel::Exact;
    let options = ch06::RenderOptions::QUIET;
    let (image, _) = ch06::render(&world, &stop, fresnel, &options)
        .map_err(|e| e.to_string())?;
    // Step 3: the PNG, written whole or not at all.
    image.write_png(out).map_err(|e| e.to_string())
}

/// Runs `budget.inputs` trials, the panic hook silenced, each given a
/// new file `input-K.EXT` in a temporary folder: one count for `method`.
fn trials(
    method: &str, expect: Expect, budget: &Budget, seed: u64, extension: &str,
    mut trial: impl FnMut(&mut Mutator, &Path) -> Verdict,
) -> Vec<(Count, Expect)> {
    let _quiet = Quiet::new();
    let dir = tempfile::tempdir().expect("a temporary folder");
    let mut random = Mutator::new(seed);
    let failures = (0..budget.inputs)
        .filter(|k| {
            // A new name each time: rewriting one file in place made
            // each trial wait for the disk (ext4 flushes a file that is
            // truncated and written again).
            let path = dir.path().join(format!("input-{k}.{extension}"));
            let verdict = trial(&mut random, &path);
            let _ = fs::remove_file(&path);
            verdict.is_err()
        })
        .count();
    let count = Count::new(method, failures as u64, budget.inputs as u64);
    vec![(count, expect)]
}

/// `work`'s result, or `Err` if it panicked.
fn guarded<T>(work: impl FnOnce() -> T) -> Result<T, String> {
    panic::catch_unwind(AssertUnwindSafe(work)).map_err(|payload| {
        let text = payload
            .downcast_ref::<&str>()
            .map(|s| s.to_string())
            .or_else(|| payload.downcast_ref::<String>().cloned());
        format!("panicked: {}", text.unwrap_or_default())
    })
}

/// A panic hook, as `std::panic::take_hook` gives it back.
type Hook = Box<dyn Fn(&PanicHookInfo<'_>) + Sync + Send + 'static>;

/// How many cases run now, and the hook they silenced.
static SILENCED: Mutex<(usize, Option<Hook>)> = Mutex::new((0, None));

/// The panic hook silenced while any input case runs (a reader's panic
/// is a failure counted, not a message), then put back.
struct Quiet;

impl Quiet {
    fn new() -> Quiet {
        let mut silenced = SILENCED.lock().unwrap_or_else(|e| e.into_inner());
        if silenced.0 == 0 {
            silenced.1 = Some(panic::take_hook());
            panic::set_hook(Box::new(|_| {}));
        }
        silenced.0 += 1;
        Quiet
    }
}

impl Drop for Quiet {
    fn drop(&mut self) {
        let mut silenced = SILENCED.lock().unwrap_or_else(|e| e.into_inner());
        silenced.0 -= 1;
        if silenced.0 == 0
            && let Some(hook) = silenced.1.take()
        {
            panic::set_hook(hook);
        }
    }
}
