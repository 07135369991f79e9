//! Exercise 2: the watertight ray–triangle test — its hits, and a closed
//! mesh that no ray leaks through and no ray hits twice.
mod common;

use std::collections::HashMap;

use ch08::{DVec3, Interval, Ray, Triangle, TriangleTest, watertight};
use common::{Rng, unit_vector};
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
                "a ray along {d} beside the triangle: expected None (a miss)"
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
            "a ray aimed at barycentric ({u}, {w}), outside the triangle: \
             expected None (a miss)"
        );
    }
    let centroid = at(&TRIANGLE, 1.0 / 3.0, 1.0 / 3.0);
    let ray = aimed(from, centroid);
    assert_eq!(
        watertight(&TRIANGLE, &ray, Interval::new(0.0, 0.999)),
        None,
        "t = 1 is beyond the interval's max 0.999: expected None"
    );
    assert_eq!(
        watertight(&TRIANGLE, &ray, Interval::new(1.001, f64::INFINITY)),
        None,
        "t = 1 is before the interval's min 1.001: expected None"
    );
    let away = Ray::new(from, from - centroid);
    assert_eq!(
        watertight(&TRIANGLE, &away, Interval::FORWARD),
        None,
        "a ray pointing away from the triangle: expected None"
    );
    // parallel to the plane, a little above it
    let normal = (TRIANGLE[1] - TRIANGLE[0])
        .cross(TRIANGLE[2] - TRIANGLE[0])
        .normalize();
    let parallel = Ray::new(centroid + 0.1 * normal, TRIANGLE[1] - TRIANGLE[0]);
    assert_eq!(
        watertight(&TRIANGLE, &parallel, Interval::UNIVERSE),
        None,
        "a ray parallel to the triangle's plane, 0.1 above it: expected \
         None"
    );
    let nan = Ray::new(v(f64::NAN, 0.0, 10.0), centroid - from);
    assert_eq!(
        watertight(&TRIANGLE, &nan, Interval::FORWARD),
        None,
        "a NaN origin: expected None"
    );
    let nan = Ray::new(from, v(0.1, f64::NAN, -1.0));
    assert_eq!(
        watertight(&TRIANGLE, &nan, Interval::FORWARD),
        None,
        "a NaN direction: expected None"
    );
}

/// A ray with a NaN or an infinity in any of its six numbers hits
/// nothing. An infinite direction is the one the other steps do not
/// catch: the shear turns it into 0s, every corner lands at z = 0 and the
/// ray would be reported hitting at t = 0; so each ray here starts on
/// the line through the triangle's centroid along the axis that goes
/// infinite.
#[test]
fn a_ray_with_an_infinity_or_a_nan_hits_nothing() {
    let centroid = at(&TRIANGLE, 1.0 / 3.0, 1.0 / 3.0);
    for bad in [f64::INFINITY, f64::NEG_INFINITY, f64::NAN] {
        for axis in 0..3 {
            for in_origin in [false, true] {
                let (mut o, mut d) = (centroid, v(0.125, -0.25, 0.5));
                o[axis] -= 3.0;
                if in_origin {
                    o[axis] = bad;
                } else {
                    d[axis] = bad;
                }
                let ray = Ray::new(o, d);
                for interval in [Interval::FORWARD, Interval::UNIVERSE] {
                    let t = watertight(&TRIANGLE, &ray, interval);
                    assert_eq!(
                        t, None,
                        "a ray from {o} along {d}, t in [{}, {}]: expected \
                         None (a NaN or an infinity in the ray hits \
                         nothing), got {t:?}",
                        interval.min, interval.max
                    );
                }
            }
        }
    }
}

