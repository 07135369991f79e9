//! The mesh accelerators: chapter 8's `MeshBvh` in its three node
//! precisions, every step of the appendix's fast path (with its SIMD
//! kernels and with the scalar fallback), chapter 9's mesh grid (cells
//! filled by boxes and exactly) and chapter 10's mesh kd-tree, each
//! asked what brute force over the same triangles is asked (chapter 8's
//! watertight test in every one, so the answers must be the same `t`
//! bit for bit): the closest hit in the case's interval, and whether
//! anything is hit in it and in its first half.
//!
//! The meshes are small (a closed sphere of 1 280 triangles; the bunny's
//! 3 674 for its leak surfaces and its quantized copy), so that brute
//! force can answer 10⁶ rays per case.
use ch08::{
    BoundingSphere, Builder, Bvh, MeshAccelerator, MeshBruteForce, MeshBvh,
    NodePrecision, Ray32, SplitMix64, TraceCounts, triangle_boxes,
};
use ch09::{Fill, MeshGrid, Resolution};
use ch10::{Clip, KdBuilder, KdCosts, MeshKd};
use ch11::{FastBvh, Kernel, Step};
use raystep_bench::{camera_rays, incoherent_rays};
use raystep_core::{Aabb, DVec3, Interval, Ray};

use crate::scenes::{bunny, icosphere};
use crate::{
    Budget, Case, Count, EDGE_REACH, Expect, leak_surfaces, shared_edge_rays,
};

/// The group's name in the table.
const GROUP: &str = "accelerators (meshes)";

/// A mesh case.
macro_rules! case {
    ($name:literal, $what:literal, $trials:expr) => {
        Case {
            group: GROUP,
            name: $name,
            what: $what,
            run: |budget| count(&$trials(budget)),
        }
    };
}

/// This group's cases.
pub fn cases() -> Vec<Case> {
    vec![
        case!(
            "shared edges: closed sphere",
            "a ray through an edge two triangles share: a leak or a double hit",
            |b: &Budget| edges(vec![icosphere(3)], b.rays)
        ),
        case!(
            "shared edges: leak surfaces",
            "chapter 8's three surfaces (bunny, bunny far away, tiled floor)",
            |b: &Budget| edges(
                leak_surfaces(bunny())
                    .into_iter()
                    .map(|s| s.triangles)
                    .collect(),
                b.rays
            )
        ),
        case!(
            "shared vertices",
            "a ray through a vertex of a fan of five or six triangles",
            vertices
        ),
        case!(
            "T-junctions",
            "a vertex on another triangle's edge: the edges are not shared",
            t_junctions
        ),
        case!(
            "quantized mesh",
            "corners on a lattice of 1/16 of the box: many equal planes, \
             flat boxes",
            quantized
        ),
        case!(
            "coincident triangles",
            "every triangle twice (half of them wound the other way)",
            coincident
        ),
        case!(
            "needles and zero-area triangles",
            "slivers 1e-9 wide and collinear corners among the sphere's",
            needles
        ),
        case!(
            "huge coordinates (1e7)",
            "the sphere at 10⁷: f32 boxes one ulp wide, rays from far",
            |b: &Budget| moved(b, 3, 10.0, DVec3::new(1e7, -1e7, 1e7))
        ),
        case!(
            "tiny coordinates (1e-30)",
            "the sphere 10⁻³⁰ across: reciprocals near f32's range",
            |b: &Budget| moved(b, 3, 1e-30, DVec3::ZERO)
        ),
        case!(
            "denormal coordinates (1e-40)",
            "80 triangles 10⁻⁴⁰ across: f32 boxes of denormal numbers",
            |b: &Budget| moved(b, 1, 1e-40, DVec3::ZERO)
        ),
        case!(
            "axis-parallel rays (±0)",
            "directions along an axis, the others +0 or −0: 1/0 = ±∞",
            axis_parallel
        ),
        case!(
            "origins on node bounds",
            "each origin on a face of one of the hierarchy's boxes",
            on_bounds
        ),
        case!(
            "origins on surfaces",
            "each origin on a triangle: the hit at t ≈ 0 decides",
            on_surfaces
        ),
        case!(
            "NaN and ∞ rays",
            "a NaN, ±∞ or a zero direction in the ray: no hit, no panic",
            not_rays
        ),
        case!(
            "NaN and ∞ in the scene",
            "triangles with NaN or ∞ corners: kept out of every tree",
            broken_scene
        ),
        case!(
            "deep tree",
            "300 slivers, each 0.9 times the last: a tree 300 levels deep",
            deep
        ),
        case!(
            "flat scene",
            "the sphere pressed into z = 0: boxes with no thickness, two \
             triangles over every point",
            flat
        ),
        case!(
            "empty and one-triangle scenes",
            "no triangle (no root at all), and one",
            tiny
        ),
        case!(
            "mesh grid lines",
            "the sphere; rays on the mesh grid's lines, planes and corners",
            grid_lines
        ),
        case!(
            "mesh kd planes",
            "the sphere; rays in, on and along the mesh kd-tree's planes",
            kd_planes
        ),
    ]
}

