//! The suite's checkout, found when the harness runs: the committed
//! references, the scene files they were rendered from, and the Python
//! generators that write them all live there, not in the installed binary.
//!
//! Three ways name it, first match wins: an explicit directory (given by
//! the caller), the [`ENV`] environment variable, and a search upward from
//! the working directory. A directory is a checkout when it holds both
//! [`MARKERS`]. The errors say what was wrong with which directory; a front
//! end adds the flag that named it and the advice its command accepts.

use std::ffi::OsString;
use std::path::{Path, PathBuf};

/// The environment variable naming the checkout.
pub const ENV: &str = "OPTICS_CHECKOUT";

/// What only a checkout of the suite holds, relative to its root: the
/// committed references and the generators' pinned requirements.
pub const MARKERS: [&str; 2] = ["validation/reference", "python-checks/requirements.txt"];

/// How the checkout was named.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Via {
    /// An explicit directory, given by the caller.
    Explicit,
    /// The [`ENV`] environment variable.
    Environment,
    /// Found searching upward from the working directory.
    Search,
    /// The checkout this crate was built from ([`Checkout::at_build_time`]).
    BuildTime,
}

/// Why no checkout could be used.
#[derive(Debug, thiserror::Error)]
pub enum CheckoutError {
    /// The named directory is not a checkout of the suite.
    #[error("{} {}: not a checkout of the suite (it has no {marker})", via_name(*.via), .path.display())]
    NotACheckout {
        /// How it was named ([`Via::Explicit`] or [`Via::Environment`]).
        via: Via,
        /// The directory.
        path: PathBuf,
        /// The first marker it lacks.
        marker: &'static str,
    },
    /// None was named and none contains the working directory.
    #[error(
        "no checkout of the suite found: none was named, {ENV} is unset or empty, and neither {} nor a \
         directory above it holds both {} and {}",
        .start.display(), MARKERS[0], MARKERS[1]
    )]
    NotFound {
        /// Where the upward search started.
        start: PathBuf,
    },
}

fn via_name(via: Via) -> &'static str {
    match via {
        Via::Explicit => "the directory named",
        Via::Environment => ENV,
        Via::Search => "the working directory",
        Via::BuildTime => "this build's checkout",
    }
}

/// A checkout of the suite.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Checkout {
    root: PathBuf,
    via: Via,
}

/// Where a checkout is looked for, as a front end read it: the directory
/// its user named, the value of [`ENV`] and the working directory. The
/// library reads no environment; it is handed this.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Lookup {
    /// The directory named (a front end's flag), if any.
    pub explicit: Option<PathBuf>,
    /// The value of [`ENV`], if set.
    pub env: Option<OsString>,
    /// The working directory, searched upward.
    pub cwd: PathBuf,
}

impl Lookup {
    /// The checkout this names ([`Checkout::locate`]).
    pub fn find(&self) -> Result<Checkout, CheckoutError> {
        Checkout::locate(self.explicit.as_deref(), self.env.clone(), &self.cwd)
    }
}

impl Checkout {
    /// The checkout named by `explicit`, else by `env` (the value of
    /// [`ENV`]), else the nearest one containing `cwd`. An empty variable
    /// counts as unset.
    pub fn locate(
        explicit: Option<&Path>,
        env: Option<OsString>,
        cwd: &Path,
    ) -> Result<Self, CheckoutError> {
        let named = match (explicit, env.filter(|v| !v.is_empty())) {
            (Some(dir), _) => Some((dir.to_owned(), Via::Explicit)),
            (None, Some(dir)) => Some((PathBuf::from(dir), Via::Environment)),
            (None, None) => None,
        };
        if let Some((path, via)) = named {
            return match missing_marker(&path) {
                Some(marker) => Err(CheckoutError::NotACheckout { via, path, marker }),
                None => Ok(Self { root: path, via }),
            };
        }
        cwd.ancestors()
            .find(|dir| missing_marker(dir).is_none())
            .map(|dir| Self {
                root: dir.to_owned(),
                via: Via::Search,
            })
            .ok_or_else(|| CheckoutError::NotFound {
                start: cwd.to_owned(),
            })
    }

