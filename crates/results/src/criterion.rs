//! Criterion's measurements, read back from the files it writes
//! (`<target>/criterion/<group>/<function>/new/{benchmark,estimates}.json`),
//! so that a bench can put its own numbers into a measured section.

use std::path::{Path, PathBuf};
use std::time::SystemTime;

use crate::document::settle;
use crate::error::Error;
use crate::root::workspace_root;
use crate::section::Section;

/// A bench's `main`, in place of `criterion_main!`: runs `benches` (a
/// `criterion_group!`), prints criterion's summary, and when the bench
/// measures (see [`Run::start`]) hands the run to `record`, which builds the
/// bench's measured section from the run's estimates, and settles that
/// section. A section that cannot be built or written (a filtered run, an
/// unwritable document) is reported and left as it was: the measurement
/// itself succeeded.
pub fn main(benches: fn(), record: fn(&Run) -> Result<Section, Error>) {
    let run = Run::start();
    benches();
    ::criterion::Criterion::default()
        .configure_from_args()
        .final_summary();
    if let Some(run) = run {
        if let Err(e) = record(&run).and_then(|section| settle(&section)) {
            eprintln!("docs/results.md not updated: {e}");
        }
    }
}

/// One benchmark's mean time per iteration, as criterion measured it.
#[derive(Debug, Clone, PartialEq)]
pub struct Estimate {
    /// Criterion's full id, `group/function` (or the name of an ungrouped
    /// benchmark).
    pub id: String,
    /// Mean time per iteration, in nanoseconds.
    pub mean_ns: f64,
    /// Elements per iteration, where the bench declared a throughput.
    pub elements: Option<u64>,
}

impl Estimate {
    /// Elements per second, where the bench declared a throughput.
    pub fn per_second(&self) -> Option<f64> {
        self.elements.map(|n| n as f64 / (self.mean_ns * 1e-9))
    }
}

/// A `cargo bench` run in progress: when it started, so that only the
/// estimates it wrote are read back.
#[derive(Debug, Clone, Copy)]
pub struct Run {
    started: SystemTime,
}

impl Run {
    /// `Some` when the bench measures (`cargo bench` passes `--bench`);
    /// `None` in criterion's test mode (`cargo test --benches`), which runs
    /// each benchmark once and measures nothing.
    pub fn start() -> Option<Self> {
        std::env::args().any(|a| a == "--bench").then(|| Self {
            started: SystemTime::now(),
        })
    }

    /// The estimates of `ids`, in that order, each written during this run;
    /// an error names the first one that was not (a filtered run).
    pub fn estimates(&self, ids: &[String]) -> Result<Vec<Estimate>, Error> {
        let found = read_all(&output_dir(), self.started)?;
        ids.iter()
            .map(|id| {
                found
                    .iter()
                    .find(|e| &e.id == id)
                    .cloned()
                    .ok_or_else(|| Error::NotMeasured(id.clone()))
            })
            .collect()
    }
}

/// Where criterion writes: `$CRITERION_HOME`, else `$CARGO_TARGET_DIR/criterion`,
/// else the workspace's `target/criterion` (criterion's own order).
pub fn output_dir() -> PathBuf {
    if let Some(home) = std::env::var_os("CRITERION_HOME") {
        return home.into();
    }
    std::env::var_os("CARGO_TARGET_DIR")
        .map(PathBuf::from)
        .unwrap_or_else(|| workspace_root().join("target"))
        .join("criterion")
}

/// Every estimate under `dir` written at or after `since`.
fn read_all(dir: &Path, since: SystemTime) -> Result<Vec<Estimate>, Error> {
    let mut found = Vec::new();
    let mut pending = vec![(dir.to_owned(), 0)];
    while let Some((dir, depth)) = pending.pop() {
        let new = dir.join("new");
        if new.join("estimates.json").is_file() {
            let modified = std::fs::metadata(new.join("estimates.json"))
                .and_then(|m| m.modified())
                .map_err(|e| Error::io(&new, e))?;
            if modified >= since {
                found.push(read_one(&new)?);
            }
        }
        if depth < 3 {
            for entry in std::fs::read_dir(&dir).map_err(|e| Error::io(&dir, e))? {
                let path = entry.map_err(|e| Error::io(&dir, e))?.path();
                if path.is_dir() && path.file_name().is_some_and(|n| n != "new" && n != "base") {
                    pending.push((path, depth + 1));
                }
            }
        }
    }
    Ok(found)
}

fn read_json(path: &Path) -> Result<serde_json::Value, Error> {
    let text = std::fs::read_to_string(path).map_err(|e| Error::io(path, e))?;
    serde_json::from_str(&text).map_err(|e| Error::Criterion(format!("{}: {e}", path.display())))
}

fn read_one(new: &Path) -> Result<Estimate, Error> {
    let benchmark = read_json(&new.join("benchmark.json"))?;
    let estimates = read_json(&new.join("estimates.json"))?;
    let field = |what: &str| Error::Criterion(format!("{}: no {what}", new.display()));
    Ok(Estimate {
        id: benchmark["full_id"]
            .as_str()
            .ok_or_else(|| field("full_id"))?
            .to_owned(),
        mean_ns: estimates["mean"]["point_estimate"]
            .as_f64()
            .ok_or_else(|| field("mean.point_estimate"))?,
        elements: benchmark["throughput"]["Elements"].as_u64(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn write(dir: &Path, id: &str, mean_ns: f64, throughput: &str) {
        std::fs::create_dir_all(dir).unwrap();
        let benchmark = format!(r#"{{"full_id": "{id}", "throughput": {throughput}}}"#);
        std::fs::write(dir.join("benchmark.json"), benchmark).unwrap();
        let estimates = format!(r#"{{"mean": {{"point_estimate": {mean_ns}}}}}"#);
        std::fs::write(dir.join("estimates.json"), estimates).unwrap();
    }

    #[test]
    fn grouped_and_ungrouped_estimates_are_read_with_their_throughput() {
        let root = tempfile_dir("read");
        write(&root.join("g/f/new"), "g/f", 50.0, r#"{"Elements": 1000}"#);
        write(&root.join("solo/new"), "solo", 8.0, "null");
        let mut found = read_all(&root, SystemTime::UNIX_EPOCH).unwrap();
        found.sort_by(|a, b| a.id.cmp(&b.id));
        assert_eq!(found[0].id, "g/f");
        // 1000 elements in 50 ns: 2e10 per second, exactly representable.
        assert_eq!(found[0].per_second(), Some(2e10));
        assert_eq!((found[1].id.as_str(), found[1].elements), ("solo", None));
        // An estimate older than the run is not this run's.
        let later = SystemTime::now() + std::time::Duration::from_secs(3600);
        assert!(read_all(&root, later).unwrap().is_empty());
        std::fs::remove_dir_all(&root).unwrap();
    }

    fn tempfile_dir(name: &str) -> PathBuf {
        let dir = std::env::temp_dir().join(format!("results-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        dir
    }
}
