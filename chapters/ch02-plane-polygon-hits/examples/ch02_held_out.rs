//! Held-out cases of chapter 2 for `raystep grade` (see
//! `raystep_check::held_out`): rays against planes drawn at grading time
//! (hits, misses behind and beyond the interval, grazing, parallel and
//! in-plane rays, exact and rounded, near and far from the origin), and
//! points against convex polygons (random ones, and lattice ones whose
//! edges pass exactly through the points, where the tie rule decides).
use std::process::ExitCode;

use ch02::{
    DVec2, DVec3, Interval, Plane, Ray, RayPlane, edge_function, inside_convex,
    ray_plane,
};
use raystep_check::held_out::{self, Case, Exercise, Rng, short, show2, show3};

fn main() -> ExitCode {
    held_out::main(&[
        Exercise::new("ray_plane", ray_plane_case, 1e-7),
        Exercise::new("inside_polygon", inside_polygon_case, 1e-9),
    ])
}

/// A size for a case's coordinates: any decade from 1e-3 to 1e6, now and
/// then one from 1e-100 to 1e100.
fn scale(rng: &mut Rng) -> f64 {
    if rng.chance(0.2) {
        10f64.powf(rng.uniform(-100.0, 100.0))
    } else {
        rng.magnitude(1e-3, 1e6).abs()
    }
}

/// `a·b + c` to nearly twice f64 precision (each product's and sum's
/// rounding error recovered exactly): what the case's numbers are
/// exactly, to tell a clear case from one within rounding of a boundary.
fn accurate_dot(a: DVec3, b: DVec3, c: f64) -> f64 {
    let (mut sum, mut error) = (c, 0.0);
    for (x, y) in [(a.x, b.x), (a.y, b.y), (a.z, b.z)] {
        let product = x * y;
        error += x.mul_add(y, -product);
        let next = sum + product;
        let bp = next - sum;
        error += (sum - (next - bp)) + (product - bp);
        sum = next;
    }
    sum + error
}

/// A unit vector along a coordinate axis, either way.
fn axis_normal(rng: &mut Rng) -> (usize, DVec3) {
    let k = rng.below(3);
    let mut n = DVec3::ZERO;
    n[k] = if rng.chance(0.5) { 1.0 } else { -1.0 };
    (k, n)
}

/// An interval of t: all of [0, ∞), the whole line, or a stretch.
fn interval(rng: &mut Rng, t_scale: f64) -> Interval {
    match rng.below(5) {
        0 | 1 => Interval::FORWARD,
        2 => Interval::UNIVERSE,
        3 => Interval::new(0.0, t_scale * rng.uniform(0.1, 4.0)),
        _ => {
            let lo = t_scale * rng.uniform(-2.0, 2.0);
            Interval::new(lo, lo + t_scale * rng.uniform(0.1, 4.0))
        }
    }
}

fn show_interval(i: Interval) -> String {
    format!("[{}, {}]", short(i.min), short(i.max))
}

/// Is `t` (exact to about 1e-9) within 1e-6 of an end of the interval,
/// where a correct solution could round to either side?
fn near_an_end(t: f64, i: Interval) -> bool {
    [i.min, i.max].iter().any(|&end| {
        end.is_finite() && (t - end).abs() <= 1e-6 * t.abs().max(end.abs())
    })
}

/// A unit direction in the plane of the unit `normal`, at a random angle.
fn along_plane(rng: &mut Rng, normal: DVec3) -> DVec3 {
    let u = normal.any_orthonormal_vector();
    let w = normal.cross(u);
    let phi = rng.uniform(0.0, std::f64::consts::TAU);
    phi.cos() * u + phi.sin() * w
}

/// N·P + d for the plane at `p`, to nearly twice f64 precision, and the
/// size of its terms (|N|·|P| + |d|), to tell how clear of 0 it is.
fn plane_distance(plane: &Plane, p: DVec3) -> (f64, f64) {
    let distance = accurate_dot(plane.normal, p, plane.d);
    (distance, plane.normal.abs().dot(p.abs()) + plane.d.abs())
}

