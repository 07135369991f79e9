//! Where a kd-tree can go wrong, counted: rays lying in a split plane,
//! starting on one, along the line where two meet, parallel to an axis
//! (with −0.0 too), through a node's corner; triangles lying in split
//! planes, triangles cut by many planes, flat scenes, deep trees on
//! clustered input. The rays are made from the built tree's own planes.
//! Seeded, so every run asks the same rays; the tests ask a few of each,
//! `raystep measure` over a million.
use ch08::SplitMix64;
use ch10::{KdNode, KdTree};
use raystep_bench::uniform_triangles;
use raystep_core::{Aabb, DVec3, Ray};
use raystep_world::Object;

use crate::grid_rays::{stability_scenes, triangle_object};
use crate::ray_cases::{Around, Cases, RayCase, inside, signed_unit};

/// A scene of the catalogue: its name and objects.
pub struct KdScene {
    /// What is special about it, for tables.
    pub name: &'static str,
    /// Its objects.
    pub objects: Vec<Object>,
}

/// The catalogue's scenes: chapter 9's (the bunny, spheres with big
/// triangles and a plane, a few spheres far apart, a flat scene), and
/// three a kd-tree finds hard.
pub fn kd_scenes(bunny: &[[DVec3; 3]]) -> Vec<KdScene> {
    let mut scenes: Vec<KdScene> = stability_scenes(bunny)
        .into_iter()
        .filter(|s| s.name != "the same in one cell")
        .map(|s| KdScene {
            name: s.name,
            objects: s.objects,
        })
        .collect();
    let mut random = SplitMix64::new(10);
    let mut r = move || random.next_f64();
    // triangles lying in planes x = k/4, y = k/4, z = k/4: the SAH puts
    // its planes right on them
    let mut planar = Vec::new();
    for k in 0..120 {
        let axis = k % 3;
        let at = ((k / 3) % 5) as f64 * 0.25 - 0.5;
        let mut corners =
            [0, 1, 2].map(|_| DVec3::new(r() - 0.5, r() - 0.5, r() - 0.5));
        for c in &mut corners {
            c[axis] = at;
        }
        planar.extend(triangle_object(&corners));
    }
    // long thin triangles across the whole scene among small ones: cut
    // by many planes, listed in many leaves
    let mut straddling: Vec<Object> = uniform_triangles(400, 11)
        .iter()
        .filter_map(triangle_object)
        .collect();
    for _ in 0..20 {
        let a = DVec3::new(r(), r(), r()) * 2.0 - 1.0;
        let b = -a + DVec3::new(r(), r(), r()) * 0.1;
        straddling.extend(triangle_object(&[
            a,
            b,
            b + DVec3::new(0.0, 0.02, 0.01),
        ]));
    }
    // a thousand tiny triangles in a 1e-3 cube, and eight far away: the
    // tree goes as deep as the rule lets it
    let mut clustered: Vec<Object> = uniform_triangles(1000, 12)
        .iter()
        .map(|t| t.map(|v| v * 1e-3 + DVec3::splat(0.25)))
        .filter_map(|t| triangle_object(&t))
        .collect();
    for k in 0..8 {
        let corner = DVec3::new(
            if k & 1 == 0 { -1.0 } else { 1.0 },
            if k & 2 == 0 { -1.0 } else { 1.0 },
            if k & 4 == 0 { -1.0 } else { 1.0 },
        );
        clustered.extend(triangle_object(&[
            corner,
            corner * 0.9,
            corner * 0.9 + DVec3::X * 0.05,
        ]));
    }
    scenes.push(KdScene {
        name: "triangles in split planes",
        objects: planar,
    });
    scenes.push(KdScene {
        name: "long triangles across it all",
        objects: straddling,
    });
    scenes.push(KdScene {
        name: "a tight cluster: a deep tree",
        objects: clustered,
    });
    scenes
}

/// `per_case` rays of each dangerous kind for `tree`, made from its own
/// planes and node boxes.
pub fn kd_rays(tree: &KdTree, per_case: usize, seed: u64) -> Vec<RayCase> {
    let boxes = tree.node_boxes();
    let splits: Vec<(usize, f64, Aabb)> = tree
        .nodes
        .iter()
        .zip(&boxes)
        .filter_map(|(node, b)| match *node {
            KdNode::Split { axis, plane, .. } => {
                Some((axis as usize, plane, *b))
            }
            KdNode::Leaf { .. } => None,
        })
        .collect();
    let around = Around::new(tree.bounds);
    let (b, centre, far) = (around.bounds, around.centre, around.far);
    // a split: its axis, plane and node box (the root's box if none)
    let split = |r: &mut SplitMix64| {
        if splits.is_empty() {
            (0, centre.x, b)
        } else {
            splits[(r.next_u64() % splits.len() as u64) as usize]
        }
    };
    let mut cases = Cases::new(per_case, seed);
    vec![
        cases.case("lying in a split plane", |r| {
            let (axis, plane, node) = split(r);
            let mut origin = around.far_point(r);
            origin[axis] = plane;
            let mut target = inside(r, &node);
            target[axis] = plane;
            Ray::new(origin, target - origin)
        }),
        cases.case("starting on a split plane", |r| {
            let (axis, plane, node) = split(r);
            let mut origin = inside(r, &node);
            origin[axis] = plane;
            Ray::new(origin, r.unit_vector())
        }),
        cases.case("along two split planes", |r| {
            // on one node's plane and an ancestor's or a stranger's plane
            // of another axis, along the third axis
            let (a, pa, node) = split(r);
            let (mut c, mut pc, _) = split(r);
            if c == a {
                c = (a + 1) % 3;
                pc = inside(r, &node)[c];
            }
            let along = 3 - a - c;
            let mut origin = inside(r, &node);
            origin[a] = pa;
            origin[c] = pc;
            origin[along] = centre[along] - far * 0.5;
            Ray::new(origin, signed_unit(r, along).abs())
        }),
        cases.case("axis-parallel in a plane (±0)", |r| {
            let (axis, plane, node) = split(r);
            let mut origin = inside(r, &node);
            origin[axis] = plane;
            let along = (axis + 1 + (r.next_u64() % 2) as usize) % 3;
            Ray::new(origin, signed_unit(r, along))
        }),
        cases.case("axis-parallel anywhere (±0)", |r| {
            let along = (r.next_u64() % 3) as usize;
            Ray::new(inside(r, &b), signed_unit(r, along))
        }),
        cases.case("through a node's corner", |r| {
            let (_, _, node) = split(r);
            let corner = DVec3::from_array([0, 1, 2].map(|a| {
                if r.next_u64().is_multiple_of(2) {
                    node.min[a]
                } else {
                    node.max[a]
                }
            }));
            around.aimed(r, corner)
        }),
        cases.case("starting inside", |r| {
            Ray::new(inside(r, &b), r.unit_vector())
        }),
        cases.case("from far away", |r| {
            let target = inside(r, &b);
            around.aimed(r, target)
        }),
    ]
}
