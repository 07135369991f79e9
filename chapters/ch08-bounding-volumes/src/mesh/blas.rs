//! The bottom level of a two-level hierarchy: one mesh, in its own frame,
//! with its own accelerator, built once however often it is placed.
use std::sync::Arc;

use raystep_core::glam::DAffine3;
use raystep_core::{Aabb, DVec3, Hit, Interval, Ray};
use raystep_scene::Mesh;
use raystep_world::{Accelerate, Accelerator, Object};

use crate::placed_triangles;

// ANCHOR: blas
/// A mesh's own structure, the *bottom-level* acceleration structure
/// (Bikker's BLAS): its triangles as objects in the mesh's frame, where
/// its file put them, and the accelerator built over them. Every
/// [`MeshInstance`](crate::MeshInstance) of the mesh shares one through
/// an `Arc`: a thousand instances hold one copy of the triangles.
#[derive(Debug)]
pub struct Blas {
    /// The triangles ([`placed_triangles`] placed nowhere). Their
    /// material is unused (0): an instance's world object has its own.
    objects: Vec<Object>,
    /// Each one's geometric normal (its hits may carry a smooth one).
    normals: Vec<DVec3>,
    /// What searches them, built by the accelerate function asked for.
    accelerator: Arc<dyn Accelerator>,
    /// The box around the mesh's vertices, in its frame.
    bounds: Aabb,
}

impl Blas {
    /// The structure of `mesh`, its triangles searched by what
    /// `accelerate` builds for them (the lecture's loop, a BVH, a grid, a
    /// kd-tree: the choice of `raystep render --accel`).
    pub fn new(mesh: &Mesh, accelerate: Accelerate) -> Blas {
        let placed = placed_triangles(mesh, &DAffine3::IDENTITY);
        let normals = placed.iter().map(|p| p.normal).collect();
        let objects: Vec<Object> = placed
            .into_iter()
            .map(|p| Object {
                shape: p.shape,
                material: 0,
            })
            .collect();
        let accelerator = accelerate(&objects);
        Blas {
            objects,
            normals,
            accelerator,
            bounds: mesh.bounds(),
        }
    }

    /// The triangles, as objects in the mesh's frame.
    pub fn objects(&self) -> &[Object] {
        &self.objects
    }

    /// The geometric normal of triangle `index`, in the mesh's frame.
    pub fn normal(&self, index: usize) -> DVec3 {
        self.normals[index]
    }

    /// The box around the mesh, in its frame.
    pub fn bounds(&self) -> Aabb {
        self.bounds
    }

    /// The closest hit of `ray` (in the mesh's frame) within `interval`:
    /// which triangle, and the hit, asked of the mesh's accelerator.
    pub fn closest_hit(
        &self, ray: &Ray, interval: Interval,
    ) -> Option<(usize, Hit)> {
        self.accelerator.closest_hit(&self.objects, ray, interval)
    }
}
// ANCHOR_END: blas
