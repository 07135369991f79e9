//! The data behind chapter 10's charts and tables, measured by `raystep
//! measure` on one thread (times: medians of the rounds, the methods
//! taking turns) and counted (nodes, tests, disagreements: the same on
//! every machine). The bunnies come from `../shared/meshes` beside the
//! workspace; the other scenes are the chapters' scene files or are
//! generated from a seed.
use std::path::{Path, PathBuf};

use ch08::{BoundingSphere, Builder};
use ch08_figures::bvh_measurements::ns;
use ch09_figures::measurements::{
    INCOHERENT, bounds, bunny, run, scene, stadium_camera,
};
use ch10::{
    Aabb, Accelerator, Clip, DVec3, Interval, KdBuilder, KdCosts, KdTree,
    Object, Ray, Structure, choose,
};
use raystep_bench::{
    KdSpec, Method, SCENE_SEED, incoherent, on_threads, on_threads_with_steps,
    stadium, triangle_objects, uniform_triangles,
};
use raystep_figure::as_jobs;
use raystep_render::timing::Timing;
use raystep_stability::{kd_disagreements, kd_rays, kd_scenes};

use crate::rows::{BuildRow, StabilityRow, StructureRow, VariantRow};

/// A mesh in `../shared/meshes`; an error names the file.
fn mesh(name: &str) -> Result<Vec<[DVec3; 3]>, String> {
    let path: PathBuf = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../../../shared/meshes")
        .join(name);
    raystep_bench::load_triangles(&path)
        .map_err(|e| format!("{e} (the meshes live in ../shared/meshes)"))
}

// ---------------------------------------------------------------------
// Build time against N: sorting at every node, events sorted once.
// ---------------------------------------------------------------------

/// The sizes of the build chart: small uniform triangles.
pub const BUILD_SIZES: [usize; 6] =
    [1_000, 3_000, 10_000, 30_000, 100_000, 300_000];

/// The builders of the build chart, with their names in the CSV.
const BUILDERS: [(&str, KdBuilder, Clip); 4] = [
    ("median", KdBuilder::Median, Clip::Boxes),
    ("SAH sorting", KdBuilder::SahSorting, Clip::Boxes),
    ("SAH events", KdBuilder::SahEvents, Clip::Boxes),
    ("SAH events perfect", KdBuilder::SahEvents, Clip::Triangles),
];

/// The steps [`measure_build`] reports.
pub fn build_steps(repeats: usize) -> u64 {
    (BUILD_SIZES.len() * (repeats.max(1) + 1)) as u64
}

/// Every builder at every size: milliseconds (medians, builders taking
/// turns) and the trees they make.
pub fn measure_build(
    repeats: usize, step: &mut dyn FnMut(),
) -> Result<Vec<BuildRow>, String> {
    let mut rows = Vec::new();
    for n in BUILD_SIZES {
        let triangles = uniform_triangles(n, SCENE_SEED);
        let costs = KdCosts::CHOSEN;
        let mut jobs: Vec<Box<dyn FnMut()>> = BUILDERS
            .iter()
            .map(|&(_, builder, clip)| {
                let triangles = &triangles;
                Box::new(move || {
                    std::hint::black_box(KdTree::for_triangles(
                        triangles, builder, costs, clip,
                    ));
                }) as Box<dyn FnMut()>
            })
            .collect();
        let ms = Timing {
            rounds: repeats.max(1),
            batch: 1,
        }
        .median_ms(&mut as_jobs(&mut jobs), &mut *step);
        step();
        for (&(name, builder, clip), ms) in BUILDERS.iter().zip(ms) {
            let s = KdTree::for_triangles(&triangles, builder, costs, clip)
                .stats(&costs);
            rows.push(BuildRow {
                builder: name.to_string(),
                triangles: n as u64,
                build_ms: ms,
                nodes: s.nodes as u64,
                entries: s.entries as u64,
                sah_cost: s.sah_cost,
            });
        }
    }
    Ok(rows)
}

// ---------------------------------------------------------------------
// The tree's variants on the benchmark's rays.
// ---------------------------------------------------------------------

