//! The scene both methods draw: chapter 03's world, whose objects are all
//! polygons, and those polygons as triangles for the rasterizer.
use ch02::Polygon;
use ch03::{Object, Shape, World};
use raystep_core::DVec3;
use raystep_scene::Scene;
use thiserror::Error;

use crate::Mesh;

/// One triangle of the stage and the object it belongs to.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Triangle {
    /// Its corners.
    pub corners: [DVec3; 3],
    /// The index of its object in the world (the id both methods write).
    pub object: usize,
}

/// Why a world cannot be rasterized.
#[derive(Debug, Error)]
pub enum StageError {
    /// The scene file is bad.
    #[error(transparent)]
    World(#[from] ch03::WorldError),
    /// An object is not a polygon: a rasterizer draws triangles only.
    #[error(
        "{file}: objects[{index}] is a {kind}: chapter 07 rasterizes polygons only; write it as polygons, or render it with a ray tracer (--chapter 06)"
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
#[derive(Clone, Debug, PartialEq)]
pub struct Stage {
    /// Chapter 03's world: camera, lights, materials, and the polygons the
    /// ray caster intersects.
    pub world: World,
    /// The same polygons cut into triangles (fans from the first corner),
    /// in object order.
    pub triangles: Vec<Triangle>,
}

impl Stage {
    /// The stage of a world whose objects are all polygons; `file` names
    /// the scene in errors.
    pub fn new(world: World, file: &str) -> Result<Stage, StageError> {
        let mut triangles = Vec::new();
        for (index, object) in world.objects.iter().enumerate() {
            let polygon = match &object.shape {
                Shape::Polygon(p) => p,
                Shape::Sphere(_) | Shape::Plane(_) => {
                    return Err(StageError::NotAPolygon {
                        file: file.to_string(),
                        index,
                        kind: match object.shape {
                            Shape::Sphere(_) => "sphere",
                            _ => "plane",
                        },
                    });
                }
            };
            let v = polygon.vertices();
            for k in 1..v.len() - 1 {
                triangles.push(Triangle {
                    corners: [v[0], v[k], v[k + 1]],
                    object: index,
                });
            }
        }
        Ok(Stage { world, triangles })
    }

    /// The stage of a scene file's text.
    pub fn from_scene(scene: &Scene, file: &str) -> Result<Stage, StageError> {
        Stage::new(World::from_scene(scene, file)?, file)
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
                    });
                    self.world.objects.push(Object {
                        shape: Shape::Polygon(polygon),
                        material,
                    });
                }
                Err(_) => skipped += 1,
            }
        }
        skipped
    }
}