/// The plane, ray and interval of one case, and the scale of its t.
struct PlaneCase {
    what: &'static str,
    plane: Plane,
    ray: Ray,
    interval: Interval,
    t_scale: f64,
}

/// A ray crossing a tilted plane clearly (not within 1e-3 rad of
/// parallel, its origin not within 1e-4 of its size from the plane): a
/// hit, or a t behind the origin or past the interval.
fn crossing(rng: &mut Rng, s: f64, m: f64) -> Option<PlaneCase> {
    let normal = rng.unit_vec3();
    let plane = Plane {
        normal,
        d: rng.uniform(-s, s),
    };
    let origin = rng.vec3(s);
    let direction = rng.unit_vec3() * m;
    let approach = accurate_dot(normal, direction, 0.0);
    let approach_size = normal.abs().dot(direction.abs());
    let (distance, distance_size) = plane_distance(&plane, origin);
    if approach.abs() < 1e-3 * approach_size
        || distance.abs() < 1e-4 * distance_size
    {
        return None;
    }
    let t_scale = s / m;
    let interval = interval(rng, t_scale);
    if near_an_end(-distance / approach, interval) {
        return None;
    }
    Some(PlaneCase {
        what: "a crossing",
        plane,
        ray: Ray::new(origin, direction),
        interval,
        t_scale,
    })
}

/// A ray at an angle of 1e-6 to 1e-1 rad to a tilted plane, from a point
/// above it: t = h / sin α, far along the ray.
fn grazing(rng: &mut Rng, s: f64, m: f64) -> Option<PlaneCase> {
    let normal = rng.unit_vec3();
    let along = along_plane(rng, normal);
    let alpha = 10f64.powf(rng.uniform(-6.0, -1.0));
    let height = s * rng.uniform(0.1, 1.0);
    let foot = rng.vec3(s);
    let plane = Plane {
        normal,
        d: -normal.dot(foot),
    };
    let origin = foot + height * normal;
    let direction = (alpha.cos() * along - alpha.sin() * normal) * m;
    let approach = accurate_dot(normal, direction, 0.0);
    let (distance, distance_size) = plane_distance(&plane, origin);
    if distance.abs() < 1e-4 * distance_size {
        return None;
    }
    let t_scale = s / m / alpha;
    let interval = if rng.chance(0.7) {
        Interval::FORWARD
    } else {
        Interval::new(0.0, t_scale * rng.uniform(0.1, 3.0))
    };
    if near_an_end(-distance / approach, interval) {
        return None;
    }
    Some(PlaneCase {
        what: "a grazing ray",
        plane,
        ray: Ray::new(origin, direction),
        interval,
        t_scale,
    })
}

/// A plane x, y or z = c and a ray whose component along its normal is
/// exactly ±0: parallel off the plane, or lying in it (origin exactly on
/// it), or starting on it and leaving it (t exactly 0).
fn axis_plane(rng: &mut Rng, s: f64, m: f64) -> Option<PlaneCase> {
    let (k, normal) = axis_normal(rng);
    let c = rng.uniform(-s, s);
    let plane = Plane {
        normal,
        d: -normal[k] * c,
    };
    let mut origin = rng.vec3(s);
    let mut direction = rng.unit_vec3() * m;
    let what = match rng.below(3) {
        0 => {
            // parallel, clearly off the plane
            origin[k] = c + s * rng.uniform(0.01, 1.0) * sign(rng);
            direction[k] = if rng.chance(0.5) { 0.0 } else { -0.0 };
            "parallel to an axis plane"
        }
        1 => {
            origin[k] = c;
            direction[k] = if rng.chance(0.5) { 0.0 } else { -0.0 };
            "lying in an axis plane"
        }
        _ => {
            origin[k] = c;
            if direction[k].abs() < 0.05 * m {
                return None;
            }
            "starting on an axis plane"
        }
    };
    let t_scale = s / m;
    let interval = match rng.below(3) {
        0 => Interval::FORWARD,
        1 => Interval::new(0.0, t_scale),
        _ => Interval::new(-t_scale, t_scale),
    };
    Some(PlaneCase {
        what,
        plane,
        ray: Ray::new(origin, direction),
        interval,
        t_scale,
    })
}

