//! The world a raystep tracer traces: its objects, their materials, the
//! lights and the camera, and the [`Accelerator`] that searches the
//! objects for a ray's hits; and its twin for triangle meshes, the
//! [`MeshAccelerator`].
//!
//! A [`World`] is built from a scene file ([`raystep_scene::Scene`]) by a
//! chapter: the chapter turns each shape of the file into a surface it has
//! taught (a [`Shape`]) and chooses how the objects are searched
//! (`ch03::world` builds chapter 3's shapes and its brute-force loop).
//! Everything a tracer does with the objects goes through
//! [`World::closest_hit`] and [`World::any_hit`].
#![deny(missing_docs)]

mod accelerator;
mod mesh_accelerator;

use std::sync::Arc;

use raystep_core::{Camera, DVec3, Hit, Interval, Ray, Shape};
use raystep_scene::{Light, Material, Scene, SceneError};
use thiserror::Error;

pub use accelerator::Accelerator;
pub use mesh_accelerator::{MeshAccelerator, MeshHit, TraceCounts};

/// A surface and the index of its material in [`World::materials`].
#[derive(Clone, Debug)]
pub struct Object {
    /// What it looks like, and how a ray hits it.
    pub shape: Arc<dyn Shape>,
    /// Its material, an index into [`World::materials`].
    pub material: usize,
}

/// Builds an [`Accelerator`] for a list of objects: how `raystep render
/// --accel` hands a chapter's renderer the search it asked for (the
/// lecture's loop, or chapter 8's hierarchy).
pub type Accelerate = fn(&[Object]) -> Arc<dyn Accelerator>;

/// Turns one shape of a scene file into a surface, or says why it cannot
/// (a degenerate polygon, or a kind of shape the chapter has not taught).
pub type MakeShape =
    fn(&raystep_scene::Shape) -> Result<Arc<dyn Shape>, String>;

/// Why a scene cannot be built into a world.
#[derive(Debug, Error)]
pub enum WorldError {
    /// The scene file cannot be read or is not a valid scene.
    #[error(transparent)]
    Scene(#[from] SceneError),
    /// One of the scene's shapes cannot be made into a surface.
    #[error("{file}:{line}: objects[{index}].{kind}: {message}")]
    Shape {
        /// The scene file.
        file: String,
        /// The line of the object in it.
        line: usize,
        /// The object's index.
        index: usize,
        /// Its shape's key: `sphere`, `polygon`, …
        kind: &'static str,
        /// What is wrong.
        message: String,
    },
    /// Something of the scene the chapter has not taught (chapters 3–7
    /// and instances of meshes).
    #[error("{file}:{line}: {field}: {message}")]
    NotTaught {
        /// The scene file.
        file: String,
        /// The line of the entry in it.
        line: usize,
        /// The entry: `instances[0]`.
        field: String,
        /// What the chapter does not do, and which does.
        message: String,
    },
}

/// Everything a render needs: the objects and how to search them, their
/// materials, the lights and the camera.
#[derive(Clone, Debug)]
pub struct World {
    /// The objects, in scene-file order: an object *is* its index here.
    pub objects: Vec<Object>,
    /// How [`World::closest_hit`] and [`World::any_hit`] search `objects`.
    /// Replace it (after building one for these objects) to speed up any
    /// tracer; change `objects` only with an accelerator that keeps no
    /// state of its own, or rebuild it.
    pub accelerator: Arc<dyn Accelerator>,
    /// The materials the objects refer to.
    pub materials: Vec<Material>,
    /// The point lights.
    pub lights: Vec<Light>,
    /// Ia, the ambient intensity.
    pub ambient: DVec3,
    /// What a ray that hits nothing sees.
    pub background: DVec3,
    /// The camera, with the image's aspect ratio.
    pub camera: Camera,
    /// Image width in pixels.
    pub width: u32,
    /// Image height in pixels.
    pub height: u32,
}

impl World {
    /// The world of `scene`, each shape made by `make_shape`, searched by
    /// `accelerator`. `file` names the scene in errors.
    pub fn from_scene(
        scene: &Scene, file: &str, make_shape: MakeShape,
        accelerator: Arc<dyn Accelerator>,
    ) -> Result<World, WorldError> {
        let mut objects = Vec::with_capacity(scene.objects.len());
        for (index, object) in scene.objects.iter().enumerate() {
            let shape = make_shape(&object.shape).map_err(|message| {
                WorldError::Shape {
                    file: file.to_string(),
                    line: object.line,
                    index,
                    kind: object.shape.kind(),
                    message,
                }
            })?;
            objects.push(Object {
                shape,
                material: object.material,
            });
        }
        let aspect = f64::from(scene.width) / f64::from(scene.height);
        Ok(World {
            objects,
            accelerator,
            materials: scene.materials.clone(),
            lights: scene.lights.clone(),
            ambient: scene.ambient,
            background: scene.background,
            camera: scene.camera.camera(aspect),
            width: scene.width,
            height: scene.height,
        })
    }

    /// The closest hit of `ray` within `interval`: which object, and the
    /// hit (asked of the [`Accelerator`]).
    pub fn closest_hit(
        &self, ray: &Ray, interval: Interval,
    ) -> Option<(usize, Hit)> {
        self.accelerator.closest_hit(&self.objects, ray, interval)
    }

    /// Does anything meet `ray` within `interval`? (Asked of the
    /// [`Accelerator`].)
    pub fn any_hit(&self, ray: &Ray, interval: Interval) -> bool {
        self.accelerator.any_hit(&self.objects, ray, interval)
    }

    /// The material of object `object`.
    pub fn material_of(&self, object: usize) -> &Material {
        &self.materials[self.objects[object].material]
    }

    /// The same world searched by `accelerator` (built for its objects).
    pub fn with_accelerator(self, accelerator: Arc<dyn Accelerator>) -> World {
        World {
            accelerator,
            ..self
        }
    }

    /// The same world searched by what `accelerate` builds for its objects.
    pub fn accelerated(self, accelerate: Accelerate) -> World {
        let accelerator = accelerate(&self.objects);
        self.with_accelerator(accelerator)
    }
}
