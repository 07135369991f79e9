//! The appendix's measurement: every step of the fast path and every
//! peer built and traced on the 235 000-triangle bunny, on the rays
//! `raystep bench` generates (1024² camera rays, their shadow rays,
//! 2²⁰ incoherent rays), rounds taking turns; on one thread, then the
//! fastest steps and the peers on two.
use std::path::Path;

use ch08::{Builder, MeshBvh, NodePrecision};
use ch08_figures::bvh_measurements::compare_on;
use ch11::{FastBvh, Step};
use raystep_bench::{
    Method, MethodReport, RaySet, incoherent, primary, shadow,
};
use raystep_core::DVec3;

use crate::rows::StepRow;

/// The mesh: `../shared/meshes/bunny-235k.obj` beside the workspace.
pub const MESH: &str = "bunny-235k.obj";

/// Step 1: chapter 8's tree as the benchmark runs it.
pub const LECTURE: Method =
    Method::Ours(Builder::BinnedSah { bins: 16 }, NodePrecision::Single);

/// Each row's label: the step's number and name.
pub fn label(method: &Method) -> String {
    match method {
        Method::Fast(step) => {
            let number = match step {
                Step::Ordered => "2",
                Step::LeafLayout => "3",
                Step::SweepTree => "4",
                Step::RotatedTree => "4b",
                Step::Wide4Scalar => "5a",
                Step::Wide4 => "5b",
                Step::Wide8Scalar => "5c",
                Step::Wide8 => "5d",
                Step::Compressed8 => "5e",
                Step::Wide8Sweep => "5f",
                Step::Compressed8Sweep => "5g",
                Step::Wide8Triangles => "6a",
                Step::Compressed8Triangles => "6b",
                Step::Wide8Parallel => "7a",
                Step::Compressed8Parallel => "7b",
                Step::Wide8Leaf4 => "8a",
                Step::Compressed8Leaf4 => "8b",
                Step::Wide8AnyUnsorted => "9",
                Step::Wide8Pairs512 => "10",
                Step::Wide8ShortPath => "11",
                Step::Wide8BlockBuild => "12",
                Step::Wide8HugePages => "13",
            };
            format!("{number} {}", step.name())
        }
        m if *m == LECTURE => "1 lecture".to_string(),
        m => m.name(),
    }
}

/// The steps measured on two threads too: 7a and 7b (tracing, and the
/// build on the pool's threads), and the fastest on one thread, 8b, 9,
/// 11 and 13 (tracing; their build stays on one).
const THREADED: [Step; 6] = [
    Step::Wide8Parallel,
    Step::Compressed8Parallel,
    Step::Compressed8Leaf4,
    Step::Wide8AnyUnsorted,
    Step::Wide8ShortPath,
    Step::Wide8HugePages,
];

/// The mesh's triangles; an error names the file.
fn mesh() -> Result<Vec<[DVec3; 3]>, String> {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../../../shared/meshes")
        .join(MESH);
    raystep_bench::load_triangles(&path)
        .map_err(|e| format!("{e} (the meshes live in ../shared/meshes)"))
}

/// The steps [`measure_steps`] reports: a round on one thread, then on
/// two.
pub fn steps(repeats: usize) -> u64 {
    2 * repeats.max(1) as u64
}

/// Runs the comparison; an error if this raystep was built without the
/// peers, or if one of ours answers a ray unlike the lecture's tree.
pub fn measure_steps(
    repeats: usize, step: &mut dyn FnMut(),
) -> Result<Vec<StepRow>, String> {
    let peers = Method::peers(None);
    if peers.is_empty() {
        return Err("the appendix compares with obvhs, bvh and Embree: \
             run `cargo run --release --features embree -- measure \
             --chapter ch11`"
            .into());
    }
    let triangles = mesh()?;
    let bounds = ch09_figures::measurements::bounds(&triangles);
    let reference = MeshBvh::new(
        &triangles,
        &ch08::Bvh::build(
            &ch08::triangle_boxes(&triangles),
            Builder::BinnedSah { bins: 16 },
        ),
        NodePrecision::Double,
    );
    let primary = primary(&bounds, 1024);
    let shadow = shadow(&bounds, &primary, &reference);
    let sets = [primary, shadow, incoherent(&bounds, 1 << 20, 1)];
    let mut ours = vec![LECTURE];
    ours.extend(Step::ALL.map(Method::Fast));
    let mut rows = Vec::new();
    for threads in [1, 2] {
        let methods: Vec<Method> = if threads == 1 {
            ours.iter().chain(&peers).copied().collect()
        } else {
            let fast = THREADED.map(Method::Fast);
            [LECTURE]
                .iter()
                .chain(&fast)
                .chain(&peers)
                .copied()
                .collect()
        };
        let reports =
            compare_on(threads, &triangles, &sets, &methods, repeats, step)?;
        for (method, report) in methods.iter().zip(&reports) {
            rows.push(row(&triangles, method, report, &sets, threads)?);
        }
    }
    Ok(rows)
}

/// One method's row; an error if it is ours and answers any ray unlike
/// the lecture's tree.
fn row(
    triangles: &[[DVec3; 3]], method: &Method, report: &MethodReport,
    sets: &[RaySet], threads: usize,
) -> Result<StepRow, String> {
    let wrong: usize = report.sets.iter().map(|s| s.disagreements).sum();
    if method.is_ours() && wrong > 0 {
        return Err(format!(
            "{} answers {wrong} rays unlike the lecture's tree",
            method.name()
        ));
    }
    let node_bytes = match method {
        Method::Fast(step) => FastBvh::build(triangles, *step).nodes().1,
        m if m.is_ours() => 32,
        _ => 0,
    };
    let set = |k: usize| &report.sets[k];
    let nodes = |k: usize| set(k).nodes_per_ray.unwrap_or(0.0);
    // the peers' counts are not known (NaN): 0
    let tests = |k: usize| {
        let t = set(k).triangles_per_ray;
        if t.is_finite() { t } else { 0.0 }
    };
    debug_assert_eq!(sets.len(), 3);
    Ok(StepRow {
        method: label(method),
        kind: if method.is_ours() { "ours" } else { "peer" }.into(),
        threads: threads as u64,
        build_ms: report.build_ms,
        mb: report.bytes.unwrap_or(0) as f64 / 1e6,
        node_bytes: node_bytes as u64,
        primary_mrays: set(0).mrays_per_s,
        shadow_mrays: set(1).mrays_per_s,
        incoherent_mrays: set(2).mrays_per_s,
        primary_nodes: nodes(0),
        primary_tests: tests(0),
        incoherent_nodes: nodes(2),
        incoherent_tests: tests(2),
        wrong: wrong as u64,
    })
}
