//! The data behind chapter 9's charts, measured by `raystep measure` on
//! one thread (times: medians of the rounds, the methods taking turns)
//! and counted (cells visited, triangle tests, repeated tests,
//! disagreements: the same on every machine). The bunny comes from
//! `../shared/meshes` beside the workspace; the other scenes are
//! generated from a seed.
use std::path::{Path, PathBuf};

use ch08::{Builder, NodePrecision, TraceCounts};
use ch08_figures::bvh_measurements::{compare_on, ns};
use ch09::{
    Aabb, DVec3, Fill, Grid, Interval, MeshGrid, Resolution, rule_cells,
};
use raystep_bench::{
    GridSpec, Method, MethodReport, RaySet, SCENE_SEED, incoherent, on_threads,
    primary, stadium, uniform_triangles,
};
use raystep_core::{Camera, Ray};
use raystep_stability::{adversarial_rays, disagreements, stability_scenes};

use crate::rows::{
    BRUTE, BVH, CompareRow, GRID, MailboxRow, ResolutionRow, StabilityRow,
};

/// The bunny: `../shared/meshes/bunny.obj`.
pub fn bunny_path() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../../../shared/meshes/bunny.obj")
}

/// The bunny's triangles; an error names the file.
pub fn bunny() -> Result<Vec<[DVec3; 3]>, String> {
    raystep_bench::load_triangles(&bunny_path())
        .map_err(|e| format!("{e} (the meshes live in ../shared/meshes)"))
}

/// A scene of the charts: its name, triangles and camera rays.
pub struct ChartScene {
    /// `uniform-10000`, `bunny`, `stadium`.
    pub name: String,
    /// Its triangles.
    pub triangles: Vec<[DVec3; 3]>,
    /// Its camera rays: fitted to the scene, or for the stadium a camera
    /// close to the bunny (the stadium fills the view behind it).
    pub primary: RaySet,
}

/// The camera rays' image size.
pub const SIZE: u32 = 256;
/// The incoherent rays: how many, and their seed.
pub const INCOHERENT: usize = 1 << 16;

/// The camera close to the bunny in its stadium, looking at it slightly
/// from above: the walls and the floor fill the view behind it.
pub fn stadium_camera(size: u32) -> RaySet {
    let camera = Camera::look_at(
        DVec3::new(0.4, 0.6, 2.4),
        DVec3::new(0.0, 0.45, 0.0),
        DVec3::Y,
        40.0,
        1.0,
    );
    let mut rays = Vec::with_capacity((size * size) as usize);
    for row in 0..size {
        for column in 0..size {
            let ray = camera.pixel_ray(column, row, size, size);
            rays.push(ch08::Ray32::rounded(&ray));
        }
    }
    RaySet {
        name: "primary".into(),
        question: raystep_bench::Question::Closest,
        rays,
    }
}

/// A scene of the charts: camera rays fitted to it (the stadium's: close
/// to the bunny).
pub fn scene(name: &str, triangles: Vec<[DVec3; 3]>) -> ChartScene {
    let primary = if name == "stadium" {
        stadium_camera(SIZE)
    } else {
        primary(&bounds(&triangles), SIZE)
    };
    ChartScene {
        name: name.to_string(),
        triangles,
        primary,
    }
}

/// The triangles' box.
pub fn bounds(triangles: &[[DVec3; 3]]) -> Aabb {
    Aabb::around(triangles.iter().flatten().copied())
}

/// The three scene families: small triangles spread evenly (10⁴), the
/// bunny, the bunny in a stadium.
pub fn families() -> Result<Vec<ChartScene>, String> {
    let bunny = bunny()?;
    Ok(vec![
        scene("uniform-10000", uniform_triangles(10_000, SCENE_SEED)),
        scene("bunny", bunny.clone()),
        scene("stadium", stadium(&bunny)),
    ])
}

/// Runs `methods` on `scene`'s sets on one thread, rounds taking turns;
/// an error if any method answers a ray unlike the first.
pub fn run(
    scene: &ChartScene, sets: &[RaySet], methods: &[Method], repeats: usize,
    step: &mut dyn FnMut(),
) -> Result<Vec<MethodReport>, String> {
    let reports =
        compare_on(1, &scene.triangles, sets, methods, repeats, step)?;
    for report in &reports {
        // every method answers every ray as the first does
        for set in &report.sets {
            if set.disagreements > 0 {
                return Err(format!(
                    "{}: {} disagrees with {} on {} {} rays",
                    scene.name,
                    report.method,
                    methods[0].name(),
                    set.disagreements,
                    set.set
                ));
            }
        }
    }
    Ok(reports)
}

/// Nodes (or cells) and triangle tests per ray of set `k`.
pub fn work(report: &MethodReport, k: usize) -> f64 {
    let set = &report.sets[k];
    set.nodes_per_ray.unwrap_or(0.0) + set.triangles_per_ray
}

/// Cells along the longest axis in the sweep (the rule's choice is added).
pub const SWEEP: [usize; 8] = [2, 4, 8, 16, 32, 64, 128, 256];