/// A ray lying in the triangle's plane is seen edge-on: det = 0, a miss
/// (in a closed mesh the neighbouring triangles' edges meet it). Every
/// number here is a small integer, so each ray lies in its triangle's
/// plane exactly and crosses the triangle's inside; but the shear's
/// D[kx]/D[kz] and D[ky]/D[kz] round, the sheared corners are then not
/// exactly on one line, and det is not exactly 0.
#[test]
fn a_ray_in_the_triangles_plane_hits_nothing() {
    let planes = [
        // a triangle's corner and two edges, tilted away from every axis
        (v(1.0, -2.0, 3.0), v(3.0, 1.0, -2.0), v(-1.0, 2.0, 1.0)),
        (v(-5.0, 4.0, 7.0), v(7.0, 3.0, 5.0), v(2.0, -6.0, 3.0)),
        (v(0.0, 0.0, 0.0), v(6.0, 0.0, 1.0), v(0.0, 6.0, 5.0)),
        // and one in the plane z = 2, where the shear is exact
        (v(0.0, 0.0, 2.0), v(5.0, 1.0, 0.0), v(-1.0, 4.0, 0.0)),
    ];
    let mut rays = 0;
    for (corner, e1, e2) in planes {
        let tri = [corner, corner + e1, corner + e2];
        // the ray from (a, b) to the inside point (1/4, 1/4) (in units of
        // the edges), with a and b from −3 to 3, and along that line from
        // inside the triangle too
        for (a, b) in (-3..=3).flat_map(|a| (-3..=3).map(move |b| (a, b))) {
            let (a, b) = (f64::from(a), f64::from(b));
            let (du, dw) = (1.0 - 4.0 * a, 1.0 - 4.0 * b);
            if (du, dw) == (0.0, 0.0) {
                continue;
            }
            let d = du * e1 + dw * e2;
            for from in [corner + a * e1 + b * e2, corner] {
                for tri in [tri, reversed(&tri)] {
                    let ray = Ray::new(from, d);
                    let t = watertight(&tri, &ray, Interval::UNIVERSE);
                    assert_eq!(
                        t,
                        None,
                        "{}: a ray from {from} along {d}, lying in the \
                         triangle's plane: expected None (seen edge-on, \
                         det = 0 but for the shear's rounding), got {t:?}",
                        corners(&tri)
                    );
                    rays += 1;
                }
            }
        }
    }
    assert!(rays > 300, "{rays} rays");
}

/// Rays in the plane of a random triangle to within rounding (their
/// origin and direction computed from the corners), through its inside: a
/// miss, or a hit where the ray's line crosses the triangle (its t within
/// 1e-9 of that stretch). A hit anywhere else is the noise of a det that
/// should count as 0.
#[test]
fn a_ray_almost_in_the_plane_misses_or_hits_where_it_crosses() {
    let mut rng = Rng::new(0x0008_1A4E);
    for _ in 0..20_000 {
        let tri = loop {
            let tri = [rng.vec3(1.0), rng.vec3(1.0), rng.vec3(1.0)];
            let (e1, e2) = (tri[1] - tri[0], tri[2] - tri[0]);
            if e1.cross(e2).length() > 0.2 * e1.length() * e2.length() {
                break tri;
            }
        };
        // the origin outside, the line through the inside, and the
        // stretch of t where the ray is in the triangle
        let inside = (rng.uniform(0.1, 0.45), rng.uniform(0.1, 0.45));
        let angle = rng.uniform(0.0, std::f64::consts::TAU);
        let (ray, lo, hi) = raystep_check::ray_in_plane(&tri, inside, angle);
        let t = watertight(&tri, &ray, Interval::UNIVERSE);
        assert!(
            t.is_none_or(|t| (lo - 1e-9..=hi + 1e-9).contains(&t)),
            "{}: a ray from {} along {}, in the triangle's plane to within \
             rounding, crossing it for t in [{lo}, {hi}]: expected None or \
             a hit in that stretch, got {t:?}",
            corners(&tri),
            ray.origin,
            ray.direction
        );
    }
}

/// A flat mesh for exact ties: its triangles and the points on its shared
/// edges and vertices that the tests aim at, every coordinate a short
/// binary fraction.
struct FlatMesh {
    name: &'static str,
    triangles: Vec<[DVec3; 3]>,
    targets: Vec<DVec3>,
}

