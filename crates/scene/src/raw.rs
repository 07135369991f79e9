//! The scene file as serde reads it, before the checks that need more than
//! one value.
//!
//! Every table is `deny_unknown_fields` (none uses `flatten` or a tagged
//! enum, where that attribute is unreliable). Checks on single numbers
//! (finite, not negative, a known index-of-refraction name) happen right
//! here, in the visitors, so their errors carry the number's own span even
//! inside arrays. Checks on a single field that need a comparison with a
//! limit happen in `build` (lib.rs), from the `Spanned` fields kept here.

use std::collections::BTreeMap;
use std::fmt;
use std::marker::PhantomData;

use raystep_core::DVec3;
use serde::Deserialize;
use serde::de::{
    self, Deserializer, IgnoredAny, MapAccess, SeqAccess, Visitor,
};
use toml::Spanned;

use crate::format::format_number;
use crate::indices::{REFRACTIVE_INDICES, index_of_refraction};

/// The whole file.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawScene {
    pub image: Option<Table<RawImage>>,
    pub camera: Spanned<Table<RawCamera>>,
    pub ambient: Option<Table<RawAmbient>>,
    pub background: Option<Table<RawBackground>>,
    #[serde(default)]
    pub lights: Vec<Table<RawLight>>,
    #[serde(default)]
    pub materials: BTreeMap<String, Spanned<Table<RawMaterial>>>,
    #[serde(default)]
    pub objects: Vec<Spanned<Table<RawObject>>>,
    #[serde(default)]
    pub meshes: BTreeMap<String, Spanned<Table<RawMeshFile>>>,
    #[serde(default)]
    pub instances: Vec<Spanned<Table<RawInstance>>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawImage {
    pub width: Option<Spanned<i64>>,
    pub height: Option<Spanned<i64>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawCamera {
    pub look_from: Vec3,
    pub look_at: Spanned<Vec3>,
    pub up: Option<Spanned<Vec3>>,
    pub vfov: Option<Spanned<Finite>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawAmbient {
    pub intensity: Option<Colour>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawBackground {
    pub intensity: Option<Colour>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawLight {
    pub position: Vec3,
    pub intensity: Option<Colour>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawMaterial {
    pub ka: Option<Colour>,
    pub kd: Option<Colour>,
    pub ks: Option<Colour>,
    pub p: Option<Spanned<Finite>>,
    pub kr: Option<Colour>,
    pub kt: Option<Colour>,
    pub ior: Option<Ior>,
    pub checker: Option<Table<RawChecker>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawChecker {
    pub size: Spanned<Finite>,
    pub ka: Option<Colour>,
    pub kd: Option<Colour>,
}

/// One `[[objects]]` entry. The shape is one of three optional keys rather
/// than an enum: serde's enum representations either lose
/// `deny_unknown_fields` (internally tagged, flattened) or give errors like
/// "expected table with exactly 1 entry"; three optional keys keep every
/// field checked and let us word the "exactly one shape" error ourselves.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawObject {
    pub sphere: Option<Spanned<Table<RawSphere>>>,
    pub plane: Option<Spanned<Table<RawPlane>>>,
    pub polygon: Option<Spanned<Table<RawPolygon>>>,
    // chapter 8's primitives
    #[serde(rename = "box")]
    pub aabb: Option<Spanned<Table<RawBox>>>,
    pub cylinder: Option<Spanned<Table<RawCylinder>>>,
    pub ellipsoid: Option<Spanned<Table<RawEllipsoid>>>,
    pub triangle: Option<Spanned<Table<RawTriangle>>>,
    pub torus: Option<Spanned<Table<RawTorus>>>,
    pub saddle: Option<Spanned<Table<RawSaddle>>>,
    pub blobby: Option<Spanned<Table<RawBlobby>>>,
    // a triangle mesh from an OBJ file
    pub mesh: Option<Spanned<Table<RawPlacedMesh>>>,
    pub material: Option<Spanned<String>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawSphere {
    pub center: Vec3,
    pub radius: Spanned<Finite>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawPlane {
    pub point: Vec3,
    pub normal: Spanned<Vec3>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawPolygon {
    pub vertices: Spanned<Vec<Vec3>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawBox {
    pub min: Vec3,
    pub max: Spanned<Vec3>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawCylinder {
    pub base: Vec3,
    pub top: Spanned<Vec3>,
    pub radius: Spanned<Finite>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawEllipsoid {
    pub center: Vec3,
    pub radii: Spanned<Vec3>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawTriangle {
    pub vertices: Spanned<Vec<Vec3>>,
    pub test: Option<Spanned<String>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawTorus {
    pub center: Vec3,
    pub axis: Option<Spanned<Vec3>>,
    pub major: Spanned<Finite>,
    pub minor: Spanned<Finite>,
    pub solver: Option<Spanned<String>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawSaddle {
    pub center: Vec3,
    pub size: Spanned<Finite>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawBlobby {
    pub threshold: Spanned<Finite>,
    pub balls: Spanned<Vec<Table<RawBall>>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawBall {
    pub center: Vec3,
    pub radius: Spanned<Finite>,
    pub strength: Option<Spanned<Finite>>,
}

/// One `[meshes.NAME]` table: an OBJ file that `[[instances]]` place.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawMeshFile {
    pub obj: Spanned<String>,
    pub smooth: Option<bool>,
}

/// An object's `mesh = { … }`: an OBJ file placed once.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawPlacedMesh {
    pub obj: Spanned<String>,
    pub smooth: Option<bool>,
    pub scale: Option<Spanned<Scale>>,
    pub rotate: Option<Vec3>,
    pub translate: Option<Vec3>,
}

/// One `[[instances]]` entry: a mesh of `[meshes]` placed once more.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawInstance {
    pub mesh: Spanned<String>,
    pub scale: Option<Spanned<Scale>>,
    pub rotate: Option<Vec3>,
    pub translate: Option<Vec3>,
    pub material: Option<Spanned<String>>,
}

/// A struct that must be written as a TOML table.
///
/// Serde's derived structs also accept a sequence of their fields in order
/// (`camera = [[0, 1, 5], [0, 0, 0]]`), which no scene author means and
/// which gives baffling errors; this wrapper accepts tables only.
pub(crate) struct Table<T>(pub T);

impl<'de, T: Deserialize<'de>> Deserialize<'de> for Table<T> {
    fn deserialize<D: Deserializer<'de>>(
        deserializer: D,
    ) -> Result<Self, D::Error> {
        struct TableVisitor<T>(PhantomData<T>);
        impl<'de, T: Deserialize<'de>> Visitor<'de> for TableVisitor<T> {
            type Value = T;
            fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
                f.write_str("a table")
            }
            fn visit_map<A: MapAccess<'de>>(
                self, map: A,
            ) -> Result<T, A::Error> {
                T::deserialize(de::value::MapAccessDeserializer::new(map))
            }
        }
        deserializer
            .deserialize_map(TableVisitor(PhantomData))
            .map(Table)
    }
}

/// A finite number, written as a TOML integer or float.
#[derive(Clone, Copy)]
pub(crate) struct Finite(pub f64);

/// A finite number that is not negative: a colour component.
#[derive(Clone, Copy)]
struct Component(f64);

/// `[x, y, z]`, three finite numbers.
#[derive(Clone, Copy)]
pub(crate) struct Vec3(pub DVec3);

/// A colour: one number (grey) or `[r, g, b]`, each finite and `≥ 0`.
#[derive(Clone, Copy)]
pub(crate) struct Colour(pub DVec3);

/// A scale: one finite number for all three axes, or `[x, y, z]`
/// (`uniform` says which was written, for the error messages).
#[derive(Clone, Copy)]
pub(crate) struct Scale {
    pub value: DVec3,
    pub uniform: bool,
}

/// An index of refraction: a positive number or a name from
/// [`REFRACTIVE_INDICES`].
#[derive(Clone, Copy)]
pub(crate) struct Ior(pub f64);

/// The numeric `visit_*` methods of a visitor, all turned into `f64` and
/// handed to `$check`. TOML has only `i64` integers, but serde may ask for
/// any of these.
macro_rules! visit_numbers {
    ($check:expr) => {
        fn visit_i64<E: de::Error>(self, v: i64) -> Result<Self::Value, E> {
            ($check)(v as f64)
        }
        fn visit_u64<E: de::Error>(self, v: u64) -> Result<Self::Value, E> {
            ($check)(v as f64)
        }
        fn visit_f64<E: de::Error>(self, v: f64) -> Result<Self::Value, E> {
            ($check)(v)
        }
    };
}

fn finite<E: de::Error>(v: f64) -> Result<f64, E> {
    if v.is_finite() {
        Ok(v)
    } else {
        Err(E::custom(format!(
            "must be a finite number, got {}",
            format_number(v)
        )))
    }
}

fn component<E: de::Error>(v: f64) -> Result<f64, E> {
    let v = finite(v)?;
    if v < 0.0 {
        Err(E::custom(format!(
            "must not be negative, got {}",
            format_number(v)
        )))
    } else {
        Ok(v)
    }
}

impl<'de> Deserialize<'de> for Finite {
    fn deserialize<D: Deserializer<'de>>(
        deserializer: D,
    ) -> Result<Self, D::Error> {
        struct V;
        impl Visitor<'_> for V {
            type Value = Finite;
            fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
                f.write_str("a number")
            }
            visit_numbers!(|v| finite(v).map(Finite));
        }
        deserializer.deserialize_any(V)
    }
}

impl<'de> Deserialize<'de> for Component {
    fn deserialize<D: Deserializer<'de>>(
        deserializer: D,
    ) -> Result<Self, D::Error> {
        struct V;
        impl Visitor<'_> for V {
            type Value = Component;
            fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
                f.write_str("a number")
            }
            visit_numbers!(|v| component(v).map(Component));
        }
        deserializer.deserialize_any(V)
    }
}

/// Reads exactly three `T`s from `seq`; `what` names them in the error.
fn three<'de, T, A>(mut seq: A, what: &str) -> Result<[T; 3], A::Error>
where
    T: Deserialize<'de> + Copy,
    A: SeqAccess<'de>,
{
    let mut items = Vec::with_capacity(3);
    while let Some(item) = seq.next_element::<T>()? {
        items.push(item);
        if items.len() == 3 {
            break;
        }
    }
    let mut count = items.len();
    if count == 3 {
        while seq.next_element::<IgnoredAny>()?.is_some() {
            count += 1;
        }
    }
    match items[..] {
        [a, b, c] if count == 3 => Ok([a, b, c]),
        _ => Err(de::Error::custom(format!(
            "expected an array of 3 numbers {what}, got {count} element{}",
            if count == 1 { "" } else { "s" }
        ))),
    }
}

impl<'de> Deserialize<'de> for Vec3 {
    fn deserialize<D: Deserializer<'de>>(
        deserializer: D,
    ) -> Result<Self, D::Error> {
        struct V;
        impl<'de> Visitor<'de> for V {
            type Value = Vec3;
            fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
                f.write_str("an array of 3 numbers [x, y, z]")
            }
            fn visit_seq<A: SeqAccess<'de>>(
                self, seq: A,
            ) -> Result<Vec3, A::Error> {
                let [x, y, z] = three::<Finite, _>(seq, "[x, y, z]")?;
                Ok(Vec3(DVec3::new(x.0, y.0, z.0)))
            }
        }
        deserializer.deserialize_any(V)
    }
}

