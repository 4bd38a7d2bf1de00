//! The key of a deterministic table: a digest of everything its output
//! can depend on, so that a table slow to compute is computed again only
//! when one of them changes, as the references are regenerated only when
//! what made them changes (`python-checks/reference_keys.py`).
//!
//! A table's inputs are the program that prints it, the source of every
//! crate of the workspace it links (its package's dependencies and
//! dev-dependencies, and theirs, as `cargo metadata` lists them), the
//! files it reads (named by the program), the workspace's `Cargo.toml`
//! and `Cargo.lock` (every other crate's version and the build profiles)
//! and the compiler's version. The keys are kept in
//! `docs/results.keys.json`, written with the table.

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};
use std::process::Command;

use serde_json::Value;

use crate::error::Error;
use crate::root::workspace_root;

/// The file of the recorded keys, beside `docs/results.md`.
pub fn keys_path() -> PathBuf {
    workspace_root().join("docs/results.keys.json")
}

/// What a keyed table is computed from, as the program names it.
#[derive(Clone, Copy, Debug)]
pub struct Inputs<'a> {
    /// The package the program belongs to (`CARGO_PKG_NAME`).
    pub package: &'a str,
    /// The program's source, relative to the workspace root (`file!()`).
    pub program: &'a str,
    /// The files and directories it reads, relative to the workspace root.
    pub data: &'a [&'a str],
}

impl Inputs<'_> {
    /// The digest of every input file (path and bytes, in path order) and
    /// the compiler's version.
    pub fn key(&self) -> Result<String, Error> {
        let root = workspace_root();
        let root = root.canonicalize().map_err(|e| Error::io(&root, e))?;
        let mut files = BTreeSet::new();
        for dir in linked_crates(&root, self.package)? {
            for part in ["src", "Cargo.toml", "build.rs"] {
                collect(&root, &dir.join(part), &mut files)?;
            }
        }
        for path in [self.program, "Cargo.toml", "Cargo.lock"]
            .into_iter()
            .chain(self.data.iter().copied())
        {
            let path = root.join(path);
            if !path.exists() {
                return Err(Error::io(&path, std::io::ErrorKind::NotFound.into()));
            }
            collect(&root, &path, &mut files)?;
        }
        let mut digest = Fnv1a::new();
        for relative in &files {
            let bytes = std::fs::read(root.join(relative)).map_err(|e| Error::io(relative, e))?;
            digest.add(relative.to_string_lossy().as_bytes());
            digest.add(&(bytes.len() as u64).to_le_bytes());
            digest.add(&bytes);
        }
        digest.add(compiler().as_bytes());
        Ok(format!("{:016x}", digest.0))
    }
}

/// The key recorded for section `name`, if any.
pub fn recorded(name: &str) -> Result<Option<String>, Error> {
    Ok(read_keys()?
        .get(name)
        .and_then(Value::as_str)
        .map(str::to_owned))
}

/// Records `key` for section `name`, the other keys kept.
pub fn record(name: &str, key: &str) -> Result<(), Error> {
    let mut keys = read_keys()?;
    keys.insert(name.to_owned(), Value::String(key.to_owned()));
    let path = keys_path();
    let text = serde_json::to_string_pretty(&keys).expect("a map of strings") + "\n";
    let tmp = path.with_extension("json.tmp");
    std::fs::write(&tmp, text).map_err(|e| Error::io(&tmp, e))?;
    std::fs::rename(&tmp, &path).map_err(|e| Error::io(&path, e))
}

fn read_keys() -> Result<serde_json::Map<String, Value>, Error> {
    let path = keys_path();
    match std::fs::read_to_string(&path) {
        Ok(text) => serde_json::from_str(&text).map_err(|e| Error::Keys {
            path,
            message: e.to_string(),
        }),
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => Ok(serde_json::Map::new()),
        Err(e) => Err(Error::io(&path, e)),
    }
}

/// The directories of the workspace's crates that a program of `package`
/// links: `package` itself, its dependencies of every kind that are
/// workspace paths, and their normal and build dependencies, transitively.
fn linked_crates(root: &Path, package: &str) -> Result<Vec<PathBuf>, Error> {
    let cargo = std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into());
    let output = Command::new(cargo)
        .args([
            "metadata",
            "--format-version",
            "1",
            "--no-deps",
            "--offline",
        ])
        .arg("--manifest-path")
        .arg(root.join("Cargo.toml"))
        .output()
        .map_err(|e| Error::io(Path::new("cargo metadata"), e))?;
    let metadata: Value = serde_json::from_slice(&output.stdout).map_err(|e| Error::Keys {
        path: "cargo metadata".into(),
        message: e.to_string(),
    })?;
    let packages = metadata["packages"].as_array().cloned().unwrap_or_default();
    let find = |name: &str| packages.iter().find(|p| p["name"] == name);
    let mut seen: Vec<String> = Vec::new();
    let mut pending = vec![(package.to_owned(), true)];
    while let Some((name, all_kinds)) = pending.pop() {
        if seen.contains(&name) {
            continue;
        }
        let Some(found) = find(&name) else {
            return Err(Error::Keys {
                path: "cargo metadata".into(),
                message: format!("no workspace package `{name}`"),
            });
        };
        seen.push(name);
        for dep in found["dependencies"].as_array().into_iter().flatten() {
            let linked = all_kinds || dep["kind"].as_str() != Some("dev");
            if linked && dep["path"].is_string() {
                pending.push((dep["name"].as_str().unwrap_or_default().to_owned(), false));
            }
        }
    }
    seen.sort();
    Ok(seen
        .iter()
        .filter_map(|name| {
            let manifest = find(name)?["manifest_path"].as_str()?;
            Some(Path::new(manifest).parent()?.to_owned())
        })
        .collect())
}

/// Every file at or under `path`, relative to `root` (canonical, as
/// `cargo metadata` names the crates; nothing where `path` does not
/// exist: a crate without a `build.rs`).
fn collect(root: &Path, path: &Path, files: &mut BTreeSet<PathBuf>) -> Result<(), Error> {
    let relative = |p: &Path| {
        p.strip_prefix(root)
            .map_or_else(|_| p.to_owned(), Path::to_owned)
    };
    if path.is_file() {
        files.insert(relative(path));
    } else if path.is_dir() {
        let entries = std::fs::read_dir(path).map_err(|e| Error::io(path, e))?;
        for entry in entries {
            let entry = entry.map_err(|e| Error::io(path, e))?;
            collect(root, &entry.path(), files)?;
        }
    }
    Ok(())
}

/// The compiler's version, as `rustc -V` prints it.
fn compiler() -> String {
    Command::new("rustc")
        .arg("-V")
        .output()
        .ok()
        .and_then(|o| String::from_utf8(o.stdout).ok())
        .unwrap_or_else(|| "rustc unknown".to_owned())
}

/// The 64-bit FNV-1a digest.
struct Fnv1a(u64);

impl Fnv1a {
    fn new() -> Self {
        Fnv1a(0xcbf2_9ce4_8422_2325)
    }

    fn add(&mut self, bytes: &[u8]) {
        for &b in bytes {
            self.0 ^= u64::from(b);
            self.0 = self.0.wrapping_mul(0x0100_0000_01b3);
        }
    }
}