/// One scene and its rays, asked over `interval`.
struct Scene {
    triangles: Vec<[DVec3; 3]>,
    rays: Vec<Ray32>,
    interval: Interval,
}

/// What a structure answers for a ray: the closest hit's `t` (its bits),
/// anything hit in the interval, anything hit in its first half.
type Answers = (Option<u64>, bool, bool);

/// What `structure` answers for `ray` over `interval`, asked through the
/// mesh seam (the counts are not kept).
fn answers(
    structure: &dyn MeshAccelerator, ray: &Ray32, interval: Interval,
) -> Answers {
    let counts = &mut TraceCounts::default();
    (
        structure
            .closest_hit(ray, interval, counts)
            .map(|h| h.t.to_bits()),
        structure.any_hit(ray, interval, counts),
        structure.any_hit(ray, half(interval), counts),
    )
}

/// Every structure over `triangles`, named, with whether it may fail:
/// only the `f32 nearest` nodes may (chapter 8 shows them for it).
fn structures(
    triangles: &[[DVec3; 3]],
) -> Vec<(String, Box<dyn MeshAccelerator>, Expect)> {
    // The four trees the steps start from, each built once.
    let boxes = triangle_boxes(triangles);
    let tree = Bvh::build(&boxes, Builder::BinnedSah { bins: 16 });
    let sweep = Bvh::build(&boxes, Builder::SweepSah);
    let mut rotated = tree.clone();
    ch11::rotations::rotate(&mut rotated);
    let parallel = ch11::parallel_build::build_parallel(&boxes, 16);
    let tree_of = |step: Step| match step {
        Step::RotatedTree => &rotated,
        Step::Wide8Parallel | Step::Compressed8Parallel => &parallel,
        step if step.builder() == Builder::SweepSah => &sweep,
        _ => &tree,
    };
    let mut all: Vec<(String, Box<dyn MeshAccelerator>, Expect)> = Vec::new();
    for precision in NodePrecision::ALL {
        let expect = if precision == NodePrecision::SingleNearest {
            Expect::Shown
        } else {
            Expect::Never
        };
        all.push((
            format!("mesh bvh: {}", precision.name()),
            Box::new(MeshBvh::new(triangles, &tree, precision)),
            expect,
        ));
    }
    for step in Step::ALL {
        let fast = FastBvh::from_tree(triangles, tree_of(step), step);
        if fast.kernel() != Kernel::Scalar {
            all.push((
                format!("fast: {}, scalar", step.name()),
                Box::new(fast.clone().scalar()),
                Expect::Never,
            ));
        }
        all.push((
            format!("fast: {}", step.name()),
            Box::new(fast),
            Expect::Never,
        ));
    }
    for fill in [Fill::Exact, Fill::Boxes] {
        all.push((
            format!("mesh grid: {}", fill.name()),
            Box::new(MeshGrid::new(triangles, Resolution::Rule, fill)),
            Expect::Never,
        ));
    }
    all.push((
        "mesh kd-tree".to_string(),
        Box::new(MeshKd::new(
            triangles,
            KdBuilder::SahEvents,
            KdCosts::CHOSEN,
            Clip::Triangles,
        )),
        Expect::Never,
    ));
    all
}

