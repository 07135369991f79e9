//! Part 2's hierarchy against the lecture's loop: for every builder,
//! the closest hit (object and t) and the any-hit answer of the BVH equal
//! brute force's on seeded rays, on mixed scenes, on degenerate ones and
//! on the bunny. Disagreements are counted and must be 0.
mod common;

use std::sync::Arc;

use ch03::{BruteForce, Sphere};
use ch08::{
    Aabb, Accelerator, AxisBox, BoundingSphere, Builder, Bvh, DVec3, Interval,
    Object, RandomLines, Ray, Shape, Triangle, TriangleTest,
};
use common::{Rng, bunny, unit_vector};
use raystep_bench::camera_rays;

fn object(shape: impl Shape + 'static) -> Object {
    Object {
        shape: Arc::new(shape),
        material: 0,
    }
}

/// A seeded jumble around `offset`: spheres, boxes and triangles of many
/// sizes, some overlapping, and one plane below them.
fn jumble(count: usize, offset: DVec3, seed: u64) -> Vec<Object> {
    let mut rng = Rng::new(seed);
    let mut objects = vec![object(ch02::InfinitePlane(ch02::Plane {
        normal: DVec3::Y,
        d: -(offset.y - 12.0) * -1.0,
    }))];
    for k in 0..count {
        let c = offset
            + DVec3::new(
                rng.uniform(-10.0, 10.0),
                rng.uniform(-10.0, 10.0),
                rng.uniform(-10.0, 10.0),
            );
        let size = rng.uniform(0.05, 2.0);
        objects.push(match k % 3 {
            0 => object(Sphere::new(c, size)),
            1 => object(
                AxisBox::new(
                    c - size * DVec3::new(1.0, 0.5, 0.7),
                    c + size * DVec3::new(0.6, 1.0, 0.4),
                )
                .unwrap(),
            ),
            _ => object(
                Triangle::new(
                    [
                        c,
                        c + size * unit_vector(&mut rng),
                        c + size * unit_vector(&mut rng),
                    ],
                    TriangleTest::Watertight,
                )
                .unwrap_or_else(|_| {
                    Triangle::new(
                        [c, c + DVec3::X, c + DVec3::Y],
                        TriangleTest::Watertight,
                    )
                    .unwrap()
                }),
            ),
        });
    }
    objects
}

/// How the BVH and brute force disagree on `rays`: closest hits at a
/// different t (or one hit and one miss), and any-hit answers on a
/// shorter interval.
fn disagreements(bvh: &Bvh, objects: &[Object], rays: &[Ray]) -> usize {
    let mut wrong = 0;
    for ray in rays {
        let expected = BruteForce.closest_hit(objects, ray, Interval::FORWARD);
        let actual = bvh.closest_hit(objects, ray, Interval::FORWARD);
        let same = match (expected, actual) {
            (None, None) => true,
            // the same t; a different object only where two objects
            // are hit at exactly that t (a tie either may win)
            (Some((i, a)), Some((j, b))) => {
                let first_t = |k: usize| {
                    objects[k]
                        .shape
                        .intersect(ray, Interval::FORWARD)
                        .map(|h| h.t)
                };
                a.t == b.t
                    && (i == j
                        || (first_t(i) == Some(a.t) && first_t(j) == Some(a.t)))
            }
            _ => false,
        };
        wrong += usize::from(!same);
        let short = Interval::new(1e-9, 7.5);
        wrong += usize::from(
            BruteForce.any_hit(objects, ray, short)
                != bvh.any_hit(objects, ray, short),
        );
    }
    wrong
}

/// Random lines through the scene's sphere, and rays from inside it.
fn rays_through(objects: &[Object], count: usize, seed: u64) -> Vec<Ray> {
    let bounds = objects
        .iter()
        .map(|o| o.shape.bounds())
        .filter(|b| b.min.is_finite() && b.max.is_finite())
        .fold(Aabb::EMPTY, Aabb::union);
    let sphere = BoundingSphere::around_box(&bounds);
    let mut rng = Rng::new(seed);
    let mut rays: Vec<Ray> =
        RandomLines::new(sphere, seed).take(count / 2).collect();
    for _ in 0..count / 2 {
        let from = sphere.center
            + 0.8
                * sphere.radius
                * rng.uniform(0.0, 1.0)
                * unit_vector(&mut rng);
        rays.push(Ray::new(from, unit_vector(&mut rng)));
    }
    rays
}

