//! `optics compare`'s errors in both languages: one exhaustive `match`
//! over its kinds. The English names the flag each error came from, or is
//! the library's own where it already names the input by the name this
//! command gave it.

use std::path::Path;

use record::{say, Lang};
use tracer::scene::SceneError;

use crate::error::compare::{CompareError, PfmProblem, IMAGE, VARIANCE};

use super::output::output;
use super::scene::scene_kind_hu;

/// An image that cannot be compared, or one that disagrees, in `lang`.
pub(super) fn compare(error: &CompareError, lang: Lang) -> String {
    // The library's English, where it names the input as this command does.
    let library = |hu: String| match lang {
        Lang::En => error.to_string(),
        Lang::Hu => hu,
    };
    match error {
        CompareError::Read {
            field,
            path,
            source,
        } => library(file_hu(field, path, format!("nem olvasható: {source}"))),
        CompareError::UnknownFormat { field, path } => library(file_hu(
            field,
            path,
            "az első bájtjai szerint sem PNG, sem PFM".into(),
        )),
        CompareError::Png {
            field,
            path,
            message,
        } => library(file_hu(field, path, format!("nem olvasható PNG: {message}"))),
        CompareError::PngPixels {
            field,
            path,
            format,
        } => library(file_hu(
            field,
            path,
            format!("{format} képpontú PNG; az összevetés 8 bites sRGB képet olvas (RGB vagy RGBA)"),
        )),
        CompareError::Pfm {
            field,
            path,
            problem,
        } => library(file_hu(
            field,
            path,
            format!("nem olvasható PFM: {}", pfm_hu(*problem)),
        )),
        CompareError::BadValue {
            field,
            x,
            y,
            channel,
            value,
        } => bad_value(field, (*x, *y), *channel, *value, lang),
        CompareError::VarianceNeedsPfm { field } => variance_needs_pfm(field, lang),
        CompareError::Size {
            width,
            height,
            error,
        } => size(*width, *height, error, lang),
        CompareError::SizeMismatch { got, expected } => size_mismatch(*got, *expected, lang),
        CompareError::CourseReference => say!(
            lang,
            "--integrator: the reference is physical; give whitted, path, photon or local, not course",
            "--integrator: a referencia fizikai; whitted, path, photon vagy local adható meg, a \
             course nem"
        ),
        CompareError::Reference { message } => {
            library(format!("a referencia renderelése nem sikerült: {message}"))
        }
        CompareError::Diff(error) => format!("--diff: {}", output(error, lang)),
        CompareError::Disagrees {
            disagreeing,
            pixels,
        } => library(format!(
            "a kép {pixels} képpontból {disagreeing} helyen eltér a referenciától"
        )),
    }
}

/// A value that is not finite, or a negative variance.
fn bad_value(field: &str, (x, y): (u32, u32), channel: char, value: f32, lang: Lang) -> String {
    let variance = field == VARIANCE;
    say!(
        lang,
        "{field}: pixel ({x}, {y}) {channel} is {value}, not a finite number{}",
        "{field}: a(z) ({x}, {y}) képpont {channel} csatornája {value}, nem véges szám{}",
        if variance {
            lang.pick(" ≥ 0", ", ≥ 0")
        } else {
            ""
        }
    )
}

/// An image of a size the scene cannot be rendered at: the scene's
/// refusal of it.
fn size(width: u32, height: u32, error: &SceneError, lang: Lang) -> String {
    match lang {
        Lang::En => format!(
            "{IMAGE} is {width} × {height} pixels, a size the scene cannot be rendered at: {error}"
        ),
        Lang::Hu => format!(
            "az {IMAGE} {width} × {height} képpontos, ekkora méretben a jelenet nem \
             renderelhető: {}: {}",
            error.field(),
            scene_kind_hu(error.kind())
        ),
    }
}

/// A variance whose size is not the image's.
fn size_mismatch(got: (u32, u32), expected: (u32, u32), lang: Lang) -> String {
    say!(
        lang,
        "{VARIANCE} is {} × {} pixels, {IMAGE} {} × {}: they must be the same size",
        "a {VARIANCE} {} × {} képpontos, az {IMAGE} {} × {}: egyforma méretűnek kell lenniük",
        got.0,
        got.1,
        expected.0,
        expected.1
    )
}

/// A variance given as a PNG (`field` is the variance's flag), or for one.
fn variance_needs_pfm(field: &str, lang: Lang) -> String {
    match field {
        VARIANCE => say!(
            lang,
            "{VARIANCE}: give the variance as a PFM of linear values, not a PNG",
            "{VARIANCE}: a szórásnégyzetet lineáris értékek PFM-jeként kell megadni, nem PNG-ként"
        ),
        _ => say!(
            lang,
            "{field}: a PNG holds 8-bit codes, not radiance; a variance goes with a PFM of the mean",
            "{field}: a PNG 8 bites kódokat tárol, nem sugársűrűséget; szórásnégyzet az átlag \
             PFM-je mellé adható meg"
        ),
    }
}

/// A file named by `field` and what is wrong with it, in Hungarian.
fn file_hu(field: &str, path: &Path, what: String) -> String {
    format!("{field} {}: {what}", path.display())
}

fn pfm_hu(problem: PfmProblem) -> String {
    match problem {
        PfmProblem::Header => "a fejléc nem PF vagy Pf, majd szélesség, magasság és skála \
                               szóközökkel elválasztva"
            .to_owned(),
        PfmProblem::Scale => {
            "a skála nulla vagy nem véges szám (előjele adja a bájtsorrendet)".to_owned()
        }
        PfmProblem::Length { expected, got } => {
            format!("a fejléc szerint {expected} bájtnyi képpont következik, a fájlban {got} van")
        }
    }
}
