//! Step 7's parallel build against chapter 8's: a tree with chapter 8's
//! invariants, the same on any number of threads, about as good, and
//! answering every ray as brute force does. The small bunny (3 674
//! triangles) is split into parts of at most 64 objects, so that the
//! top is many levels deep.
mod common;

use common::{rays, truth, wrong};
use raystep_bench::bunny;

use ch08::{Builder, Bvh, MAX_LEAF, triangle_boxes};
use ch11::parallel_build::{build_parallel, build_parallel_with};
use ch11::{FastBvh, Step};
use raystep_core::{Aabb, DVec3};

/// The parts' size on the small bunny.
const PART: usize = 64;

const BINNED: Builder = Builder::BinnedSah { bins: 16 };

/// `f` on a rayon pool of `threads` threads.
fn on_threads<T: Send>(threads: usize, f: impl FnOnce() -> T + Send) -> T {
    rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .unwrap()
        .install(f)
}

/// The objects below node `k`, sorted.
fn objects_below(tree: &Bvh, k: usize) -> Vec<u32> {
    let (mut stack, mut objects) = (vec![k], Vec::new());
    while let Some(k) = stack.pop() {
        let node = tree.nodes[k];
        let first = node.first as usize;
        if node.is_leaf() {
            objects.extend(&tree.order[first..first + node.count as usize]);
        } else {
            stack.extend([first, first + 1]);
        }
    }
    objects.sort_unstable();
    objects
}

/// Panics unless `tree` over `boxes` has chapter 8's invariants: every
/// node reached once from the root, children side by side after their
/// parent, leaves of 1 to `MAX_LEAF` objects, every bounded object in
/// exactly one leaf, each box the exact union of what is below it, and
/// the unbounded objects chapter 8's.
fn check(tree: &Bvh, boxes: &[Aabb]) {
    let reference = Bvh::build(boxes, Builder::Median);
    assert_eq!(tree.unbounded, reference.unbounded);
    let bounded = boxes.len() - reference.unbounded.len();
    assert_eq!(tree.order.len(), bounded);
    if bounded == 0 {
        assert!(tree.nodes.is_empty());
        return;
    }
    let mut reached = vec![false; tree.nodes.len()];
    let mut stack = vec![0];
    while let Some(k) = stack.pop() {
        assert!(!reached[k], "node {k} reached twice");
        reached[k] = true;
        let node = tree.nodes[k];
        let first = node.first as usize;
        let union = if node.is_leaf() {
            assert!(node.count as usize <= MAX_LEAF, "leaf {k}");
            let objects = &tree.order[first..first + node.count as usize];
            let boxes = objects.iter().map(|&i| boxes[i as usize]);
            boxes.fold(Aabb::EMPTY, Aabb::union)
        } else {
            assert!(first > k && first + 1 < tree.nodes.len(), "node {k}");
            stack.extend([first, first + 1]);
            let children = &tree.nodes[first..first + 2];
            children[0].bounds.union(children[1].bounds)
        };
        assert_eq!(node.bounds, union, "node {k}'s box");
    }
    assert!(reached.iter().all(|&r| r), "a node no walk reaches");
    let mut objects = tree.order.clone();
    objects.sort_unstable();
    objects.dedup();
    let mut expected = reference.order;
    expected.sort_unstable();
    assert!(objects == expected, "not every bounded object exactly once");
}

#[test]
fn the_tree_has_chapter_8s_invariants() {
    let boxes = triangle_boxes(&bunny());
    let tree = build_parallel_with(&boxes, 16, PART);
    check(&tree, &boxes);
    // The top splits exactly as chapter 8 does: the same objects on each
    // side of the root.
    let sequential = Bvh::build(&boxes, BINNED);
    for side in 0..2 {
        let (ours, theirs) = (tree.nodes[0].first, sequential.nodes[0].first);
        let ours = objects_below(&tree, (ours + side) as usize);
        let theirs = objects_below(&sequential, (theirs + side) as usize);
        assert!(ours == theirs, "the root's child {side} differs");
    }
    // A scene smaller than a part is chapter 8's tree itself.
    let whole = build_parallel(&boxes, 16) == sequential;
    assert!(whole, "not chapter 8's tree");
}