/// The interval's first half (up to 1 for an unbounded one).
fn half(interval: Interval) -> Interval {
    let end = if interval.max.is_finite() {
        interval.min + 0.5 * (interval.max - interval.min)
    } else {
        1.0
    };
    Interval::new(interval.min, end)
}

/// Every structure against brute force on every scene of `scenes`: one
/// count per structure, summed over the scenes.
fn count(scenes: &[Scene]) -> Vec<(Count, Expect)> {
    use rayon::prelude::*;
    let mut counts: Vec<(Count, Expect)> = Vec::new();
    for scene in scenes {
        let brute = MeshBruteForce(&scene.triangles);
        let structures = structures(&scene.triangles);
        let interval = scene.interval;
        let wrong = scene
            .rays
            .par_chunks(256)
            .map(|chunk| {
                let mut wrong = vec![0u64; structures.len()];
                for ray in chunk {
                    // (one pass: the test's t does not depend on the
                    // interval, so something is hit in the first half
                    // exactly if the closest hit is there)
                    let hit = brute.closest_hit(
                        ray,
                        interval,
                        &mut TraceCounts::default(),
                    );
                    let truth: Answers = (
                        hit.map(|h| h.t.to_bits()),
                        hit.is_some(),
                        hit.is_some_and(|h| h.t <= half(interval).max),
                    );
                    for (w, (_, s, _)) in wrong.iter_mut().zip(&structures) {
                        let ours = answers(s.as_ref(), ray, interval);
                        *w += u64::from(ours != truth);
                    }
                }
                wrong
            })
            .reduce(
                || vec![0; structures.len()],
                |a, b| a.iter().zip(&b).map(|(x, y)| x + y).collect(),
            );
        let trials = scene.rays.len() as u64;
        for ((name, _, expect), wrong) in structures.iter().zip(wrong) {
            match counts.iter_mut().find(|(c, _)| &c.method == name) {
                Some((count, _)) => {
                    count.failures += wrong;
                    count.trials += trials;
                }
                None => counts
                    .push((Count::new(name.clone(), wrong, trials), *expect)),
            }
        }
    }
    counts
}

/// One scene asked over t ≥ 0.
fn forward(triangles: Vec<[DVec3; 3]>, rays: Vec<Ray32>) -> Vec<Scene> {
    vec![Scene {
        triangles,
        rays,
        interval: Interval::FORWARD,
    }]
}

/// A ray of chapter 8's `f32` kind.
fn ray32(origin: DVec3, direction: DVec3) -> Ray32 {
    Ray32::rounded(&Ray::new(origin, direction))
}

/// `count` rays at `triangles`: a camera's and incoherent ones, half
/// each.
fn looking_at(triangles: &[[DVec3; 3]], count: usize, seed: u64) -> Vec<Ray32> {
    let bounds = Aabb::around(triangles.iter().flatten().copied());
    let side = ((count / 2) as f64).sqrt().ceil().max(1.0) as u32;
    camera_rays(BoundingSphere::around_box(&bounds), side)
        .iter()
        .chain(&incoherent_rays(bounds, count / 2, seed))
        .take(count)
        .map(Ray32::rounded)
        .collect()
}

/// Rays through the shared edges of each mesh, at seeded fractions
/// along each edge, `count` in all.
fn edges(meshes: Vec<Vec<[DVec3; 3]>>, count: usize) -> Vec<Scene> {
    let per_mesh = count.div_ceil(meshes.len());
    let mut random = SplitMix64::new(3);
    meshes
        .into_iter()
        .map(|triangles| {
            let edges = shared_edge_rays(&triangles, &[0.5]).len().max(1);
            let points: Vec<f64> = (0..per_mesh.div_ceil(edges))
                .map(|_| random.next_f64())
                .collect();
            let mut rays = shared_edge_rays(&triangles, &points);
            rays.truncate(per_mesh);
            Scene {
                triangles,
                rays,
                interval: EDGE_REACH,
            }
        })
        .collect()
}

/// Rays from random eyes through the sphere's vertices exactly.
fn vertices(budget: &Budget) -> Vec<Scene> {
    let triangles = icosphere(3);
    let corners: Vec<DVec3> = triangles.iter().flatten().copied().collect();
    let mut random = SplitMix64::new(5);
    let rays = (0..budget.rays)
        .map(|_| {
            let corner =
                corners[(random.next_u64() % corners.len() as u64) as usize];
            // an eye outside, on the vertex's side
            let eye = corner * 3.0 + random.unit_vector();
            ray32(eye, corner - eye)
        })
        .collect();
    forward(triangles, rays)
}

