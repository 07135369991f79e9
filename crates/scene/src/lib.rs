//! Scene files for chapters 3–10 of the raystep lecture: read, checked, and
//! handed over as plain data.
//!
//! A scene is a TOML file. [`load`] (or [`parse`], for a string) reads it
//! into a [`Scene`]: image size, [`CameraSpec`], ambient light, point
//! [`Light`]s, named [`Material`]s and [`Object`]s whose [`Shape`] is a
//! sphere, a plane or a polygon, one of chapter 8's primitives, or a
//! triangle mesh placed once ([`Shape::Mesh`]); and named meshes
//! ([`Scene::meshes`]) placed any number of times ([`Scene::instances`]).
//! This crate checks the data but knows no geometry: the chapters build
//! their own spheres, planes, polygons and triangles from it.
//!
//! Triangle meshes ([`Mesh`]) come from OBJ files ([`Mesh::load_obj`], or
//! a scene's `obj = "…"`) or are made in code ([`Mesh::icosphere`]). A
//! [`Placement`] puts one in the world.
//!
//! # The format
//!
//! A scene states only what it uses. Only `[camera]` with `look_from` and
//! `look_at` is required; every other field has the default noted below.
//! This example uses every field:
//!
#![doc = concat!("```toml\n", include_str!("example.toml"), "```")]
//!
//! * Numbers may be written as TOML integers or floats (`1` or `1.0`), but
//!   must be finite: TOML's `inf` and `nan` are rejected everywhere.
//! * A point or direction is `[x, y, z]`.
//! * A colour (`intensity`, `ka`, `kd`, `ks`, `kr`, `kt`) is one number for
//!   grey or `[r, g, b]`; no component may be negative (none is capped at 1).
//! * `ior` is a positive number or a name from [`REFRACTIVE_INDICES`].
//! * Each `[[objects]]` entry has exactly one shape key, `sphere`, `plane`
//!   or `polygon` (chapters 2–7), or one of chapter 8's `box`, `cylinder`,
//!   `ellipsoid`, `triangle`, `torus`, `saddle` and `blobby`, whose value
//!   is a table (inline as above, or as an `[objects.sphere]` sub-table),
//!   plus an optional `material`. We chose shape keys over
//!   `type = "sphere"` because a serde tagged enum cannot reject unknown
//!   fields reliably; optional keys can, and the "exactly one shape" rule
//!   gets an error worded for it. A chapter that has not taught a shape
//!   refuses it when it builds its world.
//! * A triangle mesh is an object's `mesh = { obj = "PATH", … }`, placed
//!   once, or a `[meshes.NAME]` table (`obj`, `smooth`) that
//!   `[[instances]]` entries place by its name, each with its own
//!   placement and `material`, sharing the mesh's triangles.
//! * A placement is `scale` (one number or `[x, y, z]`, no component 0,
//!   default 1), `rotate` (degrees about x, then y, then z, right-handed,
//!   default 0) and `translate` (default 0), applied in that order:
//!   [`Placement::to_world`] is T · Rz · Ry · Rx · S.
//! * `smooth` (default `true`) shades a mesh by its OBJ's vertex normals
//!   (`vn`) where it has them ([`Mesh::normals`]); `smooth = false`, and
//!   an OBJ without `vn`, shade it flat, by each triangle's normal.
//! * An `obj` path is found thus: an absolute path as it is; a relative
//!   one in the scene file's folder, else in each folder above it in
//!   turn, the first that has the file (for [`parse`], the folder of its
//!   `file_name`). So `shared/meshes/bunny.obj` finds the project's
//!   `../shared` from any scene in the workspace, with `shared/` beside
//!   the clone. Each file is read once, however many objects, names and
//!   instances use it ([`Scene::meshes`] and the objects share it through
//!   an [`Arc`]). Every field of the scene is checked before any file is
//!   read.
//! * The materials list always starts with the one named `"default"` (0.7
//!   grey, diffuse only, unless the file defines `[materials.default]`),
//!   followed by the file's other materials in the order they appear.
//!   Objects without `material` use it.
//! * Any key not listed here is an error, so typos do not pass silently.
//!
//! # Errors
//!
//! Every bad file gives one [`SceneError`] whose `Display` is one line:
//! `FILE:LINE:COLUMN: FIELD: what is wrong`, for example
//!
//! ```text
//! scenes/bad.toml:14:10: objects[2].sphere.radius: must be positive, got -1
//! ```
//!
//! `FIELD` is the dotted path to the value (array entries count from 0),
//! the line and column those of the value, or of its table if the value is
//! missing. Nothing in this crate panics on any input.
//!
//! A fault in a mesh file is reported at its `obj` value, with the OBJ's
//! own line where one is to blame:
//!
//! ```text
//! scenes/bunny.toml:5:7: meshes.bunny.obj: meshes/bad.obj:12: vertex index 9 is not one of the 8 before it: f 1 2 9
//! scenes/bunny.toml:9:16: objects[1].mesh.obj: cannot read meshes/x.obj (looked in /home/me/raystep/scenes and every folder above it): No such file or directory
//! ```
//!
//! ```
//! let error = raystep_scene::parse("[camera]\nlook_from = [0, 0, 5]\n", "a.toml").unwrap_err();
//! assert_eq!(error.to_string(), "a.toml:1:1: camera.look_at: required, but missing");
//! ```
#![deny(missing_docs)]

