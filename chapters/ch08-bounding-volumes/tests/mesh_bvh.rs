//! The fast walk (single-precision rays, nodes in f64, in f32 rounded
//! outward, and in f32 rounded to nearest) against brute force with the
//! chapter's own watertight test, on the bunny: camera rays, incoherent
//! rays, and rays that are not rays. Disagreements are counted; for the
//! two robust layouts they must be 0. (Rays aimed at every shared edge,
//! and the leaks, are `crates/stability`'s: `tests/mesh_bvh.rs` there.)
mod common;

use ch08::{
    Aabb, Builder, Bvh, BvhNode, DVec3, Interval, MeshAccelerator, MeshBvh,
    MeshHit, NodePrecision, Ray32, TraceCounts, triangle_boxes, watertight,
};
use common::bunny_triangles;
use raystep_bench::{camera_rays, incoherent_rays};
use raystep_core::glam::Vec3;

fn trees(triangles: &[[DVec3; 3]]) -> Vec<(NodePrecision, MeshBvh)> {
    let tree =
        Bvh::build(&triangle_boxes(triangles), Builder::BinnedSah { bins: 16 });
    NodePrecision::ALL
        .iter()
        .map(|&p| (p, MeshBvh::new(triangles, &tree, p)))
        .collect()
}

/// Two answers agree if both miss, or both hit at the same `t` (the
/// triangle may differ only on a tie: two triangles at exactly that `t`).
fn agree(a: Option<MeshHit>, b: Option<MeshHit>) -> bool {
    match (a, b) {
        (None, None) => true,
        (Some(a), Some(b)) => a.t == b.t,
        _ => false,
    }
}

fn rays(triangles: &[[DVec3; 3]]) -> Vec<Ray32> {
    let bounds =
        raystep_core::Aabb::around(triangles.iter().flatten().copied());
    let sphere = ch08::BoundingSphere::around_box(&bounds);
    camera_rays(sphere, 40)
        .iter()
        .chain(&incoherent_rays(bounds, 1600, 7))
        .map(Ray32::rounded)
        .collect()
}

#[test]
fn brute_force_is_the_chapters_watertight_test() {
    let triangles = bunny_triangles();
    let (_, bvh) = &trees(&triangles)[0];
    let mut differences = 0;
    for ray in rays(&triangles).iter().step_by(7) {
        let wide = ray.to_ray();
        let mut interval = Interval::FORWARD;
        let mut reference = None;
        for (k, v) in triangles.iter().enumerate() {
            if let Some(t) = watertight(v, &wide, interval) {
                interval = interval.with_max(t);
                reference = Some(MeshHit {
                    triangle: k as u32,
                    t,
                });
            }
        }
        if bvh.brute_force(ray, Interval::FORWARD) != reference {
            differences += 1;
        }
    }
    assert_eq!(differences, 0);
}

#[test]
fn every_layout_agrees_with_brute_force_on_the_bunny() {
    let triangles = bunny_triangles();
    let rays = rays(&triangles);
    let trees = trees(&triangles);
    let truths: Vec<_> = rays
        .iter()
        .map(|ray| trees[0].1.brute_force(ray, Interval::FORWARD))
        .collect();
    let mut table = String::new();
    for (precision, bvh) in trees {
        let (mut closest, mut any) = (0, 0);
        let mut counts = TraceCounts::default();
        for (ray, &truth) in rays.iter().zip(&truths) {
            let hit = bvh.closest_hit(ray, Interval::FORWARD, &mut counts);
            if !agree(hit, truth) {
                closest += 1;
            }
            let blocked = bvh.any_hit(ray, Interval::FORWARD, &mut counts);
            if blocked != truth.is_some() {
                any += 1;
            }
        }
        if precision != NodePrecision::SingleNearest {
            assert_eq!((closest, any), (0, 0), "{}", precision.name());
        }
        table += &format!(
            "{:<12} rays {} closest-hit disagreements {closest} \
             any-hit {any}\n",
            precision.name(),
            rays.len()
        );
    }
    insta::assert_snapshot!(table);
}

#[test]
fn rays_that_are_not_rays_are_answered_without_a_panic() {
    let triangles = bunny_triangles();
    let bad = [
        Ray32 {
            origin: Vec3::new(f32::NAN, 0.0, 0.0),
            direction: Vec3::Z,
        },
        Ray32 {
            origin: Vec3::ZERO,
            direction: Vec3::new(0.0, f32::INFINITY, 0.0),
        },
        Ray32 {
            origin: Vec3::ZERO,
            direction: Vec3::ZERO,
        },
        Ray32 {
            origin: Vec3::new(0.0, f32::NEG_INFINITY, 0.0),
            direction: Vec3::Y,
        },
    ];
    for (_, bvh) in trees(&triangles) {
        for ray in &bad {
            let mut counts = TraceCounts::default();
            assert_eq!(
                bvh.closest_hit(ray, Interval::FORWARD, &mut counts),
                None
            );
            assert!(!bvh.any_hit(ray, Interval::FORWARD, &mut counts));
            assert_eq!(counts, TraceCounts::default(), "traced {ray:?}");
        }
    }
}

