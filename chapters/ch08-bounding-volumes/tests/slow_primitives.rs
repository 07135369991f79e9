//! The slow primitives (torus, monkey saddle, blobby objects) on their
//! own: analytic hits, bounds that hold the surface, normals that are
//! never NaN at near-tangent rays, and clear errors for bad parameters.
//! (The torus's two solvers are compared in `tests/torus_solvers.rs`.)
mod common;
use ch08::{
    Aabb, Ball, Blobby, BoundingSphere, DVec3, Interval, Primitive, Ray,
    Saddle, Shape, Torus, TorusSolver,
};
use common::{Rng, unit_vector};
use std::f64::consts::PI;

const SOLVERS: [TorusSolver; 2] =
    [TorusSolver::ClosedForm, TorusSolver::Bracketed];

fn near(a: f64, b: f64, tolerance: f64) -> bool {
    (a - b).abs() <= tolerance
}

fn near_vec(a: DVec3, b: DVec3, tolerance: f64) -> bool {
    (a - b).length() <= tolerance
}

/// Is `p` in the box, allowing `slack` for the rounding of p itself?
fn in_box(b: &Aabb, p: DVec3, slack: f64) -> bool {
    (b.min - DVec3::splat(slack)).cmple(p).all()
        && p.cmple(b.max + DVec3::splat(slack)).all()
}

fn in_sphere(s: &BoundingSphere, p: DVec3, slack: f64) -> bool {
    (p - s.center).length() <= s.radius + slack
}

// ---------------------------------------------------------------------
// The torus
// ---------------------------------------------------------------------

/// Along the x axis through an upright torus (R = 1, r = 0.25) from
/// x = −5 the ray crosses the tube at x = −1.25, −0.75, 0.75 and 1.25;
/// from above at x = 1 it meets the top of the tube at y = 0.25. The same
/// with the torus tilted and moved (the ray moved with it), both solvers.
#[test]
fn torus_analytic_hits() {
    let placements = [
        (DVec3::ZERO, DVec3::Y),
        (DVec3::new(3.0, -1.0, 0.5), DVec3::new(1.0, 1.0, -2.0)),
    ];
    for (center, axis) in placements {
        for solver in SOLVERS {
            let torus = Torus::new(center, axis, 1.0, 0.25, solver).unwrap();
            let n = torus.axis();
            let (u, _) = n.any_orthonormal_pair();
            let what = format!("{solver:?} torus at {center}, axis {n}");
            // Step 1: through the middle, across the axis.
            let ray = Ray::new(center - 5.0 * u, u);
            let roots = torus.roots(&ray);
            let want = [3.75, 4.25, 5.75, 6.25];
            assert!(
                roots.len() == 4
                    && roots.iter().zip(want).all(|(r, w)| near(*r, w, 1e-9)),
                "{what}: expected roots {want:?}, got {roots:?}"
            );
            let hit = torus.intersect(&ray, Interval::FORWARD).unwrap();
            assert!(near(hit.t, 3.75, 1e-9), "{what}: first hit {hit:?}");
            assert!(near_vec(hit.normal, -u, 1e-9), "{what}: {hit:?}");
            // from t = 4 on: the exit into the hole, normal toward the axis
            let later =
                torus.intersect(&ray, Interval::new(4.0, 10.0)).unwrap();
            assert!(near(later.t, 4.25, 1e-9), "{what}: {later:?}");
            assert!(near_vec(later.normal, u, 1e-9), "{what}: {later:?}");
            assert!(torus.intersect(&ray, Interval::new(0.0, 3.7)).is_none());
            // Step 2: from above, onto the top of the tube.
            let ray = Ray::new(center + u + 5.0 * n, -n);
            let hit = torus.intersect(&ray, Interval::FORWARD).unwrap();
            assert!(near(hit.t, 4.75, 1e-9), "{what}: {hit:?}");
            assert!(near_vec(hit.normal, n, 1e-9), "{what}: {hit:?}");
            assert!(near_vec(hit.point, center + u + 0.25 * n, 1e-9));
            // Step 3: down the axis, through the hole.
            let ray = Ray::new(center + 5.0 * n, -n);
            assert!(torus.roots(&ray).is_empty(), "{what}: along the axis");
            assert!(torus.intersect(&ray, Interval::FORWARD).is_none());
        }
    }
}