mod error;
mod format;
mod indices;
mod mesh;
mod obj_check;
mod placement;
mod raw;
mod scene_meshes;
mod shapes;

use std::collections::BTreeMap;
use std::ops::Range;
use std::path::Path;
use std::sync::Arc;

use raystep_core::{Camera, DVec3};
use serde::Deserialize;
use toml::Spanned;
use toml::de::DeTable;

use error::Context;
pub use error::SceneError;
use format::{format_number, format_vec};
pub use indices::{REFRACTIVE_INDICES, index_of_refraction};
pub use mesh::{Mesh, MeshError};
pub use placement::Placement;
use raw::{RawInstance, RawMaterial, RawObject, RawScene, Table};
use scene_meshes::{MeshFiles, MeshRequest, check_placed};

/// The largest image width or height a scene may ask for, in pixels.
pub const MAX_SIZE: u32 = 4096;
/// The image width when `[image]` does not give one.
pub const DEFAULT_WIDTH: u32 = 320;
/// The image height when `[image]` does not give one.
pub const DEFAULT_HEIGHT: u32 = 180;
/// The vertical field of view, in degrees, when `[camera]` does not give one.
pub const DEFAULT_VFOV: f64 = 40.0;
/// The ambient intensity `Ia` (grey) when `[ambient]` does not give one.
pub const DEFAULT_AMBIENT: f64 = 0.1;
/// The name of the material that objects without `material` use.
pub const DEFAULT_MATERIAL: &str = "default";

/// A checked scene: everything a chapter needs to render it.
#[derive(Clone, Debug, PartialEq)]
pub struct Scene {
    /// Image width in pixels, `1 ..= MAX_SIZE`.
    pub width: u32,
    /// Image height in pixels, `1 ..= MAX_SIZE`.
    pub height: u32,
    /// Where the camera is and where it looks.
    pub camera: CameraSpec,
    /// The ambient intensity `Ia`, each component `≥ 0`.
    pub ambient: DVec3,
    /// What a ray that hits nothing sees, each component `≥ 0` (default
    /// black).
    pub background: DVec3,
    /// The point lights, in file order.
    pub lights: Vec<Light>,
    /// The materials: `materials[0]` is always the one named `"default"`,
    /// the others follow in file order.
    pub materials: Vec<Material>,
    /// The objects, in file order.
    pub objects: Vec<Object>,
    /// The meshes of `[meshes.NAME]`, by name, each read once and shared
    /// by every instance that names it.
    pub meshes: BTreeMap<String, Arc<Mesh>>,
    /// The `[[instances]]` of those meshes, in file order.
    pub instances: Vec<Instance>,
}

