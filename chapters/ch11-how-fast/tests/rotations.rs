//! Step 4b's tree rotations: the rotated tree is still a tree over every
//! object once, its boxes exact, its SAH cost what `rotate` says and no
//! higher than before; it answers every ray as brute force does; and
//! tiny or deep trees come through whole.
mod common;

use common::{rays, truth, wrong};
use raystep_bench::bunny;

use ch08::{Builder, Bvh, triangle_boxes};
use ch11::rotations::{Rotations, rotate};
use ch11::{FastBvh, Step};
use raystep_core::{Aabb, DVec3};

/// Panics unless `tree` is a tree over `boxes`: every node reached once
/// from the root, every bounded object in exactly one leaf reached, every
/// box the exact union of its children's or its objects' boxes.
fn assert_valid(tree: &Bvh, boxes: &[Aabb]) {
    let mut seen = vec![0usize; boxes.len()];
    for &i in &tree.unbounded {
        seen[i as usize] += 1;
    }
    let mut reached = vec![false; tree.nodes.len()];
    let mut stack = if tree.nodes.is_empty() {
        vec![]
    } else {
        vec![0]
    };
    while let Some(k) = stack.pop() {
        assert!(!reached[k], "node {k} reached twice");
        reached[k] = true;
        let node = tree.nodes[k];
        let (first, count) = (node.first as usize, node.count as usize);
        let exact = if node.is_leaf() {
            let objects = &tree.order[first..first + count];
            for &i in objects {
                seen[i as usize] += 1;
            }
            objects
                .iter()
                .map(|&i| boxes[i as usize])
                .fold(Aabb::EMPTY, Aabb::union)
        } else {
            stack.extend([first, first + 1]);
            tree.nodes[first].bounds.union(tree.nodes[first + 1].bounds)
        };
        assert_eq!(node.bounds, exact, "node {k}'s box");
    }
    assert!(reached.iter().all(|&r| r), "a node is unreachable");
    assert!(seen.iter().all(|&s| s == 1), "an object is not there once");
}

/// Rotates `tree` and checks what `rotate` says against the tree.
fn rotate_checked(tree: &mut Bvh, boxes: &[Aabb]) -> Rotations {
    let before = tree.sah_cost();
    let done = rotate(tree);
    assert_eq!(done.cost_before, before);
    assert!(done.cost_after <= done.cost_before, "{done:?}");
    let after = tree.sah_cost();
    assert!(
        (done.cost_after - after).abs() <= 1e-9 * after.max(1.0),
        "{done:?}, the tree's cost {after}"
    );
    assert!((1..=10).contains(&done.passes), "{done:?}");
    assert_valid(tree, boxes);
    done
}

#[test]
fn a_rotated_sah_tree_is_whole_and_no_dearer() {
    let boxes = triangle_boxes(&bunny());
    let built = Bvh::build(&boxes, Builder::BinnedSah { bins: 16 });
    assert_valid(&built, &boxes);
    let mut tree = built.clone();
    rotate_checked(&mut tree, &boxes);
    assert_eq!(tree.nodes.len(), built.nodes.len());
    assert_eq!(tree.order, built.order, "the leaves keep their objects");
}

#[test]
fn rotations_improve_a_median_tree() {
    let boxes = triangle_boxes(&bunny());
    let mut tree = Bvh::build(&boxes, Builder::Median);
    let done = rotate_checked(&mut tree, &boxes);
    assert!(done.rotations > 0, "{done:?}");
    assert!(done.cost_after < done.cost_before, "{done:?}");
}

#[test]
fn a_rotated_tree_answers_as_brute_force_does() {
    let triangles = bunny();
    let boxes = triangle_boxes(&triangles);
    let rays = rays(&triangles, 24, 600);
    let truth = truth(&triangles, &rays);
    assert!(truth.closest.iter().filter(|hit| hit.is_some()).count() > 100);
    for builder in [Builder::BinnedSah { bins: 16 }, Builder::Median] {
        let built = Bvh::build(&boxes, builder);
        let mut tree = built.clone();
        rotate(&mut tree);
        assert_ne!(tree, built, "{}: nothing rotated", builder.name());
        let fast = FastBvh::from_tree(&triangles, &tree, Step::LeafLayout);
        assert_eq!(wrong(&fast, &rays, &truth), (0, 0), "{}", builder.name());
    }
}

/// `n` small triangles far apart along a diagonal, in a scrambled order.
fn scattered(n: usize) -> Vec<[DVec3; 3]> {
    (0..n)
        .map(|k| {
            let c = DVec3::splat(((k * 7) % 5) as f64 * 10.0 + k as f64);
            [c, c + DVec3::X, c + DVec3::Y]
        })
        .collect()
}

#[test]
fn tiny_and_deep_trees_stay_whole() {
    // Step 1: no, one, two and three triangles, by every builder; one
    // set with a triangle no box holds, kept outside the tree.
    let mut outside = scattered(3);
    outside.push([DVec3::ZERO, DVec3::X, DVec3::new(0.0, f64::INFINITY, 0.0)]);
    let mut scenes: Vec<Vec<[DVec3; 3]>> = (0..=3).map(scattered).collect();
    scenes.push(outside);
    for triangles in &scenes {
        let boxes = triangle_boxes(triangles);
        for builder in Builder::ALL {
            let mut tree = Bvh::build(&boxes, builder);
            let unbounded = tree.unbounded.clone();
            rotate_checked(&mut tree, &boxes);
            assert_eq!(tree.unbounded, unbounded);
        }
    }
    // Step 2: 300 slivers, each 0.9 times the last, along x: the SAH
    // peels them off one by one, a tree 300 deep (no recursion here).
    let deep: Vec<[DVec3; 3]> = common::slivers();
    let boxes = triangle_boxes(&deep);
    for builder in [Builder::SweepSah, Builder::Median] {
        let mut tree = Bvh::build(&boxes, builder);
        rotate_checked(&mut tree, &boxes);
    }
}
