//! `OPTICS_TRACER_SOURCE`: the tracer's and the laws' source as this build
//! compiles them, FNV-1a over every `.rs` file under `crates/tracer/src`
//! and `crates/radiometry/src` (path and bytes, in path order), so that a
//! cached truth rendered by other code is of another key
//! (`tradeoff::truth::TRACER_SOURCE`).

use std::path::{Path, PathBuf};

fn main() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let dirs = ["crates/tracer/src", "crates/radiometry/src"];
    let mut files = Vec::new();
    for dir in dirs {
        println!("cargo:rerun-if-changed=../{dir}");
        collect(&root.join(dir), &mut files);
    }
    files.sort();
    let mut hash: u64 = 0xcbf2_9ce4_8422_2325;
    for file in &files {
        let name = file
            .strip_prefix(&root)
            .unwrap_or(file)
            .to_string_lossy()
            .into_owned();
        let bytes = std::fs::read(file).unwrap_or_default();
        for &byte in name.as_bytes().iter().chain(&[0]).chain(&bytes).chain(&[0]) {
            hash ^= u64::from(byte);
            hash = hash.wrapping_mul(0x0000_0100_0000_01b3);
        }
    }
    println!("cargo:rustc-env=OPTICS_TRACER_SOURCE={hash:016x}");
}

/// Every `.rs` file under `dir`.
fn collect(dir: &Path, files: &mut Vec<PathBuf>) {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return;
    };
    for entry in entries.flatten() {
        let path = entry.path();
        if path.is_dir() {
            collect(&path, files);
        } else if path.extension().is_some_and(|e| e == "rs") {
            files.push(path);
        }
    }
}