/// A strip of squares, each split in two on its left half and in four
/// on its right: the right half's middle vertices lie on the left
/// half's edges. Rays through those vertices and along the edges.
fn t_junctions(budget: &Budget) -> Vec<Scene> {
    let mut triangles = Vec::new();
    let p = |x: f64, y: f64| DVec3::new(x, y, 0.0);
    for k in 0..32 {
        let y = k as f64;
        // left: one square, two triangles
        triangles.push([p(0.0, y), p(1.0, y), p(1.0, y + 1.0)]);
        triangles.push([p(0.0, y), p(1.0, y + 1.0), p(0.0, y + 1.0)]);
        // right: the shared edge x = 1 split at its middle
        let m = p(1.0, y + 0.5);
        triangles.push([p(1.0, y), p(2.0, y), m]);
        triangles.push([m, p(2.0, y), p(2.0, y + 1.0)]);
        triangles.push([m, p(2.0, y + 1.0), p(1.0, y + 1.0)]);
    }
    let mut random = SplitMix64::new(7);
    let rays = (0..budget.rays)
        .map(|k| {
            let y = (random.next_u64() % 32) as f64;
            // the T vertex, or a point along the split edge
            let target = if k % 2 == 0 {
                p(1.0, y + 0.5)
            } else {
                p(1.0, y + random.next_f64())
            };
            let eye = target + DVec3::new(0.0, 0.0, 2.0) + random.unit_vector();
            ray32(eye, target - eye)
        })
        .collect();
    forward(triangles, rays)
}

/// The bunny with every corner snapped to a lattice of 1/16 of its box.
fn quantized(budget: &Budget) -> Vec<Scene> {
    let bunny = bunny();
    let b = Aabb::around(bunny.iter().flatten().copied());
    let step = (b.max - b.min) / 16.0;
    let snap = |p: DVec3| b.min + ((p - b.min) / step).round() * step;
    let triangles: Vec<[DVec3; 3]> =
        bunny.iter().map(|t| t.map(snap)).collect();
    let rays = looking_at(&triangles, budget.rays, 9);
    forward(triangles, rays)
}

/// The sphere with each triangle twice.
fn coincident(budget: &Budget) -> Vec<Scene> {
    let sphere = icosphere(3);
    let mut triangles = sphere.clone();
    for (k, &[a, b, c]) in sphere.iter().enumerate() {
        triangles.push(if k % 2 == 0 { [a, b, c] } else { [a, c, b] });
    }
    let rays = looking_at(&triangles, budget.rays, 11);
    forward(triangles, rays)
}

/// The sphere with 200 needles (one side 10⁻⁹ of the others) and 200
/// zero-area triangles (collinear corners) on and around it.
fn needles(budget: &Budget) -> Vec<Scene> {
    let mut triangles = icosphere(3);
    let mut random = SplitMix64::new(13);
    for k in 0..400 {
        let a = random.unit_vector() * (0.9 + 0.2 * random.next_f64());
        let d = random.unit_vector() * 0.3;
        triangles.push(if k % 2 == 0 {
            [a, a + d, a + d + random.unit_vector() * 1e-9]
        } else {
            [a, a + d, a + 2.0 * d]
        });
    }
    let rays = looking_at(&triangles, budget.rays, 15);
    forward(triangles, rays)
}

/// The sphere split `levels` times, scaled by `scale` and moved to `to`
/// (arithmetic on denormal numbers is slow: that case has a coarse one).
fn moved(budget: &Budget, levels: u32, scale: f64, to: DVec3) -> Vec<Scene> {
    let triangles: Vec<[DVec3; 3]> = icosphere(levels)
        .iter()
        .map(|t| t.map(|p| p * scale + to))
        .collect();
    let rays = looking_at(&triangles, budget.rays, 17);
    forward(triangles, rays)
}

