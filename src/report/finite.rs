//! The output guard for JSON: the first non-finite number a value would serialise.
//!
//! serde_json writes NaN and ±inf as `null`, so a guard that reads the JSON text cannot see
//! them (a `null` may also be an honest `None`). This walks the value through serde's data
//! model instead, before any text exists, and names the first non-finite number with its path
//! (`pairs[3].residual`).

use serde::ser::{self, Serialize};

/// Where a non-finite number sits in a serialised value, and the number.
#[derive(Debug, Clone, PartialEq)]
pub struct NonFinite {
    /// Path of the field, `a.b[2].c` (empty for the value itself).
    pub path: String,
    /// The number (NaN, inf or -inf).
    pub value: f64,
}

impl std::fmt::Display for NonFinite {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let v = if self.value.is_nan() {
            "NaN".to_string()
        } else {
            format!("{}", self.value)
        };
        if self.path.is_empty() {
            write!(f, "{v}")
        } else {
            write!(f, "{v} at `{}`", self.path)
        }
    }
}

/// The first non-finite number in `value`, in serialisation order; `None` when every number
/// is finite (or when the value cannot be serialised at all: the writer reports that).
pub fn first_non_finite<T: Serialize + ?Sized>(value: &T) -> Option<NonFinite> {
    let mut w = Walker { path: Vec::new() };
    match value.serialize(&mut w) {
        Err(Found::NonFinite(n)) => Some(n),
        Err(Found::Other) | Ok(()) => None,
    }
}

/// Why the walk stopped.
#[derive(Debug)]
enum Found {
    NonFinite(NonFinite),
    Other,
}

impl std::fmt::Display for Found {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{self:?}")
    }
}

impl std::error::Error for Found {}

impl ser::Error for Found {
    fn custom<M: std::fmt::Display>(_: M) -> Self {
        Found::Other
    }
}

/// One step of a path: a field name or an index.
enum Step {
    Field(&'static str),
    Index(usize),
    Key,
}

struct Walker {
    path: Vec<Step>,
}

impl Walker {
    fn path(&self) -> String {
        let mut s = String::new();
        for step in &self.path {
            match step {
                Step::Field(n) if s.is_empty() => s.push_str(n),
                Step::Field(n) => {
                    s.push('.');
                    s.push_str(n);
                }
                Step::Index(i) => s.push_str(&format!("[{i}]")),
                Step::Key => s.push_str("[…]"),
            }
        }
        s
    }

    fn float(&mut self, v: f64) -> Result<(), Found> {
        if v.is_finite() {
            Ok(())
        } else {
            Err(Found::NonFinite(NonFinite {
                path: self.path(),
                value: v,
            }))
        }
    }

    fn nested<T: Serialize + ?Sized>(&mut self, step: Step, v: &T) -> Result<(), Found> {
        self.path.push(step);
        let r = v.serialize(&mut *self);
        self.path.pop();
        r
    }
}

/// A compound value being walked: a sequence counts its elements for the path.
struct Compound<'a> {
    w: &'a mut Walker,
    index: usize,
}

impl Compound<'_> {
    fn element<T: Serialize + ?Sized>(&mut self, v: &T) -> Result<(), Found> {
        let i = self.index;
        self.index += 1;
        self.w.nested(Step::Index(i), v)
    }
}

macro_rules! finite_scalars {
    ($($f:ident: $t:ty),*) => { $(fn $f(self, _: $t) -> Result<(), Found> { Ok(()) })* };
}

impl<'a> ser::Serializer for &'a mut Walker {
    type Ok = ();
    type Error = Found;
    type SerializeSeq = Compound<'a>;
    type SerializeTuple = Compound<'a>;
    type SerializeTupleStruct = Compound<'a>;
    type SerializeTupleVariant = Compound<'a>;
    type SerializeMap = Compound<'a>;
    type SerializeStruct = Compound<'a>;
    type SerializeStructVariant = Compound<'a>;