#[test]
fn every_builder_agrees_with_brute_force_on_mixed_scenes() {
    let mut total = 0;
    for (seed, count, offset) in [
        (1, 300, DVec3::ZERO),
        (2, 60, DVec3::new(0.5, -3.0, 2.0)),
        (3, 150, DVec3::new(1e6, -1e6, 5e5)),
    ] {
        let objects = jumble(count, offset, seed);
        let rays = rays_through(&objects, 2000, seed + 10);
        for builder in Builder::ALL {
            let bvh = Bvh::for_objects(&objects, builder);
            assert_eq!(bvh.unbounded, vec![0], "the plane stays outside");
            let wrong = disagreements(&bvh, &objects, &rays);
            assert_eq!(wrong, 0, "{} on scene {seed}", builder.name());
            total += rays.len();
        }
    }
    assert!(total >= 54_000);
}

/// `Bvh::build_with_leaves_of`: no node of at most that many objects is
/// split, the tree still answers as brute force, and with 1 it is the
/// tree `Bvh::build` gives.
#[test]
fn small_nodes_stay_leaves_when_asked() {
    let objects = jumble(300, DVec3::ZERO, 4);
    let boxes: Vec<Aabb> = objects.iter().map(|o| o.shape.bounds()).collect();
    let rays = rays_through(&objects, 2000, 14);
    for builder in [
        Builder::BinnedSah { bins: 16 },
        Builder::SweepSah,
        Builder::Median,
    ] {
        let full = Bvh::build(&boxes, builder);
        assert_eq!(Bvh::build_with_leaves_of(&boxes, builder, 1), full);
        let bvh = Bvh::build_with_leaves_of(&boxes, builder, 8);
        // objects below each node (children come after their parent)
        let mut below = vec![0; bvh.nodes.len()];
        for k in (0..bvh.nodes.len()).rev() {
            let n = bvh.nodes[k];
            below[k] = match n.is_leaf() {
                true => n.count,
                false => below[n.first as usize] + below[n.first as usize + 1],
            };
            assert!(n.is_leaf() || below[k] > 8, "{}", builder.name());
        }
        assert_eq!(below[0] as usize, boxes.len() - bvh.unbounded.len());
        assert!(bvh.nodes.len() < full.nodes.len(), "{}", builder.name());
        let wrong = disagreements(&bvh, &objects, &rays);
        assert_eq!(wrong, 0, "{}", builder.name());
    }
}

/// No objects, one, all centroids equal, all in one plane, and rays with
/// NaN or infinite components: no panic, brute force's answers.
#[test]
fn degenerate_inputs_give_brute_forces_answers() {
    let same_centre: Vec<Object> = (1..=40)
        .map(|k| {
            object(Sphere::new(DVec3::new(1.0, 2.0, 3.0), 0.05 * k as f64))
        })
        .collect();
    let coplanar: Vec<Object> = (0..100)
        .map(|k| {
            let c = DVec3::new((k % 10) as f64, (k / 10) as f64, 0.0);
            object(
                Triangle::new(
                    [c, c + DVec3::X, c + DVec3::Y],
                    TriangleTest::Watertight,
                )
                .unwrap(),
            )
        })
        .collect();
    // triangles of zero area: points and segments, boxes that are flat
    // or a single point
    let zero_area: Vec<Object> = (0..60)
        .map(|k| {
            let c = DVec3::new((k % 6) as f64, (k / 6) as f64, 0.5);
            let corners = if k % 2 == 0 {
                [c, c, c]
            } else {
                [c, c + DVec3::X, c + 2.0 * DVec3::X]
            };
            object(ZeroArea(corners))
        })
        .collect();
    let far_away: Vec<Object> = (0..80)
        .map(|k| {
            let c = DVec3::splat(1e6) + DVec3::new(k as f64 * 1e-3, 0.0, 0.0);
            object(Sphere::new(c, 1e-4 * (1 + k % 3) as f64))
        })
        .collect();
    let scenes: Vec<(&str, Vec<Object>)> = vec![
        ("no objects", Vec::new()),
        ("one sphere", vec![object(Sphere::new(DVec3::ZERO, 1.0))]),
        ("40 spheres, one centre", same_centre),
        ("100 triangles in z = 0", coplanar),
        ("60 triangles of zero area", zero_area),
        ("80 tiny spheres at 1e6", far_away),
    ];
    let mut odd = vec![
        Ray::new(DVec3::ZERO, DVec3::ZERO),
        Ray::new(DVec3::splat(f64::NAN), DVec3::X),
        Ray::new(DVec3::new(0.5, 0.5, 5.0), DVec3::new(f64::NAN, 0.0, -1.0)),
        Ray::new(
            DVec3::new(0.5, 0.5, 5.0),
            DVec3::new(0.0, 0.0, f64::NEG_INFINITY),
        ),
        Ray::new(DVec3::new(f64::INFINITY, 0.0, 0.0), DVec3::NEG_X),
    ];
    for (name, objects) in &scenes {
        let mut rays = if objects.is_empty() {
            RandomLines::new(
                BoundingSphere {
                    center: DVec3::ZERO,
                    radius: 1.0,
                },
                4,
            )
            .take(100)
            .collect()
        } else {
            rays_through(objects, 1000, 5)
        };
        // rays along the plane of the coplanar triangles, and onto it
        rays.extend((0..50).map(|k| {
            Ray::new(DVec3::new(-1.0, 0.1 * k as f64, 0.0), DVec3::X)
        }));
        rays.append(&mut odd.clone());
        for builder in Builder::ALL {
            let bvh = Bvh::for_objects(objects, builder);
            assert_eq!(
                disagreements(&bvh, objects, &rays),
                0,
                "{} on {name}",
                builder.name()
            );
        }
    }
    odd.clear();
}

