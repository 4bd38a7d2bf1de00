//! Regenerating the references with the pinned tools, and checking that
//! each reproduces the committed one by the rule of
//! `python-checks/reproduce.py` (byte for byte, but for the files written
//! through colour-science's BLAS products).

use std::path::Path;
use std::process::Command;

use crate::check::Check;
use crate::checkout::Checkout;
use crate::python::{run_tool, Task, ToolError};

/// The reference generators and the files each writes, in the order the
/// full run regenerates them.
pub const GENERATORS: [(&str, &[&str]); 8] = [
    ("fresnel_mpmath.py", &["fresnel_mpmath.json"]),
    ("fresnel_random.py", &["fresnel_random.json"]),
    ("mitsuba_laws.py", &["mitsuba_laws.json"]),
    ("colorimetry.py", &["colorimetry.json", "cie_tables.rs"]),
    ("metals.py", &["metals.json"]),
    ("mitsuba_render.py", &["mitsuba_renders.json"]),
    ("mitsuba_full_light.py", &["mitsuba_full_light.json"]),
    ("flip_reference.py", &["flip.json"]),
];

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

/// Regenerates every reference into `fresh` with `python` and checks each
/// against the checkout's committed copy.
pub fn regenerate(
    python: &Path,
    checkout: &Checkout,
    fresh: &Path,
) -> Result<Check, RegenerateError> {
    let scripts = checkout.python_checks();
    let mut check = Check::new(
        "references.regenerated",
        "Every committed reference regenerates with the pinned tools",
        "python-checks/ generators in the pinned environment",
        "the rule of python-checks/reproduce.py: byte-identical, but for the files written \
         through colour-science's BLAS products, whose numbers may move within its stated \
         tolerance",
    );
    for (script, outputs) in GENERATORS {
        let mut command = Command::new(python);
        command.arg("-W").arg("ignore").arg(scripts.join(script));
        for name in outputs {
            command.arg(fresh.join(name));
        }
        run_tool(command, Task::Script(format!("python-checks/{script}")))?;
        for name in outputs {
            check.cases += 1;
            let old = committed(checkout, name);
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
    Ok(check)
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

    #[test]
    fn every_regenerated_file_has_a_committed_copy() {
        let checkout = Checkout::at_build_time();
        for (script, outputs) in GENERATORS {
            assert!(checkout.python_checks().join(script).is_file(), "{script}");
            for name in outputs {
                let old = committed(&checkout, name);
                assert!(old.is_file(), "{}", old.display());
            }
        }
    }
}
