//! Exercise 2: the watertight ray–triangle test — its hits, and a closed
//! mesh that no ray leaks through and no ray hits twice.
use std::collections::HashMap;

use ch08::{DVec3, Interval, Ray, Triangle, TriangleTest, watertight};
use proptest::prelude::*;
use raystep_check::{Table, seeded};
use raystep_core::glam::DQuat;
use raystep_scene::Mesh;

fn v(x: f64, y: f64, z: f64) -> DVec3 {
    DVec3::new(x, y, z)
}

/// A tilted triangle away from every axis plane.
const TRIANGLE: [DVec3; 3] = [
    DVec3::new(1.0, 0.5, -0.25),
    DVec3::new(3.0, 1.0, 0.5),
    DVec3::new(1.5, 2.5, 1.25),
];

/// The point with barycentric coordinates (1 − u − w, u, w).
fn at(tri: &[DVec3; 3], u: f64, w: f64) -> DVec3 {
    tri[0] + u * (tri[1] - tri[0]) + w * (tri[2] - tri[0])
}

/// A ray from `from` aimed at `target`: it reaches the target at t = 1.
fn aimed(from: DVec3, target: DVec3) -> Ray {
    Ray::new(from, target - from)
}

fn reversed(tri: &[DVec3; 3]) -> [DVec3; 3] {
    [tri[0], tri[2], tri[1]]
}

/// Rays through the inside of the triangle hit it at the right t, from
/// either side and whichever way it winds.
#[test]
fn hits_inside_at_the_right_t_from_both_sides_and_windings() {
    let centroid = at(&TRIANGLE, 1.0 / 3.0, 1.0 / 3.0);
    for from in [v(0.5, 0.25, 9.0), v(4.0, -3.0, -7.0), v(-6.0, 1.0, 0.5)] {
        let ray = aimed(from, centroid);
        for tri in [TRIANGLE, reversed(&TRIANGLE)] {
            let t = watertight(&tri, &ray, Interval::FORWARD);
            assert!(
                t.is_some_and(|t| (t - 1.0).abs() < 1e-12),
                "a ray from {from} aimed at the centroid {centroid} of \
                 {tri:?}: expected a hit at t = 1, got {t:?}"
            );
        }
        // the same hit further along a ray with a longer direction
        let twice = Ray::new(from, 2.0 * (centroid - from));
        let t = watertight(&TRIANGLE, &twice, Interval::FORWARD);
        assert!(
            t.is_some_and(|t| (t - 0.5).abs() < 1e-12),
            "direction doubled: expected t = 0.5, got {t:?}"
        );
    }
}

/// Rays along each of the six axis directions (so each dominant axis, both
/// signs, for the shear) through a triangle facing them.
#[test]
fn every_dominant_axis_and_sign() {
    for axis in 0..3 {
        for sign in [1.0, -1.0] {
            let mut d = DVec3::ZERO;
            d[axis] = sign;
            // a triangle in the plane coordinate[axis] = 2, tilted a little
            let (i, j) = ((axis + 1) % 3, (axis + 2) % 3);
            let corner = |a: f64, b: f64, c: f64| {
                let mut p = DVec3::ZERO;
                (p[i], p[j], p[axis]) = (a, b, c);
                p
            };
            let tri = [
                corner(-1.0, -1.0, 2.0),
                corner(2.0, -1.0, 2.5),
                corner(-1.0, 2.0, 1.5),
            ];
            let origin = corner(0.0, 0.0, 0.0) - 10.0 * d;
            let ray = Ray::new(origin, d);
            // it crosses the plane through the three corners at height 2
            let expected = 10.0 + sign * 2.0;
            for tri in [tri, reversed(&tri)] {
                let t = watertight(&tri, &ray, Interval::FORWARD);
                assert!(
                    t.is_some_and(|t| (t - expected).abs() < 1e-12),
                    "a ray along {d} through {tri:?}: expected t = \
                     {expected}, got {t:?}"
                );
            }
            let beside = Ray::new(corner(1.5, 1.5, 0.0) - 10.0 * d, d);
            assert_eq!(
                watertight(&tri, &beside, Interval::FORWARD),
                None,
                "a ray along {d} beside the triangle"
            );
        }
    }
}

