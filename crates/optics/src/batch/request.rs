//! A batch line read into a [`Request`]: the arguments of the law it names,
//! and whether its working is wanted.
//!
//! A line is read once, straight into its law's arguments ([`typed`]),
//! when its `law` comes first and nothing in it is wrong. Any other line
//! (the law later, a field missing, mistyped, unknown or given twice, a key
//! with escapes, text that is not JSON) is read again by [`general`]: into
//! a JSON object whose keys are each given once ([`UniqueKeys`]), then
//! into the arguments, which names what is wrong as every error object of
//! `optics batch` does. For each line the typed reading accepts, both give
//! the same request (the `batch_lines` fuzz target checks it), so the
//! reading that answers is never visible in the output.

use crate::error::{Error, ErrorKind, Result};
pub use crate::law_table::Law;
use crate::law_table::LAWS;
use record::Steps;
use safe_io::json::{without_position, UniqueKeys};
use serde::de::value::{BorrowedStrDeserializer, MapAccessDeserializer};
use serde::de::{DeserializeSeed, Deserializer, Error as _, MapAccess, Visitor};
use serde::Deserialize;
use serde_json::error::Category;
use serde_json::Value;
use std::borrow::Cow;
use std::fmt;

/// One request: the law as the line names it, its arguments, and whether
/// its working is wanted (the line's `"steps"`, else the run's choice).
#[derive(Debug)]
pub struct Request<'a> {
    pub name: Cow<'a, str>,
    pub law: Law,
    pub steps: Steps,
}

/// The request on `text` read in one pass, straight into its law's
/// arguments, `steps` unless the line says otherwise; `None` where the line
/// is not one [`typed`] reads (then [`general`] reads it and names what is
/// wrong).
pub fn typed(text: &str, steps: Steps) -> Option<Request<'_>> {
    let mut json = serde_json::Deserializer::from_str(text);
    let request = json.deserialize_map(Typed { steps }).ok()?;
    json.end().ok()?;
    Some(request)
}

#[cfg(test)]
thread_local! {
    /// A fault for the fuzz targets to find: the typed reading takes the
    /// run's choice of working over the line's own `"steps"`.
    pub(crate) static LINE_STEPS_IGNORED: std::cell::Cell<bool> =
        const { std::cell::Cell::new(false) };
}

/// Reads an object whose first key is `law`.
struct Typed {
    steps: Steps,
}

impl<'de> Visitor<'de> for Typed {
    type Value = Request<'de>;

    fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
        f.write_str("an object whose first key is law")
    }

    fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<Request<'de>, A::Error> {
        if map.next_key::<&str>()? != Some("law") {
            return Err(A::Error::custom("the law does not come first"));
        }
        let name: &str = map.next_value()?;
        let mut given = None;
        let rest = MapAccessDeserializer::new(Rest {
            map,
            steps: &mut given,
        });
        let law = Law::read(name, rest).ok_or_else(|| A::Error::custom("an unknown law"))??;
        #[cfg(test)]
        if LINE_STEPS_IGNORED.get() {
            given = None;
        }
        let steps = given.map_or(self.steps, Steps::from_wanted);
        let name = Cow::Borrowed(name);
        Ok(Request { name, law, steps })
    }
}

/// The fields after `law`, less `steps`, which it keeps aside.
struct Rest<'s, A> {
    map: A,
    steps: &'s mut Option<bool>,
}

impl<'de, A: MapAccess<'de>> MapAccess<'de> for Rest<'_, A> {
    type Error = A::Error;

    fn next_key_seed<K: DeserializeSeed<'de>>(
        &mut self,
        seed: K,
    ) -> Result<Option<K::Value>, A::Error> {
        loop {
            match self.map.next_key::<&str>()? {
                None => return Ok(None),
                Some("steps") if self.steps.is_none() => {
                    *self.steps = Some(self.map.next_value()?);
                }
                // The general reading refuses a key given twice, naming it.
                Some("law" | "steps") => return Err(A::Error::custom("a key given twice")),
                Some(key) => {
                    return seed
                        .deserialize(BorrowedStrDeserializer::new(key))
                        .map(Some)
                }
            }
        }
    }

    fn next_value_seed<V: DeserializeSeed<'de>>(&mut self, seed: V) -> Result<V::Value, A::Error> {
        self.map.next_value_seed(seed)
    }
}

