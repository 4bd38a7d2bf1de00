//! The suite's errors in its two languages ([`record::Lang`]): English is
//! each kind's `Display`, Hungarian an exhaustive `match` over the kinds here.

use crate::error::{Error, ErrorKind};
use record::Lang;

#[cfg(feature = "harness")]
mod compare;
mod domain;
#[cfg(feature = "harness")]
mod harness;
#[cfg(feature = "harness")]
mod jobs;
pub mod needs;
mod render;

pub use domain::{domain_hu, expected_hu};

impl Error {
    /// The error as JSON: `{"kind": …, "field": …, "message": …}`, the
    /// message in `lang`, the field `null` when unknown.
    pub fn to_json(&self, lang: Lang) -> serde_json::Value {
        serde_json::json!({
            "kind": self.kind().name(),
            "field": self.field(),
            "message": error_message(self, lang),
        })
    }
}

/// An error's message in `lang`: the English is the kind's `Display`, the
/// Hungarian an exhaustive `match` over the kinds.
pub fn error_message(error: &Error, lang: Lang) -> String {
    match lang {
        Lang::En => error.to_string(),
        Lang::Hu => hungarian(error.kind()),
    }
}

/// Light from inside a conductor, in the quantity it was given as.
fn conductor_from_inside_hu(name: &str, cos_i: f64, degrees: Option<f64>) -> String {
    match degrees {
        Some(degrees) => format!(
            "{name}: vezetőnél (kappa > 0) legfeljebb 90 fok lehet: fény nem érkezhet fém belsejéből, kapott érték: {degrees}"
        ),
        None => format!(
            "{name}: vezetőnél (kappa > 0) ≥ 0 kell legyen: fény nem érkezhet fém belsejéből, kapott érték: {cos_i}"
        ),
    }
}

fn hungarian(kind: &ErrorKind) -> String {
    match kind {
        ErrorKind::Domain(error) => domain_hu(error),
        ErrorKind::Usage(error) => usage_hu(error),
        ErrorKind::VectorParts { count } => format!(
            "három vesszővel elválasztott számot kell megadni (például 0,3,4), kapott részek száma: {count}"
        ),
        ErrorKind::VectorComponent { axis, text } => {
            format!("a(z) {axis} komponens ({text:?}) nem szám")
        }
        ErrorKind::AngleDegrees { name, value } => format!(
            "{name}: a [0, 180] fok tartományba eső szögnek kell lennie, kapott érték: {value}"
        ),
        ErrorKind::CosineOrAngle { cosine, angle } => {
            format!("{cosine} és {angle} közül pontosan egyet kell megadni")
        }
        ErrorKind::ConductorFromInside {
            name,
            cos_i,
            degrees,
        } => conductor_from_inside_hu(name, *cos_i, *degrees),
        ErrorKind::NoCriticalAngle {
            name,
            n,
            name_outside,
            n_outside,
        } => format!(
            "{name} = {n} nem nagyobb, mint {name_outside} = {n_outside}: sűrűbb (vagy azonos) közegbe lépő fény mindig megtörik, nincs határszög"
        ),
        ErrorKind::EmptyLine => "üres sor: minden sor egy kérést tartalmaz".to_owned(),
        ErrorKind::MalformedJson { error, non_finite } => format!(
            "hibás JSON: {error}{}",
            if *non_finite {
                " (a JSON számai végesek: a NaN és az Infinity nem szám)"
            } else {
                ""
            }
        ),
        ErrorKind::NotAnObject => "a kérésnek JSON-objektumnak kell lennie".to_owned(),
        ErrorKind::LawMissing => "law: hiányzik; minden kérés megnevezi a törvényét".to_owned(),
        ErrorKind::LawNotString => "law: szövegnek kell lennie".to_owned(),
        ErrorKind::UnknownLaw { law, expected } => format!(
            "law: ismeretlen törvény: {law:?}, a lehetségesek: {}",
            expected.join(", ")
        ),
        ErrorKind::Request {
            path: Some(path),
            message,
        } => format!("{path}: a kérés mezője nem olvasható: {message}"),
        ErrorKind::Request {
            path: None,
            message,
        } => format!("a kérés nem olvasható: {message}"),
        ErrorKind::ReadLine { line, source } => {
            format!("a(z) {line}. sor nem olvasható: {source}")
        }
        ErrorKind::LineTooLong { limit } => format!(
            "a sor hosszabb {limit} bájtnál (egy kérés néhány számból álló objektum): \
             olvasás nélkül a végéig átugorva"
        ),
        ErrorKind::NotUtf8 { column } => {
            format!("a sor nem UTF-8 szöveg: a(z) {column}. oszlopban lévő bájt hibás")
        }
        ErrorKind::Overflow { quantity, inputs } => format!(
            "{quantity} túlcsordul: {} értékével a legnagyobb véges szám (1.8e308) fölé nő; kisebb értékeket kell megadni",
            inputs.join(", ")
        ),
        ErrorKind::Write(error) => format!("a kimenet nem írható: {error}"),
        ErrorKind::Encode(error) => format!("az eredmény nem írható JSON-ként: {error}"),
        ErrorKind::Scene { file, error } => render::scene_hu(file, error),
        ErrorKind::Output(error) => format!("--output: {}", render::output_hu(error)),
        ErrorKind::Threads(error) => format!("a renderelés szálai nem indíthatók: {error}"),
        ErrorKind::RadianceNotFinite { x, y } => render::not_finite_hu(*x, *y),
        #[cfg(feature = "harness")]
        ErrorKind::Harness(kind) => harness::harness_hu(kind),
    }
}

/// A command-line error: a lead-in naming the argument, then the suite's
/// own message translated, or else the argument parser's as it wrote it.
fn usage_hu(error: &clap::Error) -> String {
    use std::error::Error as _;
    let ours = error.source().and_then(|e| e.downcast_ref::<Error>());
    let mut message = ours.map_or_else(
        || crate::error::usage_message(error),
        |e| hungarian(e.kind()),
    );
    if let Some(fixed) = crate::error::decimal_comma_fixed(error) {
        message += &format!(" (a számokban tizedespont áll, nem vessző: {fixed})");
    }
    match crate::error::usage_argument(error) {
        Some(arg) => format!("hibás parancssori argumentum ({arg}): {message}"),
        None => format!("hibás parancssor: {message}"),
    }
}

#[cfg(test)]
mod tests;
