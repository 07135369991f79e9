//! Triangle and polygon tests where they are fragile: rays parallel to
//! the plane or lying in it; rays through the shared edges and vertices
//! of closed surfaces, T-junctions and quantized meshes; needle,
//! zero-area and duplicated triangles; huge and denormal coordinates; NaN
//! and ∞ in the ray. (Chapter 2's inside tests in 2D are
//! [`polygons`](crate::polygons).)
//!
//! The triangle tests are chapter 8's three ([`TriangleTest::ALL`]). A
//! ray that enters a closed surface must be hit exactly once there: no
//! hit is a LEAK, two or more a DOUBLE HIT. Only the watertight test is
//! built to have neither at shared edges and vertices (`Expect::Never`).
use std::collections::HashMap;
use std::panic::{AssertUnwindSafe, catch_unwind};

use ch02::Polygon;
use ch08::{
    DVec3, Interval, Ray, SplitMix64, Triangle, TriangleTest, moller_trumbore,
    watertight,
};
use raystep_core::glam::DQuat;

use crate::scenes;
use crate::trials::{
    below, count_failures, cube_point, decades, per_method, uniform,
};
use crate::{Budget, Case, Count, EDGE_REACH, Expect, leak_surfaces};

const TRIANGLES: &str = "triangle tests";

/// This group's cases.
pub fn cases() -> Vec<Case> {
    vec![
        Case {
            group: TRIANGLES,
            name: "ray parallel to the plane",
            what: "a ray 1e-12…1 off the plane, parallel to it, must miss; \
                   all three survive",
            run: parallel_to_the_plane,
        },
        Case {
            group: TRIANGLES,
            name: "ray in the plane",
            what: "a ray in the plane may hit only where it crosses the \
                   triangle; plane + inside and watertight survive",
            run: in_the_plane,
        },
        Case {
            group: TRIANGLES,
            name: "shared edge: leaks",
            what: "a ray at a shared edge falls through both triangles; the \
                   watertight test never leaks",
            run: shared_edge_leaks,
        },
        Case {
            group: TRIANGLES,
            name: "shared edge: double hits",
            what: "a ray at a shared edge hits both triangles; the watertight \
                   test never does",
            run: shared_edge_doubles,
        },
        Case {
            group: TRIANGLES,
            name: "shared vertex: leaks",
            what: "a ray at a fan's shared vertex falls through all of it; \
                   the watertight test never leaks",
            run: shared_vertex_leaks,
        },
        Case {
            group: TRIANGLES,
            name: "shared vertex: double hits",
            what: "a ray at a fan's shared vertex hits two of it; the \
                   watertight test never does",
            run: shared_vertex_doubles,
        },
        Case {
            group: TRIANGLES,
            name: "T-junction",
            what: "a vertex on a neighbour's edge: no shared edge, so even \
                   the watertight test may leak",
            run: t_junction,
        },
        Case {
            group: TRIANGLES,
            name: "quantized mesh",
            what: "corners, targets and directions on a 1/8 lattice: exact \
                   ties; watertight: 0 leaks or doubles",
            run: quantized_mesh,
        },
        Case {
            group: TRIANGLES,
            name: "axis-parallel rays",
            what: "rays along ±x, ±y, ±z at a quantized mesh's edges tie \
                   exactly; watertight: 0 leaks or doubles",
            run: axis_parallel,
        },
        Case {
            group: TRIANGLES,
            name: "−0.0 in the direction",
            what: "the axis-parallel rays with their zero components −0.0; \
                   watertight: 0 leaks or doubles",
            run: negative_zero,
        },
        Case {
            group: TRIANGLES,
            name: "coplanar neighbours",
            what: "a flat tilted grid: each triangle's own plane differs; \
                   watertight: 0 leaks or doubles",
            run: coplanar_neighbours,
        },
        Case {
            group: TRIANGLES,
            name: "needle triangles",
            what: "a needle 1e-9 wide, aimed inside (hit at t = 1) or beside \
                   it (miss); watertight survives",
            run: needles,
        },
        Case {
            group: TRIANGLES,
            name: "needle pair",
            what: "two needles 1e-9 wide sharing their long edge: leaks or \
                   double hits; watertight: 0",
            run: needle_pair,
        },
        Case {
            group: TRIANGLES,
            name: "zero-area triangle",
            what: "collinear corners, called directly (meshes drop them): any \
                   hit is wrong; plane + inside and watertight refuse",
            run: zero_area,
        },
        Case {
            group: TRIANGLES,
            name: "duplicated triangle",
            what: "a copy, corners rotated or reversed, must agree near edges \
                   (hit, t to 1e-12); watertight does",
            run: duplicated,
        },
        Case {
            group: TRIANGLES,
            name: "huge coordinates",
            what: "a closed mesh at 1e7: leaks or double hits at shared edges \
                   and vertices; watertight: 0",
            run: huge_coordinates,
        },
        Case {
            group: TRIANGLES,
            name: "denormal triangle",
            what: "a triangle 1e-310 across, aimed inside: products \
                   underflow, and every test misses",
            run: denormal,
        },
        Case {
            group: TRIANGLES,
            name: "NaN in the ray",
            what: "a NaN in the origin or direction: any hit or panic is \
                   wrong; all three survive",
            run: nan_in_the_ray,
        },
        Case {
            group: TRIANGLES,
            name: "∞ in the ray",
            what: "±∞ in the origin or direction: any hit or panic is wrong; \
                   all three survive",
            run: infinity_in_the_ray,
        },
    ]
}

