//! What each step changes in the work a ray costs, counted (not timed)
//! on the bunny: nodes, bytes per node, nodes reached and triangle
//! tests per camera ray and per incoherent ray. A reviewable table: the
//! layout steps (2, 3) keep the tree; the sweep (4) and the rotations
//! (4b) change it a little; wide nodes (5) cut the nodes reached by about
//! W/2; the triangle test (6) and the parallel build (7, the same tree
//! here) change no count.
use std::fmt::Write;

use ch08::{
    BoundingSphere, Builder, Bvh, Interval, MeshAccelerator, MeshBvh,
    NodePrecision, Ray32, TraceCounts, triangle_boxes,
};
use ch11::{FastBvh, Step};
use raystep_bench::{bunny, camera_rays, incoherent_rays};
use raystep_core::Aabb;

/// Nodes reached and triangle tests per ray, over `rays`.
fn per_ray(
    rays: &[Ray32], mut trace: impl FnMut(&Ray32, &mut TraceCounts),
) -> (f64, f64) {
    let mut counts = TraceCounts::default();
    for ray in rays {
        trace(ray, &mut counts);
    }
    let n = rays.len() as f64;
    (counts.nodes as f64 / n, counts.triangles as f64 / n)
}

#[test]
fn the_work_of_each_step() {
    let triangles = bunny();
    let bounds = Aabb::around(triangles.iter().flatten().copied());
    let sphere = BoundingSphere::around_box(&bounds);
    let camera: Vec<Ray32> =
        camera_rays(sphere, 64).iter().map(Ray32::rounded).collect();
    let incoherent: Vec<Ray32> = incoherent_rays(bounds, 4096, 3)
        .iter()
        .map(Ray32::rounded)
        .collect();
    let mut table = String::from(
        "step                   nodes  B/node  camera: nodes tests  incoherent: nodes tests\n",
    );
    let mut row = |name: &str,
                   nodes: usize,
                   bytes: usize,
                   c: (f64, f64),
                   i: (f64, f64)| {
        writeln!(
            table,
            "{name:<22} {nodes:>5} {bytes:>7} {:>14.2} {:>5.2} {:>18.2} {:>5.2}",
            c.0, c.1, i.0, i.1
        )
        .unwrap();
    };
    // Step 1: chapter 8's tree, as the benchmark runs it.
    let tree = Bvh::build(
        &triangle_boxes(&triangles),
        Builder::BinnedSah { bins: 16 },
    );
    let lecture = MeshBvh::new(&triangles, &tree, NodePrecision::Single);
    let trace = |ray: &Ray32, counts: &mut TraceCounts| {
        lecture.closest_hit(ray, Interval::FORWARD, counts);
    };
    row(
        "1 lecture",
        lecture.node_count(),
        32,
        per_ray(&camera, trace),
        per_ray(&incoherent, trace),
    );
    for step in Step::ALL {
        let fast = FastBvh::build(&triangles, step);
        let trace = |ray: &Ray32, counts: &mut TraceCounts| {
            fast.closest_hit(ray, Interval::FORWARD, counts);
        };
        let (nodes, bytes) = fast.nodes();
        row(
            &step.name(),
            nodes,
            bytes,
            per_ray(&camera, trace),
            per_ray(&incoherent, trace),
        );
    }
    insta::assert_snapshot!(table);
}