/// A ray parallel to an axis plane far from the origin, a few ulps above
/// it: in the plane as far as rounding can tell (N·P₀ + d within
/// 8ε·(N.abs()·P₀.abs() + |d|)), or parallel beyond that. Never within
/// 1 % of the threshold, where the rounding of the sum could decide.
fn far_plane(rng: &mut Rng, _s: f64, m: f64) -> Option<PlaneCase> {
    let (k, normal) = axis_normal(rng);
    let far = 10f64.powf(rng.uniform(-3.0, 9.0));
    let c = far * sign(rng);
    let plane = Plane {
        normal,
        d: -normal[k] * c,
    };
    let mut origin = rng.vec3(far);
    let most = if rng.chance(0.5) { 40 } else { 400 };
    let ulps = rng.below(most) as u64;
    let z = f64::from_bits(c.to_bits() + ulps);
    origin[k] = z;
    let distance = (z - c).abs();
    let threshold = 8.0 * f64::EPSILON * (z.abs() + c.abs());
    let ratio = distance / threshold;
    if (0.99..=1.01).contains(&ratio) {
        return None;
    }
    let mut direction = rng.unit_vec3() * m;
    direction[k] = 0.0;
    if direction.length() < 0.05 * m {
        return None;
    }
    Some(PlaneCase {
        what: "parallel to a far plane, a few ulps off it",
        plane,
        ray: Ray::new(origin, direction),
        interval: Interval::FORWARD,
        t_scale: far / m,
    })
}

/// A tilted plane and a ray built parallel to it (so N·D is rounding
/// noise), from a point clearly above it or from a point built on it (so
/// N·P₀ + d is rounding noise): parallel, or in the plane. Only rays
/// whose exact N·D and N·P₀ + d are within 4ε of their sizes (any order
/// of operations then rounds to within 8ε) or clearly not.
fn rounded_parallel(rng: &mut Rng, s: f64, m: f64) -> Option<PlaneCase> {
    let normal = rng.unit_vec3();
    let along = along_plane(rng, normal);
    let plane = Plane {
        normal,
        d: rng.uniform(-s, s),
    };
    let base = rng.vec3(s);
    // N·P + d plainly (chapter 1's `Plane::eval` is its exercise)
    let on_plane = base - (normal.dot(base) + plane.d) * normal;
    let in_plane = rng.chance(0.5);
    let origin = if in_plane {
        on_plane + s * rng.uniform(0.1, 3.0) * along
    } else {
        on_plane + s * rng.uniform(0.01, 1.0) * sign(rng) * normal
    };
    let direction = along * m;
    let eps = f64::EPSILON;
    let approach = accurate_dot(normal, direction, 0.0);
    if approach.abs() > 4.0 * eps * normal.abs().dot(direction.abs()) {
        return None;
    }
    let (distance, distance_size) = plane_distance(&plane, origin);
    let clear = if in_plane {
        distance.abs() <= 4.0 * eps * distance_size
    } else {
        distance.abs() >= 1e-6 * distance_size
    };
    if !clear {
        return None;
    }
    Some(PlaneCase {
        what: if in_plane {
            "built in a tilted plane (rounded)"
        } else {
            "built parallel to a tilted plane (rounded)"
        },
        plane,
        ray: Ray::new(origin, direction),
        interval: Interval::FORWARD,
        t_scale: s / m,
    })
}

fn sign(rng: &mut Rng) -> f64 {
    if rng.chance(0.5) { 1.0 } else { -1.0 }
}