// ---------------------------------------------------------------------
// Random numbers and shapes.
// ---------------------------------------------------------------------

/// A triangle with corners in [−1, 1]³ and no thin angle (the sine of
/// each at least 0.2).
fn random_triangle(rng: &mut SplitMix64) -> [DVec3; 3] {
    loop {
        let v = [cube_point(rng), cube_point(rng), cube_point(rng)];
        let thin = (0..3).any(|i| {
            let (e1, e2) = (v[(i + 1) % 3] - v[i], v[(i + 2) % 3] - v[i]);
            e1.cross(e2).length() < 0.2 * e1.length() * e2.length()
        });
        if !thin {
            return v;
        }
    }
}

/// The point with barycentric coordinates (1 − u − w, u, w).
fn at(v: &[DVec3; 3], u: f64, w: f64) -> DVec3 {
    v[0] + u * (v[1] - v[0]) + w * (v[2] - v[0])
}

/// The unit normal (V₁ − V₀) × (V₂ − V₀), normalised.
fn normal(v: &[DVec3; 3]) -> DVec3 {
    (v[1] - v[0]).cross(v[2] - v[0]).normalize()
}

/// A unit direction toward a surface whose unit normals are `normals`:
/// D·n ≤ −0.3 for each (no silhouette, no grazing).
fn facing(rng: &mut SplitMix64, normals: &[DVec3]) -> DVec3 {
    let mean = normals.iter().sum::<DVec3>().normalize();
    loop {
        let d = -(mean + 0.7 * rng.unit_vector()).normalize();
        if normals.iter().all(|n| d.dot(*n) <= -0.3) {
            return d;
        }
    }
}

/// A unit direction making an angle of at least ~6° with the plane of
/// `normal`, from either side.
fn not_grazing(rng: &mut SplitMix64, normal: DVec3) -> DVec3 {
    loop {
        let d = rng.unit_vector();
        if d.dot(normal).abs() >= 0.1 {
            return d;
        }
    }
}

// ---------------------------------------------------------------------
// The tests, and the counts they give.
// ---------------------------------------------------------------------

/// The `t` at which `test` hits the corners `v` within `interval`:
/// chapter 8's functions for Möller–Trumbore and the watertight test
/// (called directly, as a mesh's walk calls them, whatever the corners),
/// and chapter 2's polygon for plane + inside (no hit where it refuses
/// the corners).
fn hit_once(
    test: TriangleTest, v: [DVec3; 3], ray: &Ray, interval: Interval,
) -> Option<f64> {
    match test {
        TriangleTest::PlaneInside => {
            Some(Polygon::new(v.to_vec()).ok()?.intersect(ray, interval)?.t)
        }
        TriangleTest::MollerTrumbore => moller_trumbore(&v, ray, interval),
        TriangleTest::Watertight => watertight(&v, ray, interval),
    }
}

/// Per test: does `ray` hit the corners `v` anywhere on its line?
fn hits_anywhere(v: [DVec3; 3], ray: &Ray) -> [bool; 3] {
    TriangleTest::ALL
        .map(|test| hit_once(test, v, ray, Interval::UNIVERSE).is_some())
}

/// Per test: does `ray` hit the triangles of `mesh` (within
/// [`EDGE_REACH`]) other than exactly once, a leak or a double hit?
fn not_hit_once(mesh: &[[DVec3; 3]], ray: &Ray) -> [bool; 3] {
    TriangleTest::ALL.map(|test| {
        let hits = mesh
            .iter()
            .filter(|v| hit_once(test, **v, ray, EDGE_REACH).is_some())
            .count();
        hits != 1
    })
}

/// The ray from `distance` back along `d` to `target`: it reaches the
/// target at t = 1.
fn ray_to(target: DVec3, d: DVec3, distance: f64) -> Ray {
    let from = target - distance * d;
    Ray::new(from, target - from)
}

/// One count per triangle test, in the lecture's order.
fn per_test(
    failures: [u64; 3], trials: u64, expect: [Expect; 3],
) -> Vec<(Count, Expect)> {
    let names = TriangleTest::ALL.map(TriangleTest::name);
    per_method(names, failures, trials, expect)
}

/// Every test is built for the case.
const ALL_NEVER: [Expect; 3] = [Expect::Never; 3];
/// Only the watertight test is built for the case.
const WATERTIGHT_NEVER: [Expect; 3] =
    [Expect::Shown, Expect::Shown, Expect::Never];
/// No test is built for the case.
const ALL_SHOWN: [Expect; 3] = [Expect::Shown; 3];

// ---------------------------------------------------------------------
// Parallel and in-plane rays.
// ---------------------------------------------------------------------

/// A triangle in the plane z = `z`, with corners in [−1, 1]², no thin
/// angle.
fn flat_triangle(rng: &mut SplitMix64, z: f64) -> [DVec3; 3] {
    random_triangle(rng).map(|p| DVec3::new(p.x, p.y, z))
}

