//! Appendix — how fast can it go: chapter 8's bounding volume hierarchy
//! made fast one measured step at a time, each step beside the others in
//! `raystep bench` (and in the appendix's table), every one answering
//! exactly what chapter 8's tree and brute force answer.
//!
//! - Step 1 is chapter 8's [`MeshBvh`](ch08::MeshBvh), unchanged.
//! - Step 2 ([`binary`]): compact nodes walked in the ray's direction
//!   order with an explicit stack, the ray's reciprocal once ([`ray`]).
//! - Step 3 ([`leaf_triangles`]): the leaves' triangles in `f32`.
//! - Step 4: a better tree? (chapter 8's full-sweep SAH, or 4b, tree
//!   rotations ([`rotations`]); side steps: the wide steps collapse the
//!   binned tree, 5f and 5g the sweep's).
//! - Step 5 ([`wide`]): 4- and 8-wide nodes, their boxes tested with SIMD
//!   ([`simd4`], [`simd8`]) or one by one on any CPU; 8-wide nodes
//!   compressed to 96 bytes ([`compressed`]).
//! - Step 6 ([`simd_triangle`]): each triangle's three edges tested at
//!   once (AVX2).
//! - Step 7: threads, for tracing (the benchmark's `--threads`) and for
//!   the build ([`parallel_build`]).
//! - Step 8 ([`leaf4`]): leaves of four triangles, merged where the SAH
//!   says a block of four beats the nodes above it, tested four at once
//!   (AVX2); step 9: shadow rays take the children unsorted.
//! - Step 10 ([`pairs512`]): a leaf's two blocks tested at once in the
//!   eight lanes of AVX-512, where the CPU has it.
//! - Step 11 ([`short_path`]): a walk with less between one node's load
//!   and the next.
//! - Step 12: the tree not split below eight triangles (two blocks), for
//!   a shorter build (chapter 8's `Bvh::build_with_leaves_of`).
//! - Step 13 ([`pages`]): step 12's nodes and blocks in 2 MB pages.
//!
//! The appendix has no exercises: it is written for engineers, after the
//! lecture.
#![deny(missing_docs)]

pub mod binary;
pub mod compressed;
pub mod leaf4;
pub mod leaf_triangles;
pub mod pages;
#[cfg(target_arch = "x86_64")]
pub mod pairs512;
pub mod parallel_build;
#[cfg(target_arch = "x86_64")]
mod prefetch;
pub mod ray;
pub mod rotations;
#[cfg(target_arch = "x86_64")]
pub mod short_path;
#[cfg(target_arch = "x86_64")]
pub mod simd4;
#[cfg(target_arch = "x86_64")]
pub mod simd8;
#[cfg(target_arch = "x86_64")]
pub mod simd_triangle;
mod steps;
pub mod wide;

pub use binary::Binary;
pub use compressed::CompressedNode;
pub use leaf_triangles::LeafTriangles;
pub use ray::FastRay;
pub use steps::{FastBvh, Kernel, Step};
pub use wide::{Wide, WideNode};
