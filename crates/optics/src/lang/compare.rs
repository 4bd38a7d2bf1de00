//! `optics compare`'s errors in Hungarian: an exhaustive `match` over
//! its kinds.

use crate::error::compare::{CompareError, PfmProblem};

use super::render::{output_hu, scene_kind_hu};

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

/// A file named by `field` and what is wrong with it.
fn file_hu(field: &str, path: &std::path::Path, what: String) -> String {
    format!("{field} {}: {what}", path.display())
}

/// An image that cannot be compared, or one that disagrees.
pub fn compare_hu(error: &CompareError) -> String {
    match error {
        CompareError::Read {
            field,
            path,
            source,
        } => file_hu(field, path, format!("nem olvasható: {source}")),
        CompareError::UnknownFormat { field, path } => file_hu(
            field,
            path,
            "az első bájtjai szerint sem PNG, sem PFM".to_owned(),
        ),
        CompareError::Png {
            field,
            path,
            message,
        } => file_hu(field, path, format!("nem olvasható PNG: {message}")),
        CompareError::PngPixels {
            field,
            path,
            format,
        } => file_hu(
            field,
            path,
            format!(
                "{format} képpontú PNG; az összevetés 8 bites sRGB képet olvas (RGB vagy RGBA)"
            ),
        ),
        CompareError::Pfm {
            field,
            path,
            problem,
        } => file_hu(
            field,
            path,
            format!("nem olvasható PFM: {}", pfm_hu(*problem)),
        ),
        CompareError::BadValue {
            field,
            x,
            y,
            channel,
            value,
        } => bad_value_hu(field, (*x, *y), *channel, *value),
        CompareError::VarianceNeedsPfm { field } => variance_hu(field),
        CompareError::Size {
            width,
            height,
            error,
        } => format!(
            "az IMAGE {width} × {height} képpontos, ekkora méretben a jelenet nem renderelhető: \
             {}: {}",
            error.field(),
            scene_kind_hu(error.kind())
        ),
        CompareError::SizeMismatch { got, expected } => format!(
            "a --variance {} × {} képpontos, az IMAGE {} × {}: egyforma méretűnek kell lenniük",
            got.0, got.1, expected.0, expected.1
        ),
        CompareError::CourseReference => "--integrator: a referencia fizikai; whitted, path, \
                                          photon vagy local adható meg, a course nem"
            .to_owned(),
        CompareError::Reference { message } => {
            format!("a referencia renderelése nem sikerült: {message}")
        }
        CompareError::Diff(error) => format!("--diff: {}", output_hu(error)),
        CompareError::Disagrees {
            disagreeing,
            pixels,
        } => {
            format!("a kép {pixels} képpontból {disagreeing} helyen eltér a referenciától")
        }
    }
}

/// A variance given as a PNG, or for one.
fn variance_hu(field: &str) -> String {
    match field {
        "--variance" => "--variance: a szórásnégyzetet lineáris értékek PFM-jeként kell \
                         megadni, nem PNG-ként"
            .to_owned(),
        _ => format!(
            "{field}: a PNG 8 bites kódokat tárol, nem sugársűrűséget; szórásnégyzet az átlag \
             PFM-je mellé adható meg"
        ),
    }
}

/// A value that is not finite, or a negative variance.
fn bad_value_hu(field: &str, (x, y): (u32, u32), channel: char, value: f32) -> String {
    format!(
        "{field}: a(z) ({x}, {y}) képpont {channel} csatornája {value}, nem véges szám{}",
        if field == "--variance" { ", ≥ 0" } else { "" }
    )
}