impl Scene {
    /// The camera for this scene's image size.
    pub fn camera(&self) -> Camera {
        self.camera
            .camera(f64::from(self.width) / f64::from(self.height))
    }

    /// The material of `object`.
    pub fn material(&self, object: &Object) -> &Material {
        &self.materials[object.material]
    }
}

/// The `[camera]` table, checked: `look_from ≠ look_at`, `up` not parallel
/// to the view direction, `0 < vfov < 180`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CameraSpec {
    /// The eye.
    pub look_from: DVec3,
    /// The point in the centre of the picture.
    pub look_at: DVec3,
    /// Which way is up in the picture (not necessarily perpendicular to the
    /// view direction, nor a unit vector).
    pub up: DVec3,
    /// Vertical field of view in degrees.
    pub vfov: f64,
}

impl CameraSpec {
    /// The camera for a picture `aspect` (width / height) wide.
    pub fn camera(&self, aspect: f64) -> Camera {
        Camera::look_at(
            self.look_from,
            self.look_at,
            self.up,
            self.vfov,
            aspect,
        )
    }
}

/// A point light.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Light {
    /// Where it is.
    pub position: DVec3,
    /// Its intensity `Ip` per colour channel, each `≥ 0`.
    pub intensity: DVec3,
}

/// A named material: the Phong coefficients, plus reflection and refraction
/// for chapters 5 and 06. Every colour component is `≥ 0`.
#[derive(Clone, Debug, PartialEq)]
pub struct Material {
    /// Its name in the file (the key after `materials.`).
    pub name: String,
    /// Ambient reflectance `ka`.
    pub ka: DVec3,
    /// Diffuse reflectance `kd`.
    pub kd: DVec3,
    /// Specular reflectance `ks`.
    pub ks: DVec3,
    /// Phong exponent, `> 0`.
    pub p: f64,
    /// Reflected fraction `kr` (chapter 5).
    pub kr: DVec3,
    /// Transmitted fraction `kt` (chapter 6).
    pub kt: DVec3,
    /// Index of refraction, `> 0` (chapter 6).
    pub ior: f64,
    /// An optional checkerboard: every other cube of the pattern uses the
    /// checker's `ka` and `kd` instead of the material's.
    pub checker: Option<Checker>,
}

impl Material {
    /// `(ka, kd)` at `point`: the material's own, or the checker's on its
    /// odd cubes.
    pub fn ka_kd_at(&self, point: DVec3) -> (DVec3, DVec3) {
        match &self.checker {
            Some(checker) if checker.is_odd(point) => (checker.ka, checker.kd),
            _ => (self.ka, self.kd),
        }
    }
}

/// A 3D checkerboard of cubes `size` wide, aligned with the axes and
/// centred on the multiples of `size`: the pattern a plane shows is the
/// cubes' cross-section.
///
/// Centred, not cornered, on the lattice: a floor at y = −1 then cuts a
/// layer of cubes through the middle. Were the cube faces at the
/// multiples of `size`, such a floor would lie exactly on a face, and the
/// rounding of each hit point's y would pick the colour above or below it
/// at random, pixel by pixel.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Checker {
    /// The edge length of one cube, `> 0`.
    pub size: f64,
    /// Ambient reflectance on the odd cubes (default: its `kd`).
    pub ka: DVec3,
    /// Diffuse reflectance on the odd cubes (default 0.1).
    pub kd: DVec3,
}

impl Checker {
    /// Is `point` in an odd cube (the sum of its cube indices odd)?
    pub fn is_odd(&self, point: DVec3) -> bool {
        let cube = (point / self.size + 0.5).floor();
        (cube.x + cube.y + cube.z).rem_euclid(2.0) == 1.0
    }
}