/// `(a, b, c)` with `c` along `axis` and `a`, `b` along the two axes after
/// it (a cyclic turn of x, y, z: windings are kept).
fn on_axis(axis: usize, (a, b, c): (f64, f64, f64)) -> DVec3 {
    let mut p = DVec3::ZERO;
    (p[(axis + 1) % 3], p[(axis + 2) % 3], p[axis]) = (a, b, c);
    p
}

/// A square split into four triangles around its centre and a hexagon
/// split into six, counter-clockwise seen from +`axis`, in the plane
/// coordinate[axis] = 0. Aimed at: the centre vertex, each shared edge's
/// midpoint and a point a quarter along it.
fn fans(axis: usize) -> Vec<FlatMesh> {
    let at = |a: f64, b: f64| on_axis(axis, (a, b, 0.0));
    let fan = |name, centre: DVec3, rim: &[DVec3]| {
        let triangles: Vec<[DVec3; 3]> = (0..rim.len())
            .map(|i| [centre, rim[i], rim[(i + 1) % rim.len()]])
            .collect();
        let mut targets = vec![centre];
        for tri in &triangles {
            targets.push(0.5 * (tri[0] + tri[1]));
            targets.push(0.75 * tri[0] + 0.25 * tri[1]);
        }
        FlatMesh {
            name,
            triangles,
            targets,
        }
    };
    let square = [at(0.0, 0.0), at(2.0, 0.0), at(2.0, 2.0), at(0.0, 2.0)];
    let hexagon = [
        at(2.0, 0.0),
        at(1.5, 1.0),
        at(0.5, 1.0),
        at(0.0, 0.0),
        at(0.5, -1.0),
        at(1.5, -1.0),
    ];
    vec![
        fan("a square fan", at(1.0, 1.0), &square),
        fan("a hexagon fan", at(1.0, 0.0), &hexagon),
    ]
}

/// Two triangles sharing the diagonal edge P → Q, both listing it in that
/// order, so that they wind opposite ways (one counter-clockwise seen from
/// +`axis`, one clockwise): a mesh may mix windings. Aimed at points of
/// the shared edge.
fn opposite_windings(axis: usize) -> FlatMesh {
    let at = |a: f64, b: f64| on_axis(axis, (a, b, 0.0));
    let (p, q) = (at(0.0, 0.0), at(2.0, 2.0));
    FlatMesh {
        name: "two triangles wound opposite ways, [P, Q, R] and [P, Q, S]",
        triangles: vec![[p, q, at(0.0, 2.0)], [p, q, at(2.0, 0.0)]],
        targets: vec![at(1.0, 1.0), at(0.5, 0.5), at(1.5, 1.5)],
    }
}

/// Directions toward the plane coordinate[axis] = 0: straight down and up
/// along `axis`, and tilted ones (with components of both signs).
fn tie_directions(axis: usize) -> Vec<DVec3> {
    [
        (0.0, 0.0, -1.0),
        (0.0, 0.0, 1.0),
        (0.25, -0.5, -1.0),
        (-0.5, 0.125, 2.0),
        (0.75, 0.5, 1.0),
        (-0.25, -0.75, -2.0),
    ]
    .map(|d| on_axis(axis, d))
    .to_vec()
}

/// `[a, b, c]`, each corner as x, y, z to the last bit.
fn corners(tri: &[DVec3; 3]) -> String {
    let [a, b, c] = tri.map(|p| p.to_string());
    format!("[{a}, {b}, {c}]")
}

/// Which of `triangles` the ray hits (forward).
fn hit_by(triangles: &[[DVec3; 3]], ray: &Ray) -> Vec<usize> {
    (0..triangles.len())
        .filter(|&k| {
            watertight(&triangles[k], ray, Interval::FORWARD).is_some()
        })
        .collect()
}

