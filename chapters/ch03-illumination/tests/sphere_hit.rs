//! Exercise 1: where a ray meets a sphere.
use ch03::{DVec3, Interval, Ray, Sphere};
use proptest::prelude::*;
use raystep_check::{Table, num, seeded, unit_vector, vec3};

fn v(x: f64, y: f64, z: f64) -> DVec3 {
    DVec3::new(x, y, z)
}

/// The cases of the quadratic: two roots in front, origin inside, a miss,
/// the sphere behind, the near root cut off by the interval.
#[test]
fn sphere_hit_table() {
    let unit = Sphere::new(v(0.0, 0.0, -5.0), 1.0);
    #[rustfmt::skip]
    let cases = [
        ("straight at it", v(0.0, 0.0, 0.0), v(0.0, 0.0, -1.0), Interval::FORWARD),
        ("off-centre", v(0.6, 0.0, 0.0), v(0.0, 0.0, -1.0), Interval::FORWARD),
        ("unnormalised D", v(0.0, 0.0, 0.0), v(0.0, 0.0, -2.0), Interval::FORWARD),
        ("oblique", v(0.0, 3.0, 0.0), v(0.0, -0.6, -0.8), Interval::FORWARD),
        ("from inside", v(0.0, 0.0, -5.0), v(1.0, 0.0, 0.0), Interval::FORWARD),
        ("miss", v(1.5, 0.0, 0.0), v(0.0, 0.0, -1.0), Interval::FORWARD),
        ("sphere behind", v(0.0, 0.0, 0.0), v(0.0, 0.0, 1.0), Interval::FORWARD),
        ("near root cut off", v(0.0, 0.0, 0.0), v(0.0, 0.0, -1.0), Interval::new(4.5, 100.0)),
        ("both cut off", v(0.0, 0.0, 0.0), v(0.0, 0.0, -1.0), Interval::new(0.0, 3.0)),
    ];
    let mut table = Table::new(&["case", "P0", "D", "t", "point", "normal"]);
    for (name, origin, direction, interval) in cases {
        let row = match unit.intersect(&Ray::new(origin, direction), interval) {
            Some(hit) => [num(hit.t), vec3(hit.point), vec3(hit.normal)],
            None => ["none".to_string(), "-".to_string(), "-".to_string()],
        };
        table.row(&[
            name.to_string(),
            vec3(origin),
            vec3(direction),
            row[0].clone(),
            row[1].clone(),
            row[2].clone(),
        ]);
    }
    insta::assert_snapshot!(table.to_string());
}

proptest! {
    #![proptest_config(seeded(256))]

    /// Every hit lies on the sphere, inside the interval, with a unit
    /// outward normal; a ray aimed at the centre from outside always hits,
    /// at t = |P0 − C| − r.
    #[test]
    fn hits_lie_on_the_sphere(
        cx in -10.0..10.0f64, cy in -10.0..10.0f64, cz in -10.0..10.0f64, r in 0.1..5.0f64,
        dir in unit_vector(), away in 0.0..20.0f64, aim in unit_vector(),
    ) {
        let sphere = Sphere::new(v(cx, cy, cz), r);
        let origin = sphere.center + (r + away) * dir;
        let what = |d: DVec3| format!("the sphere at {} of radius {r}, the ray from {origin} along {d}", sphere.center);
        // aimed at the centre
        let hit = sphere.intersect(&Ray::new(origin, -dir), Interval::FORWARD);
        prop_assert!(hit.is_some(), "{}, aimed at the centre: expected a hit at t = {away}, got none", what(-dir));
        let t = hit.unwrap().t;
        prop_assert!((t - away).abs() <= 1e-9 * (r + away), "{}, aimed at the centre: expected t = |P0 − C| − r = {away}, got t = {t}", what(-dir));
        // any direction
        if let Some(hit) = sphere.intersect(&Ray::new(origin, aim), Interval::FORWARD) {
            let from_centre = (hit.point - sphere.center).length();
            prop_assert!(hit.t >= 0.0, "{}: expected t ≥ 0 (the interval starts at 0), got t = {}", what(aim), hit.t);
            prop_assert!((from_centre - r).abs() <= 1e-9 * (r + away), "{}: expected the hit point on the sphere, {r} from its centre, got {} at {from_centre}", what(aim), hit.point);
            prop_assert!((hit.normal.length() - 1.0).abs() <= 1e-9, "{}: expected a unit normal, got {} of length {}", what(aim), hit.normal, hit.normal.length());
            prop_assert!(hit.normal.dot(hit.point - sphere.center) > 0.0, "{}: expected the normal pointing out of the sphere, got {} at {}", what(aim), hit.normal, hit.point);
        }
    }
}