/// Rays parallel to the plane, 10⁻¹²…1 off it, passing over the
/// triangle: half at tilted triangles (parallel to rounding), half at
/// triangles in a plane z = c with D.z = 0 exactly. Each must miss: the
/// line meets the plane (if at all) ≥ 10⁴ away, far outside.
fn parallel_to_the_plane(budget: &Budget) -> Vec<(Count, Expect)> {
    let failures = count_failures(budget.rays, 0x17_0001, |rng| {
        let (v, n) = if rng.next_f64() < 0.5 {
            let v = random_triangle(rng);
            (v, normal(&v))
        } else {
            let z = uniform(rng, -1.0, 1.0);
            (flat_triangle(rng, z), DVec3::Z)
        };
        // Step 1: a direction in the plane, along the edges (its z
        // exactly 0 for a triangle in a plane z = c).
        let d = uniform(rng, -1.0, 1.0) * (v[1] - v[0])
            + uniform(rng, -1.0, 1.0) * (v[2] - v[0]);
        // Step 2: an origin over a point of the triangle, lifted off
        // the plane and moved back along D.
        let over = at(&v, 0.3, 0.3) + decades(rng, -12.0, 0.0) * n;
        let over = if rng.next_f64() < 0.5 {
            over
        } else {
            2.0 * at(&v, 0.3, 0.3) - over
        };
        let ray = Ray::new(over - 2.0 * d, d);
        hits_anywhere(v, &ray)
    });
    per_test(failures, budget.rays as u64, ALL_NEVER)
}

/// Rays lying in the triangle's plane, through it: half at tilted
/// triangles (in the plane to rounding), half in a plane z = c exactly.
/// A hit is allowed only where the ray crosses the triangle (its t
/// within 1e-9 of that stretch) and with a finite t.
fn in_the_plane(budget: &Budget) -> Vec<(Count, Expect)> {
    let failures = count_failures(budget.rays, 0x17_0002, |rng| {
        let v = if rng.next_f64() < 0.5 {
            random_triangle(rng)
        } else {
            let z = uniform(rng, -1.0, 1.0);
            flat_triangle(rng, z)
        };
        // The origin outside, the line through the inside, and the
        // stretch of t where the ray is in the triangle.
        let inside = (uniform(rng, 0.1, 0.45), uniform(rng, 0.1, 0.45));
        let angle = uniform(rng, 0.0, std::f64::consts::TAU);
        let (ray, lo, hi) = raystep_check::ray_in_plane(&v, inside, angle);
        TriangleTest::ALL.map(|test| {
            match hit_once(test, v, &ray, Interval::UNIVERSE) {
                None => false,
                Some(t) => !(lo - 1e-9..=hi + 1e-9).contains(&t),
            }
        })
    });
    // Chapter 2's ray–plane step is built for it (its zero-within-rounding
    // test says `InPlane`), and so is the watertight test (a det within
    // the shear's rounding of 0 is 0: no hit); Möller–Trumbore divides by
    // a determinant that is rounding noise, and its t is off.
    let expect = [Expect::Never, Expect::Shown, Expect::Never];
    per_test(failures, budget.rays as u64, expect)
}

// ---------------------------------------------------------------------
// Closed surfaces: shared edges and vertices.
// ---------------------------------------------------------------------

/// A place on a surface that rays aim at: a shared edge (its two ends)
/// or an inner vertex (one), the normals of the triangles that meet
/// there, and the triangles near it that could report the hit.
struct Spot {
    ends: Vec<DVec3>,
    normals: Vec<DVec3>,
    near: Vec<usize>,
}

/// A surface's triangles as each test builds them, its shared edges and
/// inner vertices, and how far away its rays start.
struct Surface {
    built: [Vec<Option<Triangle>>; 3],
    edges: Vec<Spot>,
    vertices: Vec<Spot>,
    reach: f64,
}

impl Surface {
    /// The surface of these triangles (corners shared bit for bit).
    fn new(triangles: &[[DVec3; 3]]) -> Surface {
        // Step 1: number the corners.
        let mut ids: HashMap<[u64; 3], usize> = HashMap::new();
        let mut points: Vec<DVec3> = Vec::new();
        let mut corners = Vec::with_capacity(triangles.len());
        for v in triangles {
            corners.push(v.map(|p| {
                let key = p.to_array().map(f64::to_bits);
                *ids.entry(key).or_insert_with(|| {
                    points.push(p);
                    points.len() - 1
                })
            }));
        }
        // Step 2: the triangles at each corner and on each edge.
        let mut fans = vec![Vec::new(); points.len()];
        let mut edges: HashMap<(usize, usize), Vec<usize>> = HashMap::new();
        for (k, c) in corners.iter().enumerate() {
            for i in 0..3 {
                fans[c[i]].push(k);
                let (a, b) = (c[i], c[(i + 1) % 3]);
                edges.entry((a.min(b), a.max(b))).or_default().push(k);
            }
        }
        let near = |ends: &[usize]| {
            let mut near: Vec<usize> =
                ends.iter().flat_map(|&e| fans[e].clone()).collect();
            near.sort_unstable();
            near.dedup();
            near
        };
        let normals: Vec<DVec3> = triangles.iter().map(normal).collect();
        // Step 3: the shared edges, in a fixed order; a corner on a
        // border edge is no inner vertex.
        let mut shared = Vec::new();
        let mut border = vec![false; points.len()];
        for (&(a, b), sharing) in &edges {
            if sharing.len() == 2 {
                shared.push(((a, b), [sharing[0], sharing[1]]));
            } else {
                (border[a], border[b]) = (true, true);
            }
        }
        shared.sort_unstable();
        let edge_spots = shared
            .iter()
            .map(|&((a, b), pair)| Spot {
                ends: vec![points[a], points[b]],
                normals: pair.map(|k| normals[k]).to_vec(),
                near: near(&[a, b]),
            })
            .filter(faceable)
            .collect();
        // Step 4: the inner vertices, with the triangles around their
        // ring.
        let vertex_spots = (0..points.len())
            .filter(|&i| !border[i])
            .map(|i| {
                let ring: Vec<usize> =
                    fans[i].iter().flat_map(|&k| corners[k]).collect();
                Spot {
                    ends: vec![points[i]],
                    normals: fans[i].iter().map(|&k| normals[k]).collect(),
                    near: near(&ring),
                }
            })
            .filter(faceable)
            .collect();
        let size = points
            .iter()
            .map(|p| (*p - points[0]).abs().max_element())
            .fold(0.0, f64::max);
        Surface {
            built: TriangleTest::ALL.map(|test| {
                triangles
                    .iter()
                    .map(|&v| Triangle::new(v, test).ok())
                    .collect()
            }),
            edges: edge_spots,
            vertices: vertex_spots,
            reach: 3.0 * size,
        }
    }