/// Every ray at a tie point of `mesh` (along the directions of
/// [`tie_directions`]): its target, its direction and the triangles it
/// hits.
fn tie_hits(mesh: &FlatMesh, axis: usize) -> Vec<(DVec3, DVec3, Vec<usize>)> {
    let mut hits = Vec::new();
    for &target in &mesh.targets {
        for d in tie_directions(axis) {
            let ray = Ray::new(target - 4.0 * d, d);
            hits.push((target, d, hit_by(&mesh.triangles, &ray)));
        }
    }
    hits
}

/// Exact ties: flat triangles with small binary-fraction corners and rays
/// at a shared edge or a shared vertex, where the edge functions are
/// exactly 0. Exactly one triangle owns each such point.
#[test]
fn a_shared_edge_or_vertex_belongs_to_exactly_one_triangle() {
    for axis in 0..3 {
        for mesh in fans(axis) {
            for (target, d, hits) in tie_hits(&mesh, axis) {
                assert_eq!(
                    hits.len(),
                    1,
                    "{}: a ray along {d} at {target}, on a shared edge or \
                     vertex: expected exactly one triangle to own it, got \
                     hits from triangles {hits:?}",
                    mesh.name
                );
            }
        }
    }
}

/// Two triangles that list their shared edge the same way round wind
/// opposite ways: whichever way the ray comes, it sees one of them
/// clockwise (det < 0). That one must walk its edges the other way round
/// before the tie rule, or both would own the edge (2 hits) or neither
/// (a leak).
#[test]
fn triangles_wound_opposite_ways_share_an_edge_once() {
    for axis in 0..3 {
        let mesh = opposite_windings(axis);
        for (target, d, hits) in tie_hits(&mesh, axis) {
            assert_eq!(
                hits.len(),
                1,
                "{}, P = {}, Q = {}: a ray along {d} at {target} on the \
                 shared edge: expected exactly 1 hit (the triangle the ray \
                 sees clockwise walks its edges reversed before the tie \
                 rule), got {} (from triangles {hits:?})",
                mesh.name,
                mesh.triangles[0][0],
                mesh.triangles[0][1],
                hits.len()
            );
        }
    }
}

/// Step 1's axes for a direction: kz along the largest |component|, then
/// kx and ky after it, swapped if the ray goes toward −kz.
fn sheared_axes(d: DVec3) -> (usize, usize) {
    let kz = d.abs().max_position();
    let (kx, ky) = ((kz + 1) % 3, (kz + 2) % 3);
    if d[kz] < 0.0 { (ky, kx) } else { (kx, ky) }
}

/// Which triangle owns a tie. Chapter 2's tie rule is the same as moving
/// the point right by δ and up by δ²; in the sheared plane across the ray
/// (x along kx, y along ky, the triangle keeping its winding as the ray
/// sees it) that is moving the ray by δ along +kx and δ² along +ky. The
/// moved ray is on no edge, so which triangle it hits is plain geometry:
/// the ray on the edge must count for that same triangle. (Which one that
/// is changes if the axes are not swapped for a ray toward −kz, if a
/// clockwise triangle walks its edges as listed, or if the rule is
/// inverted; the chapter's mesh walk, `PreparedRay`, shears with step 1's
/// axes too, and must give the same triangle as `watertight`.)
#[test]
fn a_tie_goes_to_the_triangle_a_nudged_ray_hits() {
    let delta = 2f64.powi(-10);
    for axis in 0..3 {
        let mut meshes = fans(axis);
        meshes.push(opposite_windings(axis));
        for mesh in &meshes {
            for &target in &mesh.targets {
                for d in tie_directions(axis) {
                    let ray = Ray::new(target - 4.0 * d, d);
                    let (kx, ky) = sheared_axes(d);
                    let mut nudge = DVec3::ZERO;
                    nudge[kx] = delta;
                    nudge[ky] = delta * delta;
                    let nudged = Ray::new(ray.origin + nudge, d);
                    let owner = hit_by(&mesh.triangles, &nudged);
                    assert_eq!(
                        owner.len(),
                        1,
                        "test setup: {}, the ray along {d} at {target} \
                         moved by {nudge} should hit one triangle",
                        mesh.name
                    );
                    let hits = hit_by(&mesh.triangles, &ray);
                    let names = ["x", "y", "z"];
                    assert_eq!(
                        hits,
                        owner,
                        "{}: a ray along {d} exactly through {target} (on a \
                         shared edge or vertex): expected it to count for \
                         triangle {} {}, the one the ray moved by 2⁻¹⁰ \
                         along +{} and 2⁻²⁰ along +{} hits (chapter 2's tie \
                         rule in step 1's sheared axes kx = {}, ky = {}), \
                         got hits from triangles {hits:?}",
                        mesh.name,
                        owner[0],
                        corners(&mesh.triangles[owner[0]]),
                        names[kx],
                        names[ky],
                        names[kx],
                        names[ky],
                    );
                }
            }
        }
    }
}

