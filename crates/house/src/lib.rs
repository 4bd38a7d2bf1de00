//! The house rules, checked: reads the workspace's Rust sources and names
//! every offender against the rules the workspace keeps (STYLE.md, habit 15,
//! and "Front ends over libraries"):
//!
//! - a. no product source file over 400 lines;
//! - b. no product function over 80 lines, from its `fn` line to its
//!   closing brace;
//! - c. no import circle between the files of one crate;
//! - d. no upward import: no file imports a name defined in the file of
//!   one of its ancestor modules (the crate root, a parent module file); a
//!   name the ancestor only re-exports is followed to where it is defined;
//! - e. no library error text names a command-line flag (`--name`): only
//!   the front ends ([`FRONT_ENDS`]) know their flags.
//!
//! Product code is every file under a package's `src/`, `examples/` and
//! `benches/` except test-only files (`#[cfg(test)] mod tests;` makes
//! `tests.rs` and all it declares test code; `tree.rs` says exactly);
//! `tests/` folders are test code. How each rule reads the code is written
//! in its module: `size` (a, b), `imports`, `resolve` and `graph` (c, d),
//! `texts` (e).
//!
//! The test `tests/house_rules.rs` runs [`offenders`] on this workspace and
//! fails naming every offender; `cargo run -p house --example offenders`
//! prints them with a count per rule.
//!
//! # Example
//!
//! A two-file crate whose child imports a name its parent defines breaks
//! rule d, and also rule c because the parent re-exports the child's name:
//!
//! ```
//! use house::{offenders, Rule};
//! let root = std::env::temp_dir().join(format!("house-doc-{}", std::process::id()));
//! std::fs::create_dir_all(root.join("src"))?;
//! std::fs::write(root.join("Cargo.toml"), "[package]\nname = \"demo\"\n")?;
//! std::fs::write(root.join("src/lib.rs"), "mod child;\npub use child::Thing;\npub struct Floor;\n")?;
//! std::fs::write(root.join("src/child.rs"), "use crate::Floor;\npub struct Thing(Floor);\n")?;
//!
//! let found = offenders(&root)?;
//! let rules: Vec<Rule> = found.iter().map(|o| o.rule).collect();
//! assert_eq!(rules, [Rule::ImportCircle, Rule::UpwardImport]);
//! assert_eq!(
//!     found[1].to_string(),
//!     "src/child.rs:1: imports `crate::Floor` from its ancestor src/lib.rs"
//! );
//! std::fs::remove_dir_all(&root)?;
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

#![warn(missing_docs)]

use std::path::{Path, PathBuf};

mod cfg;
mod error;
mod graph;
mod imports;
mod offender;
mod resolve;
mod scope;
mod size;
mod texts;
mod tree;
mod type_name;

pub use error::Error;
pub use offender::{Offender, Place, Rule, MAX_FILE_LINES, MAX_FN_LINES};

/// The front ends, by folder from the workspace root: they parse the flags,
/// so their error texts may name them (rule e does not apply).
pub const FRONT_ENDS: [&str; 1] = ["crates/optics"];

/// Every offender against the house rules in the packages under `root`,
/// sorted by rule, then place.
///
/// # Errors
///
/// A source file that cannot be read or does not parse as Rust.
pub fn offenders(root: &Path) -> Result<Vec<Offender>, Error> {
    let mut found = Vec::new();
    for package in tree::packages(root)? {
        let rel = |file: &PathBuf| file.strip_prefix(root).unwrap_or(file).to_path_buf();
        let product: Vec<&tree::Source> = package.sources.values().filter(|s| !s.test).collect();
        for source in &product {
            found.extend(size::long_file(source));
            found.extend(size::long_functions(source));
        }
        if !FRONT_ENDS.iter().any(|f| package.rel == Path::new(f)) {
            let errors = texts::error_types(product.iter().copied());
            for source in &product {
                found.extend(texts::flags_in_errors(source, &errors));
            }
        }
        for tree in &package.crates {
            let scopes = scope::Scopes::new(tree, &package.sources);
            let resolver = resolve::Resolver {
                tree,
                scopes: &scopes,
            };
            let mut arrows = Vec::new();
            for (file, module) in &tree.files {
                if !tree.modules[module].test {
                    let ast = &package.sources[file].ast;
                    arrows.extend(imports::arrows(&resolver, file, ast));
                }
            }
            found.extend(graph::upward(tree, &arrows, rel));
            found.extend(graph::circles(&arrows, rel));
        }
    }
    found.sort();
    found.dedup();
    Ok(found)
}

#[cfg(test)]
#[cfg(test)]
mod tests;
