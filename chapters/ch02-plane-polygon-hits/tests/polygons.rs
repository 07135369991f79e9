//! Polygons in 3D: the hit map, shared edges and vertices, scale.
//! These use both exercises (through `Polygon::intersect`).
use ch02::{
    DVec2, DVec3, Interval, Polygon, Ray, closest_hit, demo_camera, demo_scene,
    hit_map,
};
use raystep_check::{Table, num, vec3};

fn v(x: f64, y: f64, z: f64) -> DVec3 {
    DVec3::new(x, y, z)
}

/// The polygon with these vertices, or a panic that says why there is none.
fn polygon(vertices: Vec<DVec3>) -> Polygon {
    Polygon::new(vertices.clone()).unwrap_or_else(|e| {
        panic!(
            "Polygon::new({vertices:?}): expected a polygon, got the error \
             \"{e}\" (it finds its plane with chapter 1's Plane::through)"
        )
    })
}

/// How many of `polygons` the ray hits (closest-hit aside).
fn hits(polygons: &[Polygon], ray: &Ray) -> usize {
    polygons
        .iter()
        .filter(|p| p.intersect(ray, Interval::FORWARD).is_some())
        .count()
}

/// Rays that must each hit exactly one polygon: how many were shot, how
/// many fell through, how many were counted twice, and the first of those.
#[derive(Default)]
struct ExactlyOnce {
    rays: usize,
    fall_through: usize,
    twice: usize,
    first: Option<String>,
}

impl ExactlyOnce {
    /// Counts a ray that hit `n` polygons; `which` says which ray it was.
    fn count(&mut self, n: usize, which: impl FnOnce() -> String) {
        self.rays += 1;
        match n {
            0 => self.fall_through += 1,
            1 => {}
            _ => self.twice += 1,
        }
        if n != 1 {
            self.first.get_or_insert_with(which);
        }
    }
}

/// The demo scene through the pinhole camera, one character per pixel.
#[test]
fn hit_map_ascii() {
    let map = hit_map(&demo_scene(), &demo_camera(), 64, 24);
    insta::assert_snapshot!(map.to_ascii());
}

/// The closest hit wins where polygons overlap: the triangle (A) hides the
/// square (B) behind it.
#[test]
fn closest_hit_table() {
    let scene = demo_scene();
    let eye = demo_camera().eye;
    let targets = [
        v(-0.4, -0.4, 0.5),
        v(0.6, 0.0, -0.5),
        v(2.1, -0.9, 0.0),
        v(1.6, 0.5, 0.0),
        v(3.0, 3.0, 0.0),
    ];
    let mut table = Table::new(&["target", "polygon", "t", "point", "normal"]);
    for target in targets {
        let ray = Ray::new(eye, (target - eye).normalize());
        let row = match closest_hit(&scene, &ray, Interval::FORWARD) {
            Some((i, hit)) => [
                vec3(target),
                char::from(b'A' + i as u8).to_string(),
                num(hit.t),
                vec3(hit.point),
                vec3(hit.normal),
            ],
            None => [
                vec3(target),
                "none".into(),
                "-".into(),
                "-".into(),
                "-".into(),
            ],
        };
        table.row(&row);
    }
    insta::assert_snapshot!(table.to_string());
}

/// A concave polygon where the edge test alone would be wrong: the
/// polygon switches to the crossing test and gets the notch right.
#[test]
fn concave_polygon_uses_the_crossing_test() {
    let l = polygon(vec![
        v(0.0, 0.0, 0.0),
        v(2.0, 0.0, 0.0),
        v(2.0, 1.0, 0.0),
        v(1.0, 1.0, 0.0),
        v(1.0, 2.0, 0.0),
        v(0.0, 2.0, 0.0),
    ]);
    assert!(!l.is_convex(), "the L-shape: expected not convex");
    let down = |x, y| Ray::new(v(x, y, 1.0), v(0.0, 0.0, -1.0));
    for (x, y, expected, where_) in [
        (0.5, 1.5, true, "in the upper arm"),
        (1.5, 0.5, true, "in the right arm"),
        (1.5, 1.5, false, "in the notch"),
    ] {
        let hit = l.intersect(&down(x, y), Interval::FORWARD);
        assert!(
            hit.is_some() == expected,
            "a ray straight down at ({x}, {y}) onto the L-shape, {where_}: \
             expected {}, got {hit:?}",
            if expected { "a hit" } else { "no hit" }
        );
    }
    // The edge test alone is wrong here: the reflex corner's edges cut off
    // part of the L, so a point inside the L fails it.
    assert!(
        !ch02::inside_convex(l.outline(), DVec2::new(0.5, 1.5)),
        "inside_convex on the L-shape (not convex) at (0.5, 1.5): expected \
         outside (the edges at the reflex corner cut off the upper arm), got \
         inside"
    );
}