/// The torus touches its tight box at the top and bottom of the tube and
/// at the outer equator. Rays along the axis onto the top of the tube
/// and across it onto the outer equator, moved off centre by δ = 1e-1 …
/// 1e-15, hit where the geometry says (t = 4.25 − √(r² − δ²)), both
/// solvers, at both placements: a root on the box's face is not lost to
/// the end of the search interval.
#[test]
fn torus_hits_where_it_touches_its_box() {
    let placements = [
        (DVec3::ZERO, DVec3::Y),
        (DVec3::new(3.0, -1.0, 0.5), DVec3::new(1.0, 1.0, -2.0)),
    ];
    let mut rng = Rng::new(9);
    let mut misses = Vec::new();
    for (center, axis) in placements {
        for solver in SOLVERS {
            let torus = Torus::new(center, axis, 1.0, 0.25, solver).unwrap();
            let n = torus.axis();
            let (u, w) = n.any_orthonormal_pair();
            for k in 1..=15 {
                let delta = 10f64.powi(-k);
                let phi = rng.uniform(0.0, 2.0 * PI);
                let out = phi.cos() * u + phi.sin() * w;
                let want = 4.25 - (0.0625 - delta * delta).sqrt();
                let rays = [
                    // down onto the top of the tube, and up onto its bottom
                    Ray::new(center + (1.0 + delta) * out + 4.25 * n, -n),
                    Ray::new(center + (1.0 - delta) * out - 4.25 * n, n),
                    // inward onto the outer equator
                    Ray::new(center + 5.25 * out + delta * n, -out),
                ];
                for ray in rays {
                    let t = torus.intersect(&ray, Interval::FORWARD);
                    if !t.is_some_and(|hit| near(hit.t, want, 1e-9)) {
                        misses.push((solver, delta, ray, t));
                    }
                }
            }
        }
    }
    assert!(
        misses.is_empty(),
        "expected hits at t = 4.25 − √(r² − δ²), got {misses:#?}"
    );
}

/// A point of the torus with tube angle θ and angle φ around the axis,
/// in world coordinates.
fn torus_point(torus: &Torus, theta: f64, phi: f64) -> DVec3 {
    let (u, w) = torus.axis().any_orthonormal_pair();
    let ring = torus.major() + torus.minor() * theta.cos();
    torus.center()
        + ring * (phi.cos() * u + phi.sin() * w)
        + torus.minor() * theta.sin() * torus.axis()
}

/// For tori with seeded axes, 40 000 points of the surface each lie in
/// the box and the bounding sphere, and the box is tight: on every side
/// some point comes within 1e-3·(R + r) of it.
#[test]
fn torus_bounds_hold_the_surface_tightly() {
    let mut rng = Rng::new(3);
    for case in 0..6 {
        let axis = if case == 0 {
            DVec3::Y
        } else {
            unit_vector(&mut rng)
        };
        let center =
            DVec3::new(rng.uniform(-5.0, 5.0), 1.0, rng.uniform(-5.0, 5.0));
        let torus =
            Torus::new(center, axis, 2.0, 0.7, TorusSolver::Bracketed).unwrap();
        let (bounds, sphere) = (torus.bounds(), torus.bounding_sphere());
        let (mut low, mut high) = (DVec3::INFINITY, DVec3::NEG_INFINITY);
        for i in 0..200 {
            for j in 0..200 {
                let theta = 2.0 * PI * f64::from(i) / 200.0;
                let p =
                    torus_point(&torus, theta, 2.0 * PI * f64::from(j) / 200.0);
                assert!(
                    in_box(&bounds, p, 1e-12),
                    "torus axis {axis}: {p} outside its box {bounds:?}"
                );
                assert!(in_sphere(&sphere, p, 1e-12), "{p} outside {sphere:?}");
                (low, high) = (low.min(p), high.max(p));
            }
        }
        let gap = (low - bounds.min).max(bounds.max - high).max_element();
        assert!(
            gap <= 1e-3 * 2.7,
            "torus axis {axis}: the box {bounds:?} is {gap} wider than the \
             surface ({low} to {high})"
        );
        assert_eq!(torus.name(), "torus");
        assert!(near(sphere.radius, 2.7, 1e-15) && sphere.center == center);
    }
}

