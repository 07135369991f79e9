//! The data behind chapter 8's charts: what one ray–primitive test costs
//! (measured, on this machine), and what a bound saves: how many random
//! lines hit the bound and the object (counted, the same on every machine)
//! and the time per ray with and without it (measured).
//!
//! `raystep measure` runs [`measure_costs`] and [`measure_bounding`] and
//! writes `book/src/figures/ch08/costs.csv` and `bounding.csv`;
//! `raystep figures` draws the charts from those files, so the figures
//! stay byte-identical between runs.
use std::hint::black_box;
use std::path::{Path, PathBuf};

use ch08::{
    Aabb, AxisBox, Ball, Blobby, Bound, BoundKind, BoundingSphere, Cylinder,
    DVec3, Ellipsoid, Interval, Primitive, RandomLines, Ray, Saddle, Shape,
    Torus, TorusSolver, Triangle, TriangleMesh, TriangleTest,
};
use raystep_bench::{TIGHTNESS_SEED, sampling_sphere};
use raystep_figure::as_jobs;
use raystep_render::timing::Timing;

use crate::measure_tightness;
use crate::rows::{BoundingRow, CostRow};

/// Rays per timed set: enough that one pass takes well over the clock's
/// resolution, few enough that a round of every job takes a second.
pub const RAYS: usize = 2000;

/// The chapter's primitives on the charts: (name, group, primitive).
pub fn primitives() -> Vec<(&'static str, &'static str, Box<dyn Primitive>)> {
    let tri = [
        DVec3::new(-1.0, -0.8, 0.1),
        DVec3::new(1.1, -0.6, -0.2),
        DVec3::new(0.1, 1.0, 0.0),
    ];
    let triangle = |test| -> Box<dyn Primitive> {
        Box::new(Triangle::new(tri, test).expect("a triangle"))
    };
    let pentagon: Vec<DVec3> = (0..5)
        .map(|k| {
            let a = std::f64::consts::TAU * f64::from(k) / 5.0;
            DVec3::new(a.cos(), a.sin(), 0.1 * a.sin())
        })
        .collect();
    let torus = |solver| -> Box<dyn Primitive> {
        Box::new(
            Torus::new(
                DVec3::ZERO,
                DVec3::new(0.0, 0.8, 0.6),
                1.0,
                0.35,
                solver,
            )
            .expect("a ring torus"),
        )
    };
    let balls = vec![
        Ball {
            center: DVec3::new(-0.4, 0.0, 0.0),
            radius: 1.0,
            strength: 1.0,
        },
        Ball {
            center: DVec3::new(0.5, 0.3, 0.0),
            radius: 0.9,
            strength: 1.0,
        },
        Ball {
            center: DVec3::new(0.2, -0.5, 0.4),
            radius: 0.8,
            strength: 1.0,
        },
    ];
    vec![
        (
            "sphere",
            "fast",
            Box::new(ch03::Sphere::new(DVec3::ZERO, 1.0)) as Box<dyn Primitive>,
        ),
        (
            "box",
            "fast",
            Box::new(
                AxisBox::new(DVec3::splat(-0.8), DVec3::new(0.8, 0.6, 0.9))
                    .expect("a box"),
            ),
        ),
        (
            "cylinder",
            "fast",
            Box::new(
                Cylinder::new(
                    DVec3::new(0.0, -0.9, 0.0),
                    DVec3::new(0.2, 0.9, 0.1),
                    0.6,
                )
                .expect("a cylinder"),
            ),
        ),
        (
            "ellipsoid",
            "fast",
            Box::new(
                Ellipsoid::new(DVec3::ZERO, DVec3::new(1.0, 0.7, 0.5))
                    .expect("an ellipsoid"),
            ),
        ),
        (
            "polygon (5 corners)",
            "fast",
            Box::new(ch02::Polygon::new(pentagon).expect("a pentagon")),
        ),
        (
            "triangle: plane + inside",
            "fast",
            triangle(TriangleTest::PlaneInside),
        ),
        (
            "triangle: Möller–Trumbore",
            "fast",
            triangle(TriangleTest::MollerTrumbore),
        ),
        (
            "triangle: watertight",
            "fast",
            triangle(TriangleTest::Watertight),
        ),
        ("torus: closed form", "slow", torus(TorusSolver::ClosedForm)),
        ("torus: bracketed", "slow", torus(TorusSolver::Bracketed)),
        (
            "monkey saddle",
            "slow",
            Box::new(Saddle::new(DVec3::ZERO, 0.9).expect("a saddle")),
        ),
        (
            "blobby (3 balls)",
            "slow",
            Box::new(Blobby::new(balls, 0.4).expect("a blobby object")),
        ),
    ]
}

