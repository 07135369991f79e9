//! Triangle meshes: what a rasterizer draws, and (from chapter 8 on) what
//! a ray tracer speeds up. Spheres become subdivided icosahedra; the
//! Stanford bunny comes from an OBJ file.
use std::collections::HashMap;
use std::path::Path;

use raystep_core::{Aabb, DVec3};
use thiserror::Error;

use crate::obj_check::{ObjProblem, check_obj};

/// Triangles sharing vertices: each triangle is three indices into
/// `vertices`, counter-clockwise seen from outside.
#[derive(Clone, Debug, PartialEq)]
pub struct Mesh {
    /// The corners.
    pub vertices: Vec<DVec3>,
    /// Three indices into `vertices` per triangle.
    pub triangles: Vec<[usize; 3]>,
    /// The unit normal at each vertex (`normals[i]` at `vertices[i]`),
    /// for smooth shading: from an OBJ's `vn`, normalised. Empty when the
    /// mesh has none (an OBJ without `vn`, a scene's `smooth = false`, an
    /// icosphere): then it is shaded flat, by each triangle's normal.
    pub normals: Vec<DVec3>,
}

/// Why a mesh file cannot be read.
#[derive(Debug, Error)]
pub enum MeshError {
    /// The file cannot be read or is not valid OBJ.
    #[error("{file}: {message}")]
    Obj {
        /// The file as given.
        file: String,
        /// What the OBJ reader said.
        message: String,
    },
    /// The file holds no triangle.
    #[error("{file}: no faces")]
    Empty {
        /// The file as given.
        file: String,
    },
}

impl Mesh {
    /// The unit sphere as an icosahedron whose faces are split into four,
    /// `subdivisions` times: 20·4ⁿ triangles, every vertex on the sphere.
    pub fn icosphere(subdivisions: u32) -> Mesh {
        // the icosahedron: three golden rectangles
        let g = (1.0 + 5f64.sqrt()) / 2.0;
        let corners = [
            (-1.0, g, 0.0),
            (1.0, g, 0.0),
            (-1.0, -g, 0.0),
            (1.0, -g, 0.0),
            (0.0, -1.0, g),
            (0.0, 1.0, g),
            (0.0, -1.0, -g),
            (0.0, 1.0, -g),
            (g, 0.0, -1.0),
            (g, 0.0, 1.0),
            (-g, 0.0, -1.0),
            (-g, 0.0, 1.0),
        ];
        let vertices = corners
            .iter()
            .map(|&(x, y, z)| DVec3::new(x, y, z).normalize())
            .collect();
        let triangles = vec![
            [0, 11, 5],
            [0, 5, 1],
            [0, 1, 7],
            [0, 7, 10],
            [0, 10, 11],
            [1, 5, 9],
            [5, 11, 4],
            [11, 10, 2],
            [10, 7, 6],
            [7, 1, 8],
            [3, 9, 4],
            [3, 4, 2],
            [3, 2, 6],
            [3, 6, 8],
            [3, 8, 9],
            [4, 9, 5],
            [2, 4, 11],
            [6, 2, 10],
            [8, 6, 7],
            [9, 8, 1],
        ];
        let mut mesh = Mesh {
            vertices,
            triangles,
            normals: Vec::new(),
        };
        for _ in 0..subdivisions {
            mesh = mesh.subdivided();
        }
        mesh
    }

    /// Every triangle split into four at its edges' midpoints, pushed out
    /// onto the unit sphere. A midpoint is made once per edge, so the two
    /// triangles of an edge share it exactly.
    fn subdivided(&self) -> Mesh {
        let mut vertices = self.vertices.clone();
        let mut midpoints: HashMap<(usize, usize), usize> = HashMap::new();
        let mut midpoint = |a: usize, b: usize, vertices: &mut Vec<DVec3>| {
            *midpoints.entry((a.min(b), a.max(b))).or_insert_with(|| {
                vertices.push(((vertices[a] + vertices[b]) / 2.0).normalize());
                vertices.len() - 1
            })
        };
        let mut triangles = Vec::with_capacity(self.triangles.len() * 4);
        for &[a, b, c] in &self.triangles {
            let ab = midpoint(a, b, &mut vertices);
            let bc = midpoint(b, c, &mut vertices);
            let ca = midpoint(c, a, &mut vertices);
            triangles.extend([
                [a, ab, ca],
                [b, bc, ab],
                [c, ca, bc],
                [ab, bc, ca],
            ]);
        }
        Mesh {
            vertices,
            triangles,
            normals: Vec::new(),
        }
    }

