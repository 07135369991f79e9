//! The fast primitives — box, cylinder, ellipsoid, chapter 3's sphere,
//! chapter 2's polygon and the three triangles — against analytic hits,
//! from inside, inside their bounds, and refusing bad parameters.
mod common;

use std::f64::consts::TAU;

use ch02::Polygon;
use ch03::Sphere;
use ch08::{
    Aabb, AxisBox, BoundingSphere, Cylinder, DVec3, Ellipsoid, Hit, Interval,
    Primitive, Ray, Shape, Triangle, TriangleTest,
};
use common::Rng;
use proptest::prelude::*;
use raystep_check::{Table, num, seeded, vec3};

fn v(x: f64, y: f64, z: f64) -> DVec3 {
    DVec3::new(x, y, z)
}

/// The lecture's box: [−1, 1] × [−2, 3] × [0.5, 4].
fn the_box() -> AxisBox {
    AxisBox::new(v(-1.0, -2.0, 0.5), v(1.0, 3.0, 4.0)).unwrap()
}

/// A unit axis a = (1, 2, 2)/3 and two unit vectors across it.
const A: DVec3 = DVec3::new(1.0 / 3.0, 2.0 / 3.0, 2.0 / 3.0);
const U: DVec3 = DVec3::new(2.0 / 3.0, -2.0 / 3.0, 1.0 / 3.0);
const W: DVec3 = DVec3::new(2.0 / 3.0, 1.0 / 3.0, -2.0 / 3.0);

/// Upright: base at the origin, height 2, radius 1.
fn upright_cylinder() -> Cylinder {
    Cylinder::new(DVec3::ZERO, v(0.0, 0.0, 2.0), 1.0).unwrap()
}

/// Tilted along `A`: base (1, 1, 1), height 4, radius 0.5.
fn tilted_cylinder() -> Cylinder {
    let base = v(1.0, 1.0, 1.0);
    Cylinder::new(base, base + 4.0 * A, 0.5).unwrap()
}

fn the_ellipsoid() -> Ellipsoid {
    Ellipsoid::new(v(1.0, -2.0, 3.0), v(2.0, 1.0, 0.5)).unwrap()
}

/// A square in the plane z = 1, counter-clockwise seen from +z.
fn the_square() -> Polygon {
    Polygon::new(vec![
        v(0.0, 0.0, 1.0),
        v(2.0, 0.0, 1.0),
        v(2.0, 2.0, 1.0),
        v(0.0, 2.0, 1.0),
    ])
    .unwrap()
}

/// The triangle cutting the corner off the positive octant, its normal
/// (1, 1, 1)/√3.
const CORNER: [DVec3; 3] = [
    DVec3::new(1.0, 0.0, 0.0),
    DVec3::new(0.0, 1.0, 0.0),
    DVec3::new(0.0, 0.0, 1.0),
];

/// One analytic case: a ray and the hit it must get (or a miss).
struct Analytic {
    shape: Box<dyn Primitive>,
    ray: Ray,
    expected: Option<(f64, DVec3, DVec3)>,
}

fn case(
    shape: impl Primitive + 'static, from: DVec3, direction: DVec3,
    expected: Option<(f64, DVec3, DVec3)>,
) -> Analytic {
    Analytic {
        shape: Box::new(shape),
        ray: Ray::new(from, direction),
        expected,
    }
}