impl Default for Material {
    /// The built-in `"default"` material: 0.7 grey, diffuse only
    /// (`ka = kd = 0.7`, `ks = kr = kt = 0`, `p = 32`, `ior = 1`).
    fn default() -> Material {
        Material {
            name: DEFAULT_MATERIAL.to_owned(),
            ka: DVec3::splat(0.7),
            kd: DVec3::splat(0.7),
            ks: DVec3::ZERO,
            p: 32.0,
            kr: DVec3::ZERO,
            kt: DVec3::ZERO,
            ior: 1.0,
            checker: None,
        }
    }
}

/// One `[[objects]]` entry.
#[derive(Clone, Debug, PartialEq)]
pub struct Object {
    /// Its shape.
    pub shape: Shape,
    /// Index of its material in [`Scene::materials`].
    pub material: usize,
    /// The 1-based line of the entry (its `[[objects]]` header), for
    /// errors found later.
    pub line: usize,
}

/// One `[[instances]]` entry: a mesh of [`Scene::meshes`] placed once
/// more, its triangles shared with every other instance of it (a tracer
/// takes each ray into the mesh's frame instead of copying the mesh).
#[derive(Clone, Debug, PartialEq)]
pub struct Instance {
    /// The name of its mesh, a key of [`Scene::meshes`].
    pub mesh: String,
    /// Where the mesh is put.
    pub placement: Placement,
    /// Index of its material in [`Scene::materials`].
    pub material: usize,
    /// The 1-based line of the entry (its `[[instances]]` header), for
    /// errors found later.
    pub line: usize,
}

/// An object's shape, its numbers checked (not its geometry).
#[derive(Clone, Debug, PartialEq)]
pub enum Shape {
    /// A sphere.
    Sphere {
        /// Its centre.
        center: DVec3,
        /// Its radius, `> 0`.
        radius: f64,
    },
    /// An infinite plane.
    Plane {
        /// A point on it.
        point: DVec3,
        /// Its normal, normalised to a unit vector.
        normal: DVec3,
    },
    /// A planar polygon. Only the count is checked: that the vertices lie in
    /// one plane and do not all lie on one line is the chapter's business.
    Polygon {
        /// Its corners in order around its edge, at least 3.
        vertices: Vec<DVec3>,
    },
    /// An axis-aligned box (chapter 8).
    Box {
        /// The corner with the smallest coordinates.
        min: DVec3,
        /// The opposite corner, greater than `min` on every axis.
        max: DVec3,
    },
    /// A cylinder closed by two discs (chapter 8).
    Cylinder {
        /// The centre of one cap.
        base: DVec3,
        /// The centre of the other cap, `≠ base`.
        top: DVec3,
        /// Its radius, `> 0`.
        radius: f64,
    },
    /// An axis-aligned ellipsoid (chapter 8).
    Ellipsoid {
        /// Its centre.
        center: DVec3,
        /// Its semi-axes along x, y and z, each `> 0`.
        radii: DVec3,
    },
    /// A triangle, hit by one of chapter 8's three tests.
    Triangle {
        /// Its corners.
        vertices: [DVec3; 3],
        /// Which ray–triangle test hits it.
        test: TriangleTest,
    },
    /// A ring torus (chapter 8): a circle of radius `minor` swept around
    /// a circle of radius `major`.
    Torus {
        /// Its centre.
        center: DVec3,
        /// The axis it is swept around, a unit vector (default y).
        axis: DVec3,
        /// The sweep's radius R, `> minor`.
        major: f64,
        /// The tube's radius r, `0 < r < R`.
        minor: f64,
        /// How its quartic is solved.
        solver: TorusSolver,
    },
    /// The monkey saddle y = (x³ − 3xz²)/s², clipped to |x|, |z| ≤ s
    /// (chapter 8's cubic surface).
    Saddle {
        /// Its centre.
        center: DVec3,
        /// Its half width s, `> 0`.
        size: f64,
    },
    /// A blobby object (chapter 8): where the summed fields of its balls
    /// reach `threshold`.
    Blobby {
        /// The balls, at least one.
        balls: Vec<Ball>,
        /// The iso-value, `0 < threshold < Σ strength`.
        threshold: f64,
    },
    /// A triangle mesh from an OBJ file, placed once: a chapter flattens
    /// it into its triangles in the world
    /// (`placement.to_world()` applied to each vertex).
    Mesh {
        /// The mesh in its own frame, as the file holds it (shared with
        /// every other object and instance that reads the same file).
        mesh: Arc<Mesh>,
        /// Where it is put.
        placement: Placement,
    },
}

