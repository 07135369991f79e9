//! Exercise 1: where a ray meets a plane.
use ch02::{DVec3, Interval, Plane, Ray, RayPlane, intersect_plane, ray_plane};
use proptest::prelude::*;
use raystep_check::{Table, num, seeded, unit_vector, vec3};

fn v(x: f64, y: f64, z: f64) -> DVec3 {
    DVec3::new(x, y, z)
}

fn describe(r: RayPlane) -> String {
    match r {
        RayPlane::Hit(t) => format!("hit, t = {}", num(t)),
        RayPlane::Outside(t) => format!("outside, t = {}", num(t)),
        RayPlane::Parallel => "parallel".to_string(),
        RayPlane::InPlane => "in plane".to_string(),
    }
}

/// The lecture's cases on the plane z = 1 and on a tilted plane.
#[test]
fn ray_plane_table() {
    let floor =
        Plane::through(v(0.0, 0.0, 1.0), v(1.0, 0.0, 1.0), v(0.0, 1.0, 1.0))
            .unwrap();
    let tilted =
        Plane::through(v(1.0, 0.0, 0.0), v(0.0, 1.0, 0.0), v(0.0, 0.0, 1.0))
            .unwrap();
    let to_10 = Interval::new(0.0, 10.0);
    #[rustfmt::skip]
    let cases = [
        ("z=1", floor, v(0.0, 0.0, 5.0), v(0.0, 0.0, -1.0), "straight down"),
        ("z=1", floor, v(0.0, 0.0, 5.0), v(0.6, 0.0, -0.8), "oblique"),
        ("z=1", floor, v(0.0, 0.0, 5.0), v(0.0, 0.0, 1.0), "pointing away: behind"),
        ("z=1", floor, v(0.0, 0.0, 5.0), v(1.0, 0.0, 0.0), "parallel, above"),
        ("z=1", floor, v(2.0, 3.0, 1.0), v(1.0, 1.0, 0.0), "in the plane"),
        ("z=1", floor, v(0.0, 0.0, 1.0), v(0.0, 0.0, -1.0), "starts on the plane"),
        ("z=1", floor, v(0.0, 0.0, 50.0), v(0.0, 0.0, -1.0), "beyond t = 10"),
        ("z=1", floor, v(0.0, 0.0, 5.0), v(0.0, 0.0, -2.0), "unnormalised D"),
        ("tilted", tilted, v(0.0, 0.0, 0.0), v(1.0, 1.0, 1.0), "from the origin"),
        ("tilted", tilted, v(1.0, 1.0, 1.0), v(1.0, -1.0, 0.0), "parallel, rounded"),
        ("tilted", tilted, v(0.1, 0.2, 0.7), v(0.3, -0.1, -0.2), "in the plane, rounded"),
    ];
    let mut table = Table::new(&["plane", "P0", "D", "case", "result"]);
    for (name, plane, origin, direction, case) in cases {
        let r = ray_plane(&plane, &Ray::new(origin, direction), to_10);
        table.row(&[
            name.to_string(),
            vec3(origin),
            vec3(direction),
            case.to_string(),
            describe(r),
        ]);
    }
    insta::assert_snapshot!(table.to_string());
}

#[test]
fn intersect_plane_returns_the_point_and_normal() {
    let floor =
        Plane::through(v(0.0, 0.0, 1.0), v(1.0, 0.0, 1.0), v(0.0, 1.0, 1.0))
            .unwrap();
    let ray = Ray::new(v(1.0, 2.0, 3.0), v(0.0, 0.0, -1.0));
    let hit = intersect_plane(&floor, &ray, Interval::FORWARD).unwrap();
    assert_eq!(
        (hit.t, hit.point, hit.normal),
        (2.0, v(1.0, 2.0, 1.0), DVec3::Z)
    );
    assert_eq!(intersect_plane(&floor, &ray, Interval::new(0.0, 1.0)), None);
}

fn point() -> impl Strategy<Value = DVec3> {
    (-50.0..50.0f64, -50.0..50.0f64, -50.0..50.0f64)
        .prop_map(|(x, y, z)| v(x, y, z))
}

