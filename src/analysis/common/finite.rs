//! Every number written must be finite: a serde serializer that walks a result and fails on
//! the first NaN or ±∞, naming its JSON path.
//!
//! serde_json writes NaN and ±∞ as `null` without complaint, so a result whose computation
//! overflowed would pass as a result with missing values. The check runs on the typed result
//! (before it becomes JSON), where a non-finite `f64` is still distinguishable from an absent
//! `Option`.

use serde::ser::{self, Serialize};
use std::fmt;

/// A non-finite number (the path is added by `serde_path_to_error`).
#[derive(Debug)]
pub struct NonFinite(pub String);

impl fmt::Display for NonFinite {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for NonFinite {}

impl ser::Error for NonFinite {
    fn custom<T: fmt::Display>(msg: T) -> Self {
        NonFinite(msg.to_string())
    }
}

/// Serializer that writes nothing and fails on a non-finite float.
pub struct Check;

fn float(v: f64) -> Result<(), NonFinite> {
    if v.is_finite() {
        Ok(())
    } else {
        Err(NonFinite(format!("the value is {v}")))
    }
}

/// Finds the first non-finite number in `v`: `Err((JSON path, message))`.
pub fn first_non_finite<T: Serialize + ?Sized>(v: &T) -> Result<(), (String, String)> {
    // The plain walk first; the path is tracked (a string per field) only to name a failure.
    if v.serialize(Check).is_ok() {
        return Ok(());
    }
    serde_path_to_error::serialize(v, Check).map_err(|e| {
        let path = e.path().to_string();
        (path, e.inner().to_string())
    })
}

macro_rules! ok_scalars {
    ($($name:ident: $t:ty),*) => {
        $(fn $name(self, _v: $t) -> Result<(), NonFinite> { Ok(()) })*
    };
}

impl ser::Serializer for Check {
    type Ok = ();
    type Error = NonFinite;
    type SerializeSeq = Check;
    type SerializeTuple = Check;
    type SerializeTupleStruct = Check;
    type SerializeTupleVariant = Check;
    type SerializeMap = Check;
    type SerializeStruct = Check;
    type SerializeStructVariant = Check;

    ok_scalars!(serialize_bool: bool, serialize_i8: i8, serialize_i16: i16, serialize_i32: i32,
        serialize_i64: i64, serialize_u8: u8, serialize_u16: u16, serialize_u32: u32,
        serialize_u64: u64, serialize_char: char, serialize_str: &str, serialize_bytes: &[u8]);

    fn serialize_f32(self, v: f32) -> Result<(), NonFinite> {
        float(v as f64)
    }
    /// Text holds no number to check: nothing is formatted (the default would build a String).
    fn collect_str<T: ?Sized + fmt::Display>(self, _v: &T) -> Result<(), NonFinite> {
        Ok(())
    }
    fn serialize_f64(self, v: f64) -> Result<(), NonFinite> {
        float(v)
    }
    fn serialize_none(self) -> Result<(), NonFinite> {
        Ok(())
    }
    fn serialize_some<T: Serialize + ?Sized>(self, value: &T) -> Result<(), NonFinite> {
        value.serialize(self)
    }
    fn serialize_unit(self) -> Result<(), NonFinite> {
        Ok(())
    }
    fn serialize_unit_struct(self, _name: &'static str) -> Result<(), NonFinite> {
        Ok(())
    }
    fn serialize_unit_variant(self, _n: &'static str, _i: u32, _v: &'static str) -> Result<(), NonFinite> {
        Ok(())
    }
    fn serialize_newtype_struct<T: Serialize + ?Sized>(self, _n: &'static str, value: &T) -> Result<(), NonFinite> {
        value.serialize(self)
    }
    fn serialize_newtype_variant<T: Serialize + ?Sized>(
        self,
        _n: &'static str,
        _i: u32,
        _v: &'static str,
        value: &T,
    ) -> Result<(), NonFinite> {
        value.serialize(self)
    }
    fn serialize_seq(self, _len: Option<usize>) -> Result<Check, NonFinite> {
        Ok(Check)
    }
    fn serialize_tuple(self, _len: usize) -> Result<Check, NonFinite> {
        Ok(Check)
    }
    fn serialize_tuple_struct(self, _n: &'static str, _len: usize) -> Result<Check, NonFinite> {
        Ok(Check)
    }
    fn serialize_tuple_variant(self, _n: &'static str, _i: u32, _v: &str, _len: usize) -> Result<Check, NonFinite> {
        Ok(Check)
    }
    fn serialize_map(self, _len: Option<usize>) -> Result<Check, NonFinite> {
        Ok(Check)
    }
    fn serialize_struct(self, _n: &'static str, _len: usize) -> Result<Check, NonFinite> {
        Ok(Check)
    }
    fn serialize_struct_variant(self, _n: &'static str, _i: u32, _v: &str, _len: usize) -> Result<Check, NonFinite> {
        Ok(Check)
    }
}

/// The compound serialisers of sequences and tuples: every element is checked.
macro_rules! check_elements {
    ($($trait:ident :: $method:ident),*) => {$(
        impl ser::$trait for Check {
            type Ok = ();
            type Error = NonFinite;
            fn $method<T: Serialize + ?Sized>(&mut self, value: &T) -> Result<(), NonFinite> {
                value.serialize(Check)
            }
            fn end(self) -> Result<(), NonFinite> {
                Ok(())
            }
        }
    )*};
}
check_elements!(
    SerializeSeq::serialize_element,
    SerializeTuple::serialize_element,
    SerializeTupleStruct::serialize_field,
    SerializeTupleVariant::serialize_field
);

impl ser::SerializeMap for Check {
    type Ok = ();
    type Error = NonFinite;
    fn serialize_key<T: Serialize + ?Sized>(&mut self, key: &T) -> Result<(), NonFinite> {
        key.serialize(Check)
    }
    fn serialize_value<T: Serialize + ?Sized>(&mut self, value: &T) -> Result<(), NonFinite> {
        value.serialize(Check)
    }
    fn end(self) -> Result<(), NonFinite> {
        Ok(())
    }
}

/// The compound serialisers of structs: every field is checked.
macro_rules! check_fields {
    ($($trait:ident),*) => {$(
        impl ser::$trait for Check {
            type Ok = ();
            type Error = NonFinite;
            fn serialize_field<T: Serialize + ?Sized>(&mut self, _key: &'static str, value: &T) -> Result<(), NonFinite> {
                value.serialize(Check)
            }
            fn end(self) -> Result<(), NonFinite> {
                Ok(())
            }
        }
    )*};
}
check_fields!(SerializeStruct, SerializeStructVariant);
