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

/// An image that cannot be compared, or one that disagrees.
pub fn compare_hu(error: &CompareError) -> String {
    match error {
        CompareError::Read {
            field,
            path,
            source,
        } => {
            format!("{field} {}: nem olvasható: {source}", path.display())
        }
        CompareError::UnknownFormat { field, path } => format!(
            "{field} {}: az első bájtjai szerint sem PNG, sem PFM",
            path.display()
        ),
        CompareError::Png {
            field,
            path,
            message,
        } => {
            format!("{field} {}: nem olvasható PNG: {message}", path.display())
        }
        CompareError::PngPixels {
            field,
            path,
            format,
        } => format!(
            "{field} {}: {format} képpontú PNG; az összevetés 8 bites sRGB képet olvas \
             (RGB vagy RGBA)",
            path.display()
        ),
        CompareError::Pfm {
            field,
            path,
            problem,
        } => format!(
            "{field} {}: nem olvasható PFM: {}",
            path.display(),
            pfm_hu(*problem)
        ),
        CompareError::BadValue {
            field,
            x,
            y,
            channel,
            value,
        } => format!(
            "{field}: a(z) ({x}, {y}) képpont {channel} csatornája {value}, nem véges szám{}",
            if *field == "--variance" {
                ", ≥ 0"
            } else {
                ""
            }
        ),
        CompareError::VarianceNeedsPfm {
            field: "--variance",
        } => "--variance: a szórásnégyzetet lineáris értékek PFM-jeként kell megadni, nem PNG-ként"
            .to_owned(),
        CompareError::VarianceNeedsPfm { field } => format!(
            "{field}: a PNG 8 bites kódokat tárol, nem sugársűrűséget; szórásnégyzet az átlag \
             PFM-je mellé adható meg"
        ),
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
        CompareError::CourseReference => "--integrator: a referencia fizikai; whitted, path \
                                          vagy local adható meg, a course nem"
            .to_owned(),
        CompareError::Reference { message } => {
            format!("a referencia renderelése nem sikerült: {message}")
        }
        CompareError::Diff(error) => format!("--diff: {}", output_hu(error)),
        CompareError::Disagrees {
            disagreeing,
            pixels,
        } => format!("a kép {pixels} képpontból {disagreeing} helyen eltér a referenciától"),
    }
}
