//! The top level's view of a mesh placed in the world: a ray taken into
//! the mesh's frame, the mesh's own structure walked there, the hit
//! brought back (Bikker's TLAS/BLAS; pbrt's object instances).
use std::sync::Arc;

use raystep_core::glam::{DAffine3, DMat3};
use raystep_core::{Aabb, DVec3, Hit, Interval, Ray, Shape};

use crate::Blas;

// ANCHOR: instance
/// One placement of a mesh: its shared [`Blas`], and the matrices that
/// take the mesh to the world and back. Each is one object of the world,
/// so the world's own accelerator (the top level, Bikker's TLAS) is built
/// over the instances' boxes and the scene's other objects together.
#[derive(Clone, Debug)]
pub struct MeshInstance {
    /// The mesh's structure, shared with its other instances.
    blas: Arc<Blas>,
    /// Mesh frame → world (the placement's T·R·S), and back.
    to_world: DAffine3,
    to_mesh: DAffine3,
    /// Normals, mesh frame → world: the inverse transpose of `to_world`.
    normal_to_world: DMat3,
}

impl MeshInstance {
    /// The mesh of `blas` put in the world by `to_world` (a placement's
    /// [`to_world`](raystep_scene::Placement::to_world), which the scene
    /// file keeps invertible: no scale is 0).
    pub fn new(blas: Arc<Blas>, to_world: DAffine3) -> MeshInstance {
        let to_mesh = to_world.inverse();
        MeshInstance {
            blas,
            to_world,
            to_mesh,
            normal_to_world: to_mesh.matrix3.transpose(),
        }
    }

    /// The mesh's structure it shares.
    pub fn blas(&self) -> &Arc<Blas> {
        &self.blas
    }

    /// The matrix that puts the mesh in the world.
    pub fn to_world(&self) -> DAffine3 {
        self.to_world
    }
}
// ANCHOR_END: instance

// ANCHOR: instance_intersect
/// An instance as an object of the world.
impl Shape for MeshInstance {
    fn intersect(&self, ray: &Ray, interval: Interval) -> Option<Hit> {
        // Step 1: the ray in the mesh's frame. The direction is not
        // normalised: the mesh's ray at t is the world ray at t taken
        // back, so t, and the interval, mean the same in both frames.
        let local = Ray::new(
            self.to_mesh.transform_point3(ray.origin),
            self.to_mesh.transform_vector3(ray.direction),
        );
        // Step 2: the closest hit among the mesh's triangles, by its own
        // accelerator.
        let (index, hit) = self.blas.closest_hit(&local, interval)?;
        // Step 3: the hit in the world: the point on the world ray at the
        // same t, the normal by the inverse transpose (a normal must stay
        // across the surface when a scale stretches it), normalised.
        let normal = self.normal_to_world * hit.normal;
        // A smooth normal, kept on its facet's side in the mesh's frame,
        // may be stretched past the facet's plane: the side rule again
        // (a flat triangle's hit normal is its facet's; nothing changes).
        let facet = self.normal_to_world * self.blas.normal(index);
        let normal = if normal.dot(facet) > 0.0 {
            normal
        } else {
            facet
        };
        Some(Hit {
            t: hit.t,
            point: ray.at(hit.t),
            normal: normal.normalize(),
        })
    }

    /// The mesh's box with its 8 corners moved to the world, and the box
    /// around them, pushed out by a hair (2⁻³⁰ of its largest coordinate):
    /// the ray taken into the mesh's frame is rounded, so a hit on the
    /// mesh's box in its frame may lie an ulp outside the moved box, and
    /// an accelerator must never turn away a ray the mesh answers.
    fn bounds(&self) -> Aabb {
        let Aabb { min, max } = self.blas.bounds();
        let corners = (0..8).map(|k| {
            let pick = |bit: usize, axis: usize| {
                if k & bit == 0 { min[axis] } else { max[axis] }
            };
            let corner = DVec3::new(pick(1, 0), pick(2, 1), pick(4, 2));
            self.to_world.transform_point3(corner)
        });
        let moved = Aabb::around(corners);
        let margin =
            moved.min.abs().max(moved.max.abs()).max_element() * 2f64.powi(-30);
        Aabb {
            min: moved.min - DVec3::splat(margin),
            max: moved.max + DVec3::splat(margin),
        }
    }
}
// ANCHOR_END: instance_intersect