    /// Reads the triangles of an OBJ file (polygons are split into fans),
    /// and its vertex normals (`vn`) where it has them.
    pub fn load_obj(path: &Path) -> Result<Mesh, MeshError> {
        let file = path.display().to_string();
        let bytes = std::fs::read(path).map_err(|e| MeshError::Obj {
            file: file.clone(),
            message: e.to_string(),
        })?;
        Mesh::from_obj(bytes).map_err(|fault| match fault {
            ObjFault::Empty => MeshError::Empty { file },
            ObjFault::Line(problem) => MeshError::Obj {
                file,
                message: problem.to_string(),
            },
            ObjFault::File(message) => MeshError::Obj { file, message },
        })
    }

    /// The mesh of an OBJ file's `bytes` ([`Mesh::load_obj`] without the
    /// file: a scene names the file its own way).
    pub(crate) fn from_obj(bytes: Vec<u8>) -> Result<Mesh, ObjFault> {
        let options = tobj::LoadOptions {
            triangulate: true,
            // one index per corner: a vertex used with two normals
            // becomes two vertices, so `normals[i]` belongs to
            // `vertices[i]`
            single_index: true,
            ..tobj::LoadOptions::default()
        };
        // Step 1: the text, every line this reader uses checked first
        // (so that each error names its line).
        let text = String::from_utf8(bytes).map_err(|e| {
            let valid = &e.as_bytes()[..e.utf8_error().valid_up_to()];
            let line = 1 + valid.iter().filter(|&&b| b == b'\n').count();
            ObjFault::Line(ObjProblem {
                line,
                what: "not UTF-8 text".to_owned(),
            })
        })?;
        if let Some(problem) = check_obj(&text) {
            return Err(ObjFault::Line(problem));
        }
        // Step 2: the OBJ reader (no materials: the lecture's meshes
        // take theirs from the scene).
        let no_materials = |_: &Path| Err(tobj::LoadError::OpenFileFailed);
        let (models, _) = tobj::load_obj_buf(
            &mut std::io::BufReader::new(text.as_bytes()),
            &options,
            no_materials,
        )
        .map_err(|e| explain(&text, &e))?;
        // Step 3: the models' vertices, normals and triangles in one
        // mesh, each model's indices moved past the vertices before it.
        let mut mesh = Mesh {
            vertices: Vec::new(),
            triangles: Vec::new(),
            normals: Vec::new(),
        };
        let vec3 = |p: &[f32]| {
            DVec3::new(f64::from(p[0]), f64::from(p[1]), f64::from(p[2]))
        };
        for model in models {
            let first = mesh.vertices.len();
            let m = model.mesh;
            mesh.vertices.extend(m.positions.chunks_exact(3).map(vec3));
            mesh.normals.extend(m.normals.chunks_exact(3).map(vec3));
            mesh.triangles.extend(m.indices.chunks_exact(3).map(|t| {
                [
                    first + t[0] as usize,
                    first + t[1] as usize,
                    first + t[2] as usize,
                ]
            }));
        }
        if mesh.triangles.is_empty() {
            return Err(ObjFault::Empty);
        }
        if let Some(k) = mesh.vertices.iter().position(|v| !v.is_finite()) {
            return Err(ObjFault::File(format!(
                "vertex {} is not finite",
                k + 1
            )));
        }
        // Step 4: a unit normal per vertex, or none at all (check_obj
        // refused a face that uses a zero normal, and corners with and
        // without normals in one file).
        if !mesh.normals.is_empty() {
            if mesh.normals.len() != mesh.vertices.len() {
                return Err(ObjFault::File(format!(
                    "{} normals for {} vertices: normals on some faces only",
                    mesh.normals.len(),
                    mesh.vertices.len()
                )));
            }
            for (k, n) in mesh.normals.iter_mut().enumerate() {
                *n = n.try_normalize().ok_or_else(|| {
                    ObjFault::File(format!(
                        "the normal at vertex {} has no direction",
                        k + 1
                    ))
                })?;
            }
        }
        Ok(mesh)
    }