    /// How many of the triangles near `spot` report a hit of `ray`
    /// within [`EDGE_REACH`] (t = 1 at the spot), per test.
    fn hits(&self, spot: &Spot, ray: &Ray) -> [usize; 3] {
        let mut counts = [0; 3];
        for (count, built) in counts.iter_mut().zip(&self.built) {
            *count = spot
                .near
                .iter()
                .filter_map(|&k| built[k].as_ref())
                .filter(|t| t.hit_t(ray, EDGE_REACH).is_some())
                .count();
        }
        counts
    }
}

/// Can rays reach the spot from a direction all its triangles face,
/// well away from a silhouette?
fn faceable(spot: &Spot) -> bool {
    let mean = spot.normals.iter().sum::<DVec3>().normalize();
    spot.normals.iter().all(|n| n.dot(mean) >= 0.5)
}

/// Which spots of a surface a case aims at.
#[derive(Clone, Copy)]
enum Spots {
    Edges,
    Vertices,
    /// Three edges, then a vertex.
    Both,
}

/// How a case's rays are made: at `spot` of a surface whose rays start
/// about `reach` away, or None if this way cannot reach that spot.
type Aim = fn(&mut SplitMix64, &Spot, f64) -> Option<Ray>;

/// A ray at the vertex, or at the midpoint or a random point of the
/// edge, from a random direction all its triangles face: it reaches
/// the spot at t = 1.
fn aim_anywhere(rng: &mut SplitMix64, spot: &Spot, reach: f64) -> Option<Ray> {
    let target = match spot.ends[..] {
        [p] => p,
        [a, b] if rng.next_f64() < 0.25 => 0.5 * (a + b),
        [a, b] => a + rng.next_f64() * (b - a),
        _ => unreachable!("a spot is an edge or a vertex"),
    };
    let d = facing(rng, &spot.normals);
    Some(ray_to(target, d, reach * (1.0 + rng.next_f64())))
}

/// The spot's vertex, or a point k/8 along its edge: exact on a 1/8
/// lattice.
fn lattice_target(rng: &mut SplitMix64, spot: &Spot) -> DVec3 {
    match spot.ends[..] {
        [p] => p,
        [a, b] => a + (b - a) * ((1 + below(rng, 7)) as f64 / 8.0),
        _ => unreachable!("a spot is an edge or a vertex"),
    }
}

/// A ray at a lattice point of the spot along a small integer direction
/// (components −4…4) all its triangles face: every number exact.
fn aim_on_the_lattice(
    rng: &mut SplitMix64, spot: &Spot, _reach: f64,
) -> Option<Ray> {
    let target = lattice_target(rng, spot);
    for _ in 0..100 {
        let d = DVec3::new(
            below(rng, 9) as f64 - 4.0,
            below(rng, 9) as f64 - 4.0,
            below(rng, 9) as f64 - 4.0,
        );
        let unit = d.normalize_or_zero();
        if spot.normals.iter().all(|n| unit.dot(*n) <= -0.3) {
            return Some(Ray::new(target - 2.0 * d, 2.0 * d));
        }
    }
    None
}

/// A ray at a lattice point of the spot along one of the six axis
/// directions that all its triangles face (at more than ~3°).
fn aim_along_an_axis(
    rng: &mut SplitMix64, spot: &Spot, _reach: f64,
) -> Option<Ray> {
    let axes: Vec<DVec3> = [DVec3::X, DVec3::Y, DVec3::Z]
        .into_iter()
        .flat_map(|a| [a, -a])
        .filter(|d| spot.normals.iter().all(|n| d.dot(*n) <= -0.05))
        .collect();
    if axes.is_empty() {
        return None;
    }
    let d = 16.0 * axes[below(rng, axes.len())];
    let target = lattice_target(rng, spot);
    Some(Ray::new(target - d, d))
}

/// [`aim_along_an_axis`] with the direction's zero components −0.0.
fn aim_along_an_axis_negative_zero(
    rng: &mut SplitMix64, spot: &Spot, reach: f64,
) -> Option<Ray> {
    let ray = aim_along_an_axis(rng, spot, reach)?;
    let d = ray
        .direction
        .to_array()
        .map(|c| if c == 0.0 { -0.0 } else { c });
    Some(Ray::new(ray.origin, DVec3::from_array(d)))
}

