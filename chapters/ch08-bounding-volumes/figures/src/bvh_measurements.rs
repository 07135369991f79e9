//! The data behind part 2's charts, measured by `raystep measure` on one
//! thread (times: medians of the rounds, the methods taking turns) and
//! counted (node visits, triangle tests, leaks: the same on every
//! machine). The meshes are the bunny (3 674 triangles) and its 235 136
//! triangle version in `../shared/meshes` beside the workspace.
use std::hint::black_box;
use std::path::{Path, PathBuf};

use ch07_figures::measurements::{ChartScene, chart_stages};
use ch08::{
    AGGLOMERATIVE_LIMIT, Aabb, Builder, Bvh, DVec3, MeshBruteForce,
    NodePrecision,
};
use raystep_bench::{
    Method, MethodReport, RaySet, compare, incoherent, on_threads_with_steps,
    primary, trace,
};
use raystep_render::timing::Timing;
use raystep_stability::{leak_surfaces, leaks, shared_edge_rays};
use raystep_world::World;

use crate::bvh_rows::{
    BRUTE, BVH, BuilderRow, PrecisionRow, RASTERIZE, RAYCAST_BRUTE,
    RAYCAST_BVH, ScalingRow, ZbufferRow,
};

/// The big bunny: `../shared/meshes/bunny-235k.obj`.
pub fn big_bunny_path() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../../../shared/meshes/bunny-235k.obj")
}

/// A mesh's triangles; an error names the file.
fn load(path: &Path) -> Result<Vec<[DVec3; 3]>, String> {
    raystep_bench::load_triangles(path)
        .map_err(|e| format!("{e} (the meshes live in ../shared/meshes)"))
}

/// Whether `builder` runs on `triangles`: the exact bottom-up builder
/// falls back to PLOC beyond [`AGGLOMERATIVE_LIMIT`] objects, so it is
/// charted on small meshes only.
fn runs_on(builder: Builder, triangles: usize) -> bool {
    builder != Builder::Agglomerative || triangles <= AGGLOMERATIVE_LIMIT
}

/// The hierarchy the other charts use: binned SAH, 16 bins.
const CHART_BUILDER: Builder = Builder::BinnedSah { bins: 16 };

/// The rays of the builder and precision charts: a 256 × 256 camera and
/// 65 536 incoherent rays (seed 1).
fn ray_sets(triangles: &[[DVec3; 3]]) -> Vec<RaySet> {
    let bounds = Aabb::around(triangles.iter().flatten().copied());
    vec![primary(&bounds, 256), incoherent(&bounds, 1 << 16, 1)]
}

/// Nanoseconds per ray of a report's set `k`.
pub fn ns(report: &MethodReport, k: usize) -> f64 {
    1e3 / report.sets[k].mrays_per_s
}

/// `methods` built on `triangles` and traced over `sets` on `threads`
/// threads, rounds taking turns, `repeats` rounds (at least one); `step`
/// is called after each round. The reports come finished, one per method.
pub fn compare_on(
    threads: usize, triangles: &[[DVec3; 3]], sets: &[RaySet],
    methods: &[Method], repeats: usize, step: &mut dyn FnMut(),
) -> Result<Vec<MethodReport>, String> {
    let (mut reports, _) = on_threads_with_steps(
        threads,
        |tick| {
            compare(
                triangles,
                sets,
                methods,
                repeats.max(1),
                &indicatif::ProgressBar::hidden(),
                tick,
            )
        },
        step,
    )
    .map_err(|e| e.to_string())?;
    for report in &mut reports {
        report.finish(sets);
    }
    Ok(reports)
}

/// The steps [`measure_builders`] reports: one per round per mesh.
pub fn builder_steps(repeats: usize) -> u64 {
    2 * repeats.max(1) as u64
}