fn analytic_cases() -> Vec<Analytic> {
    let (cyl, tilted, ell) =
        (upright_cylinder(), tilted_cylinder(), the_ellipsoid());
    let mid = tilted.base() + 2.0 * A; // halfway up the tilted axis
    let top = tilted.top();
    let theta = 60f64.to_radians();
    // a point of the ellipsoid at 60° in its xy section, and its normal
    // from the gradient (p − c)/r²
    let p = ell.center() + v(2.0 * theta.cos(), theta.sin(), 0.0);
    let n = v(2.0 * theta.cos() / 4.0, theta.sin(), 0.0).normalize();
    let third = 1.0 / 3.0;
    let diagonal = DVec3::splat(1.0 / 3f64.sqrt());
    let mut cases = vec![
        // the box: each entry face, from inside, a miss
        case(
            the_box(),
            v(-5.0, 0.0, 1.0),
            DVec3::X,
            Some((4.0, v(-1.0, 0.0, 1.0), -DVec3::X)),
        ),
        case(
            the_box(),
            v(0.0, 10.0, 2.0),
            v(0.0, -2.0, 0.0),
            Some((3.5, v(0.0, 3.0, 2.0), DVec3::Y)),
        ),
        case(
            the_box(),
            v(0.25, 0.5, 10.0),
            -DVec3::Z,
            Some((6.0, v(0.25, 0.5, 4.0), DVec3::Z)),
        ),
        case(
            the_box(),
            v(0.0, 0.0, 2.0),
            v(1.0, 1.0, 0.0),
            Some((1.0, v(1.0, 1.0, 2.0), DVec3::X)),
        ),
        case(
            the_box(),
            v(0.0, 0.0, 2.0),
            v(0.0, 0.0, -3.0),
            Some((0.5, v(0.0, 0.0, 0.5), -DVec3::Z)),
        ),
        case(the_box(), v(5.0, 5.0, 5.0), DVec3::X, None),
        // the upright cylinder: side, both caps, from inside, a miss
        case(
            cyl,
            v(-5.0, 0.0, 1.0),
            DVec3::X,
            Some((4.0, v(-1.0, 0.0, 1.0), -DVec3::X)),
        ),
        case(
            cyl,
            v(0.5, 0.0, 5.0),
            -DVec3::Z,
            Some((3.0, v(0.5, 0.0, 2.0), DVec3::Z)),
        ),
        case(
            cyl,
            v(0.0, 0.25, -3.0),
            DVec3::Z,
            Some((3.0, v(0.0, 0.25, 0.0), -DVec3::Z)),
        ),
        case(
            cyl,
            v(0.0, 0.0, 1.0),
            v(0.0, 2.0, 0.0),
            Some((0.5, v(0.0, 1.0, 1.0), DVec3::Y)),
        ),
        case(cyl, v(-5.0, 0.0, 2.5), DVec3::X, None),
        case(cyl, v(1.5, 0.0, -1.0), DVec3::Z, None),
        // the tilted cylinder: side, top cap, along the axis from inside
        case(tilted, mid + 5.0 * U, -U, Some((4.5, mid + 0.5 * U, U))),
        case(
            tilted,
            top + 0.25 * W + 3.0 * A,
            -A,
            Some((3.0, top + 0.25 * W, A)),
        ),
        case(tilted, mid, A, Some((2.0, top, A))),
        case(tilted, mid, W, Some((0.5, mid + 0.5 * W, W))),
        case(tilted, tilted.base() + 2.0 * U - A, A, None),
        // the ellipsoid: on its axes, at 60°, from inside, a miss
        case(
            ell,
            v(1.0, -2.0, 10.0),
            -DVec3::Z,
            Some((6.5, v(1.0, -2.0, 3.5), DVec3::Z)),
        ),
        case(
            ell,
            v(-10.0, -2.0, 3.0),
            DVec3::X,
            Some((9.0, v(-1.0, -2.0, 3.0), -DVec3::X)),
        ),
        case(ell, p + 5.0 * n, -n, Some((5.0, p, n))),
        case(
            ell,
            ell.center(),
            DVec3::Y,
            Some((1.0, v(1.0, -1.0, 3.0), DVec3::Y)),
        ),
        case(ell, v(1.0, -0.9, 10.0), -DVec3::Z, None),
        // chapter 3's sphere and chapter 2's polygon
        case(
            Sphere::new(v(0.0, 0.0, -5.0), 2.0),
            DVec3::ZERO,
            -DVec3::Z,
            Some((3.0, v(0.0, 0.0, -3.0), DVec3::Z)),
        ),
        case(
            the_square(),
            v(1.0, 0.5, 5.0),
            -DVec3::Z,
            Some((4.0, v(1.0, 0.5, 1.0), DVec3::Z)),
        ),
        case(the_square(), v(2.5, 0.5, 5.0), -DVec3::Z, None),
    ];
    // the three triangles: the same hit from either side, a miss
    for test in TriangleTest::ALL {
        let tri = || Triangle::new(CORNER, test).unwrap();
        let at = DVec3::splat(third);
        cases.push(case(
            tri(),
            DVec3::ZERO,
            DVec3::ONE,
            Some((third, at, diagonal)),
        ));
        cases.push(case(
            tri(),
            DVec3::splat(2.0),
            -DVec3::ONE,
            Some((5.0 / 3.0, at, diagonal)),
        ));
        cases.push(case(tri(), DVec3::ZERO, v(1.0, 1.0, -0.5), None));
    }
    cases
}