/// A kind of case: draws one (or None, to draw again) at a scale s of
/// coordinates and m of the direction.
type Kind = fn(&mut Rng, f64, f64) -> Option<PlaneCase>;

/// One ray against one plane: the case (hit, outside, parallel, in
/// plane) and t, in units of the case's scale of t.
fn ray_plane_case(rng: &mut Rng, case: &mut Case) {
    let kinds: [Kind; 5] =
        [crossing, grazing, axis_plane, far_plane, rounded_parallel];
    let weights = [0, 0, 0, 1, 1, 2, 2, 3, 4, 4];
    let kind = kinds[weights[rng.below(weights.len())]];
    let c = loop {
        let s = scale(rng);
        let m = rng.magnitude(1e-3, 1e3).abs();
        if let Some(c) = kind(rng, s, m) {
            break c;
        }
    };
    case.ask(format!(
        "{}: plane N = {}, d = {}; ray from {} along {}; t in {}",
        c.what,
        show3(c.plane.normal),
        short(c.plane.d),
        show3(c.ray.origin),
        show3(c.ray.direction),
        show_interval(c.interval)
    ));
    match ray_plane(&c.plane, &c.ray, c.interval) {
        RayPlane::Hit(t) => {
            case.word("hit");
            case.num("t/T", t / c.t_scale);
        }
        RayPlane::Outside(t) => {
            case.word("outside");
            case.num("t/T", t / c.t_scale);
        }
        RayPlane::Parallel => case.word("parallel"),
        RayPlane::InPlane => case.word("in-plane"),
    }
}

/// Twice the signed area of (a, b, p), plainly: to judge how clear a
/// case is, not to answer it.
fn cross(a: DVec2, b: DVec2, p: DVec2) -> f64 {
    (b - a).perp_dot(p - a)
}

/// Is `p` clearly off the line through `a` and `b` (by more than 1e-5 of
/// the sizes that make its edge function, so any order of operations
/// gets its sign and its value to 1e-10)?
fn clearly_off(a: DVec2, b: DVec2, p: DVec2) -> bool {
    let size = (b - a).length() * ((p - a).length() + (b - a).length());
    cross(a, b, p).abs() > 1e-5 * size
}

/// Counter-clockwise points on a circle at sorted random angles, at least
/// 0.2 rad apart: a convex polygon.
fn circle_polygon(rng: &mut Rng, s: f64) -> Vec<DVec2> {
    let centre = rng.vec2(3.0 * s);
    let r = s * rng.uniform(0.3, 2.0);
    let n = 3 + rng.below(6);
    let mut angles: Vec<f64> = (0..n)
        .map(|_| rng.uniform(0.0, std::f64::consts::TAU))
        .collect();
    angles.sort_by(f64::total_cmp);
    angles.dedup_by(|a, b| *a - *b < 0.2);
    if angles.len() > 1
        && angles[0] + std::f64::consts::TAU - angles[angles.len() - 1] < 0.2
    {
        angles.pop();
    }
    angles
        .into_iter()
        .map(|a| centre + r * DVec2::new(a.cos(), a.sin()))
        .collect()
}

/// The convex hull (counter-clockwise, no three corners in line) of
/// random points of the integer lattice in [−6, 6]², exact arithmetic.
fn lattice_polygon(rng: &mut Rng) -> Vec<DVec2> {
    loop {
        let mut points: Vec<DVec2> = (0..3 + rng.below(8))
            .map(|_| {
                DVec2::new(
                    rng.below(13) as f64 - 6.0,
                    rng.below(13) as f64 - 6.0,
                )
            })
            .collect();
        points.sort_by(|a, b| a.x.total_cmp(&b.x).then(a.y.total_cmp(&b.y)));
        points.dedup();
        let hull = hull(&points);
        if hull.len() >= 3 {
            return hull;
        }
    }
}

