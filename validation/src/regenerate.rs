//! The references, regenerated only where what made them changed.
//!
//! `python-checks/reference_keys.py` keys each reference by its generator's
//! source, the inputs it reads and the pinned tools, and
//! `validation/reference/keys.json` records the key each committed file was
//! written under, with its SHA-256. A reference whose key and bytes are as
//! recorded is current and is used as committed; any other is regenerated
//! (through the cache `out/cache`, whose entries are used only whole and of
//! the current key) and must reproduce the committed one by the rule of
//! `python-checks/reproduce.py` (byte for byte, but for the files written
//! through colour-science's BLAS products). `.ci/run` regenerates one
//! reference of each kind from scratch on every run, which keeps the proof
//! that the keyed references still reproduce.

use std::path::Path;
use std::process::Command;

use serde::Deserialize;

use crate::check::Check;
use crate::checkout::Checkout;
use crate::python::{run_tool, Task, ToolError};

/// One reference generator as `reference_keys.py --json` reports it.
#[derive(Clone, Debug, Deserialize)]
pub struct Generator {
    /// The script in `python-checks/`.
    pub generator: String,
    /// The kind of reference (the tool that computes it).
    pub kind: String,
    /// The files it writes, by name.
    pub outputs: Vec<String>,
    /// Why its committed output is not current; `None` when it is.
    pub state: Option<String>,
}

#[derive(Deserialize)]
struct States {
    generators: Vec<Generator>,
}

