//! How a row writes its numbers, field by field, so that a new
//! measurement writes the committed files' format: name one of these in
//! the field's `#[serde(with = "…")]`. Counts (`u64`) and names need
//! none; each reads back what it writes.
use serde::{Deserialize, Deserializer, Serializer};

/// A number with `N` decimals (`{:.N}`): `#[serde(with =
/// "Decimals::<3>")]` writes 2.6894 as `2.689`.
pub struct Decimals<const N: usize>;

impl<const N: usize> Decimals<N> {
    /// Writes `x` with `N` decimals.
    pub fn serialize<S: Serializer>(x: &f64, s: S) -> Result<S::Ok, S::Error> {
        let places = N;
        s.collect_str(&format_args!("{x:.places$}"))
    }

    /// Reads a number.
    pub fn deserialize<'de, D: Deserializer<'de>>(
        d: D,
    ) -> Result<f64, D::Error> {
        f64::deserialize(d)
    }
}

/// A number in e notation (`{:e}`): 0.001 as `1e-3`, 10 as `1e1`.
pub struct Exp;

impl Exp {
    /// Writes `x` in e notation.
    pub fn serialize<S: Serializer>(x: &f64, s: S) -> Result<S::Ok, S::Error> {
        s.collect_str(&format_args!("{x:e}"))
    }

    /// Reads a number.
    pub fn deserialize<'de, D: Deserializer<'de>>(
        d: D,
    ) -> Result<f64, D::Error> {
        f64::deserialize(d)
    }
}

/// A number as Rust displays it (`{}`): the shortest that reads back the
/// same, without an exponent: 1.5 as `1.5`, 200 as `200`.
pub struct Plain;

impl Plain {
    /// Writes `x` as displayed.
    pub fn serialize<S: Serializer>(x: &f64, s: S) -> Result<S::Ok, S::Error> {
        s.collect_str(x)
    }

    /// Reads a number.
    pub fn deserialize<'de, D: Deserializer<'de>>(
        d: D,
    ) -> Result<f64, D::Error> {
        f64::deserialize(d)
    }
}

/// A yes or no as `1` or `0`; read back, 1 is yes and any other count no.
pub struct Flag;

impl Flag {
    /// Writes `1` for true, `0` for false.
    pub fn serialize<S: Serializer>(x: &bool, s: S) -> Result<S::Ok, S::Error> {
        s.serialize_u8(u8::from(*x))
    }

    /// Reads a count: true if it is 1.
    pub fn deserialize<'de, D: Deserializer<'de>>(
        d: D,
    ) -> Result<bool, D::Error> {
        Ok(u64::deserialize(d)? == 1)
    }
}