/// Rays along ±x, ±y, ±z with the other components +0.0 or −0.0, from
/// random points of the sphere's box, half of them on the box's
/// midplanes (where the tree splits).
fn axis_parallel(budget: &Budget) -> Vec<Scene> {
    let triangles = icosphere(3);
    let mut random = SplitMix64::new(19);
    let rays = (0..budget.rays)
        .map(|k| {
            let axis = (random.next_u64() % 3) as usize;
            let mut direction = DVec3::ZERO;
            for a in 0..3 {
                let negative = random.next_u64().is_multiple_of(2);
                direction[a] = match (a == axis, negative) {
                    (true, false) => 1.0,
                    (true, true) => -1.0,
                    (false, false) => 0.0,
                    (false, true) => -0.0,
                };
            }
            let mut origin = DVec3::new(
                2.4 * random.next_f64() - 1.2,
                2.4 * random.next_f64() - 1.2,
                2.4 * random.next_f64() - 1.2,
            );
            if k % 2 == 0 {
                origin[(axis + 1) % 3] = 0.0;
            }
            origin[axis] = if direction[axis] > 0.0 { -3.0 } else { 3.0 };
            ray32(origin, direction)
        })
        .collect();
    forward(triangles, rays)
}

/// Origins on the faces of the nodes of the sphere's binned SAH tree.
fn on_bounds(budget: &Budget) -> Vec<Scene> {
    let triangles = icosphere(3);
    let tree = Bvh::build(
        &triangle_boxes(&triangles),
        Builder::BinnedSah { bins: 16 },
    );
    let mut random = SplitMix64::new(21);
    let rays = (0..budget.rays)
        .map(|_| {
            let node = tree.nodes
                [(random.next_u64() % tree.nodes.len() as u64) as usize];
            let b = node.bounds;
            let mut origin = b.min
                + (b.max - b.min)
                    * DVec3::new(
                        random.next_f64(),
                        random.next_f64(),
                        random.next_f64(),
                    );
            let axis = (random.next_u64() % 3) as usize;
            origin[axis] = if random.next_u64().is_multiple_of(2) {
                b.min[axis]
            } else {
                b.max[axis]
            };
            ray32(origin, random.unit_vector())
        })
        .collect();
    forward(triangles, rays)
}

/// Origins at random points of the sphere's triangles.
fn on_surfaces(budget: &Budget) -> Vec<Scene> {
    let triangles = icosphere(3);
    let mut random = SplitMix64::new(23);
    let rays = (0..budget.rays)
        .map(|_| {
            let [a, b, c] = triangles
                [(random.next_u64() % triangles.len() as u64) as usize];
            let (u, v) = (random.next_f64(), random.next_f64());
            let (u, v) = if u + v > 1.0 {
                (1.0 - u, 1.0 - v)
            } else {
                (u, v)
            };
            ray32(a + u * (b - a) + v * (c - a), random.unit_vector())
        })
        .collect();
    forward(triangles, rays)
}

/// Rays with a NaN, ±∞ in the origin or direction, or a zero direction.
fn not_rays(budget: &Budget) -> Vec<Scene> {
    let triangles = icosphere(3);
    let mut random = SplitMix64::new(25);
    let bad = [f64::NAN, f64::INFINITY, f64::NEG_INFINITY];
    let rays = (0..budget.rays)
        .map(|k| {
            let mut origin = random.unit_vector() * 3.0;
            let mut direction = -origin + random.unit_vector() * 0.5;
            let x = bad[k % 3];
            let axis = (k / 3) % 3;
            match (k / 9) % 3 {
                0 => origin[axis] = x,
                1 => direction[axis] = x,
                _ => direction = DVec3::ZERO,
            }
            Ray32 {
                origin: origin.as_vec3(),
                direction: direction.as_vec3(),
            }
        })
        .collect();
    forward(triangles, rays)
}

/// The sphere with 30 triangles that have a NaN or infinite corner.
fn broken_scene(budget: &Budget) -> Vec<Scene> {
    let mut triangles = icosphere(3);
    let bad = [f64::NAN, f64::INFINITY, f64::NEG_INFINITY];
    for k in 0..30 {
        let mut t = triangles[k * 7];
        t[k % 3][(k / 3) % 3] = bad[k % 3];
        triangles.push(t);
    }
    let rays = looking_at(&triangles[..1280], budget.rays, 27);
    forward(triangles, rays)
}

