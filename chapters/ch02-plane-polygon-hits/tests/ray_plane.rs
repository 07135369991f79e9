//! Exercise 1: where a ray meets a plane.
use ch02::{DVec3, Interval, Plane, Ray, RayPlane, intersect_plane, ray_plane};
use proptest::prelude::*;
use raystep_check::{Table, num, seeded, unit_vector, vec3};

fn v(x: f64, y: f64, z: f64) -> DVec3 {
    DVec3::new(x, y, z)
}

/// The plane through three points, or a panic that says why there is none.
fn plane(p0: DVec3, p1: DVec3, p2: DVec3) -> Plane {
    Plane::through(p0, p1, p2).unwrap_or_else(|e| {
        panic!(
            "chapter 1's Plane::through({p0}, {p1}, {p2}): expected a plane, \
             got the error \"{e}\""
        )
    })
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
    let floor = plane(v(0.0, 0.0, 1.0), v(1.0, 0.0, 1.0), v(0.0, 1.0, 1.0));
    let tilted = plane(v(1.0, 0.0, 0.0), v(0.0, 1.0, 0.0), v(0.0, 0.0, 1.0));
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
    let floor = plane(v(0.0, 0.0, 1.0), v(1.0, 0.0, 1.0), v(0.0, 1.0, 1.0));
    let ray = Ray::new(v(1.0, 2.0, 3.0), v(0.0, 0.0, -1.0));
    let what = "the ray from (1, 2, 3) straight down to the plane z = 1";
    let hit = intersect_plane(&floor, &ray, Interval::FORWARD);
    let Some(hit) = hit else {
        panic!(
            "{what}: expected a hit at t = 2, got none (ray_plane says {:?})",
            ray_plane(&floor, &ray, Interval::FORWARD)
        );
    };
    let expected = (2.0, v(1.0, 2.0, 1.0), DVec3::Z);
    let got = (hit.t, hit.point, hit.normal);
    assert!(
        got == expected,
        "{what}: expected (t, point, normal) = {expected:?}, got {got:?}"
    );
    let short = intersect_plane(&floor, &ray, Interval::new(0.0, 1.0));
    assert!(
        short.is_none(),
        "{what}, t only up to 1: expected no hit (the plane is at t = 2), \
         got {short:?}"
    );
}

/// A plane far from the origin (z = 10⁶, d = −10⁶) and rays parallel to
/// it. N·P₀ + d adds two numbers near 10⁶, so its rounding error is a few
/// ε·(N.abs()·P₀.abs() + |d|), about ε·2·10⁶, and a ray that close to the
/// plane lies in it as far as floating point can tell. Judged against
/// N.abs()·P₀.abs() alone, half as much, it would count as parallel.
#[test]
fn rays_along_a_plane_far_from_the_origin() {
    let far = 1e6;
    let plane = Plane {
        normal: DVec3::Z,
        d: -far,
    };
    let eps = f64::EPSILON;
    #[rustfmt::skip]
    let cases = [
        // 12ε·10⁶ = 2.7e-9 above it: within 8ε·(10⁶ + 10⁶) = 3.6e-9
        ("12ε·|d| above the plane", far + 12.0 * eps * far, RayPlane::InPlane),
        ("in the plane", far, RayPlane::InPlane),
        // 100ε·10⁶ = 2.2e-8 above it: far beyond the rounding error
        ("100ε·|d| above the plane", far + 100.0 * eps * far,
            RayPlane::Parallel),
    ];
    for (case, z, expected) in cases {
        let origin = v(3.0, -4.0, z);
        for direction in [v(1.0, 0.0, 0.0), v(0.6, -0.8, 0.0)] {
            let ray = Ray::new(origin, direction);
            let got = ray_plane(&plane, &ray, Interval::FORWARD);
            let distance = plane.eval(origin);
            assert!(
                got == expected,
                "plane z = 1e6 (d = -1e6), ray {case}, from {origin} along \
                 {direction}: N·P0 + d = {distance:e}, rounding allows \
                 8ε·(N.abs()·P0.abs() + |d|) = {:e}: expected {expected:?}, \
                 got {got:?}",
                8.0 * eps * (z.abs() + far)
            );
        }
    }
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
        let what = format!("plane N = {}, d = {}, ray from {origin} along {dir}, t in [0, {t_max}]", plane.normal, plane.d);
        match ray_plane(&plane, &ray, interval) {
            result @ (RayPlane::Hit(t) | RayPlane::Outside(t)) => {
                // a Hit inside the interval, an Outside not; both on the plane
                let inside = interval.contains(t);
                prop_assert!(inside == matches!(result, RayPlane::Hit(_)), "{what}: expected {} (t = {t} is {} the interval), got {result:?}", if inside { "Hit" } else { "Outside" }, if inside { "inside" } else { "outside" });
                let scale = ray.at(t).abs().max_element().max(1.0);
                let f = plane.eval(ray.at(t));
                prop_assert!(f.abs() <= 1e-12 * scale, "{what}: expected the point at t = {t} on the plane (f = 0), got f = {f}");
            }
            result @ (RayPlane::Parallel | RayPlane::InPlane) => {
                let approach = plane.normal.dot(dir);
                prop_assert!(approach.abs() < 1e-12, "{what}: expected a hit (N·D = {approach} is not 0), got {result:?}");
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
    let plane = plane(v(1.0, 0.2, -0.3), v(-0.4, 1.1, 0.5), v(0.3, -0.7, 1.3));
    let n = plane.normal;
    // two unit directions in the plane
    let u = n.any_orthonormal_vector();
    let w = n.cross(u);
    let base = v(0.3, -0.2, 0.4);
    let on_plane = base - plane.eval(base) * n;
    let (mut checked, mut failures) = (0, 0);
    let mut first_failure = None;
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
                got => {
                    failures += 1;
                    first_failure.get_or_insert(format!(
                        "a ray at {alpha:e} rad to the plane, from 1 above \
                         it: expected Hit(t) with t = {expected} (relative \
                         error at most {tolerance:e}), got {got:?}"
                    ));
                }
            }
        }
        // (2) parallel, above the plane: never a hit; (3) inside the
        // plane: InPlane, never a hit at some random t
        for (origin, expected, what) in [
            (
                on_plane + 0.5 * n,
                RayPlane::Parallel,
                "a ray parallel to the plane, 0.5 above it",
            ),
            (
                on_plane + 3.0 * along,
                RayPlane::InPlane,
                "a ray lying in the plane (built from rounded points)",
            ),
        ] {
            checked += 1;
            let ray = Ray::new(origin, along);
            let got = ray_plane(&plane, &ray, Interval::FORWARD);
            if got != expected {
                failures += 1;
                first_failure.get_or_insert(format!(
                    "{what}: expected {expected:?}, got {got:?}"
                ));
            }
        }
    }
    assert_eq!(checked, 8 * 14, "rays checked: 14 in each of 8 directions");
    assert!(
        failures == 0,
        "nearly parallel, parallel and in-plane rays judged wrong: expected \
         0 of {checked}, got {failures}; the first: {}",
        first_failure.unwrap_or_default()
    );
}