/// Andrew's monotone chain on sorted points: the hull, counter-clockwise,
/// without corners in line.
fn hull(sorted: &[DVec2]) -> Vec<DVec2> {
    let mut lower: Vec<DVec2> = Vec::new();
    for &p in sorted {
        while lower.len() >= 2
            && cross(lower[lower.len() - 2], lower[lower.len() - 1], p) <= 0.0
        {
            lower.pop();
        }
        lower.push(p);
    }
    let mut upper: Vec<DVec2> = Vec::new();
    for &p in sorted.iter().rev() {
        while upper.len() >= 2
            && cross(upper[upper.len() - 2], upper[upper.len() - 1], p) <= 0.0
        {
            upper.pop();
        }
        upper.push(p);
    }
    lower.pop();
    upper.pop();
    lower.extend(upper);
    lower
}

fn show_polygon(polygon: &[DVec2]) -> String {
    let corners: Vec<String> = polygon.iter().map(|&p| show2(p)).collect();
    format!("[{}]", corners.join(", "))
}

/// The edge function of a random edge at random points (clear of its
/// line), and at points where it is exactly 0 or antisymmetric to the
/// bit; or the edge test of a polygon at probe points.
fn inside_polygon_case(rng: &mut Rng, case: &mut Case) {
    match rng.below(4) {
        0 => edge_case(rng, case),
        1 => circle_case(rng, case),
        2 => lattice_case(rng, case),
        _ => degenerate_case(rng, case),
    }
}

/// f of a → b at p (in units of the size squared), whether it is exactly
/// 0 at both ends and exactly antisymmetric, at random points or at
/// points of a lattice exactly on the edge's line.
fn edge_case(rng: &mut Rng, case: &mut Case) {
    let s = 10f64.powf(rng.uniform(-100.0, 100.0));
    let lattice = rng.chance(0.4);
    let (a, b, p) = loop {
        if lattice {
            // small integers times a power of two: every f exact
            let unit = 2f64.powi(rng.below(60) as i32 - 30);
            let (a, b) = (small_point(rng), small_point(rng));
            // now and then the same x (the (x, y) order falls to y)
            let b = if rng.chance(0.2) {
                DVec2::new(a.x, b.y)
            } else {
                b
            };
            let k = rng.below(5) as f64 - 1.0;
            let p = if rng.chance(0.5) {
                a + k * 0.5 * (b - a)
            } else {
                small_point(rng)
            };
            if a != b {
                break (a * unit, b * unit, p * unit);
            }
        } else {
            let (a, b, p) = (rng.vec2(s), rng.vec2(s), rng.vec2(s));
            let b = if rng.chance(0.15) {
                DVec2::new(a.x, b.y)
            } else {
                b
            };
            if a != b && clearly_off(a, b, p) {
                break (a, b, p);
            }
        }
    };
    let size = (b - a).abs().max_element().max(1e-300);
    case.ask(format!(
        "edge_function({}, {}, p = {})",
        show2(a),
        show2(b),
        show2(p)
    ));
    let f = edge_function(a, b, p);
    let back = edge_function(b, a, p);
    case.num("f/size²", f / (size * size));
    case.num("reversed/size²", back / (size * size));
    case.word(if back == -f {
        "antisymmetric"
    } else {
        "not-antisymmetric"
    });
    let ends = [
        edge_function(a, b, a),
        edge_function(a, b, b),
        edge_function(b, a, a),
        edge_function(b, a, b),
    ];
    case.word(if ends.iter().all(|&e| e == 0.0) {
        "zero-at-ends"
    } else {
        "not-zero-at-ends"
    });
}

/// A point of the integer lattice in [−8, 8]².
fn small_point(rng: &mut Rng) -> DVec2 {
    DVec2::new(rng.below(17) as f64 - 8.0, rng.below(17) as f64 - 8.0)
}

