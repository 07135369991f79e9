//! `raystep bench`: the performance instrument of chapters 8–10.
//!
//! A triangle mesh and sets of rays (generated and seeded, or read from a
//! file); every method built and traced on the same triangles and rays,
//! in the same process, round after round and taking turns; the medians
//! reported with the work per ray that explains them (node visits,
//! triangle tests), every answer checked against the first method's and a
//! sample against brute force. With the `peers` feature the Rust BVH
//! libraries obvhs and bvh run beside ours; with `embree`, Intel's Embree
//! too, its library loaded at run time (reported skipped where missing).
//!
//! Its inputs are the ones every measurement and test of chapters 8–11
//! shares: the mesh ray sets, the tightness measurements' random lines and
//! the generated scenes of chapter 9.
#![deny(missing_docs)]

mod built;
#[cfg(feature = "embree")]
mod embree;
mod embree_isa;
mod error;
mod methods;
#[cfg(feature = "peers")]
mod peers;
mod ray_sets;
mod rays;
mod report;
mod run;
mod scenes;
mod tightness_lines;

use std::path::{Path, PathBuf};

use ch08::{Builder, NodePrecision};
use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use raystep_core::{Aabb, DVec3};
use raystep_scene::Mesh;

pub use built::Built;
pub use embree_isa::EmbreeIsa;
pub use error::BenchError;
pub use methods::{GridSpec, KdSpec, Method};
pub use ray_sets::{camera_rays, incoherent_rays};
pub use rays::{
    Question, RAY_BYTES, RaySet, incoherent, primary, ray_bytes, read_rays,
    shadow,
};
pub use report::agreement_name;
pub use report::{BenchReport, MethodReport, SetInfo, SetReport};
pub use run::{
    Answer, MISS, OWN_TEST_TOLERANCE, agree, agree_within, compare, median,
    trace,
};
pub use scenes::{
    SCENE_SEED, STADIUM, stadium, triangle_objects, uniform_spheres,
    uniform_triangles,
};
pub use tightness_lines::{TIGHTNESS_SEED, sampling_sphere};

/// What to benchmark.
#[derive(Clone, Debug)]
pub struct BenchOptions {
    /// The OBJ mesh.
    pub mesh: PathBuf,
    /// A ray file instead of the generated sets.
    pub rays: Option<PathBuf>,
    /// The primary camera's image is `size × size`.
    pub size: u32,
    /// How many incoherent rays.
    pub incoherent: usize,
    /// Their seed.
    pub seed: u64,
    /// Threads tracing.
    pub threads: usize,
    /// Rounds (times are medians).
    pub rounds: usize,
    /// Our builders (with every precision in `precisions`).
    pub builders: Vec<Builder>,
    /// Our node precisions.
    pub precisions: Vec<NodePrecision>,
    /// Our grids (chapter 9).
    pub grids: Vec<GridSpec>,
    /// Our kd-trees (chapter 10).
    pub kd_trees: Vec<KdSpec>,
    /// The appendix's steps.
    pub fast: Vec<ch11::Step>,
    /// Run the peers too (needs the `peers` feature).
    pub peers: bool,
    /// With the peers, Embree's default build once more, its kernels kept
    /// to this instruction set.
    pub embree_isa: Option<EmbreeIsa>,
    /// With the peers, Embree's default mode alone ([`Method::embree_alone`]).
    pub embree_alone: bool,
    /// Rays per set checked against brute force.
    pub brute_force: usize,
    /// Draw a progress bar (on a terminal).
    pub progress: bool,
}

/// The mesh's triangles, as read.
pub fn load_triangles(file: &Path) -> Result<Vec<[DVec3; 3]>, BenchError> {
    let mesh = Mesh::load_obj(file)?;
    Ok((0..mesh.triangles.len())
        .map(|k| mesh.triangle(k))
        .collect())
}

/// A mesh of `shared/meshes/README.md` (`bunny.obj`, `bunny-235k.obj`):
/// in `../shared/meshes` beside the workspace.
pub fn shared_mesh(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../../shared/meshes")
        .join(name)
}

/// The Stanford bunny's triangles (3 674), for the tests: a missing or
/// broken `bunny.obj` panics, naming the file.
pub fn bunny() -> Vec<[DVec3; 3]> {
    load_triangles(&shared_mesh("bunny.obj")).unwrap_or_else(|e| {
        panic!("{e} (the bunny lives in ../shared/meshes beside the workspace)")
    })
}

/// A finished benchmark: the report, and the first method's answers on
/// the first ray set (for a hit file).
pub struct BenchRun {
    /// The report (a table, or JSON through serde).
    pub report: BenchReport,
    /// One answer per ray of the first set.
    pub answers: Vec<Answer>,
}

/// Answers as a hit file's bytes: per ray a little-endian `f32` t (+∞ for
/// a miss) and `u32` triangle (`u32::MAX` for a miss).
pub fn hit_bytes(answers: &[Answer]) -> Vec<u8> {
    let mut bytes = Vec::with_capacity(answers.len() * 8);
    for (t, triangle) in answers {
        bytes.extend_from_slice(&t.to_le_bytes());
        bytes.extend_from_slice(&triangle.to_le_bytes());
    }
    bytes
}