/// Leaks and double hits per test, out of `trials` rays.
struct Tally {
    leaks: [u64; 3],
    doubles: [u64; 3],
    trials: u64,
}

impl Tally {
    /// Leaks plus double hits, per test.
    fn either(&self) -> [u64; 3] {
        [0, 1, 2].map(|i| self.leaks[i] + self.doubles[i])
    }

    /// `failures` (its leaks, double hits or either), one count per
    /// test out of its trials: only the watertight test is built to
    /// have none.
    fn counted(&self, failures: [u64; 3]) -> Vec<(Count, Expect)> {
        per_test(failures, self.trials, WATERTIGHT_NEVER)
    }

    /// Its leaks, [`counted`](Tally::counted).
    fn counted_leaks(&self) -> Vec<(Count, Expect)> {
        self.counted(self.leaks)
    }

    /// Its double hits, [`counted`](Tally::counted).
    fn counted_doubles(&self) -> Vec<(Count, Expect)> {
        self.counted(self.doubles)
    }
}

/// `trials` rays made by `aim`, each at a spot of the next surface in
/// turn, counted: a leak where a test reports no hit near the spot, a
/// double hit where it reports two or more.
fn leaks_and_doubles(
    surfaces: &[Surface], spots: Spots, trials: usize, seed: u64, aim: Aim,
) -> Tally {
    let mut rng = SplitMix64::new(seed);
    let mut tally = Tally {
        leaks: [0; 3],
        doubles: [0; 3],
        trials: trials as u64,
    };
    let mut k = 0;
    while k < trials {
        let surface = &surfaces[k % surfaces.len()];
        let on_edge = match spots {
            Spots::Edges => true,
            Spots::Vertices => false,
            Spots::Both => k % 4 != 3,
        };
        let list = if on_edge {
            &surface.edges
        } else {
            &surface.vertices
        };
        let spot = &list[below(&mut rng, list.len())];
        let Some(ray) = aim(&mut rng, spot, surface.reach) else {
            continue; // this way cannot reach the spot: another one
        };
        for (i, n) in surface.hits(spot, &ray).into_iter().enumerate() {
            tally.leaks[i] += u64::from(n == 0);
            tally.doubles[i] += u64::from(n > 1);
        }
        k += 1;
    }
    tally
}

/// A rotation about an awkward axis by an awkward angle.
fn awkward_rotation(axis: DVec3, angle: f64) -> DQuat {
    DQuat::from_axis_angle(axis.normalize(), angle)
}

/// An icosphere (320 triangles) rotated, scaled by `scale` and moved to
/// `centre`.
fn icosphere(rotation: DQuat, scale: f64, centre: DVec3) -> Vec<[DVec3; 3]> {
    scenes::icosphere(2)
        .into_iter()
        .map(|v| v.map(|p| centre + scale * (rotation * p)))
        .collect()
}

/// Chapter 8's leak surfaces of a tilted icosphere: the mesh, the mesh
/// moved 1000 away, and the tiled floor.
fn leak_test_surfaces() -> Vec<Surface> {
    let mesh = icosphere(
        awkward_rotation(DVec3::new(0.3, -0.7, 0.2), 0.9137),
        0.7313,
        DVec3::new(3.217, -1.91, 0.473),
    );
    leak_surfaces(&mesh)
        .iter()
        .map(|s| Surface::new(&s.triangles))
        .collect()
}

/// Rays from random directions at the `spots` (shared edges or inner
/// vertices) of chapter 8's leak surfaces, counted.
fn leak_surfaces_tally(budget: &Budget, spots: Spots, seed: u64) -> Tally {
    let surfaces = leak_test_surfaces();
    leaks_and_doubles(&surfaces, spots, budget.rays, seed, aim_anywhere)
}

/// Rays at points of shared edges of chapter 8's leak surfaces (a
/// tilted icosphere, the same 1000 away, a tiled floor), from random
/// directions that face both triangles: leaks.
fn shared_edge_leaks(budget: &Budget) -> Vec<(Count, Expect)> {
    leak_surfaces_tally(budget, Spots::Edges, 0x17_0003).counted_leaks()
}

/// The same rays: double hits.
fn shared_edge_doubles(budget: &Budget) -> Vec<(Count, Expect)> {
    leak_surfaces_tally(budget, Spots::Edges, 0x17_0003).counted_doubles()
}

/// Rays at the inner vertices of the same surfaces, from directions
/// their whole fan faces: leaks.
fn shared_vertex_leaks(budget: &Budget) -> Vec<(Count, Expect)> {
    leak_surfaces_tally(budget, Spots::Vertices, 0x17_0004).counted_leaks()
}

/// The same rays: double hits.
fn shared_vertex_doubles(budget: &Budget) -> Vec<(Count, Expect)> {
    leak_surfaces_tally(budget, Spots::Vertices, 0x17_0004).counted_doubles()
}

/// An icosphere rotated, scaled by 4 and its corners rounded to
/// multiples of 1/8 (shared corners stay shared: a closed mesh).
fn quantized_icosphere() -> Vec<Surface> {
    let mesh = icosphere(
        awkward_rotation(DVec3::new(-0.61, 0.15, 0.93), 2.3071),
        4.0,
        DVec3::new(0.5, -1.25, 2.0),
    );
    let round = |p: DVec3| (p * 8.0).round() / 8.0;
    let quantized: Vec<[DVec3; 3]> =
        mesh.iter().map(|v| v.map(round)).collect();
    vec![Surface::new(&quantized)]
}