/// Is `a` within 1e-12 of `b` (relative to their size, at least 1)?
fn close(a: DVec3, b: DVec3) -> bool {
    (a - b).length() <= 1e-12 * a.length().max(b.length()).max(1.0)
}

/// Each primitive against rays whose hit is known exactly: t, the point
/// and the unit outward normal (not turned toward the ray: rays from
/// inside get the normal pointing out too).
#[test]
fn analytic_hits() {
    let mut table = Table::new(&[
        "primitive",
        "origin",
        "direction",
        "t",
        "point",
        "normal",
    ]);
    for c in analytic_cases() {
        let got = c.shape.intersect(&c.ray, Interval::FORWARD);
        let name = c.shape.name();
        match (c.expected, got) {
            (None, None) => {}
            (Some((t, point, normal)), Some(hit)) => {
                assert!(
                    (hit.t - t).abs() <= 1e-12 * t.max(1.0)
                        && close(hit.point, point)
                        && close(hit.normal, normal),
                    "{name}, ray {:?}: expected t = {t}, point {point}, \
                     normal {normal}; got {hit:?}",
                    c.ray
                );
            }
            (expected, got) => panic!(
                "{name}, ray {:?}: expected {expected:?}, got {got:?}",
                c.ray
            ),
        }
        let (t, point, normal) = got
            .map_or(("miss".into(), String::new(), String::new()), |h: Hit| {
                (num(h.t), vec3(h.point), vec3(h.normal))
            });
        table.row(&[
            name.to_string(),
            vec3(c.ray.origin),
            vec3(c.ray.direction),
            t,
            point,
            normal,
        ]);
    }
    insta::assert_snapshot!(table.to_string());
}

/// The interval is respected: a hit before its min or after its max is
/// no hit, and the box and cylinder report the exit when the entry is
/// before the interval.
#[test]
fn the_interval_is_respected() {
    for c in analytic_cases() {
        let Some((t, ..)) = c.expected else { continue };
        let name = c.shape.name();
        let before = Interval::new(0.0, 0.99 * t);
        let got = c.shape.intersect(&c.ray, before);
        assert!(
            got.is_none_or(|h| h.t <= 0.99 * t),
            "{name}, ray {:?}: expected no hit within [0, {}], got {got:?}",
            c.ray,
            0.99 * t
        );
    }
    // entering at t = 4, leaving at t = 6: from t = 5 on, the exit
    let ray = Ray::new(v(-5.0, 0.0, 1.0), DVec3::X);
    for shape in [&the_box() as &dyn Primitive, &upright_cylinder()] {
        let hit = shape.intersect(&ray, Interval::new(5.0, 100.0)).unwrap();
        assert!(
            (hit.t - 6.0).abs() < 1e-12 && close(hit.normal, DVec3::X),
            "{}: expected the exit at t = 6 with normal +x, got {hit:?}",
            shape.name()
        );
    }
}

/// A point of a surface for three numbers in [0, 1).
type Sampler = Box<dyn Fn(f64, f64, f64) -> DVec3>;