proptest! {
    #![proptest_config(seeded(256))]

    /// A hit lies on the plane and inside the interval; a ray that
    /// approaches the plane meets it at t ≥ 0 exactly when it starts on the
    /// side it approaches from.
    #[test]
    fn hits_lie_on_the_plane_and_inside_the_interval(
        a in point(), b in point(), c in point(), origin in point(), dir in unit_vector(), t_max in 1.0..200.0f64
    ) {
        let Ok(plane) = Plane::through(a, b, c) else { return Ok(()) };
        let interval = Interval::new(0.0, t_max);
        let ray = Ray::new(origin, dir);
        match ray_plane(&plane, &ray, interval) {
            result @ (RayPlane::Hit(t) | RayPlane::Outside(t)) => {
                // a Hit inside the interval, an Outside not; both on the plane
                prop_assert_eq!(interval.contains(t), matches!(result, RayPlane::Hit(_)));
                let scale = ray.at(t).abs().max_element().max(1.0);
                prop_assert!(plane.eval(ray.at(t)).abs() <= 1e-12 * scale);
            }
            RayPlane::Parallel | RayPlane::InPlane => {
                prop_assert!(plane.normal.dot(dir).abs() < 1e-12);
            }
        }
    }
}

/// `a·b` and `a·b + c` to nearly twice f64 precision: each product's
/// rounding error is recovered exactly with a fused multiply-add and added
/// back at the end. The reference for the grazing-ray test below.
fn accurate_dot(a: DVec3, b: DVec3, c: f64) -> f64 {
    let (mut sum, mut error) = (c, 0.0);
    for (x, y) in [(a.x, b.x), (a.y, b.y), (a.z, b.z)] {
        let product = x * y;
        error += x.mul_add(y, -product); // the product's exact rounding error
        let next = sum + product;
        // the sum's exact rounding error (Knuth's two-sum)
        let bp = next - sum;
        error += (sum - (next - bp)) + (product - bp);
        sum = next;
    }
    sum + error
}

/// Rays at angles from 1e-1 down to 1e-12 rad to a tilted plane still hit
/// it; rays built parallel to it (and so off by rounding) never report a
/// hit, and rays built inside it report `InPlane`. The failures are counted
/// over every case: 0.
///
/// How good can t be? N·D ≈ sin α is computed with an error of a few
/// ε·Σ|nᵢdᵢ|, so t = −(N·P₀ + d)/(N·D) is uncertain by about that divided
/// by sin α, relatively: 1e-4 at α = 1e-12. The test compares t with a
/// reference computed to twice the precision and allows exactly that much,
/// so any correct order of operations passes.
#[test]
fn nearly_parallel_rays() {
    let plane =
        Plane::through(v(1.0, 0.2, -0.3), v(-0.4, 1.1, 0.5), v(0.3, -0.7, 1.3))
            .unwrap();
    let n = plane.normal;
    // two unit directions in the plane
    let u = n.any_orthonormal_vector();
    let w = n.cross(u);
    let base = v(0.3, -0.2, 0.4);
    let on_plane = base - plane.eval(base) * n;
    let (mut checked, mut failures) = (0, 0);
    for azimuth in 0..8 {
        let phi = f64::from(azimuth) * std::f64::consts::TAU / 8.0;
        let along = phi.cos() * u + phi.sin() * w;
        // (1) angle α below the plane from a point 1 above it: t = 1 / sin α
        for k in 1..=12 {
            let alpha = 10f64.powi(-k);
            let dir = (alpha.cos() * along - alpha.sin() * n).normalize();
            let ray = Ray::new(on_plane + n, dir);
            checked += 1;
            let approach = accurate_dot(n, dir, 0.0);
            let expected = -accurate_dot(n, ray.origin, plane.d) / approach;
            let magnitude = n.abs().dot(dir.abs());
            let tolerance =
                1e-14 + 16.0 * f64::EPSILON * magnitude / approach.abs();
            match ray_plane(&plane, &ray, Interval::FORWARD) {
                RayPlane::Hit(t)
                    if ((t - expected) / expected).abs() <= tolerance => {}
                _ => failures += 1,
            }
        }
        // (2) parallel, above the plane: never a hit
        checked += 1;
        match ray_plane(
            &plane,
            &Ray::new(on_plane + 0.5 * n, along),
            Interval::FORWARD,
        ) {
            RayPlane::Parallel => {}
            _ => failures += 1,
        }
        // (3) inside the plane: InPlane, never a hit at some random t
        checked += 1;
        match ray_plane(
            &plane,
            &Ray::new(on_plane + 3.0 * along, along),
            Interval::FORWARD,
        ) {
            RayPlane::InPlane => {}
            _ => failures += 1,
        }
    }
    assert_eq!(checked, 8 * 14);
    assert_eq!(failures, 0);
}