/// One ball of a [`Shape::Blobby`]: a field `strength·f(r / radius)` that
/// falls from `strength` at its centre to 0 at `radius`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ball {
    /// Its centre.
    pub center: DVec3,
    /// Where its field ends, `> 0`.
    pub radius: f64,
    /// Its field at the centre, `> 0` (default 1).
    pub strength: f64,
}

/// Chapter 8's three ray–triangle tests, by their names in a scene file.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TriangleTest {
    /// `"plane-inside"`: chapter 2's plane hit and inside test.
    PlaneInside,
    /// `"moller-trumbore"`: Möller and Trumbore (1997).
    MollerTrumbore,
    /// `"watertight"` (the default): Woop, Benthin and Wald (2013).
    Watertight,
}

/// How a torus's quartic is solved, by its name in a scene file.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TorusSolver {
    /// `"closed-form"`: Ferrari's formula.
    ClosedForm,
    /// `"bracketed"` (the default): roots bracketed inside the bound.
    Bracketed,
}

impl Shape {
    /// The shape's key in the file: `sphere`, `plane`, `polygon`, `box`, …
    pub fn kind(&self) -> &'static str {
        match self {
            Shape::Sphere { .. } => "sphere",
            Shape::Plane { .. } => "plane",
            Shape::Polygon { .. } => "polygon",
            Shape::Box { .. } => "box",
            Shape::Cylinder { .. } => "cylinder",
            Shape::Ellipsoid { .. } => "ellipsoid",
            Shape::Triangle { .. } => "triangle",
            Shape::Torus { .. } => "torus",
            Shape::Saddle { .. } => "saddle",
            Shape::Blobby { .. } => "blobby",
            Shape::Mesh { .. } => "mesh",
        }
    }

    /// The same shape scaled by `s > 0` about the origin (its points,
    /// sizes and distances times `s`; its directions unchanged).
    pub fn scale(&mut self, s: f64) {
        match self {
            Shape::Sphere { center, radius } => {
                *center *= s;
                *radius *= s;
            }
            Shape::Plane { point, .. } => *point *= s,
            Shape::Polygon { vertices } => {
                vertices.iter_mut().for_each(|v| *v *= s)
            }
            Shape::Box { min, max } => {
                *min *= s;
                *max *= s;
            }
            Shape::Cylinder { base, top, radius } => {
                *base *= s;
                *top *= s;
                *radius *= s;
            }
            Shape::Ellipsoid { center, radii } => {
                *center *= s;
                *radii *= s;
            }
            Shape::Triangle { vertices, .. } => {
                vertices.iter_mut().for_each(|v| *v *= s)
            }
            Shape::Torus {
                center,
                major,
                minor,
                ..
            } => {
                *center *= s;
                *major *= s;
                *minor *= s;
            }
            Shape::Saddle { center, size } => {
                *center *= s;
                *size *= s;
            }
            Shape::Blobby { balls, .. } => {
                for ball in balls {
                    ball.center *= s;
                    ball.radius *= s;
                }
            }
            // s·(T·R·S·v) = (s·T)·R·(s·S)·v: a uniform scale commutes
            // with the rotation
            Shape::Mesh { placement, .. } => {
                placement.scale *= s;
                placement.translate *= s;
            }
        }
    }
}

