//! JSON read as a [`Value`] in which no object gives a key twice.
//!
//! `serde_json::Value` keeps the last of a key given twice, so
//! `{"eta": 1.5, "eta": 2}` would be read as `2` without a word, and a
//! scene's second `"image"` would replace its first. RFC 8259 §4 leaves
//! the meaning of such an object to the reader; this one refuses it. Every
//! input read as a JSON value first (a scene file, a batch line, a line of
//! a tradeoff plan) is read through [`UniqueKeys`], so the rule is made
//! once.
//!
//! ```
//! use safe_io::json::UniqueKeys;
//!
//! let ok: UniqueKeys = serde_json::from_str(r#"{"eta": 1.5, "cos_i": [1, 2]}"#).unwrap();
//! assert_eq!(ok.0["eta"], 1.5);
//! let text = r#"{"eta": 1.5, "eta": 2}"#;
//! let twice = serde_path_to_error::deserialize::<_, UniqueKeys>(
//!     &mut serde_json::Deserializer::from_str(text),
//! )
//! .unwrap_err();
//! assert_eq!(twice.path().to_string(), "eta");
//! assert!(twice.inner().to_string().starts_with("given twice"));
//! ```
//!
//! The refusal is raised while the second value is read, so a reader that
//! tracks the path (`serde_path_to_error`) names the key itself
//! (`image.width`), and `serde_json` classifies it as
//! [`Category::Data`](serde_json::error::Category::Data), never as a
//! syntax error.

use serde::de::{DeserializeSeed, Deserializer, Error as _, MapAccess, SeqAccess, Visitor};
use serde::Deserialize;
use serde_json::{Map, Number, Value};
use std::fmt;

/// A JSON value whose objects each give every key once.
#[derive(Debug, Clone, PartialEq)]
pub struct UniqueKeys(pub Value);

impl<'de> Deserialize<'de> for UniqueKeys {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        deserializer.deserialize_any(ValueVisitor).map(UniqueKeys)
    }
}

struct ValueVisitor;

impl<'de> Visitor<'de> for ValueVisitor {
    type Value = Value;

    fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
        f.write_str("any JSON value")
    }

    fn visit_bool<E>(self, v: bool) -> Result<Value, E> {
        Ok(Value::Bool(v))
    }

    fn visit_i64<E>(self, v: i64) -> Result<Value, E> {
        Ok(Value::Number(v.into()))
    }

    fn visit_u64<E>(self, v: u64) -> Result<Value, E> {
        Ok(Value::Number(v.into()))
    }

    fn visit_f64<E>(self, v: f64) -> Result<Value, E> {
        // serde_json hands over finite numbers only.
        Ok(Number::from_f64(v).map_or(Value::Null, Value::Number))
    }

    fn visit_str<E>(self, v: &str) -> Result<Value, E> {
        Ok(Value::String(v.to_owned()))
    }

    fn visit_string<E>(self, v: String) -> Result<Value, E> {
        Ok(Value::String(v))
    }

    fn visit_unit<E>(self) -> Result<Value, E> {
        Ok(Value::Null)
    }

    fn visit_none<E>(self) -> Result<Value, E> {
        Ok(Value::Null)
    }

    fn visit_some<D: Deserializer<'de>>(self, deserializer: D) -> Result<Value, D::Error> {
        UniqueKeys::deserialize(deserializer).map(|v| v.0)
    }

    fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<Value, A::Error> {
        let mut items = Vec::new();
        while let Some(UniqueKeys(item)) = seq.next_element()? {
            items.push(item);
        }
        Ok(Value::Array(items))
    }

    fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<Value, A::Error> {
        let mut fields = Map::new();
        while let Some(key) = map.next_key::<String>()? {
            if fields.contains_key(&key) {
                // Refused as the second value is read: a path tracker then
                // names the key.
                return map.next_value_seed(GivenTwice);
            }
            let UniqueKeys(value) = map.next_value()?;
            fields.insert(key, value);
        }
        Ok(Value::Object(fields))
    }
}

/// Why JSON has no NaN or infinity, for a reader whose text spells one
/// where parsing stopped ([`spells_non_finite`]).
pub const NON_FINITE_HINT: &str = "JSON numbers are finite: NaN and Infinity are not numbers";

/// Whether `text`, where `error` stopped parsing it, spells a number JSON
/// does not have (`NaN`, `Infinity` or `inf`, signed or not).
pub fn spells_non_finite(text: &str, error: &serde_json::Error) -> bool {
    let here = text
        .lines()
        .nth(error.line().saturating_sub(1))
        .and_then(|line| line.get(error.column().saturating_sub(1)..))
        .unwrap_or("");
    let here = here.trim_start_matches(['-', '+']);
    ["NaN", "Infinity", "inf"]
        .iter()
        .any(|word| here.starts_with(word))
}

/// `error`'s message without the position `serde_json` appends to it
/// (" at line L column C"), for a reader that names the place itself.
pub fn without_position(error: &serde_json::Error) -> String {
    let text = error.to_string();
    match text.find(" at line ") {
        Some(i) => text[..i].to_owned(),
        None => text,
    }
}

/// The refusal of a key given twice; the path names the key.
pub const TWICE: &str = "given twice (a key may appear once in an object)";

/// The value of a key already given: refused, consuming nothing.
struct GivenTwice;

impl<'de> DeserializeSeed<'de> for GivenTwice {
    type Value = Value;

    fn deserialize<D: Deserializer<'de>>(self, _: D) -> Result<Value, D::Error> {
        Err(D::Error::custom(TWICE))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::error::Category;

    /// The value read, or the refusal's category, message and path.
    fn read(text: &str) -> Result<Value, (Category, String, String)> {
        let de = &mut serde_json::Deserializer::from_str(text);
        serde_path_to_error::deserialize::<_, UniqueKeys>(de)
            .map(|v| v.0)
            .map_err(|e| {
                let message = without_position(e.inner());
                (e.inner().classify(), message, e.path().to_string())
            })
    }

    /// Every JSON value without a repeated key reads as `serde_json::Value`
    /// reads it: the same value, to the bit.
    #[test]
    fn unique_keys_read_as_serde_json_value_reads_them() {
        for text in [
            r#"{"a": 1, "b": [1.5, -2, 18446744073709551615, -9223372036854775808, 1e-320]}"#,
            r#"[null, true, false, "x\u00e9", {"a": {"b": {"c": []}}}, {}]"#,
            r#"{"a": {"x": 1}, "b": {"x": 2}}"#,
            "0.1",
        ] {
            let expected: Value = serde_json::from_str(text).unwrap();
            assert_eq!(read(text), Ok(expected), "{text}");
        }
    }

    /// A key given twice in any object, at any depth, is refused as data
    /// (not syntax), and the path names that key; the same key in two
    /// objects is not a repeat.
    #[test]
    fn a_key_given_twice_is_refused_naming_it() {
        for (text, path) in [
            (r#"{"eta": 1.5, "eta": 1.5}"#, "eta"),
            (
                r#"{"image": {"width": 4, "height": 3, "width": 5}}"#,
                "image.width",
            ),
            (
                r#"{"objects": [{}, {"r": 1, "r": {"x": 1}}]}"#,
                "objects[1].r",
            ),
            (r#"[{"a": 1}, {"a": 1, "a": 2}]"#, "[1].a"),
        ] {
            let expected = (Category::Data, TWICE.to_owned(), path.to_owned());
            assert_eq!(read(text), Err(expected), "{text}");
        }
    }
}