/// A fan of polygons around a shared centre vertex, all in one plane
/// (z = 0.75) but turned by an odd angle, mixing triangles, a quad and a
/// concave quadrilateral. Rays straight down through the centre, through many
/// points of every shared edge, and through a grid of points; rays from an
/// eye through the same points. Every ray must hit exactly one polygon: 0
/// fall through, 0 counted twice.
#[test]
fn fan_shared_edges_and_vertex() {
    let z = 0.75;
    let centre = v(0.1, -0.3, z);
    let turn = 0.37f64;
    let rim: Vec<DVec3> = (0..7)
        .map(|i| {
            let a = turn + f64::from(i) * std::f64::consts::TAU / 7.0;
            let r = if i % 2 == 0 { 1.0 } else { 1.6 };
            centre + v(r * a.cos(), r * a.sin(), 0.0)
        })
        .collect();
    // polygons between consecutive rim vertices; two of them merged into a
    // quad, and one given an extra notch vertex (concave quadrilateral)
    let mut fan = Vec::new();
    fan.push(polygon(vec![centre, rim[0], rim[1], rim[2]])); // quad
    fan.push(polygon(vec![centre, rim[2], rim[3]]));
    let notch = centre + 0.8 * (rim[3] + rim[4] - 2.0 * centre) / 2.0 * 0.6;
    fan.push(polygon(vec![centre, rim[3], notch, rim[4]])); // concave
    // the neighbour of the notch fills it
    fan.push(polygon(vec![notch, rim[3], rim[4]]));
    for i in 4..7 {
        fan.push(polygon(vec![centre, rim[i], rim[(i + 1) % 7]]));
    }
    assert!(!fan[2].is_convex(), "the notched quadrilateral is concave");

    // points: the centre, points along every spoke, a grid inside the fan
    let mut targets = vec![centre, notch];
    for r in rim.iter().chain([&notch]) {
        for k in 1..50 {
            targets.push(centre + (*r - centre) * (f64::from(k) / 50.0));
        }
    }
    for k in 1..50 {
        targets.push(rim[3] + (notch - rim[3]) * (f64::from(k) / 50.0));
        targets.push(rim[4] + (notch - rim[4]) * (f64::from(k) / 50.0));
    }
    for i in -20..=20 {
        for j in -20..=20 {
            let q = centre + v(f64::from(i) * 0.035, f64::from(j) * 0.035, 0.0);
            targets.push(q);
        }
    }
    let eye = v(0.4, 0.9, 4.0);
    let mut tally = ExactlyOnce::default();
    for q in targets {
        for ray in [
            Ray::new(v(q.x, q.y, 2.0), v(0.0, 0.0, -1.0)),
            Ray::new(eye, (q - eye).normalize()),
        ] {
            let n = hits(&fan, &ray);
            tally.count(n, || {
                format!(
                    "the ray from {} through {q} hits {n} polygons",
                    ray.origin
                )
            });
        }
    }
    assert_eq!(tally.rays, 2 * (2 + 8 * 49 + 2 * 49 + 41 * 41), "rays shot");
    assert!(
        (tally.fall_through, tally.twice) == (0, 0),
        "rays through the fan that fall through a shared edge or vertex, \
         and rays counted by two polygons: expected 0 and 0 of {} (every \
         ray hits exactly one polygon), got {} and {}; the \
         first: {}",
        tally.rays,
        tally.fall_through,
        tally.twice,
        tally.first.unwrap_or_default()
    );
}