impl<'de> Deserialize<'de> for Colour {
    fn deserialize<D: Deserializer<'de>>(
        deserializer: D,
    ) -> Result<Self, D::Error> {
        struct V;
        impl<'de> Visitor<'de> for V {
            type Value = Colour;
            fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
                f.write_str("a number or an array of 3 numbers [r, g, b]")
            }
            visit_numbers!(|v| component(v).map(|v| Colour(DVec3::splat(v))));
            fn visit_seq<A: SeqAccess<'de>>(
                self, seq: A,
            ) -> Result<Colour, A::Error> {
                let [r, g, b] = three::<Component, _>(seq, "[r, g, b]")?;
                Ok(Colour(DVec3::new(r.0, g.0, b.0)))
            }
        }
        deserializer.deserialize_any(V)
    }
}

impl<'de> Deserialize<'de> for Scale {
    fn deserialize<D: Deserializer<'de>>(
        deserializer: D,
    ) -> Result<Self, D::Error> {
        struct V;
        impl<'de> Visitor<'de> for V {
            type Value = Scale;
            fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
                f.write_str("a number or an array of 3 numbers [x, y, z]")
            }
            visit_numbers!(|v| finite(v).map(|v| Scale {
                value: DVec3::splat(v),
                uniform: true,
            }));
            fn visit_seq<A: SeqAccess<'de>>(
                self, seq: A,
            ) -> Result<Scale, A::Error> {
                let [x, y, z] = three::<Finite, _>(seq, "[x, y, z]")?;
                Ok(Scale {
                    value: DVec3::new(x.0, y.0, z.0),
                    uniform: false,
                })
            }
        }
        deserializer.deserialize_any(V)
    }
}

impl<'de> Deserialize<'de> for Ior {
    fn deserialize<D: Deserializer<'de>>(
        deserializer: D,
    ) -> Result<Self, D::Error> {
        struct V;
        impl Visitor<'_> for V {
            type Value = Ior;
            fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
                f.write_str("a positive number or the name of a material such as \"glass\"")
            }
            visit_numbers!(|v| {
                let v = finite(v)?;
                if v > 0.0 {
                    Ok(Ior(v))
                } else {
                    Err(E::custom(format!(
                        "must be positive, got {}",
                        format_number(v)
                    )))
                }
            });
            fn visit_str<E: de::Error>(self, name: &str) -> Result<Ior, E> {
                index_of_refraction(name).map(Ior).ok_or_else(|| {
                    let known: Vec<&str> = REFRACTIVE_INDICES.iter().map(|(n, _)| *n).collect();
                    E::custom(format!(
                        "unknown name {name:?}, expected a positive number or one of {}",
                        known.join(", ")
                    ))
                })
            }
        }
        deserializer.deserialize_any(V)
    }
}