    finite_scalars!(serialize_bool: bool, serialize_i8: i8, serialize_i16: i16,
        serialize_i32: i32, serialize_i64: i64, serialize_u8: u8, serialize_u16: u16,
        serialize_u32: u32, serialize_u64: u64, serialize_char: char, serialize_str: &str,
        serialize_bytes: &[u8], serialize_unit_struct: &'static str);

    fn serialize_f32(self, v: f32) -> Result<(), Found> {
        self.float(f64::from(v))
    }
    fn serialize_f64(self, v: f64) -> Result<(), Found> {
        self.float(v)
    }
    fn serialize_none(self) -> Result<(), Found> {
        Ok(())
    }
    fn serialize_some<T: Serialize + ?Sized>(self, v: &T) -> Result<(), Found> {
        v.serialize(self)
    }
    fn serialize_unit(self) -> Result<(), Found> {
        Ok(())
    }
    fn serialize_unit_variant(self, _: &'static str, _: u32, _: &'static str) -> Result<(), Found> {
        Ok(())
    }
    fn serialize_newtype_struct<T: Serialize + ?Sized>(
        self,
        _: &'static str,
        v: &T,
    ) -> Result<(), Found> {
        v.serialize(self)
    }
    fn serialize_newtype_variant<T: Serialize + ?Sized>(
        self,
        _: &'static str,
        _: u32,
        variant: &'static str,
        v: &T,
    ) -> Result<(), Found> {
        self.nested(Step::Field(variant), v)
    }
    fn serialize_seq(self, _: Option<usize>) -> Result<Compound<'a>, Found> {
        Ok(Compound { w: self, index: 0 })
    }
    fn serialize_tuple(self, _: usize) -> Result<Compound<'a>, Found> {
        Ok(Compound { w: self, index: 0 })
    }
    fn serialize_tuple_struct(self, _: &'static str, _: usize) -> Result<Compound<'a>, Found> {
        Ok(Compound { w: self, index: 0 })
    }
    fn serialize_tuple_variant(
        self,
        _: &'static str,
        _: u32,
        _: &'static str,
        _: usize,
    ) -> Result<Compound<'a>, Found> {
        Ok(Compound { w: self, index: 0 })
    }
    fn serialize_map(self, _: Option<usize>) -> Result<Compound<'a>, Found> {
        Ok(Compound { w: self, index: 0 })
    }
    fn serialize_struct(self, _: &'static str, _: usize) -> Result<Compound<'a>, Found> {
        Ok(Compound { w: self, index: 0 })
    }
    fn serialize_struct_variant(
        self,
        _: &'static str,
        _: u32,
        _: &'static str,
        _: usize,
    ) -> Result<Compound<'a>, Found> {
        Ok(Compound { w: self, index: 0 })
    }
}

macro_rules! sequence_like {
    ($($tr:ident :: $m:ident),*) => {$(
        impl ser::$tr for Compound<'_> {
            type Ok = ();
            type Error = Found;
            fn $m<T: Serialize + ?Sized>(&mut self, v: &T) -> Result<(), Found> {
                self.element(v)
            }
            fn end(self) -> Result<(), Found> {
                Ok(())
            }
        }
    )*};
}

sequence_like!(
    SerializeSeq::serialize_element,
    SerializeTuple::serialize_element,
    SerializeTupleStruct::serialize_field,
    SerializeTupleVariant::serialize_field
);

impl ser::SerializeMap for Compound<'_> {
    type Ok = ();
    type Error = Found;
    fn serialize_key<T: Serialize + ?Sized>(&mut self, k: &T) -> Result<(), Found> {
        self.w.nested(Step::Key, k)
    }
    fn serialize_value<T: Serialize + ?Sized>(&mut self, v: &T) -> Result<(), Found> {
        self.w.nested(Step::Key, v)
    }
    fn end(self) -> Result<(), Found> {
        Ok(())
    }
}

macro_rules! struct_like {
    ($($tr:ident),*) => {$(
        impl ser::$tr for Compound<'_> {
            type Ok = ();
            type Error = Found;
            fn serialize_field<T: Serialize + ?Sized>(
                &mut self,
                name: &'static str,
                v: &T,
            ) -> Result<(), Found> {
                self.w.nested(Step::Field(name), v)
            }
            fn end(self) -> Result<(), Found> {
                Ok(())
            }
        }
    )*};
}

struct_like!(SerializeStruct, SerializeStructVariant);

#[cfg(test)]
mod tests {
    use super::*;
    use std::collections::BTreeMap;

    #[derive(serde::Serialize)]
    struct Pair {
        name: &'static str,
        residual: f64,
        bound: Option<f64>,
    }

    #[derive(serde::Serialize)]
    struct Out {
        pairs: Vec<Pair>,
        total: f32,
    }

    fn out(residual: f64, total: f32) -> Out {
        Out {
            pairs: vec![
                Pair {
                    name: "P",
                    residual: 1.0,
                    bound: None,
                },
                Pair {
                    name: "Q",
                    residual,
                    bound: Some(2.0),
                },
            ],
            total,
        }
    }

    #[test]
    fn finite_values_and_honest_nulls_pass() {
        assert_eq!(first_non_finite(&out(0.5, 3.0)), None);
        assert_eq!(first_non_finite(&(1.0, [2.0, -0.0], "NaN")), None);
    }

    #[test]
    fn the_first_non_finite_number_is_named_with_its_path() {
        let n = first_non_finite(&out(f64::NAN, 3.0)).unwrap();
        assert_eq!(n.path, "pairs[1].residual");
        assert_eq!(n.to_string(), "NaN at `pairs[1].residual`");
        let n = first_non_finite(&out(1.0, f32::NEG_INFINITY)).unwrap();
        assert_eq!(n.to_string(), "-inf at `total`");
        assert_eq!(first_non_finite(&f64::INFINITY).unwrap().to_string(), "inf");
        let m: BTreeMap<&str, Vec<f64>> = [("a", vec![1.0, f64::NAN])].into();
        assert_eq!(first_non_finite(&m).unwrap().path, "[…][1]");
    }
}