/// Misses: beside each edge and beyond each corner, parallel to the
/// plane, pointing away, and hits outside the interval.
#[test]
fn misses_and_the_interval() {
    let from = v(0.0, 0.0, 10.0);
    // just outside each edge (barycentric −0.01) and beyond each corner
    let outside = [
        (0.5, -0.01),
        (-0.01, 0.5),
        (0.51, 0.5),
        (1.2, -0.1),
        (-0.1, 1.2),
        (-0.1, -0.1),
    ];
    for (u, w) in outside {
        let ray = aimed(from, at(&TRIANGLE, u, w));
        assert_eq!(
            watertight(&TRIANGLE, &ray, Interval::FORWARD),
            None,
            "a ray aimed at barycentric ({u}, {w}), outside the triangle"
        );
    }
    let centroid = at(&TRIANGLE, 1.0 / 3.0, 1.0 / 3.0);
    let ray = aimed(from, centroid);
    assert_eq!(
        watertight(&TRIANGLE, &ray, Interval::new(0.0, 0.999)),
        None,
        "t = 1 is beyond the interval's max 0.999"
    );
    assert_eq!(
        watertight(&TRIANGLE, &ray, Interval::new(1.001, f64::INFINITY)),
        None,
        "t = 1 is before the interval's min 1.001"
    );
    let away = Ray::new(from, from - centroid);
    assert_eq!(
        watertight(&TRIANGLE, &away, Interval::FORWARD),
        None,
        "a ray pointing away from the triangle"
    );
    // parallel to the plane, a little above it
    let normal = (TRIANGLE[1] - TRIANGLE[0])
        .cross(TRIANGLE[2] - TRIANGLE[0])
        .normalize();
    let parallel = Ray::new(centroid + 0.1 * normal, TRIANGLE[1] - TRIANGLE[0]);
    assert_eq!(
        watertight(&TRIANGLE, &parallel, Interval::UNIVERSE),
        None,
        "a ray parallel to the triangle's plane, 0.1 above it"
    );
    let nan = Ray::new(v(f64::NAN, 0.0, 10.0), centroid - from);
    assert_eq!(
        watertight(&TRIANGLE, &nan, Interval::FORWARD),
        None,
        "a NaN origin"
    );
    let nan = Ray::new(from, v(0.1, f64::NAN, -1.0));
    assert_eq!(
        watertight(&TRIANGLE, &nan, Interval::FORWARD),
        None,
        "a NaN direction"
    );
}

/// Exact ties: flat triangles with small integer corners and rays straight
/// down (or up) at a shared edge or a shared vertex, where the edge
/// functions are exactly 0. Exactly one triangle owns each such point.
#[test]
fn a_shared_edge_or_vertex_belongs_to_exactly_one_triangle() {
    // a square split into four triangles around its centre, and a hexagon
    // split into six around its centre, all counter-clockwise from +z
    let c = v(1.0, 1.0, 0.0);
    let square = [
        v(0.0, 0.0, 0.0),
        v(2.0, 0.0, 0.0),
        v(2.0, 2.0, 0.0),
        v(0.0, 2.0, 0.0),
    ];
    let hexagon = [
        v(2.0, 0.0, 0.0),
        v(1.5, 1.0, 0.0),
        v(0.5, 1.0, 0.0),
        v(0.0, 0.0, 0.0),
        v(0.5, -1.0, 0.0),
        v(1.5, -1.0, 0.0),
    ];
    let hex_centre = v(1.0, 0.0, 0.0);
    let fan = |centre: DVec3, rim: &[DVec3]| -> Vec<[DVec3; 3]> {
        (0..rim.len())
            .map(|i| [centre, rim[i], rim[(i + 1) % rim.len()]])
            .collect()
    };
    let meshes = [
        (fan(c, &square), c),
        (fan(hex_centre, &hexagon), hex_centre),
    ];
    for (mesh, centre) in &meshes {
        // the centre vertex, each shared edge's midpoint and a point a
        // quarter along it
        let mut targets = vec![*centre];
        for tri in mesh {
            targets.push(0.5 * (tri[0] + tri[1]));
            targets.push(0.75 * tri[0] + 0.25 * tri[1]);
        }
        for target in targets {
            for (dx, dy, dz) in [
                (0.0, 0.0, -1.0),
                (0.0, 0.0, 1.0),
                (0.25, -0.5, -1.0),
                (-0.5, 0.125, 2.0),
            ] {
                let d = v(dx, dy, dz);
                let ray = Ray::new(target - 4.0 * d, d);
                let hits = mesh
                    .iter()
                    .filter(|tri| {
                        watertight(tri, &ray, Interval::FORWARD).is_some()
                    })
                    .count();
                assert_eq!(
                    hits, 1,
                    "a ray along {d} at {target}, on a shared edge or \
                     vertex: expected exactly one triangle to own it"
                );
            }
        }
    }
}