/// Grazing rays: a ray passing the centre at distance r·(1 − 10⁻ᵏ) hits,
/// one at r·(1 + 10⁻ᵏ) misses, for k = 1 … 10, at three scales and eight
/// directions. Failures counted: 0.
#[test]
fn grazing_rays() {
    let (mut checked, mut failures) = (0, 0);
    let mut first = None;
    for scale in [1e-3, 1.0, 1e3] {
        let sphere = Sphere::new(v(0.3, -0.2, 0.1) * scale, 1.5 * scale);
        for azimuth in 0..8 {
            let phi = f64::from(azimuth) * std::f64::consts::TAU / 8.0;
            let side = v(phi.cos(), phi.sin(), 0.0);
            for k in 1..=10 {
                let eps = 10f64.powi(-k);
                for (offset, should_hit) in
                    [(1.0 - eps, true), (1.0 + eps, false)]
                {
                    let origin = sphere.center
                        + side * sphere.radius * offset
                        + v(0.0, 0.0, 10.0 * scale);
                    let hit = sphere.intersect(
                        &Ray::new(origin, v(0.0, 0.0, -1.0)),
                        Interval::FORWARD,
                    );
                    checked += 1;
                    if hit.is_some() != should_hit {
                        failures += 1;
                        first.get_or_insert(format!(
                            "radius {}, a ray passing the centre at r·(1 \
                             {} 1e-{k}): expected {}, got {:?}",
                            sphere.radius,
                            if should_hit { "−" } else { "+" },
                            if should_hit { "a hit" } else { "no hit" },
                            hit.map(|h| h.t)
                        ));
                    }
                }
            }
        }
    }
    assert_eq!(checked, 3 * 8 * 10 * 2, "rays checked");
    assert!(
        failures == 0,
        "grazing rays just inside the sphere that miss or just outside that \
         hit: expected 0 of {checked}, got {failures}; the first: {}",
        first.unwrap_or_default()
    );
}

/// A unit sphere 1e7 from the origin and a 1e-6 sphere 3.7e-5 from it,
/// each hit by a grid of rays from the origin: every hit point must lie on the sphere
/// within 1e-6 of its radius. The textbook discriminant b² − a·c misses
/// this by far at 1e7 (it cancels two numbers near 1e14). Failures: 0.
#[test]
fn far_and_tiny_spheres() {
    let (mut hits, mut failures) = (0, 0);
    let mut first = None;
    for (center, radius) in
        [(v(1e7, 2e6, -3e6), 1.0), (v(2e-5, -1e-5, 3e-5), 1e-6)]
    {
        let sphere = Sphere::new(center, radius);
        let dist = center.length();
        let to_center = center / dist;
        let u = to_center.any_orthonormal_vector();
        let w = to_center.cross(u);
        for i in -10..=10 {
            for j in -10..=10 {
                let target = center
                    + 0.095 * radius * (f64::from(i) * u + f64::from(j) * w);
                let ray =
                    Ray::new(DVec3::ZERO, (target - DVec3::ZERO).normalize());
                if let Some(hit) = sphere.intersect(&ray, Interval::FORWARD) {
                    hits += 1;
                    let off = (hit.point - center).length() - radius;
                    if off.abs() > 1e-6 * radius {
                        failures += 1;
                        first.get_or_insert(format!(
                            "the sphere of radius {radius} at {center}: a hit \
                             {off:e} off its surface"
                        ));
                    }
                }
            }
        }
    }
    // the rays aimed within r of the centre hit: grid points with
    // 0.095·√(i² + j²) < 1, 349 of the 441, for each sphere
    assert!(
        hits == 2 * 349,
        "rays from the origin at a far and a tiny sphere: expected 698 hits \
         (the 349 of 441 aimed within r of each centre), got {hits}"
    );
    assert!(
        failures == 0,
        "hits more than 1e-6·r off the far or tiny sphere (the textbook \
         discriminant b² − a·c cancels there): expected 0 of {hits}, got \
         {failures}; the first: {}",
        first.unwrap_or_default()
    );
}

