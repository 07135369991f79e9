//! A scene file's shapes as chapter 8's primitives (and chapter 2's plane),
//! searched by the brute-force loop.
use std::path::Path;
use std::sync::Arc;

use ch03::BruteForce;
use raystep_core::Shape;
use raystep_scene::{Scene, Shape as ShapeSpec};
use raystep_world::{World, WorldError};

use crate::{
    AxisBox, Ball, Blobby, Cylinder, Ellipsoid, Saddle, Torus, TorusSolver,
    Triangle, TriangleTest,
};

/// The surface of one shape of a scene file: any of the chapter's
/// primitives, or chapter 2's plane. An error says what is wrong with a
/// degenerate one (a polygon or triangle whose corners lie on a line).
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
    })
}

/// The world of `scene`, with chapter 8's primitives and the lecture's
/// brute-force loop. `file` names the scene in errors.
pub fn world(scene: &Scene, file: &str) -> Result<World, WorldError> {
    World::from_scene(scene, file, shape, Arc::new(BruteForce))
}

/// The world of the scene file at `path` (see [`world`]).
pub fn load(path: &Path) -> Result<World, WorldError> {
    let scene = raystep_scene::load(path)?;
    world(&scene, &path.display().to_string())
}