/// A rotation about an awkward axis by an awkward angle.
fn awkward_rotation(axis: DVec3, angle: f64) -> DQuat {
    DQuat::from_axis_angle(axis.normalize(), angle)
}

/// SplitMix64: numbers in [0, 1) from a fixed seed.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        ((z ^ (z >> 31)) >> 11) as f64 / (1u64 << 53) as f64
    }

    fn unit_vector(&mut self) -> DVec3 {
        loop {
            let p = v(self.next(), self.next(), self.next()) * 2.0 - 1.0;
            if (0.01..=1.0).contains(&p.length_squared()) {
                return p.normalize();
            }
        }
    }

    /// A direction D toward the surface that every normal in `normals`
    /// faces: D·n ≤ −0.3 for each (no silhouette).
    fn facing(&mut self, normals: &[DVec3]) -> DVec3 {
        let mean = normals.iter().sum::<DVec3>().normalize();
        loop {
            let d = -(mean + 0.7 * self.unit_vector()).normalize();
            if normals.iter().all(|n| d.dot(*n) <= -0.3) {
                return d;
            }
        }
    }
}

/// A closed test mesh: an icosphere, rotated, scaled and moved.
struct TestMesh {
    name: &'static str,
    mesh: Mesh,
}

impl TestMesh {
    fn new(
        name: &'static str,
        rotation: DQuat,
        scale: f64,
        centre: DVec3,
    ) -> TestMesh {
        let mut mesh = Mesh::icosphere(2);
        for p in &mut mesh.vertices {
            *p = centre + scale * (rotation * *p);
        }
        TestMesh { name, mesh }
    }

    fn normal(&self, k: usize) -> DVec3 {
        let [a, b, c] = self.mesh.triangle(k);
        (b - a).cross(c - a).normalize()
    }

    /// Every edge (smaller vertex index first) and its two triangles.
    fn edges(&self) -> Vec<((usize, usize), Vec<usize>)> {
        let mut edges: HashMap<(usize, usize), Vec<usize>> = HashMap::new();
        for (k, tri) in self.mesh.triangles.iter().enumerate() {
            for i in 0..3 {
                let (a, b) = (tri[i], tri[(i + 1) % 3]);
                edges.entry((a.min(b), a.max(b))).or_default().push(k);
            }
        }
        let mut edges: Vec<_> = edges.into_iter().collect();
        edges.sort();
        assert!(
            edges.iter().all(|(_, t)| t.len() == 2),
            "{}: not closed",
            self.name
        );
        edges
    }

    /// The triangles with a corner in `corners`.
    fn around(&self, corners: &[usize]) -> Vec<usize> {
        (0..self.mesh.triangles.len())
            .filter(|&k| {
                self.mesh.triangles[k].iter().any(|i| corners.contains(i))
            })
            .collect()
    }
}

/// Leaks and double hits of one test on a batch of rays.
#[derive(Default)]
struct Count {
    rays: usize,
    leaks: usize,
    doubles: usize,
}