/// A convex polygon on a circle at any scale from 1e-3 to 1e6 (drawn
/// again until it has three corners), and its centroid.
fn some_circle_polygon(rng: &mut Rng) -> (Vec<DVec2>, DVec2) {
    let s = rng.magnitude(1e-3, 1e6).abs();
    let polygon = loop {
        let polygon = circle_polygon(rng, s);
        if polygon.len() >= 3 {
            break polygon;
        }
    };
    let centre = polygon.iter().sum::<DVec2>() / polygon.len() as f64;
    (polygon, centre)
}

/// `in` or `out`: the edge test's verdict on `p`.
fn inside_word(polygon: &[DVec2], p: DVec2) -> &'static str {
    if inside_convex(polygon, p) {
        "in"
    } else {
        "out"
    }
}

/// Asks for the edge test of `polygon` at each of `probes`, and answers.
fn inside_at_probes(case: &mut Case, polygon: &[DVec2], probes: &[DVec2]) {
    case.ask(format!(
        "inside_convex({}) at {}",
        show_polygon(polygon),
        show_polygon(probes)
    ));
    for &p in probes {
        case.word(inside_word(polygon, p));
    }
}

/// A convex polygon on a circle and points clearly inside or outside it.
fn circle_case(rng: &mut Rng, case: &mut Case) {
    let (polygon, centre) = some_circle_polygon(rng);
    let reach = polygon
        .iter()
        .map(|&p| p.distance(centre))
        .fold(0.0, f64::max);
    let probes: Vec<DVec2> = (0..8)
        .map(|_| {
            loop {
                let p = centre + rng.vec2(1.2 * reach);
                let n = polygon.len();
                if (0..n)
                    .all(|i| clearly_off(polygon[i], polygon[(i + 1) % n], p))
                {
                    break p;
                }
            }
        })
        .collect();
    inside_at_probes(case, &polygon, &probes);
}

/// A convex lattice polygon (scaled by a power of two) and points on its
/// corners, on its edges and around it: every edge function exact, the
/// tie rule deciding the points on edges.
fn lattice_case(rng: &mut Rng, case: &mut Case) {
    let unit = 2f64.powi(rng.below(40) as i32 - 20);
    let offset =
        DVec2::new(rng.below(9) as f64 - 4.0, rng.below(9) as f64 - 4.0) * 16.0;
    let polygon: Vec<DVec2> = lattice_polygon(rng)
        .into_iter()
        .map(|p| (p + offset) * unit)
        .collect();
    let n = polygon.len();
    let probes: Vec<DVec2> = (0..10)
        .map(|_| {
            let i = rng.below(n);
            let (a, b) = (polygon[i], polygon[(i + 1) % n]);
            match rng.below(4) {
                0 => a,
                1 => a + 0.5 * (b - a),
                2 => a + 0.25 * (b - a),
                _ => {
                    let q = DVec2::new(
                        rng.below(29) as f64 / 2.0 - 7.0,
                        rng.below(29) as f64 / 2.0 - 7.0,
                    );
                    (q + offset) * unit
                }
            }
        })
        .collect();
    inside_at_probes(case, &polygon, &probes);
}

/// Fewer than three corners, a NaN point, a corner repeated.
fn degenerate_case(rng: &mut Rng, case: &mut Case) {
    let (polygon, centre) = some_circle_polygon(rng);
    let (what, polygon, p) = match rng.below(3) {
        0 => {
            let keep = rng.below(3);
            ("too few corners", polygon[..keep].to_vec(), centre)
        }
        1 => {
            let mut p = centre;
            p[rng.below(2)] = f64::NAN;
            ("a NaN point", polygon, p)
        }
        _ => {
            let mut repeated = polygon.clone();
            let i = rng.below(repeated.len());
            repeated.insert(i, repeated[i]);
            ("a corner repeated", repeated, centre)
        }
    };
    case.ask(format!(
        "{what}: inside_convex({}) at {}",
        show_polygon(&polygon),
        show2(p)
    ));
    case.word(inside_word(&polygon, p));
}
