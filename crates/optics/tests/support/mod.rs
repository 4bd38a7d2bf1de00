//! What the binary's test files share: running `optics`, listing a folder.
//! Each test file uses the part it needs.
#![allow(dead_code)]

use std::path::Path;
use std::process::{Command, Output};

/// The `optics` binary run with `args`, outside any checkout named by the
/// environment.
pub fn optics(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_optics"))
        .args(args)
        .env_remove("OPTICS_CHECKOUT")
        .output()
        .expect("the optics binary runs")
}

/// `dir`'s file names, sorted.
pub fn listing(dir: &Path) -> Vec<String> {
    let mut names: Vec<String> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    names
}
