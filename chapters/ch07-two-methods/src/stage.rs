//! The scene both methods draw: chapter 3's world, whose objects are all
//! polygons, and those polygons as triangles for the rasterizer.
use std::sync::Arc;

use ch02::Polygon;
use ch03::{Object, World};
use raystep_core::DVec3;
use raystep_scene::{Mesh, Scene, Shape as ShapeSpec};
use thiserror::Error;

/// One triangle of the stage and the object it belongs to.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Triangle {
    /// Its corners.
    pub corners: [DVec3; 3],
    /// The index of its object in the world (the id both methods write).
    pub object: usize,
    /// Its object's unit normal (the polygon's plane normal, as the ray
    /// caster's hit has it).
    pub normal: DVec3,
}

/// Why a world cannot be rasterized.
#[derive(Debug, Error)]
pub enum StageError {
    /// The scene file is bad.
    #[error(transparent)]
    World(#[from] ch03::WorldError),
    /// An object is not a polygon: a rasterizer draws triangles only.
    #[error(
        "{file}: objects[{index}] is a {kind}: chapter 7 rasterizes polygons only; write it as polygons, or render it with a ray tracer (--chapter 6)"
    )]
    NotAPolygon {
        /// The scene file.
        file: String,
        /// The object's index.
        index: usize,
        /// What it is.
        kind: &'static str,
    },
}

/// The world and its triangles.
#[derive(Clone, Debug)]
pub struct Stage {
    /// Chapter 3's world: camera, lights, materials, and the polygons the
    /// ray caster intersects.
    pub world: World,
    /// The same polygons cut into triangles (fans from the first corner),
    /// in object order.
    pub triangles: Vec<Triangle>,
}

impl Stage {
    /// The stage of a scene whose objects are all polygons; `file` names
    /// the scene in errors.
    pub fn from_scene(scene: &Scene, file: &str) -> Result<Stage, StageError> {
        let world = ch03::world(scene, file)?;
        let mut triangles = Vec::new();
        for (index, object) in scene.objects.iter().enumerate() {
            let ShapeSpec::Polygon { vertices } = &object.shape else {
                return Err(StageError::NotAPolygon {
                    file: file.to_string(),
                    index,
                    kind: object.shape.kind(),
                });
            };
            // the same polygon the world holds (it was built without error)
            let normal = Polygon::new(vertices.clone())
                .map_or(DVec3::ZERO, |p| p.plane().normal);
            let v = vertices;
            for k in 1..v.len() - 1 {
                triangles.push(Triangle {
                    corners: [v[0], v[k], v[k + 1]],
                    object: index,
                    normal,
                });
            }
        }
        Ok(Stage { world, triangles })
    }

    /// Adds every triangle of `mesh` as an object of material `material`
    /// (an index into the world's materials). Triangles of zero area are
    /// left out, as a rasterizer would; returns how many were.
    pub fn add_mesh(&mut self, mesh: &Mesh, material: usize) -> usize {
        let mut skipped = 0;
        for k in 0..mesh.triangles.len() {
            let corners = mesh.triangle(k);
            match Polygon::new(corners.to_vec()) {
                Ok(polygon) => {
                    self.triangles.push(Triangle {
                        corners,
                        object: self.world.objects.len(),
                        normal: polygon.plane().normal,
                    });
                    self.world.objects.push(Object {
                        shape: Arc::new(polygon),
                        material,
                    });
                }
                Err(_) => skipped += 1,
            }
        }
        skipped
    }
}