/// Reads and checks the scene file at `path`. Errors name the file as
/// `path` shows it.
pub fn load(path: &Path) -> Result<Scene, SceneError> {
    let bytes = std::fs::read(path).map_err(|source| SceneError::Read {
        path: path.to_owned(),
        source,
    })?;
    let file = path.display().to_string();
    // Text that is not UTF-8 is named at its first bad byte.
    let source = String::from_utf8(bytes).map_err(|e| {
        let valid = &e.as_bytes()[..e.utf8_error().valid_up_to()];
        let line = 1 + valid.iter().filter(|&&b| b == b'\n').count();
        let start =
            valid.iter().rposition(|&b| b == b'\n').map_or(0, |i| i + 1);
        let column =
            1 + String::from_utf8_lossy(&valid[start..]).chars().count();
        SceneError::Syntax {
            file: file.clone(),
            line,
            column,
            message: "not UTF-8 text".to_string(),
        }
    })?;
    parse(&source, &file)
}

/// Reads and checks a scene from `source`. `file_name` names it in error
/// messages, and its folder is the scene's folder, where the search for
/// its mesh files starts (a bare name: the current folder).
pub fn parse(source: &str, file_name: &str) -> Result<Scene, SceneError> {
    let document = DeTable::parse(source).map_err(|e| {
        let span = e.span().unwrap_or(0..0);
        let (line, column) = error::line_column(source, span.start);
        let mut message = e.message().to_owned();
        if message == "duplicate key"
            && let Some(key) = source.get(span)
        {
            message = format!("duplicate key `{key}`");
        }
        SceneError::Syntax {
            file: file_name.to_owned(),
            line,
            column,
            message,
        }
    })?;
    let context = Context::new(source, file_name, &document);
    let raw = RawScene::deserialize(toml::Deserializer::from(document))
        .map_err(|e| context.serde_error(&e))?;
    let folder = Path::new(file_name).parent().unwrap_or(Path::new(""));
    build(raw, &context, folder)
}

/// The checks that compare a field with a limit or with other fields,
/// then the mesh files (found from `folder`) read.
fn build(
    raw: RawScene, cx: &Context, folder: &Path,
) -> Result<Scene, SceneError> {
    let size = |value: Option<Spanned<i64>>, default: u32| match value {
        None => Ok(default),
        Some(v) => match u32::try_from(*v.get_ref()) {
            Ok(n) if (1..=MAX_SIZE).contains(&n) => Ok(n),
            _ => Err(cx.error(
                v.span(),
                format!(
                    "must be between 1 and {MAX_SIZE} (MAX_SIZE), got {}",
                    v.get_ref()
                ),
            )),
        },
    };
    let (width, height) = match raw.image {
        None => (DEFAULT_WIDTH, DEFAULT_HEIGHT),
        Some(Table(image)) => (
            size(image.width, DEFAULT_WIDTH)?,
            size(image.height, DEFAULT_HEIGHT)?,
        ),
    };

    let camera = camera(raw.camera, cx)?;
    let ambient = raw
        .ambient
        .and_then(|Table(a)| a.intensity)
        .map_or(DVec3::splat(DEFAULT_AMBIENT), |c| c.0);
    let background = raw
        .background
        .and_then(|Table(b)| b.intensity)
        .map_or(DVec3::ZERO, |c| c.0);
    let lights = raw
        .lights
        .into_iter()
        .map(|Table(light)| Light {
            position: light.position.0,
            intensity: light.intensity.map_or(DVec3::ONE, |c| c.0),
        })
        .collect();

    let mut materials = vec![Material::default()];
    let mut defined: Vec<_> = raw.materials.into_iter().collect();
    defined.sort_by_key(|(_, m)| m.span().start);
    for (name, m) in defined {
        let material = material(name, m, cx)?;
        if material.name == DEFAULT_MATERIAL {
            materials[0] = material;
        } else {
            materials.push(material);
        }
    }

    // Every field first; then the mesh files, each read once.
    let mut named = Vec::new();
    for (name, m) in &raw.meshes {
        let Table(m) = m.get_ref();
        let request = MeshRequest::new(m.obj.clone(), m.smooth, cx)?;
        named.push((m.obj.span().start, name.clone(), request));
    }
    named.sort_by_key(|(start, ..)| *start);
    let pending: Vec<(shapes::ObjectShape, usize, usize)> = raw
        .objects
        .into_iter()
        .map(|o| object(o, &materials, cx))
        .collect::<Result<_, _>>()?;
    let placed: Vec<(Instance, Range<usize>)> = raw
        .instances
        .into_iter()
        .map(|i| instance(i, &raw.meshes, &materials, cx))
        .collect::<Result<_, _>>()?;

    let mut files = MeshFiles::new(folder);
    let mut meshes = BTreeMap::new();
    for (_, name, request) in named {
        meshes.insert(name, files.load(&request, cx)?);
    }
    let mut objects = Vec::with_capacity(pending.len());
    for (shape, material, line) in pending {
        let shape = match shape {
            shapes::ObjectShape::Ready(shape) => shape,
            shapes::ObjectShape::Mesh {
                request,
                placement,
                span,
            } => {
                let mesh = files.load(&request, cx)?;
                check_placed(&mesh, &placement, span, cx)?;
                Shape::Mesh { mesh, placement }
            }
        };
        objects.push(Object {
            shape,
            material,
            line,
        });
    }
    let mut instances = Vec::with_capacity(placed.len());
    for (instance, span) in placed {
        check_placed(&meshes[&instance.mesh], &instance.placement, span, cx)?;
        instances.push(instance);
    }

    Ok(Scene {
        width,
        height,
        camera,
        ambient,
        background,
        lights,
        materials,
        objects,
        meshes,
        instances,
    })
}