/// Why the regeneration could not be judged.
#[derive(Debug, thiserror::Error)]
pub enum RegenerateError {
    /// A generator, or the comparison, could not run or failed.
    #[error(transparent)]
    Tool(#[from] ToolError),
    /// `reproduce.py` could not tell whether a file reproduces.
    #[error("python-checks/reproduce.py could not compare {file} ({status}): {stderr}")]
    Undecided {
        /// The committed file.
        file: String,
        /// Its exit status.
        status: String,
        /// What it said.
        stderr: String,
    },
}

/// Where a regenerated file's committed copy lives: the references in
/// `validation/reference/`, the CIE tables in the radiometry crate.
fn committed(checkout: &Checkout, name: &str) -> std::path::PathBuf {
    if name.ends_with(".rs") {
        checkout.root().join("crates/radiometry/src").join(name)
    } else {
        checkout.reference_dir().join(name)
    }
}

const KEYS: &str = "python-checks/reference_keys.py";

/// Each generator and the state of its committed output, in the order the
/// references are regenerated.
pub fn states(python: &Path, checkout: &Checkout) -> Result<Vec<Generator>, RegenerateError> {
    let mut command = Command::new(python);
    command
        .arg(checkout.python_checks().join("reference_keys.py"))
        .arg("--json");
    let said = run_tool(command, Task::Script(KEYS.to_owned()))?;
    let states: States =
        serde_json::from_str(&said).map_err(|error| RegenerateError::Undecided {
            file: "validation/reference/keys.json".to_owned(),
            status: format!("{KEYS} --json printed no states"),
            stderr: error.to_string(),
        })?;
    Ok(states.generators)
}

/// Puts every reference into `fresh`: the current ones as committed, the
/// others regenerated (through `cache`) and checked against the
/// checkout's committed copy.
pub fn regenerate(
    python: &Path,
    checkout: &Checkout,
    fresh: &Path,
    cache: &Path,
) -> Result<Check, RegenerateError> {
    let scripts = checkout.python_checks();
    let mut check = Check::new(
        "references.regenerated",
        [
            "Every committed reference is current by its key, or regenerates with the pinned tools",
            "Minden tárolt referencia naprakész a kulcsa szerint, vagy újragenerálódik a rögzített eszközökkel",
        ],
        [
            "python-checks/reference_keys.py (the key: generator, inputs, pinned tools) and the \
             python-checks/ generators in the pinned environment",
            "python-checks/reference_keys.py (a kulcs: generátor, bemenetek, rögzített eszközök) és a \
             python-checks/ generátorai a rögzített környezetben",
        ],
        ["the rule of python-checks/reproduce.py: byte-identical, but for the files written \
         through colour-science's BLAS products, whose numbers may move within its stated \
         tolerance", "a python-checks/reproduce.py szabálya: bájtra azonos, kivéve a colour-science BLAS-szorzatain át írt fájlokat, amelyek számai a megadott tűrésén belül mozoghatnak"],
    );
    let mut regenerated = Vec::new();
    for generator in states(python, checkout)? {
        let script = &generator.generator;
        if let Some(why) = &generator.state {
            let mut command = Command::new(python);
            command
                .arg("-W")
                .arg("ignore")
                .arg(scripts.join("reference_keys.py"))
                .arg("--fresh")
                .arg(script)
                .arg(fresh)
                .arg("--cache")
                .arg(cache);
            run_tool(command, Task::Script(format!("python-checks/{script}")))?;
            regenerated.push(format!("{script} ({why})"));
        }
        for name in &generator.outputs {
            check.cases += 1;
            let old = committed(checkout, name);
            if generator.state.is_none() {
                copy_committed(&old, &fresh.join(name), &mut check);
                continue;
            }
            // Both must exist: two missing files are not a reproduction.
            if !(old.is_file() && fresh.join(name).is_file()) {
                check.fail(format!("{} or its regeneration is missing", old.display()));
                continue;
            }
            if let Some(said) = reproduces(python, &scripts, &old, &fresh.join(name))? {
                check.fail(format!(
                    "{} differs from what python-checks/{script} writes now ({said}): regenerate and commit it",
                    old.display()
                ));
            }
        }
    }
    let count = regenerated.len() as f64;
    check.measure_in_both(
        [
            "references regenerated, their key having changed",
            "újragenerált referenciák, mert a kulcsuk megváltozott",
        ],
        count,
        &regenerated.join("; "),
    );
    Ok(check)
}

/// The committed `old`, current by its key, copied to `new` for the checks.
fn copy_committed(old: &Path, new: &Path, check: &mut Check) {
    if let Err(error) = std::fs::copy(old, new) {
        check.fail(format!("{} could not be read: {error}", old.display()));
    }
}

/// `None` when `new` reproduces `old`; else where they differ, as
/// `reproduce.py` says it.
fn reproduces(
    python: &Path,
    scripts: &Path,
    old: &Path,
    new: &Path,
) -> Result<Option<String>, RegenerateError> {
    let output = Command::new(python)
        .arg(scripts.join("reproduce.py"))
        .arg(old)
        .arg(new)
        .output()
        .map_err(|source| ToolError::Start {
            what: Task::Script("python-checks/reproduce.py".to_owned()),
            program: python.display().to_string(),
            source,
        })?;
    let said = String::from_utf8_lossy(&output.stdout)
        .trim()
        .replace('\n', "; ");
    // 0: reproduces; 1: differs (stdout says where); anything else: it could not tell.
    match output.status.code() {
        Some(0) => Ok(None),
        Some(1) => Ok(Some(said)),
        _ => Err(RegenerateError::Undecided {
            file: old.display().to_string(),
            status: output.status.to_string(),
            stderr: String::from_utf8_lossy(&output.stderr).trim().to_owned(),
        }),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[derive(Deserialize)]
    struct Recorded {
        generators: Vec<Entry>,
    }

    #[derive(Deserialize)]
    struct Entry {
        generator: String,
        outputs: std::collections::BTreeMap<String, String>,
    }

    #[test]
    fn every_keyed_reference_has_its_generator_and_a_committed_copy() {
        let checkout = Checkout::at_build_time();
        let keys = std::fs::read_to_string(checkout.reference_dir().join("keys.json")).unwrap();
        let recorded: Recorded = serde_json::from_str(&keys).unwrap();
        let mut keyed = std::collections::BTreeSet::new();
        for entry in recorded.generators {
            let script = &entry.generator;
            assert!(checkout.python_checks().join(script).is_file(), "{script}");
            for name in entry.outputs.keys() {
                let old = committed(&checkout, name);
                assert!(old.is_file(), "{}", old.display());
                keyed.insert(name.clone());
            }
        }
        // And every reference is keyed: none is left out of the regeneration.
        for file in std::fs::read_dir(checkout.reference_dir()).unwrap() {
            let name = file.unwrap().file_name().into_string().unwrap();
            if name.ends_with(".json") && name != "keys.json" {
                assert!(keyed.contains(&name), "{name} has no key in keys.json");
            }
        }
        assert!(
            keyed.contains("cie_tables.rs"),
            "the CIE tables are keyed too"
        );
    }
}