#[test]
fn the_tree_is_the_same_on_one_and_two_threads() {
    let boxes = triangle_boxes(&bunny());
    let one = on_threads(1, || build_parallel_with(&boxes, 16, PART));
    let two = on_threads(2, || build_parallel_with(&boxes, 16, PART));
    let three = on_threads(3, || build_parallel_with(&boxes, 8, PART));
    // (assert! rather than assert_eq!: a tree's Debug is long)
    assert!(one == two, "two threads built another tree");
    let default_pool = build_parallel_with(&boxes, 8, PART);
    assert!(three == default_pool, "three threads built another tree");
    assert!(one != three, "8 bins give another tree");
}

#[test]
fn the_tree_costs_within_2_percent_of_chapter_8s() {
    let boxes = triangle_boxes(&bunny());
    let ours = build_parallel_with(&boxes, 16, PART).sah_cost();
    let theirs = Bvh::build(&boxes, BINNED).sah_cost();
    let ratio = ours / theirs;
    assert!((0.98..1.02).contains(&ratio), "{ours} against {theirs}");
}

#[test]
fn the_tree_answers_every_ray_as_brute_force_does() {
    let triangles = bunny();
    let tree = build_parallel_with(&triangle_boxes(&triangles), 16, PART);
    let fast = FastBvh::from_tree(&triangles, &tree, Step::LeafLayout);
    let rays = rays(&triangles, 24, 600);
    let truth = truth(&triangles, &rays);
    let hits = truth.closest.iter().filter(|hit| hit.is_some()).count();
    assert!(hits > rays.len() / 10, "only {hits} hits");
    assert_eq!(wrong(&fast, &rays, &truth), (0, 0));
}

/// A box of half-size `r` around `c`.
fn cube(c: DVec3, r: f64) -> Aabb {
    Aabb::new(c - DVec3::splat(r), c + DVec3::splat(r))
}

#[test]
fn tiny_scenes_and_boxes_outside_the_tree() {
    let a = cube(DVec3::ZERO, 1.0);
    let b = cube(DVec3::X * 3.0, 0.5);
    let nan = Aabb {
        min: DVec3::new(0.0, f64::NAN, 0.0),
        max: DVec3::ONE,
    };
    let infinite = Aabb {
        min: DVec3::ZERO,
        max: DVec3::new(1.0, f64::INFINITY, 1.0),
    };
    // finite, but empty: min above max
    let inside_out = Aabb {
        min: DVec3::ONE,
        max: DVec3::ZERO,
    };
    // finite in f64, not in the builders' f32 copies
    let huge = cube(DVec3::ZERO, 1e300);
    let far = cube(DVec3::splat(1e39), 1e38);
    let scenes: [&[Aabb]; 7] = [
        &[],
        &[a],
        &[a, b],
        &[nan, Aabb::EVERYTHING, infinite, Aabb::EMPTY],
        &[nan, a, infinite, b, Aabb::EMPTY, inside_out],
        &[a, nan],
        &[a, huge, b, far, a, b],
    ];
    for boxes in scenes {
        for part in [0, 1, PART] {
            let tree = build_parallel_with(boxes, 16, part);
            check(&tree, boxes);
        }
        assert_eq!(build_parallel(boxes, 16), Bvh::build(boxes, BINNED));
    }
    let outside = build_parallel(scenes[4], 16);
    assert_eq!(outside.unbounded, vec![0, 2, 4, 5]);
    assert_eq!(outside.nodes[0].bounds, a.union(b));
}

#[test]
fn sets_that_cannot_be_split_and_deep_tops_end() {
    // 1000 boxes around one centroid: no cut separates them, and
    // chapter 8 splits them by count.
    let same: Vec<Aabb> = (1..=1000)
        .map(|k| cube(DVec3::splat(0.5), f64::from(k) * 1e-3))
        .collect();
    let tree = build_parallel_with(&same, 16, PART);
    check(&tree, &same);
    assert!(tree == Bvh::build(&same, BINNED), "not chapter 8's tree");
    // Slivers across x, each 32 times as far from x = 0 as the next
    // (exact in f32): the next one in always falls in the first slice,
    // so each split peels off one sliver, a top deeper than it may go.
    let slivers: Vec<Aabb> = (-20..=20)
        .flat_map(|k| [1.0, -1.0].map(|s| s * 32f64.powi(k)))
        .map(|x| Aabb::new(DVec3::new(x, -1.0, -1.0), DVec3::new(x, 1.0, 1.0)))
        .collect();
    let tree = build_parallel_with(&slivers, 16, 1);
    check(&tree, &slivers);
    assert!(tree.depth() > 32, "depth {}", tree.depth());
}