/// Counts, per test, the hits each ray gets near t = 1 (where it meets
/// the mesh at its target) from the triangles near its target: `rays`
/// holds the triangles near a target and the rays aimed at it.
fn count(
    triangles: &[Vec<Triangle>; 3],
    rays: &[(Vec<usize>, Vec<Ray>)],
) -> [Count; 3] {
    let near = Interval::new(1.0 - 1e-6, 1.0 + 1e-6);
    let mut counts: [Count; 3] = Default::default();
    for (test, tally) in counts.iter_mut().enumerate() {
        for (nearby, aimed) in rays {
            for ray in aimed {
                let hits = nearby
                    .iter()
                    .filter(|&&k| triangles[test][k].hit_t(ray, near).is_some())
                    .count();
                tally.rays += 1;
                tally.leaks += usize::from(hits == 0);
                tally.doubles += usize::from(hits > 1);
            }
        }
    }
    counts
}

/// Rays aimed at points of shared edges (the midpoint and other points of
/// the edge, as floating point computes them) and at shared vertices of
/// two closed, tilted icospheres, one of them centred near 1e5, each ray
/// from outside and from a direction that all the triangles around its
/// target face (no silhouettes).
///
/// Each test counts LEAKS (no triangle reports a hit near the target) and
/// DOUBLE HITS (two or more do). The watertight test must have neither;
/// chapter 2's plane + inside test and Möller–Trumbore are counted.
#[test]
fn closed_meshes_neither_leak_nor_double_hit() {
    let meshes = [
        TestMesh::new(
            "tilted, near the origin",
            awkward_rotation(v(0.3, -0.7, 0.2), 0.9137),
            0.7313,
            v(3.217, -1.91, 0.473),
        ),
        TestMesh::new(
            "tilted, centred near 1e5",
            awkward_rotation(v(-0.61, 0.15, 0.93), 2.3071),
            1.377,
            v(1.0e5 + 0.317, -7.3e4 - 0.21, 4.1e4 + 0.777),
        ),
    ];
    let mut rng = Rng(0x0008_5EED);
    let mut table = Table::new(&[
        "mesh",
        "aimed at",
        "rays",
        "test",
        "leaks",
        "double hits",
    ]);
    let mut total = 0;
    for tm in &meshes {
        let triangles = TriangleTest::ALL.map(|test| {
            (0..tm.mesh.triangles.len())
                .map(|k| Triangle::new(tm.mesh.triangle(k), test).unwrap())
                .collect::<Vec<_>>()
        });
        let size = tm.mesh.bounds().max - tm.mesh.bounds().min;
        let distance = || 3.0 * size.max_element();
        // Edges: the midpoint, and points a random fraction along.
        let mut edge_rays = Vec::new();
        for ((a, b), pair) in tm.edges() {
            let (pa, pb) = (tm.mesh.vertices[a], tm.mesh.vertices[b]);
            let normals = [tm.normal(pair[0]), tm.normal(pair[1])];
            let nearby = tm.around(&[a, b]);
            let mut rays = Vec::new();
            for k in 0..EDGE_POINTS {
                let target = if k == 0 {
                    0.5 * (pa + pb)
                } else {
                    pa + rng.next() * (pb - pa)
                };
                for _ in 0..DIRECTIONS {
                    let d = rng.facing(&normals);
                    let from = target - (1.0 + rng.next()) * distance() * d;
                    rays.push(Ray::new(from, target - from));
                }
            }
            edge_rays.push((nearby, rays));
        }
        // Vertices: every vertex with its whole fan facing the ray.
        let mut vertex_rays = Vec::new();
        for i in 0..tm.mesh.vertices.len() {
            let fan = tm.around(&[i]);
            let normals: Vec<DVec3> =
                fan.iter().map(|&k| tm.normal(k)).collect();
            let ring: Vec<usize> =
                fan.iter().flat_map(|&k| tm.mesh.triangles[k]).collect();
            let nearby = tm.around(&ring);
            let target = tm.mesh.vertices[i];
            let rays = (0..VERTEX_DIRECTIONS)
                .map(|_| {
                    let d = rng.facing(&normals);
                    let from = target - (1.0 + rng.next()) * distance() * d;
                    Ray::new(from, target - from)
                })
                .collect();
            vertex_rays.push((nearby, rays));
        }
        for (aimed_at, rays) in [
            ("shared edges", &edge_rays),
            ("shared vertices", &vertex_rays),
        ] {
            let counts = count(&triangles, rays);
            for (test, c) in TriangleTest::ALL.iter().zip(&counts) {
                table.row(&[
                    tm.name.to_string(),
                    aimed_at.to_string(),
                    c.rays.to_string(),
                    test.name().to_string(),
                    c.leaks.to_string(),
                    c.doubles.to_string(),
                ]);
                if *test == TriangleTest::Watertight {
                    assert!(
                        c.leaks == 0 && c.doubles == 0,
                        "{}, rays at {aimed_at}: expected the watertight \
                         test to have 0 leaks and 0 double hits, got {} \
                         leaks and {} double hits in {} rays",
                        tm.name,
                        c.leaks,
                        c.doubles,
                        c.rays
                    );
                }
            }
            total += counts[0].rays;
        }
    }
    assert!(total >= 100_000, "expected at least 1e5 rays, made {total}");
    insta::assert_snapshot!(table.to_string());
}

