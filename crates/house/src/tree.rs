//! The workspace as files: its packages, each package's crate roots, and the
//! module tree each root declares (`mod x;` → `x.rs` or `x/mod.rs`, or the
//! file a `#[path]` names).
//!
//! A file is *product* when it lies under a package's `src/`, `examples/` or
//! `benches/` and is not test-only. A file is *test-only* when every module
//! declaration that reaches it sits under `#[cfg(test)]` (`#[cfg(test)] mod
//! tests;` makes `tests.rs` and everything it declares test code), or when it
//! opens with `#![cfg(test)]`. A product file with an inline `#[cfg(test)] mod
//! tests { .. }` is still one product file, counted whole.

use std::collections::btree_map::Entry;
use std::collections::BTreeMap;
use std::fs;
use std::path::{Path, PathBuf};

use crate::cfg;
use crate::error::Error;

/// Folders of a package whose files are product code.
const PRODUCT_FOLDERS: [&str; 3] = ["src", "examples", "benches"];

/// One parsed source file.
pub(crate) struct Source {
    /// Relative to the workspace root.
    pub rel: PathBuf,
    /// The text, for counting lines.
    pub text: String,
    /// The parsed file.
    pub ast: syn::File,
    /// Whether only test builds compile it.
    pub test: bool,
}

/// A module of one crate: the file that holds it, and whether it is test-only.
#[derive(Clone, Debug)]
pub(crate) struct Module {
    pub file: PathBuf,
    pub test: bool,
}

/// One compiled crate: a root (`lib.rs`, `main.rs`, an example, a bench) and
/// the modules it declares, by path from the root (`[]` is the root).
#[derive(Default)]
pub(crate) struct CrateTree {
    pub modules: BTreeMap<Vec<String>, Module>,
    /// Each file's own module path (the module the file is, not an inline one).
    pub files: BTreeMap<PathBuf, Vec<String>>,
}

/// A package: its folder, parsed sources by absolute path, its crates.
pub(crate) struct Package {
    /// Relative to the workspace root.
    pub rel: PathBuf,
    pub sources: BTreeMap<PathBuf, Source>,
    pub crates: Vec<CrateTree>,
}

/// Every package under `root` (a folder with a `Cargo.toml` holding
/// `[package]`), skipping hidden folders and `target*` folders.
pub(crate) fn packages(root: &Path) -> Result<Vec<Package>, Error> {
    let mut folders = Vec::new();
    find_packages(root, &mut folders)?;
    folders.sort();
    folders.into_iter().map(|dir| package(root, &dir)).collect()
}

fn find_packages(dir: &Path, found: &mut Vec<PathBuf>) -> Result<(), Error> {
    let manifest = dir.join("Cargo.toml");
    if manifest.is_file() && read(&manifest)?.contains("[package]") {
        found.push(dir.to_path_buf());
    }
    for entry in entries(dir)? {
        let name = entry.file_name().and_then(|n| n.to_str()).unwrap_or("");
        let skipped = name.starts_with('.') || name.starts_with("target");
        if entry.is_dir() && !skipped {
            find_packages(&entry, found)?;
        }
    }
    Ok(())
}

fn package(root: &Path, dir: &Path) -> Result<Package, Error> {
    let mut package = Package {
        rel: dir.strip_prefix(root).unwrap_or(dir).to_path_buf(),
        sources: BTreeMap::new(),
        crates: Vec::new(),
    };
    for crate_root in crate_roots(dir)? {
        let mut tree = CrateTree::default();
        let walk = Walk {
            root,
            dir: &crate_root,
        };
        walk.file(
            &mut package,
            &mut tree,
            &crate_root,
            Vec::new(),
            false,
            true,
        )?;
        package.crates.push(tree);
    }
    // Product files no root declares are still product files.
    for folder in PRODUCT_FOLDERS {
        for file in rust_files(&dir.join(folder))? {
            if let Entry::Vacant(entry) = package.sources.entry(file) {
                let source = parse(root, entry.key(), false)?;
                entry.insert(source);
            }
        }
    }
    Ok(package)
}

/// `src/lib.rs`, `src/main.rs`, `src/bin/*`, `examples/*`, `benches/*`.
fn crate_roots(dir: &Path) -> Result<Vec<PathBuf>, Error> {
    let mut roots: Vec<PathBuf> = ["src/lib.rs", "src/main.rs"]
        .iter()
        .map(|r| dir.join(r))
        .filter(|p| p.is_file())
        .collect();
    for folder in ["src/bin", "examples", "benches"] {
        for entry in entries(&dir.join(folder))? {
            if entry.extension().is_some_and(|e| e == "rs") && entry.is_file() {
                roots.push(entry);
            } else if entry.join("main.rs").is_file() {
                roots.push(entry.join("main.rs"));
            }
        }
    }
    Ok(roots)
}

/// Walks one crate's module declarations.
struct Walk<'a> {
    root: &'a Path,
    dir: &'a Path,
}