/// Degenerate meshes: none, one triangle, all centroids equal, all in one
/// plane, zero-area triangles, far from the origin.
#[test]
fn degenerate_meshes_agree_with_brute_force() {
    let t = |a: [f64; 3], b: [f64; 3], c: [f64; 3]| {
        [DVec3::from(a), DVec3::from(b), DVec3::from(c)]
    };
    let mut cases: Vec<(&str, Vec<[DVec3; 3]>)> = vec![
        ("none", vec![]),
        (
            "one",
            vec![t([0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0])],
        ),
    ];
    let mut same = Vec::new();
    let mut flat = Vec::new();
    let mut zero = Vec::new();
    for k in 0..64 {
        let a = k as f64 * 0.37;
        let (c, s) = (a.cos(), a.sin());
        same.push(t([c, s, 0.0], [-c, -s, 0.1], [s, -c, -0.1]));
        let (x, y) = ((k % 8) as f64, (k / 8) as f64);
        flat.push(t([x, y, 0.0], [x + 1.0, y, 0.0], [x, y + 1.0, 0.0]));
        zero.push(t([x, y, 0.0], [x + 1.0, y, 0.0], [x + 2.0, y, 0.0]));
        zero.push(t([x, y, 0.5], [x + 1.0, y + 0.5, 0.5], [x, y, 0.5]));
    }
    let far: Vec<_> = flat
        .iter()
        .map(|v| v.map(|p| p + DVec3::splat(1e6)))
        .collect();
    cases.extend([
        ("same centroid", same),
        ("coplanar", flat),
        ("zero area", zero),
        ("offset 1e6", far),
    ]);
    for (name, triangles) in cases {
        let b = raystep_core::Aabb::around(
            triangles.iter().flatten().copied().chain([DVec3::ZERO]),
        );
        let centre = 0.5 * (b.min + b.max);
        let mut disagreements = 0;
        for (precision, bvh) in trees(&triangles) {
            let mut seed = 11u64;
            for _ in 0..500 {
                let mut next = || {
                    seed =
                        seed.wrapping_mul(6364136223846793005).wrapping_add(1);
                    (seed >> 11) as f64 / (1u64 << 53) as f64 - 0.5
                };
                let origin =
                    centre + DVec3::new(next(), next(), 2.0 + next()) * 8.0;
                let target = centre + DVec3::new(next(), next(), next()) * 8.0;
                let ray = Ray32 {
                    origin: origin.as_vec3(),
                    direction: (target - origin).as_vec3(),
                };
                let mut counts = TraceCounts::default();
                let truth = bvh.brute_force(&ray, Interval::FORWARD);
                let hit = bvh.closest_hit(&ray, Interval::FORWARD, &mut counts);
                let any = bvh.any_hit(&ray, Interval::FORWARD, &mut counts);
                if precision != NodePrecision::SingleNearest
                    && (!agree(hit, truth) || any != truth.is_some())
                {
                    disagreements += 1;
                }
            }
        }
        assert_eq!(disagreements, 0, "{name}");
    }
}

/// A tree deeper than the walk's stack on the call stack (32 entries):
/// triangles in the planes x = 0, 1, …, 79 in a chain built by hand, each
/// interior node a leaf of one plane beside the rest (depth 80). Rays
/// between each pair of planes, both ways, find the next plane through
/// every layout, as brute force does.
#[test]
fn a_tree_deeper_than_the_fixed_stack_is_walked_on_the_heap() {
    let n = 80usize;
    let triangles: Vec<[DVec3; 3]> = (0..n)
        .map(|k| {
            let x = k as f64;
            [
                DVec3::new(x, -1.0, -1.0),
                DVec3::new(x, 2.0, -1.0),
                DVec3::new(x, -1.0, 2.0),
            ]
        })
        .collect();
    // Node 2j is the chain over planes j.., node 2j + 1 the leaf of plane
    // j; the chain's children are nodes 2j + 1 and 2j + 2.
    let boxes = triangle_boxes(&triangles);
    let over = |from: usize| {
        boxes[from..].iter().fold(Aabb::EMPTY, |a, b| a.union(*b))
    };
    let mut nodes = Vec::new();
    for (j, &own) in boxes.iter().enumerate() {
        let last = j == n - 1;
        nodes.push(BvhNode {
            bounds: over(j),
            first: if last { j as u32 } else { 2 * j as u32 + 1 },
            count: u32::from(last),
        });
        if !last {
            nodes.push(BvhNode {
                bounds: own,
                first: j as u32,
                count: 1,
            });
        }
    }
    let tree = Bvh {
        nodes,
        order: (0..n as u32).collect(),
        unbounded: Vec::new(),
    };
    assert_eq!(tree.depth(), n);
    let mut wrong = 0;
    for precision in NodePrecision::ALL {
        let bvh = MeshBvh::new(&triangles, &tree, precision);
        for k in 0..n - 1 {
            for (direction, expected) in [(1.0, k + 1), (-1.0, k)] {
                let ray = Ray32 {
                    origin: Vec3::new(k as f32 + 0.5, 0.25, 0.25),
                    direction: Vec3::new(direction, 0.0, 0.0),
                };
                let reach = Interval::new(0.0, f64::INFINITY);
                let mut counts = TraceCounts::default();
                let hit = bvh.closest_hit(&ray, reach, &mut counts);
                let brute = bvh.brute_force(&ray, reach);
                let shadow = bvh.any_hit(&ray, reach, &mut counts);
                if hit.map(|h| h.triangle) != Some(expected as u32)
                    || !agree(hit, brute)
                    || !shadow
                {
                    wrong += 1;
                    eprintln!(
                        "{precision:?}: plane {k}, direction {direction}"
                    );
                }
            }
        }
    }
    assert_eq!(wrong, 0);
}