    /// The checkout this crate was built from, for tests and examples; the
    /// harness's command finds its checkout with [`Lookup::find`].
    pub fn at_build_time() -> Self {
        let manifest = Path::new(env!("CARGO_MANIFEST_DIR"));
        Self {
            root: manifest.parent().unwrap_or(manifest).to_owned(),
            via: Via::BuildTime,
        }
    }

    /// Its root directory.
    pub fn root(&self) -> &Path {
        &self.root
    }

    /// How it was named.
    pub fn via(&self) -> Via {
        self.via
    }

    /// The committed references, `validation/reference/`.
    pub fn reference_dir(&self) -> PathBuf {
        self.root.join("validation/reference")
    }

    /// The reference generators and their requirements, `python-checks/`.
    pub fn python_checks(&self) -> PathBuf {
        self.root.join("python-checks")
    }
}

/// The first of [`MARKERS`] that `dir` lacks.
fn missing_marker(dir: &Path) -> Option<&'static str> {
    MARKERS.into_iter().find(|m| !dir.join(m).exists())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A directory holding a checkout's markers at `checkout/`, and a
    /// directory nested inside it.
    fn fake_checkout() -> (tempfile::TempDir, PathBuf, PathBuf) {
        let top = tempfile::tempdir().unwrap();
        let root = top.path().join("checkout");
        std::fs::create_dir_all(root.join("validation/reference")).unwrap();
        std::fs::create_dir_all(root.join("python-checks")).unwrap();
        std::fs::write(root.join("python-checks/requirements.txt"), "").unwrap();
        let nested = root.join("crates/optics");
        std::fs::create_dir_all(&nested).unwrap();
        (top, root, nested)
    }

    #[test]
    fn the_search_finds_the_checkout_above_the_working_directory() {
        let (_top, root, nested) = fake_checkout();
        let found = Checkout::locate(None, None, &nested).unwrap();
        assert_eq!((found.root(), found.via()), (root.as_path(), Via::Search));
    }

    #[test]
    fn the_explicit_directory_wins_over_the_variable_and_the_variable_over_the_search() {
        let (top, root, _) = fake_checkout();
        let elsewhere = top.path().to_owned();
        let env = Some(OsString::from(&root));
        let by_env = Checkout::locate(None, env.clone(), &elsewhere).unwrap();
        assert_eq!(by_env.via(), Via::Environment);
        let by_flag = Checkout::locate(Some(&root), Some("/nonexistent".into()), &elsewhere);
        assert_eq!(by_flag.unwrap().via(), Via::Explicit);
        // An empty variable is unset: the search decides.
        let error = Checkout::locate(None, Some(OsString::new()), &elsewhere).unwrap_err();
        assert!(matches!(error, CheckoutError::NotFound { .. }), "{error}");
    }

    #[test]
    fn a_named_directory_that_is_not_a_checkout_is_refused_with_what_it_lacks() {
        let (top, _, _) = fake_checkout();
        let error = Checkout::locate(None, Some(top.path().into()), top.path()).unwrap_err();
        let message = error.to_string();
        assert!(
            message.starts_with(ENV) && message.contains("validation/reference"),
            "{message}"
        );
    }

    #[test]
    fn no_checkout_names_the_places_searched_and_no_flag() {
        let top = tempfile::tempdir().unwrap();
        let message = Checkout::locate(None, None, top.path())
            .unwrap_err()
            .to_string();
        let start = top.path().display().to_string();
        for place in [ENV, &start, MARKERS[0], MARKERS[1]] {
            assert!(message.contains(place), "{message}");
        }
        assert!(!message.contains("--"), "{message}");
    }

    #[test]
    fn an_explicit_directory_that_is_not_a_checkout_is_named_by_no_flag() {
        let (top, _, _) = fake_checkout();
        let error = Checkout::locate(Some(top.path()), None, top.path()).unwrap_err();
        let message = error.to_string();
        assert!(message.starts_with("the directory named "), "{message}");
        assert!(!message.contains("--"), "{message}");
    }

    #[test]
    fn this_build_s_checkout_is_one() {
        let checkout = Checkout::at_build_time();
        assert_eq!(missing_marker(checkout.root()), None);
        assert!(checkout.reference_dir().join("mitsuba_laws.json").is_file());
    }
}