/// Leaks plus double hits of rays made by `aim` at the edges and
/// vertices of `surfaces`: only the watertight test is built to have
/// none.
fn at_edges_and_vertices(
    surfaces: &[Surface], budget: &Budget, seed: u64, aim: Aim,
) -> Vec<(Count, Expect)> {
    let tally =
        leaks_and_doubles(surfaces, Spots::Both, budget.rays, seed, aim);
    tally.counted(tally.either())
}

/// Rays at lattice points of a quantized icosphere's edges and vertices
/// along small integer directions: leaks and double hits.
fn quantized_mesh(budget: &Budget) -> Vec<(Count, Expect)> {
    let surfaces = quantized_icosphere();
    at_edges_and_vertices(&surfaces, budget, 0x17_0005, aim_on_the_lattice)
}

/// Rays along the axes at lattice points of a quantized icosphere's
/// edges and vertices: every edge function exact, ties exactly 0.
fn axis_parallel(budget: &Budget) -> Vec<(Count, Expect)> {
    let surfaces = quantized_icosphere();
    at_edges_and_vertices(&surfaces, budget, 0x17_0006, aim_along_an_axis)
}

/// The same rays (the same seed) with the direction's zero components
/// −0.0: equal counts show that the sign of zero changes nothing.
fn negative_zero(budget: &Budget) -> Vec<(Count, Expect)> {
    let surfaces = quantized_icosphere();
    let aim = aim_along_an_axis_negative_zero;
    at_edges_and_vertices(&surfaces, budget, 0x17_0006, aim)
}

/// A flat grid of 6 × 6 squares split into triangles, on a tilted
/// lattice plane: corners O + i·U + j·W with integer O, U, W, so every
/// triangle lies exactly in one plane.
fn coplanar_grid() -> Vec<Surface> {
    let (o, u, w) = (
        DVec3::new(1000.0, -3.0, 7.0),
        DVec3::new(3.0, 1.0, -2.0),
        DVec3::new(-1.0, 2.0, 1.0),
    );
    let corner = |i: i32, j: i32| o + f64::from(i) * u + f64::from(j) * w;
    let mut triangles = Vec::new();
    for i in 0..6 {
        for j in 0..6 {
            let [p, q, r, s] = [(i, j), (i + 1, j), (i + 1, j + 1), (i, j + 1)]
                .map(|(a, b)| corner(a, b));
            // alternate the diagonal, so vertices have 4 and 8 triangles
            if (i + j) % 2 == 0 {
                triangles.extend([[p, q, r], [p, r, s]]);
            } else {
                triangles.extend([[p, q, s], [q, r, s]]);
            }
        }
    }
    vec![Surface::new(&triangles)]
}

/// Rays at the inner edges and vertices of a flat tilted grid: each
/// triangle computes its own plane, so chapter 2's test finds slightly
/// different hit points on either side of an edge.
fn coplanar_neighbours(budget: &Budget) -> Vec<(Count, Expect)> {
    let surfaces = coplanar_grid();
    at_edges_and_vertices(&surfaces, budget, 0x17_0007, aim_anywhere)
}

/// Rays at the edges and vertices of a closed mesh at 1e7 (radius 1.4;
/// the ulp there is 2e-9).
fn huge_coordinates(budget: &Budget) -> Vec<(Count, Expect)> {
    let mesh = icosphere(
        awkward_rotation(DVec3::new(0.2, 0.9, -0.4), 1.1731),
        1.377,
        DVec3::new(1.0e7 + 0.317, -7.3e6 - 0.21, 4.1e6 + 0.777),
    );
    let surfaces = [Surface::new(&mesh)];
    at_edges_and_vertices(&surfaces, budget, 0x17_0008, aim_anywhere)
}

/// A vertex on another triangle's edge: triangle A = (p, q, r) on one
/// side of p–q, triangles (m, p, s) and (q, m, s) on the other, with m
/// the exact midpoint of p–q (corners on a 1/8 lattice), folded a
/// little. Rays at points of p–q and at m: leaks and double hits.
fn t_junction(budget: &Budget) -> Vec<(Count, Expect)> {
    let lattice = |rng: &mut SplitMix64, lo: f64, hi: f64| {
        (uniform(rng, lo, hi) * 8.0).round() / 8.0
    };
    let failures = count_failures(budget.rays, 0x17_0009, |rng| {
        // Step 1: p–q along x, r on one side (+y), s on the other (−y),
        // each lifted a little in z.
        let p = DVec3::new(lattice(rng, -2.0, -1.0), 0.0, 0.0);
        let q = DVec3::new(lattice(rng, 1.0, 2.0), 0.0, 0.0);
        let r = DVec3::new(
            lattice(rng, -1.0, 1.0),
            lattice(rng, 1.0, 2.0),
            lattice(rng, -0.5, 0.5),
        );
        let s = DVec3::new(
            lattice(rng, -1.0, 1.0),
            lattice(rng, -2.0, -1.0),
            lattice(rng, -0.5, 0.5),
        );
        let lift = DVec3::new(
            lattice(rng, -4.0, 4.0),
            lattice(rng, -4.0, 4.0),
            lattice(rng, -4.0, 4.0),
        );
        // Step 2: all moved by an integer matrix of positive determinant
        // (lattice points stay lattice points, m stays the exact
        // midpoint, p–q leaves the axes), until a direction can face
        // all three triangles.
        let (mesh, normals, m) = loop {
            let mut entry = || below(rng, 4) as f64 - 1.0;
            let columns = [0; 3].map(|_| DVec3::new(entry(), entry(), entry()));
            let [x, y, z] = columns;
            if x.dot(y.cross(z)) <= 0.0 {
                continue;
            }
            let place = |v: DVec3| v.x * x + v.y * y + v.z * z + lift;
            let (p, q, r, s) = (place(p), place(q), place(r), place(s));
            let m = 0.5 * (p + q); // exact
            let mesh = [[p, q, r], [m, p, s], [q, m, s]];
            let normals = mesh.map(|v| normal(&v));
            let spot = Spot {
                ends: vec![p, q],
                normals: normals.to_vec(),
                near: Vec::new(),
            };
            if faceable(&spot) {
                break (mesh, normals, m);
            }
        };
        let [p, q] = [mesh[0][0], mesh[0][1]];
        // Step 3: a ray at m or at a point of p–q, facing all three.
        let target = if rng.next_f64() < 0.2 {
            m
        } else {
            p + rng.next_f64() * (q - p)
        };
        let d = facing(rng, &normals);
        let ray = ray_to(target, d, 8.0 * (1.0 + rng.next_f64()));
        not_hit_once(&mesh, &ray)
    });
    per_test(failures, budget.rays as u64, ALL_SHOWN)
}

