//! # Chapter 8 — bounding volumes (part 1: fast and slow primitives)
//!
//! "Ray tracing speed-ups": some primitives are fast to intersect —
//! spheres, boxes, cylinders, ellipsoids, polygons and triangles — and
//! some are slow — a torus (a quartic in t), a cubic surface, blobby
//! objects — and need robust root finding. A bounding volume (a sphere or
//! a box) around something slow or big is cheap to test *versus* the cost
//! of what is inside; the tighter it fits, the more rays it turns away.
//!
//! Student mode: with the feature `exercise` the modules marked below are
//! replaced by the stubs in `exercise/`.

mod bounding_sphere;
mod primitive;

pub use bounding_sphere::BoundingSphere;
pub use primitive::Primitive;
pub use raystep_core::{Aabb, DVec3, Hit, Interval, Ray, Shape};

// ---------------------------------------------------------------------
// Fast primitives: the box's slab test, cylinder, ellipsoid, triangles.
// ---------------------------------------------------------------------

mod axis_box;
mod chapter_shapes;
mod cylinder;
mod ellipsoid;
mod moller_trumbore;
mod shear;
mod sphere_roots;
mod triangle;

// Exercise 1: the robust slab test.
#[cfg_attr(feature = "exercise", path = "../exercise/slab.rs")]
mod slab;
// Exercise 2: the watertight ray–triangle test.
#[cfg_attr(feature = "exercise", path = "../exercise/watertight.rs")]
mod watertight;

pub use axis_box::AxisBox;
pub use cylinder::Cylinder;
pub use ellipsoid::Ellipsoid;
pub use moller_trumbore::moller_trumbore;
pub use shear::Shear;
pub use slab::slab_test;
pub use triangle::{Triangle, TriangleTest};
pub use watertight::watertight;

// ---------------------------------------------------------------------
// Slow primitives: polynomial roots, the torus, the saddle, blobs.
// ---------------------------------------------------------------------

mod blobby;
mod bracketed;
mod closed_form;
mod polynomial;
mod saddle;
mod torus;
// Exercise 3: the torus quartic's coefficients.
#[cfg_attr(feature = "exercise", path = "../exercise/torus_quartic.rs")]
mod torus_quartic;

pub use blobby::{Ball, Blobby, WYVILL};
pub use bracketed::roots_in;
pub use closed_form::{cubic_roots, quadratic_roots, quartic_roots};
pub use polynomial::{derivative, horner, multiply};
pub use saddle::{Saddle, saddle_cubic};
pub use torus::{Torus, TorusSolver};
pub use torus_quartic::torus_quartic;

// ---------------------------------------------------------------------
// Bounding volumes: spheres around point sets, tightness, meshes.
// ---------------------------------------------------------------------

mod bounded;
mod lecture_sketch;
mod mesh_bound;
mod random_lines;
mod tightness;

// Exercise 4: a bounding sphere of a point set.
#[cfg_attr(feature = "exercise", path = "../exercise/sphere_of_points.rs")]
mod sphere_of_points;

pub use bounded::{Bound, BoundKind, Bounded, TestCounts, bounded_intersect};
pub use lecture_sketch::{sketch_bounds, sketch_shapes};
pub use mesh_bound::{
    MeshBoxCounts, MeshTriangle, TriangleMesh, camera_rays, incoherent_rays,
    mesh_behind_box, mesh_triangle,
};
pub use random_lines::{RandomLines, SplitMix64};
pub use sphere_of_points::sphere_of_points;
pub use tightness::{
    TIGHTNESS_SEED, Tightness, measure_tightness, sampling_sphere, tightness,
};

// ---------------------------------------------------------------------
// Part 2: bounding volume hierarchies.
// ---------------------------------------------------------------------

mod bvh;
mod bvh_agglomerative;
mod bvh_build;
mod bvh_flatten;
mod bvh_ploc;
mod bvh_stats;
mod bvh_sweep;
mod bvh_traverse;
mod edge_rays;
mod mesh_brute_force;
mod mesh_bvh;
mod mesh_trace;
mod prepared_ray;

// Exercise 5: the SAH cost of one split.
#[cfg_attr(feature = "exercise", path = "../exercise/sah_split.rs")]
mod sah_split;
// Exercise 6: the near-first walk for the closest hit.
#[cfg_attr(feature = "exercise", path = "../exercise/near_first.rs")]
mod near_first;

pub use bvh::{
    AGGLOMERATIVE_LIMIT, Builder, Bvh, BvhNode, INTERSECTION, SahCosts,
    TRAVERSAL,
};
pub use bvh_build::MAX_LEAF;
pub use bvh_stats::TreeStats;
pub use edge_rays::{
    EDGE_REACH, LeakSurface, leak_surfaces, leaks, shared_edge_rays,
};
pub use mesh_brute_force::MeshBruteForce;
pub use mesh_bvh::{MeshBvh, NodePrecision, outward, triangle_boxes};
pub use near_first::near_first_closest_hit;
pub use prepared_ray::{Closest, PreparedRay};
pub use raystep_core::Ray32;
pub use raystep_world::{
    Accelerator, MeshAccelerator, MeshHit, Object, TraceCounts, World,
};
pub use sah_split::split_cost;

// ---------------------------------------------------------------------
// Scene files: every primitive from TOML.
// ---------------------------------------------------------------------

mod scene_shapes;

pub use scene_shapes::{load, shape, world};
