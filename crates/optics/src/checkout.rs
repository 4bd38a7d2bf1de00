//! Where the commands look for the suite's checkout: the directory a flag
//! names, else `OPTICS_CHECKOUT`, else the working directory's. Read here,
//! once, from the process's environment, and handed to the library, which
//! reads none.

use std::path::{Path, PathBuf};

use validation::checkout::{Lookup, ENV};

/// The checkout's whereabouts, `explicit` the directory a flag named.
pub fn lookup(explicit: Option<&Path>) -> Lookup {
    Lookup {
        explicit: explicit.map(Path::to_owned),
        env: std::env::var_os(ENV),
        cwd: std::env::current_dir().unwrap_or_else(|_| PathBuf::from(".")),
    }
}