// ---------------------------------------------------------------------
// Thin, flat and duplicated triangles.
// ---------------------------------------------------------------------

/// A needle's long edge a–b (a in the cube [−1, 1]³, b 0.5…2 away
/// along a random unit `along`), and a unit `across` ⟂ it.
fn long_edge(rng: &mut SplitMix64) -> (DVec3, DVec3, DVec3, DVec3) {
    let a = cube_point(rng);
    let along = rng.unit_vector();
    let across = along.any_orthonormal_vector();
    let b = a + uniform(rng, 0.5, 2.0) * along;
    (a, b, along, across)
}

/// A needle: V₀ random, V₁ 0.5…2 away, V₂ 1e-9 from V₁ across the
/// needle. Half the rays aim inside (barycentric coordinates ≥ 0.05:
/// must hit at t = 1 to 1e-6), half beside the long edge V₀V₁ by
/// 0.05…1 needle widths (must miss).
fn needles(budget: &Budget) -> Vec<(Count, Expect)> {
    let failures = count_failures(budget.rays, 0x17_000A, |rng| {
        let (v0, v1, along, across) = long_edge(rng);
        let v = [v0, v1, v1 + 1e-9 * across];
        let inside = rng.next_f64() < 0.5;
        // (u, w): u + w along the needle, w across it (w < 0: beside)
        let length = uniform(rng, 0.1, 0.9);
        let w = if inside {
            length * uniform(rng, 0.05, 0.95)
        } else {
            -length * uniform(rng, 0.05, 1.0)
        };
        let target = at(&v, length - w, w);
        let d = not_grazing(rng, along.cross(across));
        let ray = ray_to(target, d, 3.0);
        TriangleTest::ALL.map(|test| {
            let t = hit_once(test, v, &ray, Interval::FORWARD);
            if inside {
                !t.is_some_and(|t| (t - 1.0).abs() <= 1e-6)
            } else {
                t.is_some()
            }
        })
    });
    // The watertight test's edge functions have exact signs: only the
    // shear's rounding (1e-16) could move a corner, far below the
    // margin (5e-12). Chapter 2's plane of a needle is off by ~1e-7.
    per_test(failures, budget.rays as u64, WATERTIGHT_NEVER)
}

/// Two needles sharing their long edge a–b, their third corners 1e-9
/// either side of its middle (a thin quad split along its length).
/// Rays at points of a–b: leaks and double hits.
fn needle_pair(budget: &Budget) -> Vec<(Count, Expect)> {
    let failures = count_failures(budget.rays, 0x17_000B, |rng| {
        let (a, b, along, across) = long_edge(rng);
        let middle = 0.5 * (a + b);
        let (c, e) = (middle + 1e-9 * across, middle - 1e-9 * across);
        let mesh = [[a, b, c], [b, a, e]];
        let n = along.cross(across);
        let target = a + uniform(rng, 0.05, 0.95) * (b - a);
        let d = facing(rng, &[n]);
        not_hit_once(&mesh, &ray_to(target, d, 3.0))
    });
    per_test(failures, budget.rays as u64, WATERTIGHT_NEVER)
}

/// Triangles with exactly collinear corners (on a 1/8 lattice: a
/// repeated corner, or the third at a dyadic point of the line through
/// the first two), and rays aimed at points of that segment from any
/// direction. Any hit is wrong (a NaN t never counts as a hit: no
/// interval contains it). Chapter 8's functions are called directly.
fn zero_area(budget: &Budget) -> Vec<(Count, Expect)> {
    let failures = count_failures(budget.rays, 0x17_000C, |rng| {
        let lattice =
            |rng: &mut SplitMix64| (cube_point(rng) * 16.0).round() / 8.0;
        let (a, b) = (lattice(rng), lattice(rng));
        let c = match below(rng, 4) {
            0 => a,
            1 => b,
            2 => a + 0.5 * (b - a),
            _ => a + 2.0 * (b - a),
        };
        let mut v = [a, b, c];
        v.rotate_left(below(rng, 3));
        let target = a + rng.next_f64() * (b - a);
        let d = rng.unit_vector();
        let ray = Ray::new(target - 3.0 * d, d);
        hits_anywhere(v, &ray)
    });
    // Chapter 2's polygon refuses the corners. The watertight test sees
    // collinear corners as it sees a ray in the plane: their exact det is
    // 0, the computed one within the shear's rounding of 0, so no hit.
    let expect = [Expect::Never, Expect::Shown, Expect::Never];
    per_test(failures, budget.rays as u64, expect)
}