/// Rays from every side at a tilted torus: each hit lies on the surface
/// (its distance to the centre circle is r), its normal is a unit vector
/// pointing away from the centre circle, and no hit comes before the
/// reported one (both solvers agree on these near rays).
#[test]
fn torus_hits_lie_on_the_surface_with_outward_normals() {
    let mut rng = Rng::new(4);
    let (center, axis) = (DVec3::new(1.0, 2.0, 3.0), DVec3::new(0.3, 1.0, 0.2));
    let mut hits = 0;
    for solver in SOLVERS {
        let torus = Torus::new(center, axis, 1.5, 0.5, solver).unwrap();
        let n = torus.axis();
        for _ in 0..2000 {
            let from = center + 6.0 * unit_vector(&mut rng);
            let aim = center + 2.0 * unit_vector(&mut rng);
            let ray = Ray::new(from, aim - from);
            let Some(hit) = torus.intersect(&ray, Interval::FORWARD) else {
                continue;
            };
            hits += 1;
            let v = hit.point - center;
            let across = v - v.dot(n) * n;
            let circle = center + 1.5 * across.normalize();
            let distance = (hit.point - circle).length();
            assert!(
                near(distance, 0.5, 1e-9),
                "{solver:?}: hit {hit:?} is {distance} from the centre circle"
            );
            let outward = (hit.point - circle) / distance;
            assert!(
                near_vec(hit.normal, outward, 1e-8),
                "{solver:?}: normal {} at {hit:?}, expected {outward}",
                hit.normal
            );
        }
    }
    assert!(hits > 1000, "only {hits} of 4000 rays hit the torus");
}

/// Bad tori are refused with a message naming what is wrong: only ring
/// tori (r < R) are allowed; a horn (r = R) or spindle (r > R) torus is
/// refused.
#[test]
fn torus_refuses_bad_parameters() {
    let ok = (DVec3::ZERO, DVec3::Y, 1.0, 0.25);
    let cases = [
        ((ok.0, ok.1, 1.0, 1.0), "minor radius 1 must be smaller"),
        ((ok.0, ok.1, 1.0, 2.0), "horn or spindle"),
        ((ok.0, ok.1, 1.0, 0.0), "minor radius 0 must be a positive"),
        (
            (ok.0, ok.1, -1.0, 0.25),
            "major radius -1 must be a positive",
        ),
        ((ok.0, ok.1, f64::INFINITY, 0.25), "major radius inf"),
        ((ok.0, ok.1, 1.0, f64::NAN), "minor radius NaN"),
        ((DVec3::new(0.0, f64::NAN, 0.0), ok.1, 1.0, 0.25), "center"),
        ((ok.0, DVec3::ZERO, 1.0, 0.25), "axis"),
        ((ok.0, DVec3::new(f64::NAN, 1.0, 0.0), 1.0, 0.25), "axis"),
    ];
    for ((center, axis, major, minor), expected) in cases {
        let result =
            Torus::new(center, axis, major, minor, TorusSolver::Bracketed);
        match result {
            Err(message) => assert!(
                message.starts_with("torus: ") && message.contains(expected),
                "Torus::new({center}, {axis}, {major}, {minor}): expected an \
                 error containing {expected:?}, got {message:?}"
            ),
            Ok(t) => panic!("expected an error ({expected}), got {t:?}"),
        }
    }
    assert!(
        Torus::new(ok.0, ok.1, ok.2, ok.3, TorusSolver::ClosedForm).is_ok()
    );
}

