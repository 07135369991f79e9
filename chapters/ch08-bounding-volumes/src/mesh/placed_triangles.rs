//! A mesh of a scene file put where its placement says, one shape per
//! triangle: what a scene's `mesh = { … }` object is flattened into, and
//! (placed nowhere) what an instanced mesh's own structure holds.
use std::sync::Arc;

use raystep_core::glam::DAffine3;
use raystep_core::{DVec3, Shape};
use raystep_scene::Mesh;

use crate::{SmoothTriangle, Triangle, TriangleTest};

/// One triangle of a placed mesh: the shape a ray hits, and its geometric
/// normal (which its hits need not carry: a smooth triangle's blend).
#[derive(Clone, Debug)]
pub struct PlacedTriangle {
    /// A flat [`Triangle`] or a [`SmoothTriangle`].
    pub shape: Arc<dyn Shape>,
    /// The unit normal of its plane, by its winding.
    pub normal: DVec3,
}

// ANCHOR: placed_triangles
/// The triangles of `mesh` moved by `to_world`, one shape each: a flat
/// watertight [`Triangle`] if the mesh has no normals, else a
/// [`SmoothTriangle`] with its corners' normals moved too.
///
/// A triangle whose corners fix no plane (two coincide, or all three lie
/// on a line) is left out: it has no area, and no ray hits it.
pub fn placed_triangles(
    mesh: &Mesh, to_world: &DAffine3,
) -> Vec<PlacedTriangle> {
    // Step 1: the corners go by the matrix, the normals by its inverse
    // transpose (which keeps them across the surface under any scale).
    let vertices: Vec<DVec3> = mesh
        .vertices
        .iter()
        .map(|&v| to_world.transform_point3(v))
        .collect();
    let normal_matrix = to_world.matrix3.inverse().transpose();
    let normals: Vec<DVec3> =
        mesh.normals.iter().map(|&n| normal_matrix * n).collect();
    // Step 2: a mirror (a negative determinant) reverses every winding;
    // walk the corners the other way round, so that each triangle stays
    // counter-clockwise seen from outside and its normal still points out.
    let mirrored = to_world.matrix3.determinant() < 0.0;
    let mut placed = Vec::with_capacity(mesh.triangles.len());
    for &[a, b, c] in &mesh.triangles {
        let corners = if mirrored { [a, c, b] } else { [a, b, c] };
        let v = corners.map(|i| vertices[i]);
        // Step 3: flat or smooth, as the mesh says.
        let Ok(flat) = Triangle::new(v, TriangleTest::Watertight) else {
            continue;
        };
        let normal = flat.normal();
        let shape: Arc<dyn Shape> = if normals.is_empty() {
            Arc::new(flat)
        } else {
            let at_corners = corners.map(|i| normals[i]);
            Arc::new(SmoothTriangle::from_triangle(flat, at_corners))
        };
        placed.push(PlacedTriangle { shape, normal });
    }
    placed
}
// ANCHOR_END: placed_triangles