/// The bunny's triangles, one object each: the BVH finds the same hits
/// as the loop over all 3 674, and a table of each tree's shape.
#[test]
fn the_bunny_agrees_and_its_trees() {
    let mesh = bunny();
    let objects: Vec<Object> = (0..mesh.triangles.len())
        .map(|k| {
            object(
                Triangle::new(mesh.triangle(k), TriangleTest::Watertight)
                    .unwrap(),
            )
        })
        .collect();
    let bounds = objects
        .iter()
        .map(|o| o.shape.bounds())
        .fold(Aabb::EMPTY, Aabb::union);
    let rays = camera_rays(BoundingSphere::around_box(&bounds), 14);
    let mut table = String::from(
        "builder         | nodes | leaves | depth | balance | largest leaf | SAH cost\n",
    );
    for builder in Builder::ALL {
        let bvh = Bvh::for_objects(&objects, builder);
        assert_eq!(
            disagreements(&bvh, &objects, &rays),
            0,
            "{}",
            builder.name()
        );
        // every triangle in exactly one leaf
        let mut seen = bvh.order.clone();
        seen.sort_unstable();
        assert_eq!(seen, (0..objects.len() as u32).collect::<Vec<_>>());
        let leaves: u32 = bvh
            .nodes
            .iter()
            .filter(|n| n.is_leaf())
            .map(|n| n.count)
            .sum();
        assert_eq!(leaves as usize, objects.len());
        let stats = bvh.stats();
        table.push_str(&format!(
            "{:<15} | {:>5} | {:>6} | {:>5} | {:>7.3} | {:>12} | {:>8.1}\n",
            builder.name(),
            stats.nodes,
            stats.leaves,
            stats.depth,
            stats.balance,
            stats.max_leaf,
            stats.sah_cost,
        ));
    }
    insta::assert_snapshot!(table);
}

/// A triangle that may have no area (a point, a segment): its box, and
/// the hits of no ray; a flat box in the tree.
#[derive(Debug)]
struct ZeroArea([DVec3; 3]);

impl Shape for ZeroArea {
    fn intersect(&self, _ray: &Ray, _interval: Interval) -> Option<ch08::Hit> {
        None
    }

    fn bounds(&self) -> Aabb {
        Aabb::around(self.0)
    }
}

/// Two pairs of unit cubes side by side, ten apart: the tree's numbers
/// by hand.
#[test]
fn tree_stats_of_two_pairs_of_cubes() {
    let cube = |x: f64, z: f64| {
        Aabb::new(DVec3::new(x, 0.0, z), DVec3::new(x + 1.0, 1.0, z + 1.0))
    };
    let boxes = [
        cube(0.0, 0.0),
        cube(1.0, 0.0),
        cube(0.0, 10.0),
        cube(1.0, 10.0),
    ];
    for builder in Builder::ALL {
        let stats = Bvh::build(&boxes, builder).stats();
        // Each pair is a leaf (2 tests against a split's 1 + 2·6/10 = 2.2)
        // and the root splits the pairs apart.
        assert_eq!(stats.nodes, 3, "{}", builder.name());
        assert_eq!((stats.leaves, stats.depth, stats.max_leaf), (2, 2, 2));
        assert_eq!(stats.mean_leaf, 2.0);
        // both leaves at depth 2 = log₂ 2 + 1: balanced
        assert_eq!(stats.balance, 1.0);
        // the root, then each pair's box (area 2·(2 + 1 + 2) = 10 of the
        // root's 2·(2·1 + 1·11 + 11·2) = 70) times its 2 tests
        let expected = 1.0 + 2.0 * (10.0 / 70.0 * 2.0);
        assert!((stats.sah_cost - expected).abs() < 1e-12);
        assert_eq!(stats.bytes, 3 * size_of::<ch08::BvhNode>() + 4 * 4);
    }
    let empty = Bvh::build(&[], Builder::Midpoint).stats();
    assert_eq!((empty.nodes, empty.leaves, empty.depth), (0, 0, 0));
    assert_eq!(
        (empty.balance, empty.mean_leaf, empty.sah_cost),
        (0.0, 0.0, 0.0)
    );
}