// ---------------------------------------------------------------------
// The monkey saddle
// ---------------------------------------------------------------------

/// y = (x³ − 3xz²)/s² relative to the centre, and its normal
/// (−∂y/∂x, 1, −∂y/∂z) normalised.
fn saddle_height(s: f64, x: f64, z: f64) -> (f64, DVec3) {
    let y = (x * x * x - 3.0 * x * z * z) / (s * s);
    let normal = DVec3::new(
        -3.0 * (x * x - z * z) / (s * s),
        1.0,
        6.0 * x * z / (s * s),
    );
    (y, normal.normalize())
}

/// Straight down onto the saddle at a grid of points of its square: the
/// hit is at the height of the formula with the graph's normal; also by
/// the corners where the surface touches its box. Beside the square the
/// ray misses; along the x axis the ray meets y = x³/s² at x = ∛(y·s²).
#[test]
fn saddle_analytic_hits() {
    let (center, s) = (DVec3::new(1.0, 2.0, 3.0), 2.0);
    let saddle = Saddle::new(center, s).unwrap();
    for i in -4..=4 {
        for k in -4..=4 {
            let (x, z) = (0.49 * f64::from(i), 0.49 * f64::from(k));
            let ray = Ray::new(center + DVec3::new(x, 10.0, z), DVec3::NEG_Y);
            let hit = saddle.intersect(&ray, Interval::FORWARD).unwrap();
            let (y, normal) = saddle_height(s, x, z);
            assert!(
                near(hit.t, 10.0 - y, 1e-9),
                "down at ({x}, {z}): expected t = {}, got {hit:?}",
                10.0 - y
            );
            assert!(near_vec(hit.normal, normal, 1e-12), "{hit:?}");
        }
    }
    // Near the corners where the surface touches the top and the bottom
    // of its box (y = ±2s at x = ∓s, z = ±s): the root is at an end of
    // the box's interval, and still found.
    for k in 1..=15 {
        let inset = 2.0 - 10f64.powi(-k);
        for (x, z, down) in [(-inset, inset, true), (inset, -inset, false)] {
            let (y, _) = saddle_height(s, x, z);
            let (from, d) = if down { (10.0, -1.0) } else { (-10.0, 1.0) };
            let ray = Ray::new(
                center + DVec3::new(x, from, z),
                DVec3::new(0.0, d, 0.0),
            );
            let hit = saddle.intersect(&ray, Interval::FORWARD);
            assert!(
                hit.is_some_and(|h| near(h.t, (from - y).abs(), 1e-9)),
                "at the corner ({x}, {z}): expected t = {}, got {hit:?}",
                (from - y).abs()
            );
        }
    }
    let beside = Ray::new(center + DVec3::new(2.1, 10.0, 0.0), DVec3::NEG_Y);
    assert!(saddle.intersect(&beside, Interval::FORWARD).is_none());
    // along +x at height 1.5: x³/4 = 1.5, x = ∛6
    let ray = Ray::new(center + DVec3::new(-5.0, 1.5, 0.0), DVec3::X);
    let hit = saddle.intersect(&ray, Interval::FORWARD).unwrap();
    assert!(near(hit.t, 5.0 + 6f64.cbrt(), 1e-9), "{hit:?}");
    assert_eq!(saddle.name(), "saddle");
}