fn camera(
    raw: Spanned<Table<raw::RawCamera>>, cx: &Context,
) -> Result<CameraSpec, SceneError> {
    let table_span = raw.span();
    let Table(c) = raw.into_inner();
    let look_from = c.look_from.0;
    let look_at = c.look_at.get_ref().0;
    let vfov = match c.vfov {
        None => DEFAULT_VFOV,
        Some(v) if v.get_ref().0 > 0.0 && v.get_ref().0 < 180.0 => {
            v.get_ref().0
        }
        Some(v) => {
            return Err(cx.error(
                v.span(),
                format!(
                    "must be between 0 and 180 degrees (both excluded), got {}",
                    format_number(v.get_ref().0)
                ),
            ));
        }
    };
    // These checks mirror what `Camera::look_at` computes, so that the
    // camera a chapter builds from a checked scene has unit vectors.
    if look_at == look_from {
        return Err(cx.error(
            c.look_at.span(),
            format!(
                "must differ from look_from, both are {}",
                format_vec(look_from)
            ),
        ));
    }
    let view = look_at - look_from;
    let forward = view.normalize();
    if !forward.is_normalized() {
        return Err(cx.error(
            c.look_at.span(),
            format!(
                "too close to or too far from look_from to give a view direction \
                 (look_at - look_from = {})",
                format_vec(view)
            ),
        ));
    }
    let up = match &c.up {
        Some(up) => up.get_ref().0,
        None => DVec3::Y,
    };
    let problem = if up == DVec3::ZERO {
        Some("must not be zero-length".to_owned())
    } else if !up.normalize().is_normalized() {
        Some("is too short or too long to give a direction".to_owned())
    } else if forward.cross(up.normalize()).length() < 1e-9 {
        Some(format!(
            "must not be parallel to the view direction (look_at - look_from = {})",
            format_vec(view)
        ))
    } else if !forward.cross(up).normalize().is_normalized() {
        Some("is too short or too long to give a direction".to_owned())
    } else {
        None
    };
    if let Some(problem) = problem {
        return Err(match &c.up {
            Some(up) => cx.error(
                up.span(),
                format!("{problem}, got {}", format_vec(up.get_ref().0)),
            ),
            None => cx.error_in(
                table_span.clone(),
                cx.child(&table_span, "up"),
                format!(
                    "the default [0, 1, 0] is parallel to the view direction \
                     (look_at - look_from = {}); give another `up`",
                    format_vec(view)
                ),
            ),
        });
    }
    Ok(CameraSpec {
        look_from,
        look_at,
        up,
        vfov,
    })
}