/// The same square and the same rays at scales 1e-6 … 1e6, moved away from
/// the origin by 3 square sizes: rays through points inside hit at the
/// right t (relative error below 1e-9), rays just outside miss. 0 failures.
#[test]
fn stable_from_1e_minus_6_to_1e6() {
    let (mut checked, mut failures) = (0, 0);
    let mut first = None;
    for exponent in -6..=6 {
        let s = 10f64.powi(exponent);
        let o = v(3.0, -3.0, 3.0) * s;
        // a unit square tilted in z, scaled by s and moved to o
        let plane_point = |x: f64, y: f64| o + v(x, y, 0.2 * x + 0.5 * y) * s;
        let corners = [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)];
        let square = polygon(corners.map(|(x, y)| plane_point(x, y)).to_vec());
        let eye = o + v(0.3, 0.4, 5.0) * s;
        for (x, y, inside) in [
            (0.5, 0.5, true),
            (0.01, 0.99, true),
            (0.999, 0.001, true),
            (1.01, 0.5, false),
            (0.5, -0.01, false),
        ] {
            let target = plane_point(x, y);
            let ray = Ray::new(eye, (target - eye).normalize());
            checked += 1;
            let expected_t = (target - eye).length();
            let hit = square.intersect(&ray, Interval::FORWARD);
            let ok = match hit {
                Some(hit) => {
                    inside && ((hit.t - expected_t) / expected_t).abs() < 1e-9
                }
                None => !inside,
            };
            if !ok {
                failures += 1;
                first.get_or_insert(format!(
                    "scale 1e{exponent}, square point ({x}, {y}): expected \
                     {}, got {:?}",
                    if inside {
                        format!("a hit at t = {expected_t}")
                    } else {
                        "no hit (just outside)".to_string()
                    },
                    hit.map(|h| h.t)
                ));
            }
        }
    }
    assert_eq!(checked, 13 * 5, "rays checked: 5 at each of 13 scales");
    assert!(
        failures == 0,
        "rays at a tilted square scaled from 1e-6 to 1e6 that miss it inside, \
         hit it outside or hit at a wrong t: expected 0 of {checked}, got \
         {failures}; the first: {}",
        first.unwrap_or_default()
    );
}

/// Two polygons sharing a chain a → m → b whose middle vertex m is placed by
/// rounding, a hair off the straight line: one polygon is concave there, the
/// other convex by a rounding error only. The edge test would consult the
/// almost-in-line neighbour edge, whose f is noise, and leak; such a
/// polygon counts as not convex and gets the crossing test, like its
/// neighbour. Rays straight down through points along the chain and at m:
/// 0 fall through, 0 counted twice.
#[test]
fn chain_with_an_almost_straight_vertex() {
    let mut tally = ExactlyOnce::default();
    for i in 0..40 {
        let x0 = 0.1 + 0.0173 * f64::from(i);
        let x1 = 0.9 - 0.0131 * f64::from(i);
        let (a, b) = (v(x0, 0.0, 0.0), v(x1, 1.0, 0.0));
        for k in 1..7 {
            let m = a + (b - a) * (f64::from(k) / 7.0); // rounded: not exactly on a–b
            let left =
                polygon(vec![a, m, b, v(-1.0, 1.0, 0.0), v(-1.0, 0.0, 0.0)]);
            let right =
                polygon(vec![a, v(2.0, 0.0, 0.0), v(2.0, 1.0, 0.0), b, m]);
            let pair = [left, right];
            let mut targets = vec![m];
            for j in 1..25 {
                let s = f64::from(j) / 25.0;
                targets.push(a + (m - a) * s);
                targets.push(m + (b - m) * s);
            }
            for q in targets {
                let n =
                    hits(&pair, &Ray::new(v(q.x, q.y, 1.0), v(0.0, 0.0, -1.0)));
                tally.count(n, || {
                    format!(
                        "the ray down through ({}, {}) on the chain {a} → {m} \
                         → {b} hits {n} polygons",
                        q.x, q.y
                    )
                });
            }
        }
    }
    assert_eq!(tally.rays, 40 * 6 * 49, "rays shot");
    assert!(
        (tally.fall_through, tally.twice) == (0, 0),
        "rays along the shared chain that fall through, and rays counted by \
         both polygons: expected 0 and 0 of {}, got {} and \
         {}; the first: {}",
        tally.rays,
        tally.fall_through,
        tally.twice,
        tally.first.unwrap_or_default()
    );
}