/// 300 slivers across x, each 0.9 times as far as the last: rays along
/// x through all of them, and random ones.
fn deep(budget: &Budget) -> Vec<Scene> {
    let triangles: Vec<[DVec3; 3]> = (0..300)
        .map(|k| {
            let x = 0.9f64.powi(k);
            [
                DVec3::new(x, -1.0, 0.0),
                DVec3::new(x, 1.0, -1.0),
                DVec3::new(x, 1.0, 1.0),
            ]
        })
        .collect();
    let mut random = SplitMix64::new(29);
    let rays = (0..budget.rays)
        .map(|k| {
            if k % 2 == 0 {
                let (y, z) = (random.next_f64() * 1.8 - 0.9, 0.0);
                ray32(DVec3::new(2.0, y, z), -DVec3::X)
            } else {
                let eye = random.unit_vector() * 3.0;
                ray32(eye, random.unit_vector() * 0.5 - eye)
            }
        })
        .collect();
    forward(triangles, rays)
}

/// The sphere with every z set to 0: rays from above and rays in the
/// plane.
fn flat(budget: &Budget) -> Vec<Scene> {
    let sphere = icosphere(3);
    let b = Aabb::around(sphere.iter().flatten().copied());
    let z = 0.0;
    let triangles: Vec<[DVec3; 3]> = sphere
        .iter()
        .map(|t| t.map(|p| DVec3::new(p.x, p.y, z)))
        .collect();
    let mut random = SplitMix64::new(31);
    let size = (b.max - b.min).length();
    let rays = (0..budget.rays)
        .map(|k| {
            let target = DVec3::new(
                b.min.x + random.next_f64() * (b.max.x - b.min.x),
                b.min.y + random.next_f64() * (b.max.y - b.min.y),
                z,
            );
            let mut from = random.unit_vector() * size;
            if k % 2 == 0 {
                from.z = 0.0; // in the plane
            }
            ray32(target + from, -from)
        })
        .collect();
    forward(triangles, rays)
}

/// No triangle, and one.
fn tiny(budget: &Budget) -> Vec<Scene> {
    let one = vec![[DVec3::ZERO, DVec3::X, DVec3::Y]];
    let rays = |seed| {
        let mut random = SplitMix64::new(seed);
        (0..budget.rays / 2)
            .map(|_| {
                let eye = random.unit_vector() * 2.0;
                let target =
                    DVec3::new(random.next_f64(), random.next_f64(), 0.0);
                ray32(eye, target - eye)
            })
            .collect()
    };
    vec![
        Scene {
            triangles: Vec::new(),
            rays: rays(33),
            interval: Interval::FORWARD,
        },
        Scene {
            triangles: one,
            rays: rays(35),
            interval: Interval::FORWARD,
        },
    ]
}

/// Rays made from the sphere's mesh grid: its lines, planes and corners.
fn grid_lines(budget: &Budget) -> Vec<Scene> {
    let triangles = icosphere(3);
    let grid = MeshGrid::new(&triangles, Resolution::Rule, Fill::Exact);
    let kinds = crate::adversarial_rays(&grid.grid.lattice, 1, 37).len();
    let rays = crate::adversarial_rays(
        &grid.grid.lattice,
        budget.rays.div_ceil(kinds),
        37,
    )
    .into_iter()
    .flat_map(|case| case.rays)
    .map(|ray| Ray32::rounded(&ray))
    .collect();
    forward(triangles, rays)
}

/// Rays made from the sphere's mesh kd-tree: in, on and along its
/// planes, through its nodes' corners.
fn kd_planes(budget: &Budget) -> Vec<Scene> {
    let triangles = icosphere(3);
    let kd = MeshKd::new(
        &triangles,
        KdBuilder::SahEvents,
        KdCosts::CHOSEN,
        Clip::Triangles,
    );
    let kinds = crate::kd_rays(&kd.tree, 1, 39).len();
    let rays = crate::kd_rays(&kd.tree, budget.rays.div_ceil(kinds), 39)
        .into_iter()
        .flat_map(|case| case.rays)
        .map(|ray| Ray32::rounded(&ray))
        .collect();
    forward(triangles, rays)
}
