//! # Chapter 8 — bounding volumes
//!
//! "Ray tracing speed-ups", in two parts.
//!
//! Part 1 (8.1): some primitives are fast to intersect — boxes, cylinders,
//! ellipsoids, triangles (`src/primitives/`) — and some are slow — a torus
//! (a quartic in t), a cubic surface, blobby objects — and need robust
//! root finding (`src/roots/`). A bounding volume (a sphere or a box)
//! around something slow or big is cheap to test *versus* the cost of what
//! is inside; the tighter it fits, the more rays it turns away
//! (`src/bounds/`).
//!
//! Part 2 (8.2): boxes inside boxes, a bounding volume hierarchy: its
//! walks and its builders (`src/bvh/`), and the fast path for triangle
//! meshes (`src/mesh/`).
//!
//! Student mode: with the feature `exercise` the six exercise modules
//! (marked in each part's module) are replaced by the stubs in
//! `exercise/`.

// ---------------------------------------------------------------------
// What every part uses: a primitive, and the sphere around it.
// ---------------------------------------------------------------------

mod bounding_sphere;
mod primitive;

pub use bounding_sphere::BoundingSphere;
pub use primitive::Primitive;
pub use raystep_core::{Aabb, DVec3, Hit, Interval, Ray, Shape};

// ---------------------------------------------------------------------
// Part 1: fast primitives: the box's slab test (exercise 1), cylinder,
// ellipsoid, triangles (exercise 2: the watertight test).
// ---------------------------------------------------------------------

mod primitives;

pub use primitives::{
    AxisBox, Cylinder, Ellipsoid, Shear, Triangle, TriangleTest,
    moller_trumbore, slab_test, watertight,
};

// ---------------------------------------------------------------------
// Part 1: slow primitives: polynomial roots, the torus (exercise 3: its
// quartic), the saddle, blobs.
// ---------------------------------------------------------------------

mod roots;

pub use roots::{
    Ball, Blobby, Saddle, Torus, TorusSolver, WYVILL, cubic_roots, derivative,
    horner, multiply, quadratic_roots, quartic_roots, roots_in, saddle_cubic,
    torus_quartic,
};

// ---------------------------------------------------------------------
// Part 1: bounding volumes: spheres around point sets (exercise 4),
// tightness (random lines from a seeded generator), meshes behind one box.
// ---------------------------------------------------------------------

mod bounds;

pub use bounds::{
    Bound, BoundKind, Bounded, MeshBoxCounts, MeshTriangle, RandomLines,
    SplitMix64, TestCounts, Tightness, TriangleMesh, bounded_intersect,
    mesh_behind_box, mesh_triangle, sphere_of_points,
};

// ---------------------------------------------------------------------
// Part 2: bounding volume hierarchies: the tree, its builders (exercise
// 5: the SAH cost of a split), its walks (exercise 6: near first).
// ---------------------------------------------------------------------

mod bvh;

pub use bvh::{
    AGGLOMERATIVE_LIMIT, Builder, Bvh, BvhNode, INTERSECTION, MAX_LEAF,
    SahCosts, TRAVERSAL, TreeStats, near_first_closest_hit, split_cost,
};
pub use raystep_world::{Accelerator, Object, World};

// ---------------------------------------------------------------------
// Part 2: the fast path for triangle meshes, asked through the mesh seam.
// ---------------------------------------------------------------------

mod mesh;

pub use mesh::{
    Closest, MeshBruteForce, MeshBvh, NodePrecision, PreparedRay, outward,
    triangle_boxes,
};
pub use raystep_core::Ray32;
pub use raystep_world::{MeshAccelerator, MeshHit, TraceCounts};

// ---------------------------------------------------------------------
// Part 2: meshes in scenes: smooth shading from vertex normals, a mesh
// flattened into the world, and instances: a two-level hierarchy (the
// world's accelerator over the instances, each mesh's own inside).
// ---------------------------------------------------------------------

pub use mesh::{
    Blas, MeshInstance, PlacedTriangle, SmoothTriangle, barycentric,
    placed_triangles,
};
pub use raystep_world::Accelerate;

// ---------------------------------------------------------------------
// Scene files: every primitive from TOML, and meshes: flattened, or
// instanced with their own structures built as `--accel` asks.
// ---------------------------------------------------------------------

mod scene_shapes;

pub use scene_shapes::{load, shape, world, world_with};
