use crate::Sphere;
use ch02::{Plane, Polygon, PolygonError, intersect_plane};
use raystep_core::{Camera, DVec3, Hit, Interval, Ray};
use raystep_scene::{Light, Material, Scene, Shape as ShapeSpec};
use thiserror::Error;

/// A surface the tracer can hit.
#[derive(Clone, Debug, PartialEq)]
pub enum Shape {
    /// Chapter 03's sphere.
    Sphere(Sphere),
    /// Chapter 01's plane, hit as in chapter 02.
    Plane(Plane),
    /// Chapter 02's polygon.
    Polygon(Polygon),
}

impl Shape {
    /// The first hit of `ray` with the shape within `interval`.
    pub fn intersect(&self, ray: &Ray, interval: Interval) -> Option<Hit> {
        match self {
            Shape::Sphere(s) => s.intersect(ray, interval),
            Shape::Plane(p) => intersect_plane(p, ray, interval),
            Shape::Polygon(p) => p.intersect(ray, interval),
        }
    }
}

/// A shape and the index of its material in [`World::materials`].
#[derive(Clone, Debug, PartialEq)]
pub struct Object {
    /// What it looks like.
    pub shape: Shape,
    /// Its material, an index into [`World::materials`].
    pub material: usize,
}

/// Why a scene cannot be built into a world.
#[derive(Debug, Error)]
pub enum WorldError {
    /// The scene file cannot be read or is not a valid scene.
    #[error(transparent)]
    Scene(#[from] raystep_scene::SceneError),
    /// A polygon of the scene file is degenerate.
    #[error("{file}:{line}: objects[{index}].polygon: {source}")]
    Polygon {
        /// The scene file.
        file: String,
        /// The line of the object in it.
        line: usize,
        /// The object's index.
        index: usize,
        /// What is wrong.
        source: PolygonError,
    },
}

/// Everything a render needs: the objects, their materials, the lights and
/// the camera.
#[derive(Clone, Debug, PartialEq)]
pub struct World {
    /// The objects, in scene-file order.
    pub objects: Vec<Object>,
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
    /// Reads the scene file at `path` and builds its world.
    pub fn load(path: &std::path::Path) -> Result<World, WorldError> {
        let scene = raystep_scene::load(path)?;
        World::from_scene(&scene, &path.display().to_string())
    }

    /// Builds the geometry a scene file describes. `file` names the file in
    /// errors.
    pub fn from_scene(scene: &Scene, file: &str) -> Result<World, WorldError> {
        let mut objects = Vec::with_capacity(scene.objects.len());
        for (index, object) in scene.objects.iter().enumerate() {
            let shape = match &object.shape {
                ShapeSpec::Sphere { center, radius } => {
                    Shape::Sphere(Sphere::new(*center, *radius))
                }
                ShapeSpec::Plane { point, normal } => Shape::Plane(Plane {
                    normal: *normal,
                    d: -normal.dot(*point),
                }),
                ShapeSpec::Polygon { vertices } => {
                    Shape::Polygon(Polygon::new(vertices.clone()).map_err(|source| {
                        WorldError::Polygon {
                            file: file.to_string(),
                            line: object.line,
                            index,
                            source,
                        }
                    })?)
                }
            };
            objects.push(Object {
                shape,
                material: object.material,
            });
        }
        let aspect = f64::from(scene.width) / f64::from(scene.height);
        Ok(World {
            objects,
            materials: scene.materials.clone(),
            lights: scene.lights.clone(),
            ambient: scene.ambient,
            background: scene.background,
            camera: scene.camera.camera(aspect),
            width: scene.width,
            height: scene.height,
        })
    }

    // ANCHOR: closest_hit
    /// The lecture's loop over objects: the closest hit of `ray` within
    /// `interval`, and the object hit.
    pub fn closest_hit(&self, ray: &Ray, interval: Interval) -> Option<(Hit, &Object)> {
        let (hit, index) = self.closest_index(ray, interval)?;
        Some((hit, &self.objects[index]))
    }

    /// The same loop, naming the object hit by its index in `objects`.
    pub fn closest_index(&self, ray: &Ray, interval: Interval) -> Option<(Hit, usize)> {
        let mut closest = None;
        let mut interval = interval;
        for (index, object) in self.objects.iter().enumerate() {
            if let Some(hit) = object.shape.intersect(ray, interval) {
                interval = interval.with_max(hit.t); // only closer hits from now on
                closest = Some((hit, index));
            }
        }
        closest
    }
    // ANCHOR_END: closest_hit
}
