//! Each kind's text in the suite's two languages, side by side.
//! [`ErrorKind::message`] is one exhaustive `match` over the kinds, and each
//! arm gives both languages at once: by `say!`, which takes the English and
//! the Hungarian together, or by a function of the kind's domain (`input`,
//! `batch`, `scene`, `harness`, …) that does the same for its family. So a
//! kind without its Hungarian does not build. The English is also the
//! kind's `Display`.
//!
//! Kinds from a crate below (the radiometry crate's domain errors, the
//! tracer's scene and output errors, the harness's) keep that crate's own
//! English `Display`; their Hungarian is an exhaustive `match` here, beside
//! whatever this crate adds to them in both languages (a flag leading the
//! message, advice on what the command accepts).

use std::fmt;

use record::{say, Lang};

use super::kind::ErrorKind;

mod batch;
#[cfg(feature = "harness")]
mod budget;
#[cfg(feature = "harness")]
mod checkout;
#[cfg(feature = "harness")]
mod compare;
mod domain;
mod errata;
#[cfg(feature = "harness")]
mod harness;
mod input;
#[cfg(feature = "harness")]
mod jobs;
mod output;
#[cfg(feature = "harness")]
mod pipeline;
mod scene;
mod usage;
mod usage_hu;

pub(crate) use usage::rendered as usage_rendered;

impl ErrorKind {
    /// The kind's message in `lang`.
    pub fn message(&self, lang: Lang) -> String {
        match self {
            ErrorKind::Domain(error) => domain::domain(error, lang),
            ErrorKind::Usage(error) => usage::usage(error, lang),
            ErrorKind::VectorParts { count } => input::vector_parts(*count, lang),
            ErrorKind::VectorComponent { axis, text } => input::vector_component(axis, text, lang),
            ErrorKind::AngleDegrees { name, value } => input::angle_degrees(name, *value, lang),
            ErrorKind::CosineOrAngle { cosine, angle } => {
                input::cosine_or_angle(cosine, angle, lang)
            }
            ErrorKind::IndexOrMetal { eta, kappa, metal } => {
                input::index_or_metal([eta, kappa, metal], lang)
            }
            ErrorKind::EmptyList { name } => input::empty_list(name, lang),
            ErrorKind::ConductorFromInside {
                name,
                cos_i,
                degrees,
            } => input::conductor_from_inside(name, *cos_i, *degrees, lang),
            ErrorKind::NoCriticalAngle {
                name,
                n,
                name_outside,
                n_outside,
            } => input::no_critical_angle((name, *n), (name_outside, *n_outside), lang),
            ErrorKind::Overflow { quantity, inputs } => input::overflow(quantity, inputs, lang),
            ErrorKind::SchlickFormUnnamed { name } => {
                format!("{name}: {}", scene::schlick_form_unnamed(lang))
            }
            ErrorKind::EmptyLine => batch::empty_line(lang),
            ErrorKind::MalformedJson { error, non_finite } => {
                batch::malformed_json(error, *non_finite, lang)
            }
            ErrorKind::NotAnObject => batch::not_an_object(lang),
            ErrorKind::LawMissing => batch::law_missing(lang),
            ErrorKind::LawNotString => batch::law_not_string(lang),
            ErrorKind::UnknownLaw { law, expected } => batch::unknown_law(law, expected, lang),
            ErrorKind::Request { path, message } => batch::request(path.as_deref(), message, lang),
            ErrorKind::ReadLine { line, source } => batch::read_line(*line, source, lang),
            ErrorKind::LineTooLong { limit } => batch::line_too_long(*limit, lang),
            ErrorKind::NotUtf8 { column } => batch::not_utf8(*column, lang),
            ErrorKind::Write(error) => say!(
                lang,
                "cannot write the output: {error}",
                "a kimenet nem írható: {error}"
            ),
            ErrorKind::Encode(error) => say!(
                lang,
                "cannot write the result as JSON: {error}",
                "az eredmény nem írható JSON-ként: {error}"
            ),
            ErrorKind::Scene { file, error } => scene::scene(file, error, lang),
            ErrorKind::Output(error) => format!("--output: {}", output::output(error, lang)),
            ErrorKind::Threads(error) => say!(
                lang,
                "cannot start the render's threads: {error}",
                "a renderelés szálai nem indíthatók: {error}"
            ),
            ErrorKind::RadianceNotFinite { x, y } => say!(
                lang,
                "the radiance at pixel ({x}, {y}) is not finite in f32: the paths' gain \
                 exceeds f32 there; nothing was written",
                "a(z) ({x}, {y}) képpont sugársűrűsége nem véges f32-ben: az utak erősítése ott \
                 meghaladja az f32 tartományát; semmi sem íródott ki"
            ),
            ErrorKind::Errata(error) => errata::lookup(error, lang),
            #[cfg(feature = "harness")]
            ErrorKind::Harness(kind) => kind.message(lang),
        }
    }
}

impl fmt::Display for ErrorKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.message(Lang::En))
    }
}

#[cfg(test)]
mod tests;