/// Every builder on both bunnies: build time, tree, trace times and work
/// per ray, f32 nodes, one thread.
pub fn measure_builders(
    repeats: usize, step: &mut dyn FnMut(),
) -> Result<Vec<BuilderRow>, String> {
    let meshes = [
        ("bunny", load(&crate::measurements::bunny_path())?),
        ("bunny-235k", load(&big_bunny_path())?),
    ];
    let mut rows = Vec::new();
    for (mesh, triangles) in &meshes {
        let sets = ray_sets(triangles);
        let methods: Vec<Method> = Builder::ALL
            .into_iter()
            .filter(|b| runs_on(*b, triangles.len()))
            .map(|b| Method::Ours(b, NodePrecision::Single))
            .collect();
        let reports = compare_on(1, triangles, &sets, &methods, repeats, step)?;
        for (method, report) in methods.iter().zip(&reports) {
            let Method::Ours(builder, _) = method else {
                continue;
            };
            let Some(tree) = report.tree else {
                continue;
            };
            let incoherent = &report.sets[1];
            rows.push(BuilderRow {
                mesh: mesh.to_string(),
                triangles: triangles.len() as u64,
                // no commas in a CSV field
                builder: builder.name().replace(", ", " "),
                build_ms: report.build_ms,
                sah_cost: tree.sah_cost,
                nodes: tree.nodes as u64,
                depth: tree.depth as u64,
                balance: tree.balance,
                primary_ns: ns(report, 0),
                incoherent_ns: ns(report, 1),
                incoherent_nodes: incoherent.nodes_per_ray.unwrap_or(0.0),
                incoherent_triangles: incoherent.triangles_per_ray,
            });
        }
    }
    Ok(rows)
}

/// Each triangle cut into four at its edges' midpoints: the same surface,
/// four times the triangles.
pub fn split_in_four(triangles: &[[DVec3; 3]]) -> Vec<[DVec3; 3]> {
    let mut out = Vec::with_capacity(4 * triangles.len());
    for &[a, b, c] in triangles {
        let (ab, bc, ca) = ((a + b) / 2.0, (b + c) / 2.0, (c + a) / 2.0);
        out.extend([[a, ab, ca], [b, bc, ab], [c, ca, bc], [ab, bc, ca]]);
    }
    out
}

/// The bunny's sizes on the scaling chart: 3 674 · 4ⁿ, n = 0 … 3.
pub const SCALING_LEVELS: usize = 4;
/// The rays of the scaling chart: a 128 × 128 camera; brute force traces
/// every 16th of them.
const SCALING_SIZE: u32 = 128;
const BRUTE_EVERY: usize = 16;

/// The steps [`measure_scaling`] reports.
pub fn scaling_steps(repeats: usize) -> u64 {
    (SCALING_LEVELS * repeats.max(1)) as u64
}

/// Brute force beside the hierarchy on the bunny split 0 to 3 times:
/// time and work per camera ray.
pub fn measure_scaling(
    repeats: usize, step: &mut dyn FnMut(),
) -> Result<Vec<ScalingRow>, String> {
    let mut triangles = load(&crate::measurements::bunny_path())?;
    let mut rows = Vec::new();
    for level in 0..SCALING_LEVELS {
        if level > 0 {
            triangles = split_in_four(&triangles);
        }
        let bounds = Aabb::around(triangles.iter().flatten().copied());
        let camera = primary(&bounds, SCALING_SIZE);
        let sample = RaySet {
            rays: camera.rays.iter().step_by(BRUTE_EVERY).copied().collect(),
            ..camera.clone()
        };
        let built = Method::Ours(CHART_BUILDER, NodePrecision::Single)
            .build(&triangles);
        let brute = MeshBruteForce(&triangles);
        let rows_here = on_threads_with_steps(
            1,
            |tick| {
                let mut fast = || {
                    black_box(trace(built.tracer.as_ref(), &camera));
                };
                let mut slow = || {
                    black_box(trace(&brute, &sample));
                };
                let timing = Timing {
                    rounds: repeats.max(1),
                    batch: 1,
                };
                let ms = timing.median_ms(&mut [&mut fast, &mut slow], tick);
                let (_, fast_counts) = trace(built.tracer.as_ref(), &camera);
                let (_, slow_counts) = trace(&brute, &sample);
                let row = |method: &str, set: &RaySet, ms: f64, nodes, tris| {
                    let rays = set.rays.len() as f64;
                    ScalingRow {
                        triangles: triangles.len() as u64,
                        method: method.to_string(),
                        rays: set.rays.len() as u64,
                        ns_per_ray: ms * 1e6 / rays,
                        nodes_per_ray: nodes as f64 / rays,
                        triangles_per_ray: tris as f64 / rays,
                    }
                };
                [
                    row(
                        BRUTE,
                        &sample,
                        ms[1],
                        slow_counts.nodes,
                        slow_counts.triangles,
                    ),
                    row(
                        BVH,
                        &camera,
                        ms[0],
                        fast_counts.nodes,
                        fast_counts.triangles,
                    ),
                ]
            },
            step,
        )
        .map_err(|e| e.to_string())?;
        rows.extend(rows_here);
    }
    Ok(rows)
}

/// The steps [`measure_precision`] reports.
pub fn precision_steps(repeats: usize) -> u64 {
    repeats.max(1) as u64
}