/// Runs `work` on a pool of `threads` threads (the tracing inside runs
/// on it): measurements that must be single-threaded use 1.
pub fn on_threads<T: Send>(
    threads: usize, work: impl FnOnce() -> T + Send,
) -> Result<T, BenchError> {
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads.max(1))
        .build()
        .map_err(|e| BenchError::Argument {
            argument: "--threads",
            message: e.to_string(),
        })?;
    Ok(pool.install(work))
}

/// Runs `work` on a pool of `threads` threads, as [`on_threads`], while
/// this thread calls `step` each time `work` calls the tick it is given:
/// a measurement's progress bar, which need not be sendable.
pub fn on_threads_with_steps<T: Send>(
    threads: usize, work: impl FnOnce(&mut dyn FnMut()) -> T + Send,
    step: &mut dyn FnMut(),
) -> Result<T, BenchError> {
    let (ticks, ticked) = std::sync::mpsc::channel::<()>();
    std::thread::scope(|scope| {
        let worker = scope.spawn(move || {
            on_threads(threads, move || {
                work(&mut || {
                    let _ = ticks.send(());
                })
            })
        });
        for () in ticked {
            step();
        }
        worker
            .join()
            .unwrap_or_else(|panic| std::panic::resume_unwind(panic))
    })
}

/// Runs the benchmark. It writes no file: the caller writes the report
/// and the answers, once everything has worked.
pub fn run(options: &BenchOptions) -> Result<BenchRun, BenchError> {
    // Step 1: everything that can be wrong with the input, before any
    // work: the arguments, the mesh, the ray file.
    if options.threads == 0 {
        return Err(BenchError::Argument {
            argument: "--threads",
            message: "must be at least 1".into(),
        });
    }
    if options.peers && !cfg!(feature = "peers") {
        return Err(BenchError::Argument {
            argument: "--peers",
            message: "this raystep was built without them; run \
                      `cargo run --release --features peers -- bench ...`"
                .into(),
        });
    }
    let triangles = load_triangles(&options.mesh)?;
    let bounds = Aabb::around(triangles.iter().flatten().copied());
    let file_set = options.rays.as_deref().map(read_rays).transpose()?;
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(options.threads)
        .build()
        .map_err(|e| BenchError::Argument {
            argument: "--threads",
            message: e.to_string(),
        })?;
    // Step 2: the methods; ours first (the reference), then the peers.
    let mut methods: Vec<Method> = Vec::new();
    for &builder in &options.builders {
        for &precision in &options.precisions {
            methods.push(Method::Ours(builder, precision));
        }
    }
    for &spec in &options.grids {
        methods.push(Method::Grid(spec));
    }
    for &spec in &options.kd_trees {
        methods.push(Method::Kd(spec));
    }
    for &step in &options.fast {
        methods.push(Method::Fast(step));
    }
    let mut skipped = Vec::new();
    if options.peers {
        let peers = Method::peers(options.embree_isa);
        methods.extend(if options.embree_alone {
            Method::embree_alone(peers)
        } else {
            peers
        });
        skipped = Method::skipped_peers();
    }
    let Some(&first) = methods.first() else {
        return Err(BenchError::Argument {
            argument: "--builders",
            message: "no method to run".into(),
        });
    };
    pool.install(|| {
        // Step 3: the ray sets.
        let sets = match file_set {
            Some(set) => vec![set],
            None => {
                let primary = primary(&bounds, options.size);
                let reference = ch08::MeshBvh::new(
                    &triangles,
                    &ch08::Bvh::build(
                        &ch08::triangle_boxes(&triangles),
                        Builder::BinnedSah { bins: 16 },
                    ),
                    NodePrecision::Double,
                );
                let shadow = shadow(&bounds, &primary, &reference);
                let incoherent =
                    incoherent(&bounds, options.incoherent, options.seed);
                vec![primary, shadow, incoherent]
            }
        };
        // Step 4: the rounds, then brute force on a sample.
        let units =
            options.rounds * methods.len() * (1 + sets.len()) + sets.len();
        let progress = ProgressBar::with_draw_target(
            Some(units as u64),
            if options.progress {
                ProgressDrawTarget::stderr()
            } else {
                ProgressDrawTarget::hidden()
            },
        );
        progress.set_style(
            ProgressStyle::with_template("{bar:30} {pos}/{len} {msg}")
                .expect("a valid template"),
        );
        let (mut reports, first_answers) = run::compare(
            &triangles,
            &sets,
            &methods,
            options.rounds.max(1),
            &progress,
            &mut || {},
        );
        let reference = first.build(&triangles);
        let checks = run::check_brute_force(
            &triangles,
            &sets,
            reference.tracer.as_ref(),
            // brute force uses our test: only the first's own one counts
            first.own_triangle_test().then_some(run::OWN_TEST_TOLERANCE),
            options.brute_force,
            &progress,
        );
        progress.finish_and_clear();
        for report in &mut reports {
            report.finish(&sets);
        }
        let report = BenchReport {
            mesh: options.mesh.display().to_string(),
            triangles: triangles.len(),
            threads: options.threads,
            rounds: options.rounds.max(1),
            sets: sets
                .iter()
                .zip(&checks)
                .map(|(set, &(checked, wrong))| SetInfo {
                    name: set.name.clone(),
                    rays: set.rays.len(),
                    question: set.question,
                    brute_force_checked: checked,
                    brute_force_disagreements: wrong,
                })
                .collect(),
            methods: reports,
            skipped,
        };
        Ok(BenchRun {
            report,
            answers: first_answers,
        })
    })
}