/// The steps [`measure_resolution`] reports: one per round per scene.
pub fn resolution_steps(repeats: usize) -> u64 {
    3 * repeats.max(1) as u64
}

/// The resolution sweep on each family: build, memory and camera rays.
pub fn measure_resolution(
    repeats: usize, step: &mut dyn FnMut(),
) -> Result<Vec<ResolutionRow>, String> {
    let mut rows = Vec::new();
    for scene in families()? {
        let rule = rule_cells(scene.triangles.len());
        let mut sweep: Vec<usize> = SWEEP.to_vec();
        if !sweep.contains(&rule) {
            sweep.push(rule);
            sweep.sort_unstable();
        }
        let methods: Vec<Method> = sweep
            .iter()
            .map(|&n| {
                Method::Grid(GridSpec {
                    fill: Fill::Exact,
                    cells: Some(n),
                    mailbox: true,
                })
            })
            .collect();
        let sets = [scene.primary.clone()];
        let reports = run(&scene, &sets, &methods, repeats, step)?;
        for (&n, report) in sweep.iter().zip(&reports) {
            let b = bounds(&scene.triangles);
            let cells = ch09::cells_for(&b, n);
            let set = &report.sets[0];
            rows.push(ResolutionRow {
                scene: scene.name.clone(),
                triangles: scene.triangles.len() as u64,
                longest: n as u64,
                rule: n == rule,
                cells: cells.iter().product::<usize>() as u64,
                build_ms: report.build_ms,
                bytes: report.bytes.unwrap_or(0) as u64,
                primary_ns: ns(report, 0),
                primary_cells: set.nodes_per_ray.unwrap_or(0.0),
                primary_tests: set.triangles_per_ray,
            });
        }
    }
    Ok(rows)
}

/// The sizes of the uniform family on the comparison chart.
pub const UNIFORM_SIZES: [usize; 3] = [1_000, 10_000, 100_000];

/// Brute force traces at most this many triangle tests per ray set.
const BRUTE_BUDGET: usize = 20_000_000;

/// The steps [`measure_compare`] reports.
pub fn compare_steps(repeats: usize) -> u64 {
    (UNIFORM_SIZES.len() + 2) as u64 * (repeats.max(1) as u64 + 1)
}

/// Brute force, the BVH (16-bin SAH, f32 nodes) and the grid (the rule,
/// exact fill) on the uniform family at three sizes, the bunny and the
/// bunny in a stadium: build, trace, memory.
pub fn measure_compare(
    repeats: usize, step: &mut dyn FnMut(),
) -> Result<Vec<CompareRow>, String> {
    let bunny = bunny()?;
    let mut scenes: Vec<ChartScene> = UNIFORM_SIZES
        .iter()
        .map(|&n| {
            scene(&format!("uniform-{n}"), uniform_triangles(n, SCENE_SEED))
        })
        .collect();
    scenes.push(scene("bunny", bunny.clone()));
    scenes.push(scene("stadium", stadium(&bunny)));
    let methods = [
        Method::Ours(Builder::BinnedSah { bins: 16 }, NodePrecision::Single),
        Method::Grid(GridSpec::rule(Fill::Exact)),
    ];
    let mut rows = Vec::new();
    for scene in &scenes {
        let sets = [
            scene.primary.clone(),
            incoherent(&bounds(&scene.triangles), INCOHERENT, 1),
        ];
        let reports = run(scene, &sets, &methods, repeats, step)?;
        for (name, report) in [BVH, GRID].iter().zip(&reports) {
            rows.push(CompareRow {
                scene: scene.name.clone(),
                triangles: scene.triangles.len() as u64,
                method: name.to_string(),
                build_ms: report.build_ms,
                bytes: report.bytes.unwrap_or(0) as u64,
                primary_ns: ns(report, 0),
                incoherent_ns: ns(report, 1),
                primary_work: work(report, 0),
                incoherent_work: work(report, 1),
            });
        }
        // brute force on an evenly spread sample of each set
        let every = (scene.triangles.len() * sets[0].rays.len())
            .div_ceil(BRUTE_BUDGET)
            .max(1);
        let sample: Vec<RaySet> = sets
            .iter()
            .map(|set| RaySet {
                rays: set.rays.iter().step_by(every).copied().collect(),
                ..set.clone()
            })
            .collect();
        let brute = on_threads(1, || {
            let tracer = ch08::MeshBruteForce(&scene.triangles);
            sample
                .iter()
                .map(|set| {
                    let timing = raystep_render::timing::Timing {
                        rounds: repeats.max(1),
                        batch: 1,
                    };
                    let ms = timing.median_ms(
                        &mut [&mut || {
                            std::hint::black_box(raystep_bench::trace(
                                &tracer, set,
                            ));
                        }],
                        || {},
                    )[0];
                    ms * 1e6 / set.rays.len() as f64
                })
                .collect::<Vec<f64>>()
        })
        .map_err(|e| e.to_string())?;
        step();
        let n = scene.triangles.len();
        rows.push(CompareRow {
            scene: scene.name.clone(),
            triangles: n as u64,
            method: BRUTE.to_string(),
            build_ms: 0.0,
            bytes: (n * size_of::<[DVec3; 3]>()) as u64,
            primary_ns: brute[0],
            incoherent_ns: brute[1],
            primary_work: n as f64,
            incoherent_work: n as f64,
        });
    }
    Ok(rows)
}

