//! `optics errata`'s look-ups that found nothing, in both languages side
//! by side: each names the argument and what it accepts.

use ::errata::LookupError;
use record::{say, Lang};

/// An erratum id or a class of errata that the table does not have.
pub(super) fn lookup(error: &LookupError, lang: Lang) -> String {
    match error {
        LookupError::UnknownId { id } => say!(
            lang,
            "ID: no erratum has the id {id:?}; `optics errata` lists them all",
            "ID: egyik hiba azonosítója sem {id:?}; az `optics errata` mindet felsorolja"
        ),
        LookupError::UnknownClass { class } => say!(
            lang,
            "--class: {class:?} is not a class of errata; expected physics, picture or cosmetic",
            "--class: {class:?} nem hibaosztály; lehetséges: physics (fizika), picture (kép) vagy cosmetic (kozmetikai)"
        ),
    }
}