/// The primitives, and a point of each one's surface for three numbers
/// in [0, 1) (`a` picks a part of the surface, `b` and `c` a point of it).
fn primitives() -> Vec<(Box<dyn Primitive>, Sampler)> {
    let b = the_box();
    let on_box = move |a: f64, s: f64, t: f64| {
        let face = (a * 6.0) as usize % 6;
        let (axis, i, j) = (face % 3, (face + 1) % 3, (face + 2) % 3);
        let mut p = DVec3::ZERO;
        p[axis] = if face < 3 {
            b.min()[axis]
        } else {
            b.max()[axis]
        };
        p[i] = b.min()[i] + s * (b.max()[i] - b.min()[i]);
        p[j] = b.min()[j] + t * (b.max()[j] - b.min()[j]);
        p
    };
    let on_cylinder = |cyl: Cylinder| {
        move |a: f64, s: f64, t: f64| {
            let axis = cyl.top() - cyl.base();
            let (u, w) = axis.normalize().any_orthonormal_pair();
            let r = cyl.radius();
            let around = |radius: f64, angle: f64| {
                radius * (angle.cos() * u + angle.sin() * w)
            };
            if a < 0.6 {
                cyl.base() + t * axis + around(r, TAU * s)
            } else if a < 0.8 {
                cyl.base() + around(r * s.sqrt(), TAU * t)
            } else {
                cyl.top() + around(r * s.sqrt(), TAU * t)
            }
        }
    };
    let unit = |s: f64, t: f64| {
        let z = 2.0 * s - 1.0;
        let rho = (1.0 - z * z).sqrt();
        v(rho * (TAU * t).cos(), rho * (TAU * t).sin(), z)
    };
    let ell = the_ellipsoid();
    let sphere = Sphere::new(v(0.0, 0.0, -5.0), 2.0);
    // a point of triangle (p, q, r), its corners weighted away from 0
    let in_triangle = |p: DVec3, q: DVec3, r: DVec3, s: f64, t: f64| {
        let s = s.sqrt();
        (1.0 - s) * p + s * (1.0 - t) * q + s * t * r
    };
    let square = the_square();
    let corners = square.vertices().to_vec();
    let mut list: Vec<(Box<dyn Primitive>, Sampler)> = vec![
        (Box::new(b), Box::new(on_box)),
        (
            Box::new(upright_cylinder()),
            Box::new(on_cylinder(upright_cylinder())),
        ),
        (
            Box::new(tilted_cylinder()),
            Box::new(on_cylinder(tilted_cylinder())),
        ),
        (
            Box::new(ell),
            Box::new(move |_, s, t| ell.center() + ell.radii() * unit(s, t)),
        ),
        (
            Box::new(sphere),
            Box::new(move |_, s, t| sphere.center + sphere.radius * unit(s, t)),
        ),
        (
            Box::new(square),
            Box::new(move |a, s, t| {
                let k = 1 + (a * 2.0) as usize % 2; // one of the two halves
                in_triangle(corners[0], corners[k], corners[k + 1], s, t)
            }),
        ),
    ];
    for test in TriangleTest::ALL {
        list.push((
            Box::new(Triangle::new(CORNER, test).unwrap()),
            Box::new(move |_, s, t| {
                in_triangle(CORNER[0], CORNER[1], CORNER[2], s, t)
            }),
        ));
    }
    list
}

/// Is `p` in `b`, allowing for the rounding of `p`?
fn box_contains(b: &Aabb, p: DVec3) -> bool {
    let slack = DVec3::splat(1e-12) * (1.0 + p.abs());
    (b.min - slack).cmple(p).all() && p.cmple(b.max + slack).all()
}

fn sphere_contains(s: &BoundingSphere, p: DVec3) -> bool {
    p.distance(s.center) <= s.radius * (1.0 + 1e-12) + 1e-12
}

/// Every sampled surface point lies in the primitive's box and bounding
/// sphere, and both are tight: the samples come within 1 % of each face
/// of the box and of the sphere's radius.
#[test]
fn bounds_and_bounding_spheres_contain_the_surface_and_fit_it() {
    let mut rng = Rng::new(0xB0_0D5);
    let mut table = Table::new(&[
        "primitive",
        "box min",
        "box max",
        "sphere centre",
        "sphere radius",
    ]);
    for (shape, sample) in primitives() {
        let (b, s) = (shape.bounds(), shape.bounding_sphere());
        let name = shape.name();
        let mut reach = Aabb::EMPTY;
        let mut farthest: f64 = 0.0;
        for _ in 0..20_000 {
            let p = sample(rng.unit(), rng.unit(), rng.unit());
            assert!(
                box_contains(&b, p),
                "{name}: {p} is outside its box {b:?}"
            );
            assert!(
                sphere_contains(&s, p),
                "{name}: {p} is outside its bounding sphere {s:?}"
            );
            reach = reach.grow(p);
            farthest = farthest.max(p.distance(s.center));
        }
        let size = (b.max - b.min).max_element();
        let gap = (reach.min - b.min).max(b.max - reach.max).max_element();
        assert!(
            gap <= 0.01 * size,
            "{name}: box {b:?}, but the surface only reaches {reach:?}"
        );
        assert!(
            farthest >= 0.99 * s.radius,
            "{name}: bounding sphere {s:?}, but the surface only reaches \
             {farthest} from its centre"
        );
        table.row(&[
            name.to_string(),
            vec3(b.min),
            vec3(b.max),
            vec3(s.center),
            num(s.radius),
        ]);
    }
    insta::assert_snapshot!(table.to_string());
}