/// Each node precision on the big bunny (speed, one thread), and the
/// rays aimed at the shared edges of the small bunny, the moved bunny and
/// a tiled floor that leak through it.
pub fn measure_precision(
    repeats: usize, step: &mut dyn FnMut(),
) -> Result<Vec<PrecisionRow>, String> {
    let small = load(&crate::measurements::bunny_path())?;
    let big = load(&big_bunny_path())?;
    // Counted: the leaks, per surface and precision.
    let surfaces = leak_surfaces(&small);
    let mut edge_rays = 0u64;
    let mut leaked = vec![[0u64; 3]; NodePrecision::ALL.len()];
    for (s, surface) in surfaces.iter().enumerate() {
        let rays = shared_edge_rays(&surface.triangles, surface.points);
        edge_rays += rays.len() as u64;
        let boxes = ch08::triangle_boxes(&surface.triangles);
        let tree = Bvh::build(&boxes, CHART_BUILDER);
        for (p, &precision) in NodePrecision::ALL.iter().enumerate() {
            let bvh = ch08::MeshBvh::new(&surface.triangles, &tree, precision);
            leaked[p][s] = leaks(&bvh, &rays) as u64;
        }
    }
    // Measured: the speed on the big bunny.
    let sets = ray_sets(&big);
    let methods: Vec<Method> = NodePrecision::ALL
        .iter()
        .map(|&p| Method::Ours(CHART_BUILDER, p))
        .collect();
    let reports = compare_on(1, &big, &sets, &methods, repeats, step)?;
    Ok(NodePrecision::ALL
        .iter()
        .zip(&reports)
        .zip(leaked)
        .map(|((precision, report), leaks)| {
            let [leaks_bunny, leaks_moved, leaks_floor] = leaks;
            PrecisionRow {
                precision: precision.name().to_string(),
                primary_ns: ns(report, 0),
                incoherent_ns: ns(report, 1),
                edge_rays,
                leaks_bunny,
                leaks_moved,
                leaks_floor,
            }
        })
        .collect())
}

/// Chapter 7's stages on which brute-force ray casting is still timed:
/// the larger balls take seconds to minutes a render (chapter 7's chart
/// has them).
fn brute_too_slow(scene: ChartScene) -> bool {
    matches!(scene, ChartScene::Ball(n) if n >= 5)
}

/// The steps [`measure_zbuffer`] reports.
pub fn zbuffer_steps(repeats: usize) -> u64 {
    ch07_figures::measurements::chart_scenes()
        .into_iter()
        .map(|s| s.timing(repeats.max(1)).rounds.max(1) as u64)
        .sum()
}

/// Chapter 7's stages drawn three ways on one thread: the z-buffer
/// rasterizer, ray casting over every object, and ray casting through the
/// hierarchy (its build timed apart).
pub fn measure_zbuffer(
    repeats: usize, step: &mut dyn FnMut(),
) -> Result<Vec<ZbufferRow>, String> {
    let stages = chart_stages(&crate::measurements::bunny_path())?;
    let mut rows = Vec::new();
    for (scene, stage) in &stages {
        let timing = scene.timing(repeats.max(1));
        let start = std::time::Instant::now();
        let bvh = Bvh::for_objects(&stage.world.objects, CHART_BUILDER);
        let build_ms = start.elapsed().as_secs_f64() * 1e3;
        let fast = ch07::Stage {
            world: World::clone(&stage.world)
                .with_accelerator(std::sync::Arc::new(bvh)),
            triangles: stage.triangles.clone(),
        };
        let ms = on_threads_with_steps(
            1,
            |tick| {
                let mut raster = || {
                    black_box(ch07::rasterize(stage));
                };
                let mut cast = || {
                    black_box(ch07::raycast(stage));
                };
                let mut cast_bvh = || {
                    black_box(ch07::raycast(&fast));
                };
                let mut jobs: Vec<&mut dyn FnMut()> =
                    vec![&mut raster, &mut cast_bvh];
                if !brute_too_slow(*scene) {
                    jobs.push(&mut cast);
                }
                timing.median_ms(&mut jobs, tick)
            },
            step,
        )
        .map_err(|e| e.to_string())?;
        let row = |method: &str, build_ms, millis| ZbufferRow {
            scene: scene.name(),
            triangles: stage.triangles.len() as u64,
            method: method.to_string(),
            build_ms,
            millis,
        };
        rows.push(row(RASTERIZE, 0.0, ms[0]));
        if let Some(&brute) = ms.get(2) {
            rows.push(row(RAYCAST_BRUTE, 0.0, brute));
        }
        rows.push(row(RAYCAST_BVH, build_ms, ms[1]));
    }
    Ok(rows)
}