/// Directions that are not unit vectors: a = D·D is not 1, and a root is
/// a distance divided by |D|. These rays decide by the root q/a (b > 0):
/// from inside toward the centre (the near root is behind), and with the
/// near root cut off.
#[test]
fn unnormalised_directions_by_hand() {
    let unit = Sphere::new(v(0.0, 0.0, -5.0), 1.0);
    #[rustfmt::skip]
    let cases = [
        // |D| = 2: the surface, 1.5 away, is reached at t = 0.75
        ("from (0, 0, -4.5) along (0, 0, -2)", v(0.0, 0.0, -4.5), v(0.0, 0.0, -2.0), Interval::FORWARD, 0.75),
        // |D| = 0.5: the roots 8 and 12; [9, 100] keeps the far one
        ("from (0, 0, 0) along (0, 0, -0.5), t in [9, 100]", v(0.0, 0.0, 0.0), v(0.0, 0.0, -0.5), Interval::new(9.0, 100.0), 12.0),
    ];
    for (what, origin, direction, interval, t) in cases {
        let hit = unit.intersect(&Ray::new(origin, direction), interval);
        let got = hit.map(|h| h.t);
        assert!(
            got.is_some_and(|got| (got - t).abs() <= 1e-12 * t),
            "the sphere at (0, 0, -5) of radius 1, {what}: expected a hit at \
             t = {t}, got {}",
            got.map_or("none".to_string(), |t| format!("t = {t}"))
        );
    }
}

/// The hit is the first root inside the interval, whichever of c/q and q/a
/// it is: for a ray going away from the centre (b < 0) c/q is the larger.
/// An interval reaching back to t = −10 holds both roots of a sphere
/// behind the ray, at t = −6 and −4.
#[test]
fn the_first_root_in_the_interval_going_away() {
    let unit = Sphere::new(v(0.0, 0.0, -5.0), 1.0);
    let ray = Ray::new(v(0.0, 0.0, 0.0), v(0.0, 0.0, 1.0));
    let got = unit
        .intersect(&ray, Interval::new(-10.0, 10.0))
        .map(|h| h.t);
    assert!(
        got == Some(-6.0),
        "the sphere at (0, 0, -5) of radius 1, the ray from (0, 0, 0) along \
         (0, 0, 1), t in [-10, 10] (roots -6 and -4): expected the first, \
         t = -6, got {}",
        got.map_or("none".to_string(), |t| format!("t = {t}"))
    );
}

/// A ray that only touches the sphere, its discriminant exactly 0, hits it
/// at the one (double) root: only a negative discriminant is a miss.
#[test]
fn a_touching_ray_hits() {
    let unit = Sphere::new(v(0.0, 0.0, -5.0), 1.0);
    for (direction, t) in [(v(0.0, 0.0, -1.0), 5.0), (v(0.0, 0.0, -2.0), 2.5)] {
        let ray = Ray::new(v(1.0, 0.0, 0.0), direction);
        let got = unit.intersect(&ray, Interval::FORWARD).map(|h| h.t);
        assert!(
            got.is_some_and(|got| (got - t).abs() <= 1e-12 * t),
            "the sphere at (0, 0, -5) of radius 1, the ray from (1, 0, 0) \
             along {direction} touching it at (1, 0, -5) (discriminant 0): \
             expected a hit at t = {t}, got {}",
            got.map_or("none".to_string(), |t| format!("t = {t}"))
        );
    }
}

proptest! {
    #![proptest_config(seeded(256))]

    /// A ray that starts on the sphere (a hit point, to rounding) and goes
    /// in, as a refracted ray does, leaves it at t = 2·(C − P₀)·D / D·D.
    /// Its c = |P₀ − C|² − r² is rounding noise, so of the two roots only
    /// q/a with q = b + sign(b)·√Δ is precise: b − sign(b)·√Δ would cancel
    /// to noise too, and c divided by it is no root at all.
    #[test]
    fn from_the_surface_inward_to_the_far_side(
        cx in -10.0..10.0f64, cy in -10.0..10.0f64, cz in -10.0..10.0f64, r in 0.1..5.0f64,
        normal in unit_vector(), aim in unit_vector(), length in 0.1..10.0f64,
    ) {
        let sphere = Sphere::new(v(cx, cy, cz), r);
        let origin = sphere.center + r * normal;
        // inward, at most about 70° from −normal (a chord of at least 2r/3)
        let direction = (aim - 2.0 * normal).normalize() * length;
        let exit = 2.0 * (sphere.center - origin).dot(direction) / direction.dot(direction);
        // past the near root, which is rounding noise about 0
        let interval = Interval::new(1e-6 * r / length, f64::INFINITY);
        let got = sphere.intersect(&Ray::new(origin, direction), interval).map(|h| h.t);
        prop_assert!(
            got.is_some_and(|t| (t - exit).abs() * length <= 1e-9 * r),
            "the sphere at {} of radius {r}, the ray from its surface point {origin} inward along {direction}, t ≥ {}: expected the far side at t = 2·(C − P₀)·D / D·D = {exit}, got {}",
            sphere.center, interval.min, got.map_or("none".to_string(), |t| format!("t = {t}"))
        );
    }
}