/// The tilted cylinder's box is the box of its two cap discs: along axis
/// i a disc reaches r·√(1 − aᵢ²) from its centre.
#[test]
fn the_cylinder_box_is_the_box_of_its_caps() {
    let cyl = tilted_cylinder();
    let reach = 0.5 * (DVec3::ONE - A * A).sqrt(); // (√8, √5, √5)/6
    let expected = Aabb::around([
        cyl.base() - reach,
        cyl.base() + reach,
        cyl.top() - reach,
        cyl.top() + reach,
    ]);
    let got = cyl.bounds();
    assert!(
        close(got.min, expected.min) && close(got.max, expected.max),
        "expected {expected:?}, got {got:?}"
    );
    // an axis along x: the discs are flat in x
    let along_x = Cylinder::new(DVec3::ZERO, DVec3::X, 2.0).unwrap();
    assert_eq!(
        along_x.bounds(),
        Aabb::new(v(0.0, -2.0, -2.0), v(1.0, 2.0, 2.0))
    );
}

/// Rays from inside a closed primitive leave it once, with the normal
/// pointing out (the way the ray goes).
#[test]
fn rays_from_inside_leave_with_the_outward_normal() {
    let mut rng = Rng::new(0x1D5);
    let insides = [
        (Box::new(the_box()) as Box<dyn Primitive>, v(0.25, 0.5, 2.0)),
        (Box::new(upright_cylinder()), v(0.1, -0.2, 1.5)),
        (
            Box::new(tilted_cylinder()),
            tilted_cylinder().base() + 3.0 * A + 0.2 * U,
        ),
        (
            Box::new(the_ellipsoid()),
            the_ellipsoid().center() + v(0.5, 0.2, -0.1),
        ),
        (
            Box::new(Sphere::new(v(0.0, 0.0, -5.0), 2.0)),
            v(0.5, 0.5, -4.0),
        ),
    ];
    for (shape, inside) in &insides {
        for _ in 0..2000 {
            let d = v(rng.unit(), rng.unit(), rng.unit()) * 2.0 - 1.0;
            let ray = Ray::new(*inside, d);
            let hit = shape.intersect(&ray, Interval::FORWARD);
            let ok = hit.is_some_and(|h| {
                h.t > 0.0
                    && h.normal.dot(d) > 0.0
                    && (h.normal.length() - 1.0).abs() < 1e-12
            });
            assert!(
                ok,
                "{}: a ray {ray:?} from inside: expected to leave with an \
                 outward unit normal, got {hit:?}",
                shape.name()
            );
            // and past the exit there is nothing more
            let t = hit.unwrap().t;
            let beyond = shape.intersect(
                &ray,
                Interval::new(t * (1.0 + 1e-9), f64::INFINITY),
            );
            assert!(
                beyond.is_none(),
                "{}: a ray {ray:?} from inside hits again after leaving at \
                 t = {t}: {beyond:?}",
                shape.name()
            );
        }
    }
}