/// For each of 4000 seeded points of the saddle and a direction in its
/// tangent plane, rays along it moved off the surface by ±1e-3 … ±1e-12,
/// from 1 and from 100 before the point (64 000 rays), and 20 000 random
/// rays through the box. No hit has a NaN or non-unit normal; every hit
/// lies on the surface and in the box; and no ray misses a surface it
/// crosses (a sign change of y − h(x, z) between samples along the ray,
/// the point of tangency among them).
#[test]
fn saddle_near_tangent_rays() {
    let (center, s) = (DVec3::new(-1.0, 0.5, 2.0), 1.5);
    let saddle = Saddle::new(center, s).unwrap();
    let (bounds, sphere) = (saddle.bounds(), saddle.bounding_sphere());
    let height = |p: DVec3| {
        let v = p - center;
        v.y - saddle_height(s, v.x, v.z).0
    };
    let mut rng = Rng::new(5);
    let mut rays = Vec::new();
    for _ in 0..4000 {
        let (x, z) =
            (rng.uniform(-0.99, 0.99) * s, rng.uniform(-0.99, 0.99) * s);
        let (y, normal) = saddle_height(s, x, z);
        let point = center + DVec3::new(x, y, z);
        let tangent = normal.cross(unit_vector(&mut rng)).normalize();
        for k in [3, 6, 9, 12] {
            for sign in [-1.0, 1.0] {
                for lead in [1.0, 100.0] {
                    let start =
                        point + sign * 10f64.powi(-k) * normal - lead * tangent;
                    rays.push((Ray::new(start, tangent), Some(lead)));
                }
            }
        }
    }
    for _ in 0..20_000 {
        let from = center + 4.0 * s * unit_vector(&mut rng);
        let aim = center + s * DVec3::new(rng.uniform(-1.0, 1.0), 0.0, 0.0);
        rays.push((Ray::new(from, aim - from), None));
    }
    let (mut nan_normals, mut off_surface, mut missed, mut hits) = (0, 0, 0, 0);
    for (ray, tangent_at) in &rays {
        let hit = saddle.intersect(ray, Interval::FORWARD);
        if let Some(hit) = hit {
            hits += 1;
            if hit.normal.is_nan() || !near(hit.normal.length(), 1.0, 1e-12) {
                nan_normals += 1;
            }
            if height(hit.point).abs() > 1e-9 * s
                || !in_box(&bounds, hit.point, 1e-9)
                || !in_sphere(&sphere, hit.point, 1e-9)
            {
                off_surface += 1;
            }
        }
        // Does y − h change sign along the ray inside the box?
        let Some(inside) = ch08::slab_test(&bounds, ray, Interval::FORWARD)
        else {
            continue;
        };
        let mut samples: Vec<f64> = (0..=64)
            .map(|i| inside.min + inside.size() * f64::from(i) / 64.0)
            .chain(tangent_at.filter(|t| inside.contains(*t)))
            .collect();
        samples.sort_by(f64::total_cmp);
        let signs: Vec<bool> =
            samples.iter().map(|&t| height(ray.at(t)) < 0.0).collect();
        if signs.windows(2).any(|w| w[0] != w[1]) && hit.is_none() {
            missed += 1;
        }
    }
    assert_eq!(
        (nan_normals, off_surface, missed),
        (0, 0, 0),
        "of {} rays ({hits} hits): NaN or non-unit normals, hits off the \
         surface, rays that cross it without a hit",
        rays.len()
    );
    assert!(hits > 40_000, "only {hits} hits of {} rays", rays.len());
}

/// Bad saddles are refused with a message naming the parameter.
#[test]
fn saddle_refuses_bad_parameters() {
    for (center, size, expected) in [
        (DVec3::ZERO, 0.0, "size 0 must be a positive"),
        (DVec3::ZERO, -1.0, "size -1"),
        (DVec3::ZERO, f64::NAN, "size NaN"),
        (DVec3::new(f64::INFINITY, 0.0, 0.0), 1.0, "center"),
    ] {
        match Saddle::new(center, size) {
            Err(message) => assert!(
                message.starts_with("saddle: ") && message.contains(expected),
                "Saddle::new({center}, {size}): expected an error containing \
                 {expected:?}, got {message:?}"
            ),
            Ok(s) => panic!("expected an error ({expected}), got {s:?}"),
        }
    }
}

