//! Each rule shown to fail by a planted offender in a temporary tree, and
//! a clean tree (with the look-alikes each rule must let pass) shown to have
//! none.

use std::fs;
use std::path::PathBuf;

use crate::{offenders, Offender, Rule};

mod clean;
mod planted;
mod resolved;

/// A temporary workspace holding one package at its root.
struct Tree(tempfile::TempDir);

impl Tree {
    fn new() -> Self {
        let tree = Tree(tempfile::tempdir().expect("a temporary folder"));
        tree.file("Cargo.toml", "[package]\nname = \"planted\"\n")
    }

    /// Writes `text` at `path` (relative to the tree), making its folders.
    fn file(self, path: &str, text: &str) -> Self {
        let path = self.0.path().join(path);
        fs::create_dir_all(path.parent().expect("a folder")).expect("folders");
        fs::write(path, text).expect("a written file");
        self
    }

    fn offenders(&self) -> Vec<Offender> {
        offenders(self.0.path()).expect("a readable tree")
    }

    fn rules(&self) -> Vec<Rule> {
        self.offenders().iter().map(|o| o.rule).collect()
    }
}

/// `n` lines of comment.
fn lines(n: usize) -> String {
    "// a line\n".repeat(n)
}

/// A function `name` of exactly `n` lines, `fn` line to closing brace.
fn function(name: &str, n: usize) -> String {
    format!("fn {name}() {{\n{}}}\n", "    let _ = 1;\n".repeat(n - 2))
}

fn path(p: &str) -> PathBuf {
    PathBuf::from(p)
}
