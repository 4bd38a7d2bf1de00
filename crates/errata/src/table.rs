//! The table, read once from `errata.json`, and the ways into it: all in
//! the table's order, ranked, by id, by class, counted.

use std::fmt;
use std::sync::LazyLock;

use crate::erratum::{Class, Erratum};

/// The table as committed; its tests check every row (`tests.rs`).
pub(crate) const TABLE: &str = include_str!("../errata.json");

static ERRATA: LazyLock<Vec<Erratum>> = LazyLock::new(|| {
    // Compiled in and checked by the crate's tests: a row that does not
    // read is a build that fails its tests, never a user's input.
    serde_json::from_str(TABLE).expect("errata.json reads as the table of errata")
});

/// Every erratum, in the table's order: by class, worst first within each.
pub fn all() -> &'static [Erratum] {
    &ERRATA
}

/// Every erratum ranked: physics first, then picture, then cosmetic, and
/// within a class in the table's order, worst first.
pub fn ranked() -> Vec<&'static Erratum> {
    let mut ranked: Vec<&Erratum> = all().iter().collect();
    ranked.sort_by_key(|e| e.class);
    ranked
}

/// The `n` worst errata of the ranking.
pub fn worst(n: usize) -> Vec<&'static Erratum> {
    ranked().into_iter().take(n).collect()
}

/// How many errata each class has, worst class first.
pub fn counts() -> [(Class, usize); 3] {
    Class::ALL.map(|class| (class, all().iter().filter(|e| e.class == class).count()))
}

/// Why a look-up found nothing: the text asked for, as given.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum LookupError {
    /// No erratum has this id.
    UnknownId {
        /// The id asked for.
        id: String,
    },
    /// No class has this name.
    UnknownClass {
        /// The name asked for.
        class: String,
    },
}

impl fmt::Display for LookupError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            LookupError::UnknownId { id } => write!(f, "no erratum has the id {id:?}"),
            LookupError::UnknownClass { class } => write!(
                f,
                "{class:?} is not a class of errata: physics, picture or cosmetic"
            ),
        }
    }
}

impl std::error::Error for LookupError {}

/// The erratum with the id `id`.
pub fn find(id: &str) -> Result<&'static Erratum, LookupError> {
    all()
        .iter()
        .find(|e| e.id == id)
        .ok_or_else(|| LookupError::UnknownId { id: id.to_owned() })
}

/// The class named `name`, in English (`physics`, `picture`, `cosmetic`)
/// or Hungarian (`fizika`, `kép`, `kozmetikai`), in any case.
pub fn parse_class(name: &str) -> Result<Class, LookupError> {
    let lower = name.to_lowercase();
    Class::ALL
        .into_iter()
        .find(|c| c.name() == lower || c.word(record::Lang::Hu) == lower)
        .ok_or_else(|| LookupError::UnknownClass {
            class: name.to_owned(),
        })
}