// ---------------------------------------------------------------------
// Blobby objects
// ---------------------------------------------------------------------

fn ball(center: DVec3, radius: f64, strength: f64) -> Ball {
    Ball {
        center,
        radius,
        strength,
    }
}

/// One ball of radius 2 at threshold ½ of its strength is a sphere of
/// radius 1 (Wyvill's w(½) = ½): hit from outside at distance − 1, from
/// its centre at 1 (the exit, normal outward), missed beside it.
#[test]
fn one_ball_is_a_sphere() {
    let center = DVec3::new(0.5, -1.0, 2.0);
    let blob = Blobby::new(vec![ball(center, 2.0, 3.0)], 1.5).unwrap();
    let mut rng = Rng::new(6);
    for _ in 0..200 {
        let d = unit_vector(&mut rng);
        let ray = Ray::new(center - 5.0 * d, d);
        let hit = blob.intersect(&ray, Interval::FORWARD).unwrap();
        assert!(near(hit.t, 4.0, 1e-9), "{hit:?}");
        assert!(near_vec(hit.normal, -d, 1e-9), "{hit:?}");
        let out = blob.intersect(&Ray::new(center, d), Interval::FORWARD);
        let out = out.unwrap();
        assert!(near(out.t, 1.0, 1e-9) && near_vec(out.normal, d, 1e-9));
        let beside =
            Ray::new(center - 5.0 * d + 1.01 * d.any_orthonormal_vector(), d);
        assert!(blob.intersect(&beside, Interval::FORWARD).is_none());
    }
    assert_eq!(blob.name(), "blobby");
}

/// Two equal balls 1.6 apart (radius 2, strength 1, threshold ½) merge:
/// on the plane between them the field is 2·w(ρ), so a ray down that
/// plane hits where w(ρ) = ¼, found here by bisection on w; the normal
/// there is straight up by symmetry.
#[test]
fn two_balls_merge() {
    let balls = vec![
        ball(DVec3::new(-0.8, 0.0, 0.0), 2.0, 1.0),
        ball(DVec3::new(0.8, 0.0, 0.0), 2.0, 1.0),
    ];
    let blob = Blobby::new(balls, 0.5).unwrap();
    let w = |rho: f64| {
        let q = rho * rho;
        1.0 - 4.0 / 9.0 * q * q * q + 17.0 / 9.0 * q * q - 22.0 / 9.0 * q
    };
    let (mut lo, mut hi) = (0.0, 1.0); // w falls from 1 to 0
    for _ in 0..100 {
        let mid = 0.5 * (lo + hi);
        if w(mid) > 0.25 { lo = mid } else { hi = mid }
    }
    // ρ = √(0.8² + y²)/2
    let y = ((2.0 * lo).powi(2) - 0.64).sqrt();
    let ray = Ray::new(DVec3::new(0.0, 5.0, 0.0), DVec3::NEG_Y);
    let hit = blob.intersect(&ray, Interval::FORWARD).unwrap();
    assert!(near(hit.t, 5.0 - y, 1e-9), "expected y = {y}, got {hit:?}");
    assert!(near_vec(hit.normal, DVec3::Y, 1e-12), "{hit:?}");
    // midway between the centres the two pulls cancel: still a unit normal
    let n = blob.normal_at(DVec3::ZERO);
    assert!(near(n.length(), 1.0, 1e-12), "normal at the midpoint: {n}");
    let lone = Blobby::new(vec![ball(DVec3::ONE, 1.0, 1.0)], 0.5).unwrap();
    let n = lone.normal_at(DVec3::ONE);
    assert!(near(n.length(), 1.0, 1e-12), "normal at a lone centre: {n}");
}