fn material(
    name: String, raw: Spanned<Table<RawMaterial>>, cx: &Context,
) -> Result<Material, SceneError> {
    let Table(m) = raw.into_inner();
    let kd = m.kd.map_or(DVec3::splat(0.7), |c| c.0);
    let p = match &m.p {
        None => 32.0,
        Some(p) => shapes::positive(p, cx)?,
    };
    let checker = match m.checker {
        None => None,
        Some(Table(c)) => {
            let size = shapes::positive(&c.size, cx)?;
            let kd = c.kd.map_or(DVec3::splat(0.1), |c| c.0);
            Some(Checker {
                size,
                ka: c.ka.map_or(kd, |c| c.0),
                kd,
            })
        }
    };
    Ok(Material {
        name,
        ka: m.ka.map_or(kd, |c| c.0),
        kd,
        ks: m.ks.map_or(DVec3::ZERO, |c| c.0),
        p,
        kr: m.kr.map_or(DVec3::ZERO, |c| c.0),
        kt: m.kt.map_or(DVec3::ZERO, |c| c.0),
        ior: m.ior.map_or(1.0, |i| i.0),
        checker,
    })
}

/// An object's shape (a mesh not yet read), material and line.
fn object(
    raw: Spanned<Table<RawObject>>, materials: &[Material], cx: &Context,
) -> Result<(shapes::ObjectShape, usize, usize), SceneError> {
    let span = raw.span();
    let Table(mut o) = raw.into_inner();
    let line = cx.line_column(span.start).0;

    let material_name = o.material.take();
    let shape = shapes::shape(o, span, cx)?;
    let material = material_index(material_name.as_ref(), materials, cx)?;
    Ok((shape, material, line))
}

/// An `[[instances]]` entry, checked, and its table's span.
fn instance(
    raw: Spanned<Table<RawInstance>>,
    meshes: &BTreeMap<String, Spanned<Table<raw::RawMeshFile>>>,
    materials: &[Material], cx: &Context,
) -> Result<(Instance, Range<usize>), SceneError> {
    let span = raw.span();
    let Table(i) = raw.into_inner();
    let line = cx.line_column(span.start).0;
    let mesh = i.mesh.get_ref();
    if !meshes.contains_key(mesh) {
        let names: Vec<&str> = meshes.keys().map(String::as_str).collect();
        let there = match names.is_empty() {
            true => "none".to_owned(),
            false => names.join(", "),
        };
        return Err(cx.error(
            i.mesh.span(),
            format!("no mesh {mesh:?} in [meshes]; there are {there}"),
        ));
    }
    let placement =
        scene_meshes::placement(i.scale, i.rotate, i.translate, cx)?;
    let material = material_index(i.material.as_ref(), materials, cx)?;
    let instance = Instance {
        mesh: i.mesh.into_inner(),
        placement,
        material,
        line,
    };
    Ok((instance, span))
}

/// The index of the material `name` (None: the default, 0).
fn material_index(
    name: Option<&Spanned<String>>, materials: &[Material], cx: &Context,
) -> Result<usize, SceneError> {
    let Some(name) = name else {
        return Ok(0);
    };
    materials
        .iter()
        .position(|m| m.name == *name.get_ref())
        .ok_or_else(|| {
            let defined: Vec<&str> =
                materials.iter().map(|m| m.name.as_str()).collect();
            cx.error(
                name.span(),
                format!(
                    "unknown material {:?}, defined: {}",
                    name.get_ref(),
                    defined.join(", ")
                ),
            )
        })
}
