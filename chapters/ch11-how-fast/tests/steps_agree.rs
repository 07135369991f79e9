//! Every step of the appendix against brute force with chapter 8's
//! watertight test (the same test every step runs, so the answers must
//! be the same `t`s exactly): on the bunny's camera and incoherent rays,
//! as closest-hit and any-hit questions, and on rays that are not rays.
//! (On rays aimed at every shared edge of three surfaces none may leak:
//! `crates/stability/tests/mesh_bvh.rs`.)
mod common;

use common::{Truth, rays, truth, wrong};
use raystep_bench::bunny;

use ch08::{
    Aabb, Builder, Bvh, BvhNode, Interval, MeshAccelerator, Ray32, TraceCounts,
    triangle_boxes,
};
use ch11::{FastBvh, Step};
use raystep_core::DVec3;
use raystep_core::glam::Vec3;

/// (closest-hit disagreements, any-hit disagreements) of `step` with
/// brute force's `truth` about `rays`, with its SIMD kernel (where the
/// CPU has it) and with the scalar fallback.
fn disagreements(
    triangles: &[[DVec3; 3]], step: Step, rays: &[Ray32], truth: &Truth,
) -> (usize, usize) {
    let simd = FastBvh::build(triangles, step);
    let scalar = simd.clone().scalar();
    let (a, b) = wrong(&simd, rays, truth);
    let (c, d) = wrong(&scalar, rays, truth);
    (a + c, b + d)
}

#[test]
fn every_step_agrees_with_brute_force_on_the_bunny() {
    let triangles = bunny();
    let rays = rays(&triangles, 48, 2000);
    let truth = truth(&triangles, &rays);
    for step in Step::ALL {
        assert_eq!(
            disagreements(&triangles, step, &rays, &truth),
            (0, 0),
            "{}",
            step.name()
        );
    }
}

#[test]
fn rays_that_are_not_rays_hit_nothing() {
    let triangles = bunny();
    let centre = Vec3::new(0.0, 0.1, 0.0);
    let bad = [
        Ray32 {
            origin: Vec3::new(f32::NAN, 0.0, 1.0),
            direction: -Vec3::Z,
        },
        Ray32 {
            origin: centre + Vec3::Z,
            direction: Vec3::new(0.0, f32::NAN, -1.0),
        },
        Ray32 {
            origin: centre + Vec3::Z,
            direction: Vec3::ZERO,
        },
        Ray32 {
            origin: Vec3::new(f32::INFINITY, 0.1, 0.0),
            direction: -Vec3::X,
        },
        Ray32 {
            origin: centre + Vec3::Z,
            direction: Vec3::new(0.0, 0.0, f32::NEG_INFINITY),
        },
    ];
    for step in Step::ALL {
        let fast = FastBvh::build(&triangles, step);
        let mut counts = TraceCounts::default();
        for ray in &bad {
            assert_eq!(
                fast.closest_hit(ray, Interval::FORWARD, &mut counts),
                None
            );
            assert!(!fast.any_hit(ray, Interval::FORWARD, &mut counts));
        }
        assert_eq!(counts, TraceCounts::default(), "{}: traced", step.name());
    }
}

#[test]
fn a_deep_tree_and_tiny_scenes_work() {
    // 300 slivers, each 0.9 times the last, along x: the SAH peels them
    // off one by one, a tree far deeper than the walks' fixed stacks.
    let deep: Vec<[DVec3; 3]> = common::slivers();
    let tree = Bvh::build(&triangle_boxes(&deep), Builder::SweepSah);
    assert!(tree.depth() > 64, "depth {}", tree.depth());
    let mut rays = Vec::new();
    for k in 0..200 {
        let y = -0.99 + 0.0099 * k as f32;
        rays.push(Ray32 {
            origin: Vec3::new(2.0, y, 0.01),
            direction: -Vec3::X,
        });
        rays.push(Ray32 {
            origin: Vec3::new(-1.0, y, -0.3),
            direction: Vec3::X,
        });
    }
    let one = vec![deep[0]];
    let empty: Vec<[DVec3; 3]> = Vec::new();
    // a triangle with no finite box, kept outside the tree: a plane-like
    // sliver reaching to infinity across the rays
    let mut outside = deep[..20].to_vec();
    outside.push([
        DVec3::new(0.5, -1.0, -1.0),
        DVec3::new(0.5, 1.0, -1.0),
        DVec3::new(0.5, 0.0, f64::INFINITY),
    ]);
    for scene in [&deep, &one, &empty, &outside] {
        let truth = truth(scene, &rays);
        for step in Step::ALL {
            let wrong = disagreements(scene, step, &rays, &truth);
            assert_eq!(wrong, (0, 0), "{}", step.name());
        }
    }
}

#[cfg(target_arch = "x86_64")]
#[test]
fn step_11_takes_the_bunny_and_leaves_a_deep_tree_to_step_9s_walk() {
    // its walk's array holds the waiting children of a tree at most
    // MAX_DEPTH nodes deep; a deeper tree keeps step 9's walk
    use ch11::Kernel;
    let avx2 = is_x86_feature_detected!("avx2");
    let bunny = FastBvh::build(&bunny(), Step::Wide8ShortPath);
    assert_eq!(bunny.kernel() == Kernel::ShortPath, avx2);
    // a chain made by hand, each node a sliver and the rest: 600 deep
    let slivers: Vec<[DVec3; 3]> = (0..600)
        .map(|k| {
            let x = f64::from(k) / 600.0;
            [(-1.0, -1.0), (1.0, -1.0), (0.0, 1.0)]
                .map(|(y, z)| DVec3::new(x, y, z))
        })
        .collect();
    let boxes = triangle_boxes(&slivers);
    let mut nodes = vec![BvhNode {
        bounds: Aabb::EMPTY,
        first: 0,
        count: 0,
    }];
    for k in 0..slivers.len() as u32 - 1 {
        let (at, children) = (nodes.len() - 1, nodes.len() as u32);
        nodes[at] = BvhNode {
            bounds: Aabb::EMPTY,
            first: children,
            count: 0,
        };
        nodes.push(BvhNode {
            bounds: boxes[k as usize],
            first: k,
            count: 1,
        });
        nodes.push(BvhNode {
            bounds: Aabb::EMPTY,
            first: k + 1,
            count: 1,
        });
    }
    let last = nodes.len() - 1;
    nodes[last].bounds = boxes[slivers.len() - 1];
    for k in (0..nodes.len()).rev() {
        if nodes[k].count == 0 {
            let first = nodes[k].first as usize;
            nodes[k].bounds =
                nodes[first].bounds.union(nodes[first + 1].bounds);
        }
    }
    let tree = Bvh {
        nodes,
        order: (0..slivers.len() as u32).collect(),
        unbounded: Vec::new(),
    };
    let deep = FastBvh::from_tree(&slivers, &tree, Step::Wide8ShortPath);
    assert!(
        deep.depth()
            .is_some_and(|d| d > ch11::short_path::MAX_DEPTH)
    );
    assert_ne!(deep.kernel(), Kernel::ShortPath);
    let rays: Vec<Ray32> = (0..400)
        .map(|k| Ray32 {
            origin: Vec3::new(2.0, -0.99 + 0.00495 * k as f32, -0.3),
            direction: -Vec3::X,
        })
        .collect();
    let truth = truth(&slivers, &rays);
    let hits = truth.closest.iter().flatten().count();
    assert!(hits > 200, "{hits} of the rays hit");
    assert_eq!(wrong(&deep, &rays, &truth), (0, 0));
}