/// Four overlapping balls of different sizes and strengths, at a seeded
/// threshold. Rays tangent to the one-ball sphere of `one_ball_is_a_sphere`
/// moved in and out by 1e-3 … 1e-12 (40 000 rays), and 20 000 random rays
/// at the four-ball blob: no NaN or non-unit normal; every hit is on the
/// surface (field = threshold within 1e-9) and in the bounds; no sample
/// before it along the ray is inside the blob (it is the first crossing);
/// the tangent rays moved inward by 1e-9 or more all hit.
#[test]
fn blobby_near_tangent_rays() {
    let mut rng = Rng::new(7);
    let center = DVec3::new(0.5, -1.0, 2.0);
    let sphere_blob = Blobby::new(vec![ball(center, 2.0, 3.0)], 1.5).unwrap();
    let blob = Blobby::new(
        vec![
            ball(DVec3::new(0.0, 0.0, 0.0), 1.5, 1.0),
            ball(DVec3::new(1.2, 0.3, 0.0), 1.0, 2.0),
            ball(DVec3::new(0.4, 1.1, -0.5), 1.2, 0.7),
            ball(DVec3::new(-0.9, -0.4, 0.8), 0.8, 1.5),
        ],
        0.6,
    )
    .unwrap();
    let mut cases = Vec::new();
    for _ in 0..2500 {
        // a point of the unit sphere around `center`, a tangent there
        let normal = unit_vector(&mut rng);
        let tangent = normal.cross(unit_vector(&mut rng)).normalize();
        for k in 3..=12 {
            for sign in [-1.0, 1.0] {
                let start = center + (1.0 + sign * 10f64.powi(-k)) * normal
                    - 3.0 * tangent;
                let must_hit = sign < 0.0 && k <= 9;
                cases.push((&sphere_blob, Ray::new(start, tangent), must_hit));
            }
        }
    }
    for _ in 0..20_000 {
        let from = 5.0 * unit_vector(&mut rng);
        let aim = 1.5 * unit_vector(&mut rng);
        cases.push((&blob, Ray::new(from, aim - from), false));
    }
    let (mut nan_normals, mut off_surface, mut not_first, mut missed) =
        (0, 0, 0, 0);
    let mut hits = 0;
    for (blob, ray, must_hit) in &cases {
        let Some(hit) = blob.intersect(ray, Interval::FORWARD) else {
            missed += usize::from(*must_hit);
            continue;
        };
        hits += 1;
        if hit.normal.is_nan() || !near(hit.normal.length(), 1.0, 1e-12) {
            nan_normals += 1;
        }
        let (bounds, sphere) = (blob.bounds(), blob.bounding_sphere());
        if !near(blob.field(hit.point), blob.threshold(), 1e-9)
            || !in_box(&bounds, hit.point, 1e-9)
            || !in_sphere(&sphere, hit.point, 1e-9)
        {
            off_surface += 1;
        }
        // samples before the hit, up to a little short of it, are outside
        if (0..32).any(|i| {
            let t = hit.t * f64::from(i) / 32.0 * 0.999;
            blob.field(ray.at(t)) > blob.threshold()
        }) {
            not_first += 1;
        }
    }
    assert_eq!(
        (nan_normals, off_surface, not_first, missed),
        (0, 0, 0, 0),
        "of {} rays ({hits} hits): NaN or non-unit normals, hits off the \
         surface, hits after an earlier crossing, tangent rays moved inward \
         that missed",
        cases.len()
    );
    assert!(hits > 20_000, "only {hits} hits of {} rays", cases.len());
}

/// Bad blobs are refused with a message naming the ball and parameter.
#[test]
fn blobby_refuses_bad_parameters() {
    let good = ball(DVec3::ZERO, 1.0, 1.0);
    let cases = [
        (vec![], 0.5, "at least one ball"),
        (
            vec![good, ball(DVec3::X, 0.0, 1.0)],
            0.5,
            "ball 1: radius 0",
        ),
        (vec![ball(DVec3::X, 1.0, -2.0)], 0.5, "ball 0: strength -2"),
        (vec![ball(DVec3::NAN, 1.0, 1.0)], 0.5, "ball 0: center"),
        (vec![good], 0.0, "threshold 0 must be between 0 and the sum"),
        (vec![good, good], 2.0, "threshold 2"),
        (vec![good], f64::NAN, "threshold NaN"),
    ];
    for (balls, threshold, expected) in cases {
        match Blobby::new(balls.clone(), threshold) {
            Err(message) => assert!(
                message.starts_with("blobby: ") && message.contains(expected),
                "Blobby::new({balls:?}, {threshold}): expected an error \
                 containing {expected:?}, got {message:?}"
            ),
            Ok(b) => panic!("expected an error ({expected}), got {b:?}"),
        }
    }
}