    /// The corners of triangle `k`.
    pub fn triangle(&self, k: usize) -> [DVec3; 3] {
        self.triangles[k].map(|i| self.vertices[i])
    }

    /// The box around every vertex (so around every triangle).
    pub fn bounds(&self) -> Aabb {
        Aabb::around(self.vertices.iter().copied())
    }

    /// The mesh moved and scaled so that its bounding box is centred on
    /// `centre` and its largest side is `size`.
    pub fn fitted(&self, centre: DVec3, size: f64) -> Mesh {
        let Aabb { min: lo, max: hi } = self.bounds();
        let scale = size / (hi - lo).max_element();
        let middle = (lo + hi) / 2.0;
        Mesh {
            vertices: self
                .vertices
                .iter()
                .map(|&v| centre + (v - middle) * scale)
                .collect(),
            triangles: self.triangles.clone(),
            // (a negative size turns the mesh inside out: its normals too)
            normals: self.normals.iter().map(|&n| n * scale.signum()).collect(),
        }
    }
}

/// Why an OBJ file's text is not a mesh.
#[derive(Clone, Debug, PartialEq)]
pub(crate) enum ObjFault {
    /// A line is to blame.
    Line(ObjProblem),
    /// No line is to blame; what is wrong.
    File(String),
    /// The file holds no triangle.
    Empty,
}

/// What the OBJ reader's error means for the file's `text`: the first
/// line that does not parse (the reader itself names no line). After
/// [`check_obj`] this is rare.
fn explain(text: &str, error: &tobj::LoadError) -> ObjFault {
    let mut vertices = 0usize;
    for (number, line) in text.lines().enumerate() {
        let mut words = line.split_whitespace();
        let bad = match words.next() {
            Some("v") => {
                vertices += 1;
                words.take(3).filter(|w| w.parse::<f32>().is_ok()).count() < 3
            }
            Some("vt" | "vn") => words.any(|w| w.parse::<f32>().is_err()),
            Some("f") => words.any(|w| {
                let index = w.split('/').next().unwrap_or("");
                match index.parse::<i64>() {
                    Ok(i) => i == 0 || i.unsigned_abs() as usize > vertices,
                    Err(_) => true,
                }
            }),
            _ => false,
        };
        if bad {
            return ObjFault::Line(ObjProblem {
                line: number + 1,
                what: format!("{error}: {}", line.trim()),
            });
        }
    }
    ObjFault::File(format!("{error} (the OBJ reader names no line)"))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_icosphere_has_20_times_4_to_the_n_triangles_on_the_sphere() {
        for n in 0..4 {
            let mesh = Mesh::icosphere(n);
            assert_eq!(mesh.triangles.len(), 20 * 4usize.pow(n));
            // Euler: V − E + F = 2 with E = 3F/2
            assert_eq!(mesh.vertices.len(), 2 + mesh.triangles.len() / 2);
            assert!(
                mesh.vertices
                    .iter()
                    .all(|v| (v.length() - 1.0).abs() < 1e-12)
            );
            // counter-clockwise from outside: every normal points away
            for k in 0..mesh.triangles.len() {
                let [a, b, c] = mesh.triangle(k);
                assert!(
                    (b - a).cross(c - a).dot(a + b + c) > 0.0,
                    "triangle {k}"
                );
            }
        }
    }

    #[test]
    fn fitting_centres_and_scales_the_bounding_box() {
        let mesh = Mesh::icosphere(1).fitted(DVec3::new(1.0, 2.0, 3.0), 0.5);
        let lo = mesh.vertices.iter().fold(DVec3::MAX, |a, &v| a.min(v));
        let hi = mesh.vertices.iter().fold(DVec3::MIN, |a, &v| a.max(v));
        assert_eq!(mesh.bounds(), Aabb { min: lo, max: hi });
        assert!(((lo + hi) / 2.0 - DVec3::new(1.0, 2.0, 3.0)).length() < 1e-12);
        assert!(((hi - lo).max_element() - 0.5).abs() < 1e-12);
    }

    #[test]
    fn a_missing_obj_file_is_named() {
        let error = Mesh::load_obj(Path::new("no/such/mesh.obj")).unwrap_err();
        assert!(
            error.to_string().starts_with("no/such/mesh.obj: "),
            "{error}"
        );
    }
}
