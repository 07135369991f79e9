//! A scene's triangle meshes: `[meshes.NAME]`, an object's `mesh = { … }`
//! and the placements of `[[instances]]`. Each OBJ file is found by the
//! path rule (the scene's folder, then each folder above it), read once
//! however often it is named, and its faults are named with the OBJ's own
//! line.
use std::collections::HashMap;
use std::fs;
use std::io;
use std::ops::Range;
use std::path::{Path, PathBuf};
use std::sync::Arc;

use raystep_core::DVec3;
use toml::Spanned;

use crate::error::Context;
use crate::format::{format_number, format_vec};
use crate::mesh::ObjFault;
use crate::raw::{Scale, Vec3};
use crate::{Mesh, Placement, SceneError};

/// An OBJ file a scene names (`obj = "…"`, `smooth = …`), checked but
/// not yet read: every field of the scene is checked before any file is
/// read, so a typo is reported at once, not after a large mesh loads.
pub(crate) struct MeshRequest {
    obj: Spanned<String>,
    smooth: bool,
}

impl MeshRequest {
    /// The request for the file `obj`, if it names one; `smooth`
    /// defaults to true.
    pub(crate) fn new(
        obj: Spanned<String>, smooth: Option<bool>, cx: &Context,
    ) -> Result<MeshRequest, SceneError> {
        if obj.get_ref().is_empty() {
            return Err(cx.error(obj.span(), "must name an OBJ file, got \"\""));
        }
        Ok(MeshRequest {
            obj,
            smooth: smooth.unwrap_or(true),
        })
    }
}

/// `scale`, `rotate` and `translate`, each with its default; no scale
/// component may be 0 (the mesh would lose a dimension).
pub(crate) fn placement(
    scale: Option<Spanned<Scale>>, rotate: Option<Vec3>,
    translate: Option<Vec3>, cx: &Context,
) -> Result<Placement, SceneError> {
    let scale = match scale {
        None => DVec3::ONE,
        Some(s) => {
            let Scale { value, uniform } = *s.get_ref();
            if value.cmpeq(DVec3::ZERO).any() {
                let got = match uniform {
                    true => format_number(value.x),
                    false => format_vec(value),
                };
                return Err(
                    cx.error(s.span(), format!("must not be 0, got {got}"))
                );
            }
            value
        }
    };
    Ok(Placement {
        scale,
        rotate: rotate.map_or(DVec3::ZERO, |r| r.0),
        translate: translate.map_or(DVec3::ZERO, |t| t.0),
    })
}

/// Refuses a placement that takes the mesh beyond the finite numbers:
/// the corners of its box must stay finite in the world (`span` is the
/// table that places it).
pub(crate) fn check_placed(
    mesh: &Mesh, placement: &Placement, span: Range<usize>, cx: &Context,
) -> Result<(), SceneError> {
    let to_world = placement.to_world();
    let (lo, hi) = (mesh.bounds().min, mesh.bounds().max);
    let pick = |bit: bool, lo: f64, hi: f64| if bit { hi } else { lo };
    for k in 0..8 {
        let local = DVec3::new(
            pick(k & 1 != 0, lo.x, hi.x),
            pick(k & 2 != 0, lo.y, hi.y),
            pick(k & 4 != 0, lo.z, hi.z),
        );
        let world = to_world.transform_point3(local);
        if !world.is_finite() {
            return Err(cx.error(
                span,
                format!(
                    "scale, rotate and translate take the mesh beyond the \
                     finite numbers: its corner {} goes to {}",
                    format_vec(local),
                    format_vec(world)
                ),
            ));
        }
    }
    Ok(())
}

/// The OBJ files of one scene, each read once.
pub(crate) struct MeshFiles {
    /// The scene's folder, absolute.
    folder: PathBuf,
    /// Each file read, by its canonical path, with its normals.
    read: HashMap<PathBuf, Arc<Mesh>>,
    /// The same without normals, for `smooth = false`.
    flat: HashMap<PathBuf, Arc<Mesh>>,
}

impl MeshFiles {
    /// The files of a scene in `folder` (`""` is the current folder).
    pub(crate) fn new(folder: &Path) -> MeshFiles {
        let folder = match folder.as_os_str().is_empty() {
            true => Path::new("."),
            false => folder,
        };
        let folder = fs::canonicalize(folder)
            .or_else(|_| std::path::absolute(folder))
            .unwrap_or_else(|_| folder.to_owned());
        MeshFiles {
            folder,
            read: HashMap::new(),
            flat: HashMap::new(),
        }
    }

    /// The mesh `request` names, read if it was not yet.
    pub(crate) fn load(
        &mut self, request: &MeshRequest, cx: &Context,
    ) -> Result<Arc<Mesh>, SceneError> {
        let written = request.obj.get_ref();
        let fail = |message: String| cx.error(request.obj.span(), message);
        // Step 1: the path rule.
        let found = self.find(written).map_err(fail)?;
        let key = fs::canonicalize(&found).unwrap_or_else(|_| found.clone());
        // Step 2: the file, read once.
        let mesh = match self.read.get(&key) {
            Some(mesh) => mesh.clone(),
            None => {
                let bytes = fs::read(&found).map_err(|e| {
                    fail(format!(
                        "cannot read {written} (found {}): {}",
                        found.display(),
                        io_message(&e)
                    ))
                })?;
                let mesh = Mesh::from_obj(bytes).map_err(|fault| {
                    fail(match fault {
                        ObjFault::Line(p) => {
                            format!("{written}:{}: {}", p.line, p.what)
                        }
                        ObjFault::File(message) => {
                            format!("{written}: {message}")
                        }
                        ObjFault::Empty => format!("{written}: no faces"),
                    })
                })?;
                let mesh = Arc::new(mesh);
                self.read.insert(key.clone(), mesh.clone());
                mesh
            }
        };
        // Step 3: its normals dropped for flat shading (the one copy
        // shared as well).
        if request.smooth || mesh.normals.is_empty() {
            return Ok(mesh);
        }
        let flat = self.flat.entry(key).or_insert_with(|| {
            Arc::new(Mesh {
                normals: Vec::new(),
                ..Mesh::clone(&mesh)
            })
        });
        Ok(flat.clone())
    }

    /// Where `written` is: itself if absolute, else the first of the
    /// scene's folder and the folders above it that holds it as a file.
    fn find(&self, written: &str) -> Result<PathBuf, String> {
        let path = Path::new(written);
        let mut candidates: Vec<PathBuf> = match path.is_absolute() {
            true => vec![path.to_owned()],
            false => self.folder.ancestors().map(|d| d.join(path)).collect(),
        };
        if let Some(k) = candidates.iter().position(|c| c.is_file()) {
            return Ok(candidates.swap_remove(k));
        }
        // Nowhere: say why not where it was looked for first.
        let why = match fs::metadata(&candidates[0]) {
            Err(e) => io_message(&e),
            Ok(m) if m.is_dir() => "a folder, not a file".to_owned(),
            Ok(_) => "not a regular file".to_owned(),
        };
        Err(match path.is_absolute() {
            true => format!("cannot read {written}: {why}"),
            false => format!(
                "cannot read {written} (looked in {} and every folder above \
                 it): {why}",
                self.folder.display()
            ),
        })
    }
}

/// What the operating system said, without its error number
/// (`No such file or directory`, not `… (os error 2)`).
fn io_message(error: &io::Error) -> String {
    let message = error.to_string();
    match message.rsplit_once(" (os error ") {
        Some((text, _)) => text.to_owned(),
        None => message,
    }
}