impl Walk<'_> {
    /// Reads `file` as module `module`; `mod_rs` says whether its children
    /// live beside it (a root, `mod.rs`, a `#[path]` file) or in a folder
    /// named after it.
    fn file(
        &self,
        package: &mut Package,
        tree: &mut CrateTree,
        file: &Path,
        module: Vec<String>,
        test: bool,
        mod_rs: bool,
    ) -> Result<(), Error> {
        if tree.files.contains_key(file) {
            return Ok(());
        }
        if !package.sources.contains_key(file) {
            let source = parse(self.root, file, test)?;
            package.sources.insert(file.to_path_buf(), source);
        }
        let source = package.sources.get_mut(file).expect("inserted above");
        source.test &= test || cfg::is_test_only(&source.ast.attrs);
        let test = test || cfg::is_test_only(&source.ast.attrs);
        let items = source.ast.items.clone();
        tree.files.insert(file.to_path_buf(), module.clone());
        tree.modules.insert(
            module.clone(),
            Module {
                file: file.to_path_buf(),
                test,
            },
        );
        let parent = file.parent().unwrap_or(self.dir);
        let children = if mod_rs {
            parent.to_path_buf()
        } else {
            parent.join(file.file_stem().unwrap_or_default())
        };
        let at = Place { file, module, test };
        self.items(package, tree, &items, &at, &children, parent)
    }

    fn items(
        &self,
        package: &mut Package,
        tree: &mut CrateTree,
        items: &[syn::Item],
        at: &Place,
        children: &Path,
        file_dir: &Path,
    ) -> Result<(), Error> {
        for item in items {
            let syn::Item::Mod(declared) = item else {
                continue;
            };
            let name = declared.ident.to_string();
            let name = name.trim_start_matches("r#").to_string();
            let mut module = at.module.clone();
            module.push(name.clone());
            let test = at.test || cfg::is_test_only(&declared.attrs);
            let path = path_attribute(&declared.attrs);
            if let Some((_, inline)) = &declared.content {
                let place = Module {
                    file: at.file.to_path_buf(),
                    test,
                };
                tree.modules.insert(module.clone(), place);
                let inner = Place {
                    file: at.file,
                    module,
                    test,
                };
                let dir = path.map_or_else(|| children.join(&name), |p| children.join(p));
                self.items(package, tree, inline, &inner, &dir, file_dir)?;
            } else if let Some(path) = path {
                let base = if at.module.len() == tree.files[at.file].len() {
                    file_dir
                } else {
                    children
                };
                self.file(
                    package,
                    tree,
                    &lexical(&base.join(path)),
                    module,
                    test,
                    true,
                )?;
            } else if children.join(format!("{name}.rs")).is_file() {
                let file = children.join(format!("{name}.rs"));
                self.file(package, tree, &file, module, test, false)?;
            } else if children.join(&name).join("mod.rs").is_file() {
                let file = children.join(&name).join("mod.rs");
                self.file(package, tree, &file, module, test, true)?;
            }
        }
        Ok(())
    }
}

/// Where a walk stands: the file, the module path (a file's own or an
/// inline module's inside it), and whether it is test-only.
struct Place<'a> {
    file: &'a Path,
    module: Vec<String>,
    test: bool,
}

/// `path` with its `.` and `..` steps taken, without asking the file
/// system, so a file a `#[path]` reaches twice is one file.
fn lexical(path: &Path) -> PathBuf {
    let mut out = PathBuf::new();
    for part in path.components() {
        match part {
            std::path::Component::CurDir => {}
            std::path::Component::ParentDir if out.file_name().is_some() => {
                out.pop();
            }
            other => out.push(other),
        }
    }
    out
}

/// The value of a `#[path = "..."]` attribute.
fn path_attribute(attrs: &[syn::Attribute]) -> Option<String> {
    attrs.iter().find_map(|attr| match &attr.meta {
        syn::Meta::NameValue(nv) if nv.path.is_ident("path") => match &nv.value {
            syn::Expr::Lit(syn::ExprLit {
                lit: syn::Lit::Str(s),
                ..
            }) => Some(s.value()),
            _ => None,
        },
        _ => None,
    })
}

fn parse(root: &Path, file: &Path, test: bool) -> Result<Source, Error> {
    let text = read(file)?;
    let ast = syn::parse_file(&text).map_err(|e| Error::new(file, e))?;
    let test = test || cfg::is_test_only(&ast.attrs);
    Ok(Source {
        rel: file.strip_prefix(root).unwrap_or(file).to_path_buf(),
        text,
        ast,
        test,
    })
}

fn read(file: &Path) -> Result<String, Error> {
    fs::read_to_string(file).map_err(|e| Error::new(file, e))
}

/// The entries of a folder, sorted; none if it does not exist.
fn entries(dir: &Path) -> Result<Vec<PathBuf>, Error> {
    if !dir.is_dir() {
        return Ok(Vec::new());
    }
    let mut found = Vec::new();
    for entry in fs::read_dir(dir).map_err(|e| Error::new(dir, e))? {
        found.push(entry.map_err(|e| Error::new(dir, e))?.path());
    }
    found.sort();
    Ok(found)
}

/// Every `.rs` file under `dir`, at any depth.
fn rust_files(dir: &Path) -> Result<Vec<PathBuf>, Error> {
    let mut found = Vec::new();
    for entry in entries(dir)? {
        if entry.is_dir() {
            found.extend(rust_files(&entry)?);
        } else if entry.extension().is_some_and(|e| e == "rs") {
            found.push(entry);
        }
    }
    Ok(found)
}