/// A triangle and a copy with its corners rotated (V₁, V₂, V₀) or
/// reversed (V₀, V₂, V₁), and rays aimed 1e-16…1e-9 inside or outside
/// an edge: the two must agree on hit or miss, and on t to 1e-12.
fn duplicated(budget: &Budget) -> Vec<(Count, Expect)> {
    let failures = count_failures(budget.rays, 0x17_000D, |rng| {
        let v = random_triangle(rng);
        let copy = if rng.next_f64() < 0.5 {
            [v[1], v[2], v[0]]
        } else {
            [v[0], v[2], v[1]]
        };
        // a point of a random edge, moved a hair across it
        let i = below(rng, 3);
        let (a, b, c) = (v[i], v[(i + 1) % 3], v[(i + 2) % 3]);
        let on_edge = a + uniform(rng, 0.05, 0.95) * (b - a);
        let inward = (c - on_edge).normalize();
        let sign = if rng.next_f64() < 0.5 { 1.0 } else { -1.0 };
        let target = on_edge + sign * decades(rng, -16.0, -9.0) * inward;
        let d = not_grazing(rng, normal(&v));
        let ray = ray_to(target, d, 3.0);
        TriangleTest::ALL.map(|test| {
            let first = hit_once(test, v, &ray, Interval::FORWARD);
            let second = hit_once(test, copy, &ray, Interval::FORWARD);
            match (first, second) {
                (None, None) => false,
                (Some(s), Some(t)) => (s - t).abs() > 1e-12 * s.abs(),
                _ => true,
            }
        })
    });
    // The watertight test computes the same three edge functions in any
    // order (negated, with exact signs, when reversed), so the copies
    // decide alike; Möller–Trumbore measures from V₀, and chapter 2's
    // plane is fixed from the first corners.
    per_test(failures, budget.rays as u64, WATERTIGHT_NEVER)
}

/// A random triangle scaled to 1e-310 (subnormal: about 44 bits left),
/// hit by unit rays from 3e-310 away, aimed at a point with barycentric
/// coordinates ≥ 0.1: a miss, or t off by more than 1e-6, fails.
fn denormal(budget: &Budget) -> Vec<(Count, Expect)> {
    const SCALE: f64 = 1e-310;
    let failures = count_failures(budget.rays, 0x17_000E, |rng| {
        let unscaled = random_triangle(rng);
        let v = unscaled.map(|p| p * SCALE);
        let (u, w) = (uniform(rng, 0.1, 0.45), uniform(rng, 0.1, 0.45));
        let target = at(&v, u, w);
        let d = not_grazing(rng, normal(&unscaled));
        let ray = Ray::new(target - 3.0 * SCALE * d, d);
        let expected = 3.0 * SCALE;
        TriangleTest::ALL.map(|test| {
            let t = hit_once(test, v, &ray, Interval::FORWARD);
            !t.is_some_and(|t| (t - expected).abs() <= 1e-6 * expected)
        })
    });
    per_test(failures, budget.rays as u64, ALL_SHOWN)
}

/// A ray aimed at a triangle's centroid with one or two of its six
/// numbers replaced by `bad`: any hit, or a panic, fails.
fn poisoned_rays(budget: &Budget, seed: u64, bad: &[f64]) -> [u64; 3] {
    count_failures(budget.rays, seed, |rng| {
        let v = random_triangle(rng);
        let from = 3.0 * cube_point(rng);
        let target = at(&v, 1.0 / 3.0, 1.0 / 3.0);
        let mut numbers = [from.to_array(), (target - from).to_array()];
        for _ in 0..1 + below(rng, 2) {
            numbers[below(rng, 2)][below(rng, 3)] = bad[below(rng, bad.len())];
        }
        let ray = Ray::new(
            DVec3::from_array(numbers[0]),
            DVec3::from_array(numbers[1]),
        );
        TriangleTest::ALL.map(|test| {
            let hit = catch_unwind(AssertUnwindSafe(|| {
                hit_once(test, v, &ray, Interval::FORWARD)
            }));
            !matches!(hit, Ok(None))
        })
    })
}

/// NaN in the origin or the direction.
fn nan_in_the_ray(budget: &Budget) -> Vec<(Count, Expect)> {
    let failures = poisoned_rays(budget, 0x17_000F, &[f64::NAN]);
    per_test(failures, budget.rays as u64, ALL_NEVER)
}

/// ±∞ in the origin or the direction.
fn infinity_in_the_ray(budget: &Budget) -> Vec<(Count, Expect)> {
    let failures =
        poisoned_rays(budget, 0x17_0010, &[f64::INFINITY, f64::NEG_INFINITY]);
    // The watertight test rejects a non-finite ray before its shear
    // (which would divide by the direction's ∞: every corner at z = 0,
    // and a hit at t = 0).
    per_test(failures, budget.rays as u64, ALL_NEVER)
}
