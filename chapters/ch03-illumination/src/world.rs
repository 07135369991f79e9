//! A scene file's shapes as the surfaces chapters 2 and 03 taught,
//! searched by the brute-force loop.
use std::path::Path;
use std::sync::Arc;

use ch02::{InfinitePlane, Plane, Polygon};
use raystep_core::Shape;
use raystep_scene::{Scene, Shape as ShapeSpec};
use raystep_world::{World, WorldError};

use crate::{BruteForce, Sphere};

/// The surface of one shape of a scene file: chapter 3's sphere, or
/// chapter 2's plane or polygon (an error names what is wrong with a
/// degenerate polygon, or that the shape is a later chapter's).
pub fn shape(spec: &ShapeSpec) -> Result<Arc<dyn Shape>, String> {
    Ok(match spec {
        ShapeSpec::Sphere { center, radius } => {
            Arc::new(Sphere::new(*center, *radius))
        }
        ShapeSpec::Plane { point, normal } => Arc::new(InfinitePlane(Plane {
            normal: *normal,
            d: -normal.dot(*point),
        })),
        ShapeSpec::Polygon { vertices } => {
            Arc::new(Polygon::new(vertices.clone()).map_err(|e| e.to_string())?)
        }
        other => {
            return Err(format!(
                "a {} is one of chapter 8's primitives, which chapters 3–7 \
                 do not know: render this scene with `--chapter ch08`",
                other.kind()
            ));
        }
    })
}

/// The world of `scene`, with chapter 3's shapes and the lecture's
/// brute-force loop. `file` names the scene in errors.
pub fn world(scene: &Scene, file: &str) -> Result<World, WorldError> {
    // Instances of a mesh are chapter 8's two-level hierarchy.
    if let Some(instance) = scene.instances.first() {
        return Err(WorldError::NotTaught {
            file: file.to_string(),
            line: instance.line,
            field: "instances[0]".to_string(),
            message: "instances of a mesh are chapter 8's, which chapters \
                      3–7 do not know: render this scene with `--chapter \
                      ch08`"
                .to_string(),
        });
    }
    World::from_scene(scene, file, shape, Arc::new(BruteForce))
}

/// The world of the scene file at `path` (see [`world`]).
pub fn load(path: &Path) -> Result<World, WorldError> {
    let scene = raystep_scene::load(path)?;
    world(&scene, &path.display().to_string())
}

/// The world of scene-file text; `file` names it in errors (see [`world`]).
pub fn parse(text: &str, file: &str) -> Result<World, WorldError> {
    world(&raystep_scene::parse(text, file)?, file)
}