/// The steps [`measure_mailbox`] reports.
pub fn mailbox_steps(repeats: usize) -> u64 {
    3 * repeats.max(1) as u64
}

/// Each fill with the mailbox on and off, on each family's incoherent
/// rays: tests, repeated tests (counted) and time (measured).
pub fn measure_mailbox(
    repeats: usize, step: &mut dyn FnMut(),
) -> Result<Vec<MailboxRow>, String> {
    let mut rows = Vec::new();
    for scene in families()? {
        let set = incoherent(&bounds(&scene.triangles), INCOHERENT, 1);
        let specs: Vec<GridSpec> = [Fill::Boxes, Fill::Exact]
            .iter()
            .flat_map(|&fill| {
                [false, true].map(|mailbox| GridSpec {
                    fill,
                    cells: None,
                    mailbox,
                })
            })
            .collect();
        let methods: Vec<Method> =
            specs.iter().map(|&s| Method::Grid(s)).collect();
        let reports =
            run(&scene, std::slice::from_ref(&set), &methods, repeats, step)?;
        // counted: every test, and the repeats, ray by ray
        let counted: Vec<(f64, f64)> = specs
            .iter()
            .map(|spec| {
                let mut grid = MeshGrid::new(
                    &scene.triangles,
                    Resolution::Rule,
                    spec.fill,
                );
                grid.grid.mailboxing = spec.mailbox;
                let (mut tests, mut repeats) = (0usize, 0usize);
                let mut counts = TraceCounts::default();
                let mut seen = Vec::new();
                for ray in &set.rays {
                    seen.clear();
                    grid.closest_recorded(
                        ray,
                        Interval::FORWARD,
                        &mut counts,
                        |k| seen.push(k),
                    );
                    let asked = seen.len();
                    seen.sort_unstable();
                    seen.dedup();
                    tests += asked;
                    repeats += asked - seen.len();
                }
                let n = set.rays.len() as f64;
                (tests as f64 / n, repeats as f64 / n)
            })
            .collect();
        for fill in [Fill::Boxes, Fill::Exact] {
            let at = |mailbox: bool| {
                specs
                    .iter()
                    .position(|s| s.fill == fill && s.mailbox == mailbox)
                    .expect("measured")
            };
            let (off, on) = (at(false), at(true));
            let entries =
                Grid::for_triangles(&scene.triangles, Resolution::Rule, fill)
                    .stats()
                    .entries;
            rows.push(MailboxRow {
                scene: scene.name.clone(),
                fill: fill.name().to_string(),
                entries: entries as u64,
                tests_off: counted[off].0,
                repeats_off: counted[off].1,
                tests_on: counted[on].0,
                repeats_on: counted[on].1,
                ns_off: ns(&reports[off], 0),
                ns_on: ns(&reports[on], 0),
            });
        }
    }
    Ok(rows)
}

/// Rays of each kind per scene of the stability catalogue: 5 scenes × 9
/// kinds × 25 000 = 1 125 000 rays.
pub const STABILITY_RAYS: usize = 25_000;

/// The steps [`measure_stability`] reports: one per scene.
pub fn stability_steps(_repeats: usize) -> u64 {
    5
}

/// The stability catalogue over a million rays (counted, not timed; on
/// every core): the grid against brute force, mailbox on and off.
pub fn measure_stability(
    _repeats: usize, step: &mut dyn FnMut(),
) -> Result<Vec<StabilityRow>, String> {
    let bunny = bunny()?;
    let threads = std::thread::available_parallelism().map_or(1, |n| n.get());
    let mut rows = Vec::new();
    for scene in stability_scenes(&bunny) {
        let mut grid = Grid::for_objects(&scene.objects, scene.resolution);
        for case in adversarial_rays(&grid.lattice, STABILITY_RAYS, 7) {
            let mut wrong = [0u64; 2];
            for (k, mailboxing) in [true, false].into_iter().enumerate() {
                grid.mailboxing = mailboxing;
                wrong[k] = on_threads(threads, || {
                    count_parallel(&grid, &scene.objects, &case.rays)
                })
                .map_err(|e| e.to_string())?;
            }
            rows.push(StabilityRow {
                scene: scene.name.to_string(),
                case: case.name.to_string(),
                rays: case.rays.len() as u64,
                wrong_mailbox: wrong[0],
                wrong_plain: wrong[1],
            });
        }
        step();
    }
    Ok(rows)
}

/// [`disagreements`] over `rays` in chunks on the current pool.
fn count_parallel(grid: &Grid, objects: &[ch09::Object], rays: &[Ray]) -> u64 {
    use rayon::prelude::*;
    rays.par_chunks(1024)
        .map(|chunk| disagreements(grid, objects, chunk) as u64)
        .sum()
}