/// Points per shared edge (the first is its midpoint).
const EDGE_POINTS: usize = 10;
/// Directions per point on an edge.
const DIRECTIONS: usize = 10;
/// Directions per shared vertex.
const VERTEX_DIRECTIONS: usize = 50;

/// Barycentric coordinates (u, w) of a point at least `margin` inside
/// the triangle.
fn inside(margin: f64) -> impl Strategy<Value = (f64, f64)> {
    (margin..1.0 - 2.0 * margin, margin..1.0 - 2.0 * margin)
        .prop_filter("inside", move |(u, w)| u + w <= 1.0 - margin)
}

fn corner() -> impl Strategy<Value = DVec3> {
    (-10.0..10.0f64, -10.0..10.0f64, -10.0..10.0f64)
        .prop_map(|(x, y, z)| v(x, y, z))
}

fn triangle() -> impl Strategy<Value = [DVec3; 3]> {
    (corner(), corner(), corner())
        .prop_map(|(a, b, c)| [a, b, c])
        .prop_filter("not too thin", |[a, b, c]| {
            let (e1, e2) = (*b - *a, *c - *a);
            e1.cross(e2).length() > 0.05 * e1.length() * e2.length()
        })
}

proptest! {
    #![proptest_config(seeded(512))]

    /// A ray aimed at a point inside a random triangle hits it there
    /// (t = 1), whichever way the triangle winds.
    #[test]
    fn aimed_inside_hits(
        tri in triangle(),
        (u, w) in inside(1e-3),
        from in corner(),
    ) {
        let target = at(&tri, u, w);
        let ray = aimed(from * 3.0, target);
        let normal = (tri[1] - tri[0]).cross(tri[2] - tri[0]).normalize();
        prop_assume!(ray.direction.normalize().dot(normal).abs() > 0.05);
        for tri in [tri, reversed(&tri)] {
            let t = watertight(&tri, &ray, Interval::FORWARD);
            prop_assert!(
                t.is_some_and(|t| (t - 1.0).abs() < 1e-9),
                "{tri:?}, ray {ray:?} aimed at barycentric ({u}, {w}): \
                 expected a hit at t = 1, got {t:?}"
            );
        }
    }

    /// A ray aimed at a point outside a random triangle (beyond one edge)
    /// misses it.
    #[test]
    fn aimed_outside_misses(
        tri in triangle(),
        (u, w) in inside(1e-3),
        past in 1e-3..1.0f64,
        edge in 0..3usize,
        from in corner(),
    ) {
        // move the point beyond one edge's line (in barycentrics)
        let (u, w) = match edge {
            0 => (u, -past),           // beyond V₀V₁
            1 => (-past, w),           // beyond V₀V₂
            _ => (u + past, w + past), // beyond V₁V₂ (u + w > 1)
        };
        prop_assume!(edge != 2 || u + w > 1.0 + 1e-3);
        let target = at(&tri, u, w);
        let ray = aimed(from * 3.0, target);
        let normal = (tri[1] - tri[0]).cross(tri[2] - tri[0]).normalize();
        prop_assume!(ray.direction.normalize().dot(normal).abs() > 0.05);
        let t = watertight(&tri, &ray, Interval::FORWARD);
        prop_assert!(
            t.is_none(),
            "{tri:?}, ray {ray:?} aimed at barycentric ({u}, {w}), outside: \
             expected a miss, got {t:?}"
        );
    }
}
