//! No ray leaks through a shared edge: the rays of [`shared_edge_rays`]
//! at chapter 8's three leak surfaces (the bunny as read, moved far away,
//! and a tiled floor), through chapter 8's mesh BVH in each node
//! precision, through brute force, and through every step of the
//! appendix (chapter 11). A *leak* is a ray aimed at a point on the
//! surface that hits nothing at or before it.
use ch08::{
    Builder, Bvh, MeshBruteForce, MeshBvh, NodePrecision, triangle_boxes,
};
use ch11::{FastBvh, Step};
use raystep_core::DVec3;
use raystep_stability::scenes::bunny;
use raystep_stability::{leak_surfaces, leaks, shared_edge_rays};

/// The rays aimed at `triangles`' shared edges at fractions `points`:
/// how many, and how many leak through each layout of chapter 8's mesh
/// BVH (f64, f32, f32 to nearest; 16-bin SAH) and through brute force.
fn bvh_leaks(triangles: &[[DVec3; 3]], points: &[f64]) -> (usize, [usize; 4]) {
    let rays = shared_edge_rays(triangles, points);
    let tree =
        Bvh::build(&triangle_boxes(triangles), Builder::BinnedSah { bins: 16 });
    let through = |k: usize| {
        leaks(
            &MeshBvh::new(triangles, &tree, NodePrecision::ALL[k]),
            &rays,
        )
    };
    let brute = leaks(&MeshBruteForce(triangles), &rays);
    (rays.len(), [through(0), through(1), through(2), brute])
}

#[test]
fn no_ray_leaks_through_a_shared_edge() {
    // The bunny as read (its corners are f32 numbers), moved 1000 away
    // and shrunk by 3 (corners no f32 can hold: nodes rounded), and a
    // floor of tiles 0.1 wide (no f32 holds 0.1): its edges lie on the
    // faces of the leaves' boxes.
    let mut table = String::new();
    for surface in leak_surfaces(bunny()) {
        let name = surface.name.replace("mesh", "bunny");
        let (aimed, leaks) = bvh_leaks(&surface.triangles, surface.points);
        assert!(aimed > 4_000, "{name}: {aimed}");
        assert_eq!(
            leaks[..2],
            [0, 0],
            "{name}: leaks through f64 and f32 nodes (brute force: {})",
            leaks[3]
        );
        assert_eq!(leaks[3], 0, "{name}: leaks by brute force");
        table += &format!(
            "{name}: {aimed} rays aimed at shared edges (no silhouettes)\n\
             leaks: f64 nodes {}, f32 nodes {}, f32 rounded to nearest {}, \
             brute force {}\n",
            leaks[0], leaks[1], leaks[2], leaks[3]
        );
    }
    insta::assert_snapshot!(table);
}

/// Every step of the appendix, with its SIMD kernel where the CPU has
/// it: no leak on any of the three surfaces.
#[test]
fn no_step_of_the_appendix_leaks() {
    for surface in leak_surfaces(bunny()) {
        let rays = shared_edge_rays(&surface.triangles, surface.points);
        assert!(rays.len() > 1000, "{}: {} rays", surface.name, rays.len());
        for step in Step::ALL {
            let fast = FastBvh::build(&surface.triangles, step);
            let leaked = leaks(&fast, &rays);
            assert_eq!(leaked, 0, "{} leaks on {}", step.name(), surface.name);
        }
    }
}