/// `RAYS` rays that hit `object` (random lines through its sampling
/// sphere) and `RAYS` near misses: random lines through its own bounding
/// sphere, grown by a quarter (a sphere's own bounding sphere has no
/// misses), that miss it. A bound turns far misses away; the object's own
/// test is asked only about the near ones, so those are the misses that
/// cost (and the slow primitives' tests, which clip the ray to their own
/// box first, are not flattered by rays far away).
fn hits_and_misses(object: &dyn Primitive) -> (Vec<Ray>, Vec<Ray>) {
    let take = |sphere: BoundingSphere, hit: bool| -> Vec<Ray> {
        RandomLines::new(sphere, TIGHTNESS_SEED)
            .take(400 * RAYS)
            .filter(|ray| {
                object.intersect(ray, Interval::FORWARD).is_some() == hit
            })
            .take(RAYS)
            .collect()
    };
    (
        take(sampling_sphere(object), true),
        take(
            BoundingSphere {
                radius: 1.25 * object.bounding_sphere().radius,
                ..object.bounding_sphere()
            },
            false,
        ),
    )
}

/// Tests `object` against every ray of `rays`; returns the hits found
/// (so that the work cannot be optimised away).
fn test_all(object: &dyn Shape, rays: &[Ray]) -> usize {
    rays.iter()
        .filter(|ray| {
            black_box(object.intersect(black_box(ray), Interval::FORWARD))
                .is_some()
        })
        .count()
}

/// The steps [`measure_costs`] reports: one per round.
pub fn cost_steps(repeats: usize) -> u64 {
    repeats as u64
}

/// The median time of one test of each primitive (and of the two bounds)
/// for rays that hit it and rays that miss it. `repeats` rounds, every job
/// in every round, taking turns.
pub fn measure_costs(repeats: usize, step: &mut dyn FnMut()) -> Vec<CostRow> {
    let objects = primitives();
    let sets: Vec<(Vec<Ray>, Vec<Ray>)> = objects
        .iter()
        .map(|(_, _, o)| hits_and_misses(o.as_ref()))
        .collect();
    let sphere_bound = BoundingSphere {
        center: DVec3::ZERO,
        radius: 1.0,
    };
    let sphere_sets = hits_and_misses(&ch03::Sphere::new(DVec3::ZERO, 1.0));
    let box_bound = ch08::Aabb::new(DVec3::splat(-1.0), DVec3::splat(1.0));
    let bound_sets = hits_and_misses(
        &AxisBox::new(box_bound.min, box_bound.max).expect("a box"),
    );
    let mut jobs: Vec<Box<dyn FnMut()>> = Vec::new();
    for ((_, _, object), (hits, misses)) in objects.iter().zip(&sets) {
        jobs.push(Box::new(move || {
            black_box(test_all(object.as_ref() as &dyn Shape, hits));
        }));
        jobs.push(Box::new(move || {
            black_box(test_all(object.as_ref() as &dyn Shape, misses));
        }));
    }
    // the bare bound tests, as the Bounded wrapper asks them
    for rays in [&sphere_sets.0, &sphere_sets.1] {
        jobs.push(Box::new(move || {
            for ray in rays {
                black_box(sphere_bound.hit(black_box(ray), Interval::FORWARD));
            }
        }));
    }
    for rays in [&bound_sets.0, &bound_sets.1] {
        jobs.push(Box::new(move || {
            for ray in rays {
                black_box(ch08::slab_test(
                    &box_bound,
                    black_box(ray),
                    Interval::FORWARD,
                ));
            }
        }));
    }
    let timing = Timing {
        rounds: repeats,
        batch: 1,
    };
    let ms = timing.median_ms(&mut as_jobs(&mut jobs), step);
    let ns = |k: usize| ms[k] * 1e6 / RAYS as f64;
    let mut rows = Vec::new();
    let mut k = 0;
    for (name, group, _) in &objects {
        for rays in ["hit", "miss"] {
            rows.push(CostRow {
                primitive: name.to_string(),
                group: group.to_string(),
                rays: rays.to_string(),
                nanos: ns(k),
            });
            k += 1;
        }
    }
    for name in ["bound: sphere", "bound: box (Aabb::hit)"] {
        for rays in ["hit", "miss"] {
            rows.push(CostRow {
                primitive: name.to_string(),
                group: "bound".to_string(),
                rays: rays.to_string(),
                nanos: ns(k),
            });
            k += 1;
        }
    }
    rows
}