#[cfg(test)]
thread_local! {
    /// A fault for the fuzz targets to find: the general reading keeps the
    /// last of a key given twice, as `serde_json::Value` does.
    pub(crate) static REPEATED_KEYS_KEPT: std::cell::Cell<bool> =
        const { std::cell::Cell::new(false) };
}

/// The line as one JSON value, each object's keys given once; a key
/// given twice is refused as a field of the request, named.
fn object(text: &str) -> std::result::Result<Value, ErrorKind> {
    #[cfg(test)]
    if REPEATED_KEYS_KEPT.get() {
        return serde_json::from_str(text).map_err(|e| malformed(text, e));
    }
    let json = &mut serde_json::Deserializer::from_str(text);
    let UniqueKeys(value) = serde_path_to_error::deserialize(&mut *json).map_err(|e| {
        if e.inner().classify() != Category::Data {
            return malformed(text, e.into_inner());
        }
        let path = Some(e.path().to_string());
        let message = without_position(e.inner());
        ErrorKind::Request { path, message }
    })?;
    json.end().map_err(|e| malformed(text, e))?;
    Ok(value)
}

/// A line that is not JSON, with the hint where it spells NaN or an
/// infinity.
fn malformed(text: &str, error: serde_json::Error) -> ErrorKind {
    let non_finite = safe_io::json::spells_non_finite(text, &error);
    ErrorKind::MalformedJson { error, non_finite }
}

/// What is wrong with a line: the error, and the law as the line gave it
/// (`null` when it gave none, or the line is not a JSON object).
pub type Refusal = (Value, Error);

/// The request on `text` read into a JSON object first, then into its
/// law's arguments, `steps` unless the line says otherwise; else what is
/// wrong with it. The line's `law` is checked first, then its `steps`,
/// then the law's own fields.
pub fn general(text: &str, steps: Steps) -> Result<Request<'static>, Refusal> {
    let refuse = |law: Value, kind: ErrorKind| Err((law, Error::from(kind)));
    if text.trim().is_empty() {
        return refuse(Value::Null, ErrorKind::EmptyLine);
    }
    let mut fields = match object(text) {
        Ok(Value::Object(map)) => map,
        Ok(_) => return refuse(Value::Null, ErrorKind::NotAnObject),
        Err(kind) => return refuse(Value::Null, kind),
    };
    let name = match fields.remove("law") {
        Some(Value::String(law)) => law,
        Some(other) => return refuse(other, ErrorKind::LawNotString),
        None => return refuse(Value::Null, ErrorKind::LawMissing),
    };
    let steps = match fields.remove("steps").map(bool::deserialize) {
        None => steps,
        Some(Ok(wanted)) => Steps::from_wanted(wanted),
        Some(Err(e)) => {
            let path = Some("steps".to_owned());
            let message = e.to_string();
            return refuse(Value::String(name), ErrorKind::Request { path, message });
        }
    };
    let mut track = serde_path_to_error::Track::new();
    let fields = serde_path_to_error::Deserializer::new(Value::Object(fields), &mut track);
    match Law::read(&name, fields) {
        Some(Ok(law)) => Ok(Request {
            name: Cow::Owned(name),
            law,
            steps,
        }),
        Some(Err(e)) => {
            let path = track.path().to_string();
            let path = (path != ".").then_some(path);
            let message = e.to_string();
            refuse(Value::String(name), ErrorKind::Request { path, message })
        }
        None => {
            let law = Value::String(name.clone());
            let expected = LAWS;
            refuse(
                law,
                ErrorKind::UnknownLaw {
                    law: name,
                    expected,
                },
            )
        }
    }
}
