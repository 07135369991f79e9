//! A row type's column names, read off its `Deserialize` impl: serde's
//! derive hands the struct's field names (after any `rename`) to the
//! deserializer it is given, and this one keeps them and stops there.
use serde::de::{self, DeserializeOwned, Deserializer, Visitor};
use serde::forward_to_deserialize_any;

/// The columns of `R`, its field names in order.
///
/// # Panics
/// If `R` is not a struct with named fields (a programming error: every
/// chart row is one).
pub fn columns<R: DeserializeOwned>() -> &'static [&'static str] {
    let mut fields = None;
    let _ = R::deserialize(FieldNames(&mut fields));
    fields.expect("a CSV row is a struct with named fields")
}

/// A deserializer that only notes the names of the struct asked for.
struct FieldNames<'a>(&'a mut Option<&'static [&'static str]>);

impl<'de> Deserializer<'de> for FieldNames<'_> {
    type Error = de::value::Error;

    fn deserialize_any<V: Visitor<'de>>(
        self, _visitor: V,
    ) -> Result<V::Value, Self::Error> {
        Err(de::Error::custom("not a struct"))
    }

    fn deserialize_struct<V: Visitor<'de>>(
        self, _name: &'static str, fields: &'static [&'static str], _visitor: V,
    ) -> Result<V::Value, Self::Error> {
        *self.0 = Some(fields);
        Err(de::Error::custom("only the names were asked for"))
    }

    forward_to_deserialize_any! {
        bool i8 i16 i32 i64 i128 u8 u16 u32 u64 u128 f32 f64 char str string
        bytes byte_buf option unit unit_struct newtype_struct seq tuple
        tuple_struct map enum identifier ignored_any
    }
}