/// Random lines per object in the bounding measurement.
pub const BOUNDING_RAYS: u64 = 4000;

/// The Stanford bunny: `../shared/meshes/bunny.obj` beside the workspace
/// (it is not part of the repository).
pub fn bunny_path() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../../../shared/meshes/bunny.obj")
}

/// An object and its name on the chart.
type Named = (String, Box<dyn Primitive>);

/// One timed job of the bounding chart: an object (its index), the kind
/// of bound (None: no bound), that bound, and the rays.
struct Case {
    object: usize,
    kind: Option<BoundKind>,
    bound: Option<Bound>,
    rays: Vec<Ray>,
}

/// The objects of the bounding chart: the slow primitives, a few fast
/// ones, and the bunny as one object of 3674 triangles.
fn bounded_objects() -> Result<Vec<Named>, String> {
    let mut objects: Vec<Named> = primitives()
        .into_iter()
        .filter(|(name, _, _)| !name.starts_with("triangle: plane"))
        .map(|(name, _, p)| (name.to_string(), p))
        .collect();
    let path = bunny_path();
    let mesh = raystep_scene::Mesh::load_obj(&path)
        .map_err(|e| format!("{e} (the bunny lives in ../shared/meshes)"))?;
    let bunny = TriangleMesh::new(&mesh);
    objects.push((
        format!("bunny ({} triangles)", bunny.triangles().len()),
        Box::new(bunny),
    ));
    Ok(objects)
}

/// The steps [`measure_bounding`] reports: one per round.
pub fn bounding_steps(repeats: usize) -> u64 {
    repeats as u64
}

/// Each object alone and behind each kind of bound, on the same seeded
/// random lines: the counts, and the median time per ray.
pub fn measure_bounding(
    repeats: usize, step: &mut dyn FnMut(),
) -> Result<Vec<BoundingRow>, String> {
    let objects = bounded_objects()?;
    let kinds: Vec<Option<BoundKind>> = std::iter::once(None)
        .chain(BoundKind::ALL.into_iter().map(Some))
        .collect();
    let mut cases: Vec<Case> = Vec::new();
    for (k, (_, object)) in objects.iter().enumerate() {
        let rays: Vec<Ray> = RandomLines::new(
            sampling_sphere(object.as_ref() as &dyn Shape),
            TIGHTNESS_SEED,
        )
        .take(BOUNDING_RAYS as usize)
        .collect();
        for kind in &kinds {
            cases.push(Case {
                object: k,
                kind: *kind,
                bound: kind.map(|kind| kind.around(object.as_ref())),
                rays: rays.clone(),
            });
        }
    }
    let mut jobs: Vec<Box<dyn FnMut() + '_>> = Vec::new();
    for Case {
        object,
        bound,
        rays,
        ..
    } in &cases
    {
        let object = objects[*object].1.as_ref() as &dyn Shape;
        jobs.push(Box::new(move || {
            for ray in rays {
                let hit = match bound {
                    None => object.intersect(black_box(ray), Interval::FORWARD),
                    Some(bound) => ch08::bounded_intersect(
                        bound,
                        object,
                        black_box(ray),
                        Interval::FORWARD,
                    ),
                };
                black_box(hit);
            }
        }));
    }
    let timing = Timing {
        rounds: repeats,
        batch: 1,
    };
    let ms = timing.median_ms(&mut as_jobs(&mut jobs), step);
    let mut rows = Vec::new();
    for (case, ms) in cases.iter().zip(ms) {
        let Case {
            object: k,
            kind,
            bound,
            rays,
        } = case;
        // the counts on the same rays, counted by the chapter's own
        // tightness measurement (no bound: a box around everything)
        let object = objects[*k].1.as_ref() as &dyn Shape;
        let counts = measure_tightness(
            object,
            &bound.unwrap_or(Bound::Box(Aabb::EVERYTHING)),
            rays.len() as u64,
            TIGHTNESS_SEED,
        );
        rows.push(BoundingRow {
            object: objects[*k].0.clone(),
            bound: kind.map_or("none", BoundKind::name).to_string(),
            rays: rays.len() as u64,
            bound_hits: counts.bound_hits,
            object_hits: counts.bound_hits - counts.wasted,
            nanos: ms * 1e6 / rays.len() as f64,
        });
    }
    Ok(rows)
}