/// The variants: perfect splits, pbrt's costs, pbrt's depth rule, the
/// median tree, beside the chapter's tree (SAH, events, Wald and
/// Havran's costs, depth 8 + 2·log₂ N, boxes).
fn variants() -> [(&'static str, KdSpec); 5] {
    let sah = KdSpec::sah(Clip::Boxes);
    let chosen = KdCosts::CHOSEN;
    [
        ("SAH W&H boxes", sah),
        ("SAH W&H perfect", KdSpec::sah(Clip::Triangles)),
        (
            "SAH pbrt costs",
            KdSpec {
                costs: KdCosts {
                    depth_factor: chosen.depth_factor,
                    ..KdCosts::PBRT_V3
                },
                ..sah
            },
        ),
        (
            "SAH W&H depth 1.3",
            KdSpec {
                costs: KdCosts {
                    depth_factor: KdCosts::PBRT_V3.depth_factor,
                    ..chosen
                },
                ..sah
            },
        ),
        (
            "median",
            KdSpec {
                builder: KdBuilder::Median,
                ..sah
            },
        ),
    ]
}

/// The steps [`measure_variants`] reports.
pub fn variants_steps(repeats: usize) -> u64 {
    3 * (repeats.max(1) as u64 + 1)
}

/// Each variant on the bunny, the big bunny and 10⁴ small triangles:
/// camera and incoherent rays, through the benchmark (chapter 8's
/// watertight test, single-precision rays; every variant must answer
/// every ray as the first does).
pub fn measure_variants(
    repeats: usize, step: &mut dyn FnMut(),
) -> Result<Vec<VariantRow>, String> {
    let scenes = [
        scene("bunny", bunny()?),
        scene("bunny-235k", mesh("bunny-235k.obj")?),
        scene("uniform-10000", uniform_triangles(10_000, SCENE_SEED)),
    ];
    let variants = variants();
    let methods: Vec<Method> =
        variants.iter().map(|(_, spec)| Method::Kd(*spec)).collect();
    let mut rows = Vec::new();
    for scene in &scenes {
        let sets = [
            scene.primary.clone(),
            incoherent(&bounds(&scene.triangles), INCOHERENT, 1),
        ];
        let reports = run(scene, &sets, &methods, repeats, step)?;
        for ((name, _), report) in variants.iter().zip(&reports) {
            let (p, i) = (&report.sets[0], &report.sets[1]);
            rows.push(VariantRow {
                scene: scene.name.clone(),
                variant: name.to_string(),
                build_ms: report.build_ms,
                bytes: report.bytes.unwrap_or(0) as u64,
                primary_ns: ns(report, 0),
                incoherent_ns: ns(report, 1),
                primary_nodes: p.nodes_per_ray.unwrap_or(0.0),
                primary_tests: p.triangles_per_ray,
                incoherent_nodes: i.nodes_per_ray.unwrap_or(0.0),
                incoherent_tests: i.triangles_per_ray,
            });
        }
    }
    Ok(rows)
}

// ---------------------------------------------------------------------
// Which structure a scene needs.
// ---------------------------------------------------------------------

/// A scene family of the comparison: objects and two sets of rays.
pub struct Family {
    /// `handful`, `primitives`, `spheres-1000`, `uniform-10000`, `bunny`,
    /// `stadium`, `bunny-235k`.
    pub name: &'static str,
    /// Its objects.
    pub objects: Vec<Object>,
    /// Camera rays fitted to it (the stadium's: close to the bunny).
    pub primary: Vec<Ray>,
    /// Rays from all around at random points of its box.
    pub incoherent: Vec<Ray>,
}

/// Camera rays a side and incoherent rays of the comparison.
const FAMILY_SIZE: u32 = 64;
const FAMILY_INCOHERENT: usize = 4096;

/// A scene file of the chapters as objects (chapter 8's shapes).
fn scene_file(path: &str) -> Result<Vec<Object>, String> {
    let file = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../..")
        .join(path);
    let scene = raystep_scene::load(&file).map_err(|e| e.to_string())?;
    scene
        .objects
        .iter()
        .map(|o| {
            Ok(Object {
                shape: ch08::shape(&o.shape)
                    .map_err(|e| format!("{path}: {e}"))?,
                material: 0,
            })
        })
        .collect()
}

fn family(name: &'static str, objects: Vec<Object>) -> Family {
    let b = objects
        .iter()
        .map(|o| o.shape.bounds())
        .filter(|b| !b.is_empty() && b.min.is_finite() && b.max.is_finite())
        .fold(Aabb::EMPTY, Aabb::union);
    let primary = if name == "stadium" {
        stadium_camera(FAMILY_SIZE)
            .rays
            .iter()
            .map(|r| r.to_ray())
            .collect()
    } else {
        raystep_bench::camera_rays(BoundingSphere::around_box(&b), FAMILY_SIZE)
    };
    Family {
        name,
        incoherent: raystep_bench::incoherent_rays(b, FAMILY_INCOHERENT, 1),
        primary,
        objects,
    }
}

/// The comparison's scene families, fewest objects first.
pub fn families() -> Result<Vec<Family>, String> {
    let bunny = bunny()?;
    Ok(vec![
        family(
            "handful",
            scene_file("chapters/ch03-illumination/scenes/spheres.toml")?,
        ),
        family(
            "primitives",
            scene_file(
                "chapters/ch08-bounding-volumes/scenes/primitives.toml",
            )?,
        ),
        family(
            "spheres-1000",
            scene_file("chapters/ch09-grids/scenes/uniform-spheres.toml")?,
        ),
        family(
            "uniform-10000",
            triangle_objects(&uniform_triangles(10_000, SCENE_SEED)),
        ),
        family("bunny", triangle_objects(&bunny)),
        family("stadium", triangle_objects(&stadium(&bunny))),
        family("bunny-235k", triangle_objects(&mesh("bunny-235k.obj")?)),
    ])
}

/// The structures of the comparison, in the table's order.
pub const STRUCTURES: [Structure; 4] = [
    Structure::Brute,
    Structure::Bvh,
    Structure::Grid,
    Structure::KdTree,
];

/// Brute force traces at most this many object tests per ray set.
const BRUTE_BUDGET: usize = 20_000_000;

/// The steps [`measure_structures`] reports.
pub fn structures_steps(_repeats: usize) -> u64 {
    7
}

/// Bytes of a built structure (not the objects).
fn structure_bytes(structure: Structure, objects: &[Object]) -> usize {
    match structure {
        Structure::Brute => 0,
        Structure::Bvh => {
            let bvh = ch08::Bvh::for_objects(
                objects,
                Builder::BinnedSah { bins: 16 },
            );
            bvh.nodes.len() * size_of::<ch08::BvhNode>()
                + (bvh.order.len() + bvh.unbounded.len()) * size_of::<u32>()
        }
        Structure::Grid => {
            ch09::Grid::for_objects(objects, ch09::Resolution::Rule)
                .stats()
                .bytes
        }
        Structure::KdTree => {
            KdTree::for_objects(objects, KdBuilder::SahEvents, KdCosts::CHOSEN)
                .bytes()
        }
    }
}

/// Closest hits of every ray, for timing.
fn trace(
    accelerator: &dyn Accelerator, objects: &[Object], rays: &[Ray],
) -> usize {
    rays.iter()
        .filter(|ray| {
            accelerator
                .closest_hit(objects, ray, Interval::FORWARD)
                .is_some()
        })
        .count()
}

/// Brute force, the BVH, the grid and the kd-tree on each family, on the
/// tracers' own path (objects, double precision): build, memory, camera
/// and incoherent rays; every structure's answers checked against brute
/// force on the rays brute force traces.
pub fn measure_structures(
    repeats: usize, step: &mut dyn FnMut(),
) -> Result<Vec<StructureRow>, String> {
    let mut rows = Vec::new();
    for family in families()? {
        let objects = &family.objects;
        let boxes: Vec<Aabb> =
            objects.iter().map(|o| o.shape.bounds()).collect();
        let chosen = choose(&boxes);
        // brute force on an evenly spread sample
        let every = (objects.len() * family.primary.len())
            .div_ceil(BRUTE_BUDGET)
            .max(1);
        let sample = |rays: &[Ray]| {
            rays.iter().step_by(every).copied().collect::<Vec<Ray>>()
        };
        let (p_sample, i_sample) =
            (sample(&family.primary), sample(&family.incoherent));
        let timing = Timing {
            rounds: repeats.max(1),
            batch: 1,
        };
        let measured = on_threads(1, || {
            STRUCTURES
                .iter()
                .map(|&structure| {
                    let build_ms = if structure == Structure::Brute {
                        0.0
                    } else {
                        timing.median_ms(
                            &mut [&mut || {
                                std::hint::black_box(structure.build(objects));
                            }],
                            || {},
                        )[0]
                    };
                    let built = structure.build(objects);
                    let (p, i) = if structure == Structure::Brute {
                        (&p_sample, &i_sample)
                    } else {
                        (&family.primary, &family.incoherent)
                    };
                    let ms = timing.median_ms(
                        &mut [
                            &mut || {
                                std::hint::black_box(trace(
                                    built.as_ref(),
                                    objects,
                                    p,
                                ));
                            },
                            &mut || {
                                std::hint::black_box(trace(
                                    built.as_ref(),
                                    objects,
                                    i,
                                ));
                            },
                        ],
                        || {},
                    );
                    let wrong: usize = [&p_sample, &i_sample]
                        .iter()
                        .map(|rays| {
                            kd_disagreements(&[built.as_ref()], objects, rays)
                                [0]
                        })
                        .sum();
                    (
                        structure,
                        build_ms,
                        ms[0] * 1e6 / p.len() as f64,
                        ms[1] * 1e6 / i.len() as f64,
                        wrong,
                    )
                })
                .collect::<Vec<_>>()
        })
        .map_err(|e| e.to_string())?;
        for (structure, build_ms, primary_ns, incoherent_ns, wrong) in measured
        {
            if wrong > 0 {
                return Err(format!(
                    "{}: {} disagrees with brute force on {wrong} rays",
                    family.name,
                    structure.name()
                ));
            }
            rows.push(StructureRow {
                scene: family.name.to_string(),
                objects: objects.len() as u64,
                method: structure.name().to_string(),
                chosen: structure == chosen,
                build_ms,
                bytes: structure_bytes(structure, objects) as u64,
                primary_ns,
                incoherent_ns,
                disagreements: wrong as u64,
            });
        }
        step();
    }
    Ok(rows)
}

// ---------------------------------------------------------------------
// Stability: over a million rays.
// ---------------------------------------------------------------------

/// Rays of each kind per scene and per tree they are made from: 7 scenes
/// × 8 kinds × 3 trees × 6 000 = 1 008 000 rays.
pub const STABILITY_RAYS: usize = 6_000;

/// The steps [`measure_stability`] reports: one per scene.
pub fn stability_steps(_repeats: usize) -> u64 {
    7
}

/// The catalogue over a million rays (counted, not timed; on every
/// core): four trees against brute force.
pub fn measure_stability(
    _repeats: usize, step: &mut dyn FnMut(),
) -> Result<Vec<StabilityRow>, String> {
    use rayon::prelude::*;
    let bunny = bunny()?;
    let threads = std::thread::available_parallelism().map_or(1, |n| n.get());
    let rows = on_threads_with_steps(
        threads,
        |tick| {
            let mut rows = Vec::new();
            for scene in kd_scenes(&bunny) {
                let objects = &scene.objects;
                let sah = KdTree::for_objects(
                    objects,
                    KdBuilder::SahEvents,
                    KdCosts::CHOSEN,
                );
                let mut plain = sah.clone();
                plain.mailboxing = false;
                let median = KdTree::for_objects(
                    objects,
                    KdBuilder::Median,
                    KdCosts::CHOSEN,
                );
                let pbrt = KdTree::for_objects(
                    objects,
                    KdBuilder::SahEvents,
                    KdCosts::PBRT_V3,
                );
                let trees: [&dyn Accelerator; 4] =
                    [&sah, &plain, &median, &pbrt];
                let mut cases: Vec<(&'static str, Vec<Ray>)> = Vec::new();
                for (seed, tree) in
                    [&sah, &median, &pbrt].into_iter().enumerate()
                {
                    for (k, case) in kd_rays(tree, STABILITY_RAYS, seed as u64)
                        .into_iter()
                        .enumerate()
                    {
                        match cases.get_mut(k) {
                            Some((_, rays)) => rays.extend(case.rays),
                            None => cases.push((case.name, case.rays)),
                        }
                    }
                }
                for (name, rays) in cases {
                    let wrong = rays
                        .par_chunks(512)
                        .map(|chunk| kd_disagreements(&trees, objects, chunk))
                        .reduce(
                            || vec![0; 4],
                            |a, b| {
                                a.iter().zip(&b).map(|(x, y)| x + y).collect()
                            },
                        );
                    rows.push(StabilityRow {
                        scene: scene.name.to_string(),
                        case: name.to_string(),
                        rays: rays.len() as u64,
                        wrong_sah: wrong[0] as u64,
                        wrong_no_mailbox: wrong[1] as u64,
                        wrong_median: wrong[2] as u64,
                        wrong_sah_pbrt: wrong[3] as u64,
                    });
                }
                tick();
            }
            rows
        },
        step,
    )
    .map_err(|e| e.to_string())?;
    Ok(rows)
}
