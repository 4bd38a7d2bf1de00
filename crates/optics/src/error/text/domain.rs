//! The radiometry crate's domain errors: its `Display` in English, an
//! exhaustive `match` over its kinds in Hungarian.

use radiometry::domain::{self, DomainError, Expected};
use record::Lang;

/// A domain error of the laws in `lang`: the input's name, what it should
/// have been, the value given.
pub(super) fn domain(error: &DomainError, lang: Lang) -> String {
    match lang {
        Lang::En => error.to_string(),
        Lang::Hu => domain_hu(error),
    }
}

/// A domain error of the laws in Hungarian.
fn domain_hu(error: &DomainError) -> String {
    match error {
        DomainError::NotFinite { name, value } => {
            format!("{name}: véges számnak kell lennie, kapott érték: {value}")
        }
        DomainError::OutOfRange {
            name,
            value,
            expected,
        } => format!(
            "{name}: {}, kapott érték: {}",
            expected_hu(*expected),
            domain::shown(*value)
        ),
        DomainError::ZeroVector { name, x, y, z } => {
            format!("{name}: nem nulla hosszú iránynak kell lennie, kapott: ({x}, {y}, {z})")
        }
    }
}

/// What an input should have been, as the rest of a Hungarian sentence
/// that names the input.
fn expected_hu(expected: Expected) -> String {
    let (low, high) = expected
        .index_range()
        .map(domain::IndexRange::ends_text)
        .unwrap_or_default();
    let f32_tier = "(az f32 törvények tartománya)";
    match expected {
        Expected::Cosine => "a [-1, 1] tartományba kell esnie".to_owned(),
        Expected::Fraction => "a [0, 1] tartományba kell esnie".to_owned(),
        Expected::NonNegative => "nemnegatívnak kell lennie".to_owned(),
        Expected::IncidenceAngle => "a [0, π/2] rad tartományba eső szögnek kell lennie".to_owned(),
        Expected::PositiveIndex => "pozitív törésmutatónak kell lennie".to_owned(),
        Expected::NonNegativeExtinction => "nemnegatív kioltási tényezőnek kell lennie".to_owned(),
        Expected::IndexInRange => format!("{low} és {high} közötti törésmutatónak kell lennie"),
        Expected::ExtinctionInRange => {
            format!("0 vagy {low} és {high} közötti kioltási tényezőnek kell lennie")
        }
        Expected::IndexInRangeF32 => {
            format!("{low} és {high} közötti törésmutatónak kell lennie {f32_tier}")
        }
        Expected::ExtinctionInRangeF32 => {
            format!("0 vagy {low} és {high} közötti kioltási tényezőnek kell lennie {f32_tier}")
        }
        Expected::WithinF32 => {
            "az f32 ábrázolási tartományán belül kell lennie (|x| < 3.4e38)".to_owned()
        }
        Expected::PositiveF32 => "pozitívnak (és f32-ben ábrázolhatónak) kell lennie".to_owned(),
    }
}