/// Every parameter that makes no shape is refused, with a message that
/// names it.
#[test]
fn bad_parameters_are_refused_by_name() {
    let nan = f64::NAN;
    let mut results: Vec<(&str, &str, Result<(), String>)> = vec![
        (
            "box with min = max in y",
            "max",
            AxisBox::new(v(0.0, 1.0, 0.0), v(1.0, 1.0, 1.0)).map(drop),
        ),
        (
            "box with min > max",
            "max",
            AxisBox::new(v(0.0, 0.0, 2.0), v(1.0, 1.0, 1.0)).map(drop),
        ),
        (
            "box with a NaN corner",
            "min",
            AxisBox::new(v(nan, 0.0, 0.0), v(1.0, 1.0, 1.0)).map(drop),
        ),
        (
            "box to infinity",
            "max",
            AxisBox::new(DVec3::ZERO, v(1.0, f64::INFINITY, 1.0)).map(drop),
        ),
        (
            "cylinder of radius 0",
            "radius",
            Cylinder::new(DVec3::ZERO, DVec3::Z, 0.0).map(drop),
        ),
        (
            "cylinder of radius -1",
            "radius",
            Cylinder::new(DVec3::ZERO, DVec3::Z, -1.0).map(drop),
        ),
        (
            "cylinder of radius NaN",
            "radius",
            Cylinder::new(DVec3::ZERO, DVec3::Z, nan).map(drop),
        ),
        (
            "cylinder with base = top",
            "top",
            Cylinder::new(DVec3::ONE, DVec3::ONE, 1.0).map(drop),
        ),
        (
            "cylinder with a NaN base",
            "base",
            Cylinder::new(v(0.0, nan, 0.0), DVec3::Z, 1.0).map(drop),
        ),
        (
            "ellipsoid with a radius 0",
            "radii",
            Ellipsoid::new(DVec3::ZERO, v(1.0, 0.0, 1.0)).map(drop),
        ),
        (
            "ellipsoid with a radius -1",
            "radii",
            Ellipsoid::new(DVec3::ZERO, v(1.0, 1.0, -1.0)).map(drop),
        ),
        (
            "ellipsoid with a NaN centre",
            "center",
            Ellipsoid::new(v(nan, 0.0, 0.0), DVec3::ONE).map(drop),
        ),
        (
            "ellipsoid with a NaN radius",
            "radii",
            Ellipsoid::new(DVec3::ZERO, v(1.0, nan, 1.0)).map(drop),
        ),
    ];
    let mut triangles = Vec::new();
    let bad = [
        ("collinear", [DVec3::ZERO, DVec3::ONE, DVec3::splat(2.0)]),
        ("two corners equal", [DVec3::ZERO, DVec3::ONE, DVec3::ONE]),
        ("a NaN corner", [DVec3::ZERO, DVec3::X, v(0.0, nan, 0.0)]),
    ];
    for (what, corners) in bad {
        let first = Triangle::new(corners, TriangleTest::PlaneInside).map(drop);
        for test in TriangleTest::ALL {
            let got = Triangle::new(corners, test).map(drop);
            assert_eq!(got, first, "{what}: the same error for {test:?}");
        }
        triangles.push((format!("triangle, {what}"), first));
    }
    for (what, result) in &triangles {
        results.push((what, "vertices", result.clone()));
    }
    let mut table = Table::new(&["parameters", "error"]);
    for (what, field, result) in results {
        let message = result.expect_err(what);
        assert!(
            message.starts_with(&format!("{field}: "))
                && !message.contains('\n'),
            "{what}: expected a one-line error starting with \"{field}: \", \
             got {message:?}"
        );
        table.row(&[what, &message]);
    }
    insta::assert_snapshot!(table.to_string());
}

/// The names charts and tables show.
#[test]
fn names() {
    let names: Vec<&str> = primitives().iter().map(|(p, _)| p.name()).collect();
    assert_eq!(
        names,
        [
            "box",
            "cylinder",
            "cylinder",
            "ellipsoid",
            "sphere",
            "polygon",
            "triangle (plane + inside)",
            "triangle (Möller–Trumbore)",
            "triangle (watertight)"
        ]
    );
}

proptest! {
    #![proptest_config(seeded(256))]

    /// A ray from outside aimed at a point of the surface hits the
    /// surface at that point or before it (t ≤ 1), with a unit normal.
    #[test]
    fn aimed_at_the_surface_hits_at_or_before(
        which in 0..9usize,
        (a, s, t) in (0.0..1.0f64, 0.01..0.99f64, 0.01..0.99f64),
        direction in raystep_check::unit_vector(),
        distance in 1.5..20.0f64,
    ) {
        let list = primitives();
        let (shape, sample) = &list[which];
        let target = sample(a, s, t);
        let s = shape.bounding_sphere();
        let from = s.center + distance * s.radius * direction;
        let ray = Ray::new(from, target - from);
        // planar shapes: not seen edge-on
        let planar_normal = match shape.name() {
            "polygon" => Some(DVec3::Z),
            name if name.starts_with("triangle") => {
                Some(DVec3::ONE.normalize())
            }
            _ => None,
        };
        let facing = |n: DVec3| ray.direction.normalize().dot(n).abs() > 0.05;
        prop_assume!(planar_normal.is_none_or(facing));
        let probe = shape.intersect(&ray, Interval::FORWARD);
        prop_assert!(
            probe.is_some_and(|h| {
                h.t <= 1.0 + 1e-9 && (h.normal.length() - 1.0).abs() < 1e-12
            }),
            "{}: ray {ray:?} aimed at {target} on its surface (t = 1): \
             expected a hit at t ≤ 1 with a unit normal, got {probe:?}",
            shape.name()
        );
    }
}