/// An edge function whose exact value is tiny but whose fast value, two
/// rounded products subtracted, is exactly 0: the corners P and Q below
/// (sheared by a ray along ±z to their own x and y) give
/// P.x·Q.y − P.y·Q.x = −2⁻¹⁰⁴ exactly, while both products round to
/// −(1 + 2⁻⁵¹). The ray passes 2⁻¹⁰⁴ inside triangle B, across the edge it
/// shares with A: the sign must come from the exact fallback, not from
/// the tie rule (which would hand the point to A).
#[test]
fn a_tiny_edge_function_gets_its_exact_sign() {
    let u = f64::EPSILON; // 2⁻⁵²
    let p = v(1.0 + u, 1.0 + 2.0 * u, 0.0);
    let q = v(-1.0, -(1.0 + u), 0.0);
    let a = [p, q, v(1.0, -1.0, 0.0)];
    let b = [q, p, v(-1.0, 1.0, 0.0)];
    for (origin, d) in [
        (v(0.0, 0.0, -1.0), v(0.0, 0.0, 1.0)),
        (v(0.0, 0.0, 1.0), v(0.0, 0.0, -1.0)),
    ] {
        let ray = Ray::new(origin, d);
        let got = (
            watertight(&a, &ray, Interval::FORWARD),
            watertight(&b, &ray, Interval::FORWARD),
        );
        assert_eq!(
            got,
            (None, Some(1.0)),
            "a ray from {origin} along {d} through (0, 0, 0), 2⁻¹⁰⁴ inside \
             B = {} across the edge it shares with A = {} (the fast edge \
             function rounds to 0 there; the exact one is −2⁻¹⁰⁴): expected \
             (A, B) = (None, Some(1.0)), got {got:?}",
            corners(&b),
            corners(&a)
        );
    }
}

/// A direction D toward the surface that every normal in `normals`
/// faces: D·n ≤ −0.3 for each (no silhouette).
fn facing(rng: &mut Rng, normals: &[DVec3]) -> DVec3 {
    let mean = normals.iter().sum::<DVec3>().normalize();
    loop {
        let d = -(mean + 0.7 * unit_vector(rng)).normalize();
        if normals.iter().all(|n| d.dot(*n) <= -0.3) {
            return d;
        }
    }
}

/// A rotation about an awkward axis by an awkward angle.
fn awkward_rotation(axis: DVec3, angle: f64) -> DQuat {
    DQuat::from_axis_angle(axis.normalize(), angle)
}

/// A closed test mesh: an icosphere, rotated, scaled and moved.
struct TestMesh {
    name: &'static str,
    mesh: Mesh,
}

impl TestMesh {
    fn new(
        name: &'static str, rotation: DQuat, scale: f64, centre: DVec3,
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
    triangles: &[Vec<Triangle>; 3], rays: &[(Vec<usize>, Vec<Ray>)],
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
    let mut rng = Rng::new(0x0008_5EED);
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
                    pa + rng.unit() * (pb - pa)
                };
                for _ in 0..DIRECTIONS {
                    let d = facing(&mut rng, &normals);
                    let from = target - (1.0 + rng.unit()) * distance() * d;
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
                    let d = facing(&mut rng, &normals);
                    let from = target - (1.0 + rng.unit()) * distance() * d;
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