/// The blob's box is the union of its balls' boxes, and its bounding
/// sphere holds every ball.
#[test]
fn blobby_bounds() {
    let blob = Blobby::new(
        vec![
            ball(DVec3::new(-1.0, 0.0, 0.0), 1.0, 1.0),
            ball(DVec3::new(2.0, 1.0, 0.5), 0.5, 1.0),
        ],
        0.5,
    )
    .unwrap();
    let b = blob.bounds();
    assert_eq!(b.min, DVec3::new(-2.0, -1.0, -1.0));
    assert_eq!(b.max, DVec3::new(2.5, 1.5, 1.0));
    let sphere = blob.bounding_sphere();
    for ball in blob.balls() {
        let reach = (ball.center - sphere.center).length() + ball.radius;
        assert!(reach <= sphere.radius + 1e-12, "{ball:?} sticks out");
    }
}

/// Asked again from just past a hit (interval.min = t.next_up(), as a
/// shadow ray leaving the surface asks, and as chapter 4's shadow check
/// walks past an object's own hits), a slow primitive moves on to its
/// next root or to none: its roots do not depend on where the interval
/// starts. Were they searched from the interval's start, a ray leaving
/// the surface would find a new root of the rounding noise one ulp
/// further on every time, and that walk would never end.
#[test]
fn asked_again_past_a_hit_the_roots_move_on() {
    let objects: Vec<Box<dyn Primitive>> = vec![
        Box::new(
            Torus::new(
                DVec3::new(0.3, -0.2, 0.1),
                DVec3::new(0.0, 0.8, 0.6),
                1.2,
                0.4,
                TorusSolver::Bracketed,
            )
            .unwrap(),
        ),
        Box::new(Saddle::new(DVec3::new(0.1, 0.0, -0.2), 0.9).unwrap()),
        Box::new(
            Blobby::new(
                vec![
                    ball(DVec3::ZERO, 1.1, 1.0),
                    ball(DVec3::new(1.0, 0.5, 0.0), 1.0, 1.0),
                ],
                0.4,
            )
            .unwrap(),
        ),
    ];
    let mut rng = Rng::new(11);
    let mut worst = [0usize; 3];
    for (k, object) in objects.iter().enumerate() {
        let sphere = object.bounding_sphere();
        let mut surface_points = 0;
        while surface_points < 300 {
            // a ray from outside onto the surface, then one leaving the
            // hit point toward a random "light"
            let from =
                sphere.center + 3.0 * sphere.radius * unit_vector(&mut rng);
            let at =
                sphere.center + 0.5 * sphere.radius * unit_vector(&mut rng);
            let Some(hit) =
                object.intersect(&Ray::new(from, at - from), Interval::FORWARD)
            else {
                continue;
            };
            surface_points += 1;
            let light =
                sphere.center + 4.0 * sphere.radius * unit_vector(&mut rng);
            let leaving = Ray::new(hit.point, light - hit.point);
            let mut interval = Interval::new(0.0, 1.0);
            let mut steps = 0;
            while let Some(next) = object.intersect(&leaving, interval) {
                steps += 1;
                assert!(steps <= 8, "object {k}: a root at every start");
                interval.min = next.t.next_up();
            }
            worst[k] = worst[k].max(steps);
        }
    }
    // a torus line meets it at most 4 times, the others fewer here
    assert!(worst.iter().all(|&w| w <= 5), "{worst:?}");
}
