//! A scene file's shapes as chapter 8's primitives (and chapter 2's plane),
//! its meshes flattened into triangles or placed as instances of their
//! own structures, searched by the brute-force loop.
use std::collections::BTreeMap;
use std::path::Path;
use std::sync::Arc;

use ch03::BruteForce;
use raystep_core::Shape;
use raystep_scene::{Scene, SceneError, Shape as ShapeSpec};
use raystep_world::{Accelerate, Object, World, WorldError};

use crate::{
    AxisBox, Ball, Blas, Blobby, Builder, Bvh, Cylinder, Ellipsoid,
    MeshInstance, Saddle, Torus, TorusSolver, Triangle, TriangleTest,
    placed_triangles,
};

/// The surface of one shape of a scene file: any of the chapter's
/// primitives, or chapter 2's plane. An error says what is wrong with a
/// degenerate one (a polygon or triangle whose corners lie on a line), or
/// that the shape is a mesh, which is many surfaces ([`world`] flattens
/// it).
pub fn shape(spec: &ShapeSpec) -> Result<Arc<dyn Shape>, String> {
    Ok(match spec {
        // Chapters 2 and 3's surfaces, as chapter 3 reads them.
        ShapeSpec::Sphere { .. }
        | ShapeSpec::Plane { .. }
        | ShapeSpec::Polygon { .. } => ch03::shape(spec)?,
        ShapeSpec::Box { min, max } => Arc::new(AxisBox::new(*min, *max)?),
        ShapeSpec::Cylinder { base, top, radius } => {
            Arc::new(Cylinder::new(*base, *top, *radius)?)
        }
        ShapeSpec::Ellipsoid { center, radii } => {
            Arc::new(Ellipsoid::new(*center, *radii)?)
        }
        ShapeSpec::Triangle { vertices, test } => {
            let test = match test {
                raystep_scene::TriangleTest::PlaneInside => {
                    TriangleTest::PlaneInside
                }
                raystep_scene::TriangleTest::MollerTrumbore => {
                    TriangleTest::MollerTrumbore
                }
                raystep_scene::TriangleTest::Watertight => {
                    TriangleTest::Watertight
                }
            };
            Arc::new(Triangle::new(*vertices, test)?)
        }
        ShapeSpec::Torus {
            center,
            axis,
            major,
            minor,
            solver,
        } => {
            let solver = match solver {
                raystep_scene::TorusSolver::ClosedForm => {
                    TorusSolver::ClosedForm
                }
                raystep_scene::TorusSolver::Bracketed => TorusSolver::Bracketed,
            };
            Arc::new(Torus::new(*center, *axis, *major, *minor, solver)?)
        }
        ShapeSpec::Saddle { center, size } => {
            Arc::new(Saddle::new(*center, *size)?)
        }
        ShapeSpec::Blobby { balls, threshold } => {
            let balls = balls
                .iter()
                .map(|b| Ball {
                    center: b.center,
                    radius: b.radius,
                    strength: b.strength,
                })
                .collect();
            Arc::new(Blobby::new(balls, *threshold)?)
        }
        ShapeSpec::Mesh { .. } => {
            return Err("a mesh is one surface per triangle: build the \
                 world with ch08::world, which flattens it"
                .to_string());
        }
    })
}

/// The world of `scene`, with chapter 8's primitives and the lecture's
/// brute-force loop; each instanced mesh searched by chapter 8's
/// hierarchy (binned SAH, 16 bins), as [`world_with`] builds it. `file`
/// names the scene in errors.
pub fn world(scene: &Scene, file: &str) -> Result<World, WorldError> {
    world_with(scene, file, |objects| {
        Arc::new(Bvh::for_objects(objects, Builder::BinnedSah { bins: 16 }))
    })
}

// ANCHOR: world_with
/// The world of `scene`, with chapter 8's primitives, each `mesh = { … }`
/// object flattened into its triangles (one object each, in the world,
/// with the object's material) and each `[[instances]]` entry one object,
/// a [`MeshInstance`] after the scene's objects. Each instanced mesh's own
/// structure ([`Blas`]) is built once, by `accelerate`, and shared by its
/// instances.
///
/// The world's objects are searched by the lecture's loop, as [`world`]'s
/// are: `.accelerated(accelerate)` builds the top level over them (what
/// `raystep render --accel` does). `file` names the scene in errors.
pub fn world_with(
    scene: &Scene, file: &str, accelerate: Accelerate,
) -> Result<World, WorldError> {
    // Step 1: the scene's objects, in file order, a mesh flattened.
    let mut objects = Vec::with_capacity(scene.objects.len());
    for (index, object) in scene.objects.iter().enumerate() {
        let material = object.material;
        if let ShapeSpec::Mesh { mesh, placement } = &object.shape {
            let triangles = placed_triangles(mesh, &placement.to_world());
            objects.extend(triangles.into_iter().map(|placed| Object {
                shape: placed.shape,
                material,
            }));
            continue;
        }
        let shape =
            shape(&object.shape).map_err(|message| WorldError::Shape {
                file: file.to_string(),
                line: object.line,
                index,
                kind: object.shape.kind(),
                message,
            })?;
        objects.push(Object { shape, material });
    }
    // Step 2: the instances, each mesh's structure built on its first use.
    let mut built: BTreeMap<&str, Arc<Blas>> = BTreeMap::new();
    for (index, instance) in scene.instances.iter().enumerate() {
        let name = instance.mesh.as_str();
        let blas = match built.get(name) {
            Some(blas) => blas.clone(),
            None => {
                let mesh = scene.meshes.get(name).ok_or_else(|| {
                    SceneError::Invalid {
                        file: file.to_string(),
                        line: instance.line,
                        column: 1,
                        field: format!("instances[{index}].mesh"),
                        message: format!("no mesh named {name:?}"),
                    }
                })?;
                let blas = Arc::new(Blas::new(mesh, accelerate));
                built.insert(name, blas.clone());
                blas
            }
        };
        let placed = MeshInstance::new(blas, instance.placement.to_world());
        objects.push(Object {
            shape: Arc::new(placed),
            material: instance.material,
        });
    }
    // Step 3: the rest of the world (materials, lights, camera) as every
    // chapter builds it, with these objects.
    let rest = Scene {
        objects: Vec::new(),
        instances: Vec::new(),
        ..scene.clone()
    };
    let world = World::from_scene(&rest, file, shape, Arc::new(BruteForce))?;
    Ok(World { objects, ..world })
}
// ANCHOR_END: world_with

/// The world of the scene file at `path` (see [`world`]).
pub fn load(path: &Path) -> Result<World, WorldError> {
    let scene = raystep_scene::load(path)?;
    world(&scene, &path.display().to_string())
}
