//! Writing a set of files atomically as a set: each to a temporary beside
//! it, then all renamed into place under the interruption lock, with the
//! files already renamed put back if a later rename fails.

use std::io::{self, Write};
use std::path::{Path, PathBuf};

use tempfile::TempPath;

use crate::error::WriteError;
use crate::interrupt::{self, PausePoint, Phase, Registry};

/// A complete temporary and the file it becomes.
struct Staged<'a> {
    target: &'a Path,
    temp: TempPath,
}

/// A destination's previous file, moved aside while the set is renamed.
struct Backup<'a> {
    target: &'a Path,
    aside: Option<TempPath>,
}

fn io_error(path: &Path) -> impl Fn(io::Error) -> WriteError + '_ {
    move |source| WriteError::Io {
        path: path.display().to_string(),
        source,
    }
}

/// The directory `path` is written into, which must exist.
pub(crate) fn directory(path: &Path) -> Result<&Path, WriteError> {
    let dir = match path.parent() {
        Some(d) if !d.as_os_str().is_empty() => d,
        _ => Path::new("."),
    };
    if !dir.is_dir() {
        return Err(WriteError::NoDirectory {
            path: path.display().to_string(),
            dir: dir.display().to_string(),
        });
    }
    Ok(dir)
}

/// A new, empty, registered temporary in `dir`.
fn temporary(dir: &Path) -> io::Result<tempfile::NamedTempFile> {
    new_temporary(&mut interrupt::lock(), dir)
}

/// Whether a file can be created in `dir`: one is, then removed.
pub(crate) fn probe(dir: &Path) -> io::Result<()> {
    let mut registry = interrupt::lock();
    let file = new_temporary(&mut registry, dir)?;
    registry.forget(file.path());
    Ok(())
}

/// A new, empty temporary in `dir`, registered in the locked `registry`.
fn new_temporary(registry: &mut Registry, dir: &Path) -> io::Result<tempfile::NamedTempFile> {
    // tempfile's message repeats the path; the error names the destination.
    let file = tempfile::NamedTempFile::new_in(dir).map_err(|e| {
        let text = e.to_string();
        io::Error::new(e.kind(), text.split(" at path ").next().unwrap_or_default())
    })?;
    registry.add(file.path().to_owned());
    Ok(file)
}

/// Writes `bytes` to `path` atomically: a temporary file beside it, renamed.
pub fn write_atomically(path: &Path, bytes: &[u8]) -> Result<(), WriteError> {
    write_all_atomically(&[(path, bytes)])
}

/// Writes every `(path, bytes)` of `files` so that either each of them is
/// replaced whole or none is: after a write error, a failed rename or
/// SIGINT/SIGTERM the previous files are as they were (see
/// [`crate::interrupt`] for what SIGKILL and power loss can leave).
pub fn write_all_atomically(files: &[(&Path, &[u8])]) -> Result<(), WriteError> {
    interrupt::set_phase(Phase::Staging);
    let mut staged = Vec::with_capacity(files.len());
    let mut result = Ok(());
    for (i, (path, bytes)) in files.iter().enumerate() {
        if i > 0 {
            interrupt::pause(PausePoint::MidStage);
        }
        match stage(path, bytes) {
            Ok(file) => staged.push(file),
            Err(error) => {
                result = Err(error);
                break;
            }
        }
    }
    if result.is_ok() {
        interrupt::set_phase(Phase::Staged);
        interrupt::pause(PausePoint::BeforeCommit);
    }
    // Under the lock each temporary is renamed or removed before a signal
    // can be handled, so none needs to stay registered.
    let mut registry = interrupt::lock();
    for file in &staged {
        registry.forget(&file.temp);
    }
    if result.is_ok() {
        result = commit(&mut registry, staged, &|from, to| std::fs::rename(from, to));
    } else {
        drop(staged);
    }
    interrupt::set_phase(Phase::Idle);
    result
}

/// Writes `bytes` to a complete temporary beside `path`.
fn stage<'a>(path: &'a Path, bytes: &[u8]) -> Result<Staged<'a>, WriteError> {
    let io = io_error(path);
    let mut temp = temporary(directory(path)?).map_err(&io)?;
    if let Err(error) = fill(&mut temp, path, bytes) {
        // Removed under the lock, so that no signal finds it registered and gone.
        let mut registry = interrupt::lock();
        registry.forget(temp.path());
        drop(temp);
        return Err(io(error));
    }
    Ok(Staged {
        target: path,
        temp: temp.into_temp_path(),
    })
}

/// Writes `bytes` to `temp`, with the permissions of `path`'s previous
/// file (an ordinary 0644 when there is none), and flushes it to disk.
fn fill(temp: &mut tempfile::NamedTempFile, path: &Path, bytes: &[u8]) -> io::Result<()> {
    // Temporary files are private (0600); an image is an ordinary file.
    #[cfg(unix)]
    {
        use std::os::unix::fs::PermissionsExt;
        let mode = std::fs::metadata(path).map_or(0o644, |m| m.permissions().mode());
        temp.as_file()
            .set_permissions(std::fs::Permissions::from_mode(mode))?;
    }
    #[cfg(not(unix))]
    let _ = path;
    temp.write_all(bytes)?;
    temp.as_file().sync_all()
}

/// Renames every staged file into place with `rename`, under the
/// interruption lock (held as `registry`); on a failure, puts back what
/// was renamed.
fn commit(
    registry: &mut Registry,
    staged: Vec<Staged<'_>>,
    rename: &dyn Fn(&Path, &Path) -> io::Result<()>,
) -> Result<(), WriteError> {
    interrupt::set_phase(Phase::Committing);
    let last = staged.len().saturating_sub(1);
    let mut done: Vec<Backup> = Vec::new();
    for (i, file) in staged.into_iter().enumerate() {
        if i > 0 {
            interrupt::pause(PausePoint::MidCommit);
        }
        match commit_one(registry, file, i < last, rename) {
            Ok(backup) => done.push(backup),
            Err(error) => {
                for backup in done.into_iter().rev() {
                    restore(backup);
                }
                return Err(error);
            }
        }
    }
    // Dropping the backups removes the previous files.
    drop(done);
    Ok(())
}

/// Renames one staged file into place, its previous file first set aside
/// when `keep_previous` (the last file of a set needs no backup: if its
/// rename fails, it is unchanged).
fn commit_one<'a>(
    registry: &mut Registry,
    file: Staged<'a>,
    keep_previous: bool,
    rename: &dyn Fn(&Path, &Path) -> io::Result<()>,
) -> Result<Backup<'a>, WriteError> {
    let temp: PathBuf = file.temp.to_path_buf();
    let aside = match keep_previous {
        true => set_aside(registry, file.target)?,
        false => None,
    };
    let backup = Backup {
        target: file.target,
        aside,
    };
    match rename(&temp, file.target) {
        Ok(()) => {
            // Renamed: nothing is left to delete under the old name.
            let _ = file.temp.keep();
            Ok(backup)
        }
        Err(error) => {
            if backup.aside.is_some() {
                restore(backup);
            }
            Err(io_error(file.target)(error))
        }
    }
}

/// Moves `target`'s previous file, if any, to a new name beside it; the
/// backup is removed when dropped.
fn set_aside(registry: &mut Registry, target: &Path) -> Result<Option<TempPath>, WriteError> {
    if std::fs::symlink_metadata(target).is_err() {
        return Ok(None);
    }
    let io = io_error(target);
    let aside = new_temporary(registry, directory(target)?)
        .map_err(&io)?
        .into_temp_path();
    registry.forget(&aside);
    std::fs::rename(target, &aside).map_err(&io)?;
    Ok(Some(aside))
}

/// Puts `backup`'s previous file back in place, or, when there was none,
/// removes what was renamed there.
fn restore(backup: Backup<'_>) {
    match backup.aside {
        Some(aside) => {
            if std::fs::rename(&aside, backup.target).is_ok() {
                let _ = aside.keep();
            }
        }
        None => {
            let _ = std::fs::remove_file(backup.target);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `dir`'s file names, sorted.
    fn listing(dir: &Path) -> Vec<String> {
        let mut names: Vec<String> = std::fs::read_dir(dir)
            .unwrap()
            .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
            .collect();
        names.sort();
        names
    }

    /// Stages `files` and commits them with a rename that fails for
    /// `failing`.
    fn commit_failing_at(files: &[(&Path, &[u8])], failing: &Path) -> Result<(), WriteError> {
        let staged = files
            .iter()
            .map(|(path, bytes)| stage(path, bytes))
            .collect::<Result<Vec<_>, _>>()?;
        let mut registry = interrupt::lock();
        for file in &staged {
            registry.forget(&file.temp);
        }
        let rename = |from: &Path, to: &Path| match to == failing {
            true => Err(io::Error::other("injected rename failure")),
            false => std::fs::rename(from, to),
        };
        commit(&mut registry, staged, &rename)
    }

    #[test]
    fn a_pair_is_replaced_whole_and_leaves_no_temporary() {
        let dir = tempfile::tempdir().unwrap();
        let (png, pfm) = (dir.path().join("a.png"), dir.path().join("a.pfm"));
        std::fs::write(&png, "old png").unwrap();
        std::fs::write(&pfm, "old pfm").unwrap();
        write_all_atomically(&[(&png, b"new png"), (&pfm, b"new pfm")]).unwrap();
        assert_eq!(std::fs::read(&png).unwrap(), b"new png");
        assert_eq!(std::fs::read(&pfm).unwrap(), b"new pfm");
        assert_eq!(listing(dir.path()), ["a.pfm", "a.png"]);
    }

    #[test]
    fn a_failed_second_rename_puts_the_first_file_back() {
        let dir = tempfile::tempdir().unwrap();
        let (png, pfm) = (dir.path().join("a.png"), dir.path().join("a.pfm"));
        std::fs::write(&png, "old png").unwrap();
        std::fs::write(&pfm, "old pfm").unwrap();
        let error = commit_failing_at(&[(&png, b"new png"), (&pfm, b"new pfm")], &pfm);
        assert!(matches!(error, Err(WriteError::Io { .. })), "{error:?}");
        assert_eq!(std::fs::read(&png).unwrap(), b"old png");
        assert_eq!(std::fs::read(&pfm).unwrap(), b"old pfm");
        assert_eq!(listing(dir.path()), ["a.pfm", "a.png"]);
    }

    #[test]
    fn a_failed_second_rename_of_a_new_pair_leaves_neither() {
        let dir = tempfile::tempdir().unwrap();
        let (png, pfm) = (dir.path().join("a.png"), dir.path().join("a.pfm"));
        let error = commit_failing_at(&[(&png, b"new png"), (&pfm, b"new pfm")], &pfm);
        assert!(error.is_err());
        assert_eq!(listing(dir.path()), Vec::<String>::new());
    }

    #[test]
    fn a_failed_second_write_leaves_the_first_file_unchanged() {
        let (first, second) = (tempfile::tempdir().unwrap(), tempfile::tempdir().unwrap());
        let kept = first.path().join("report.json");
        std::fs::write(&kept, "old").unwrap();
        let gone = second.path().join("report.html");
        std::fs::remove_dir(second.path()).unwrap();
        let error = write_all_atomically(&[(&kept, b"new"), (&gone, b"new")]);
        assert!(
            matches!(error, Err(WriteError::NoDirectory { .. })),
            "{error:?}"
        );
        assert_eq!(std::fs::read(&kept).unwrap(), b"old");
        assert_eq!(listing(first.path()), ["report.json"]);
    }

    #[test]
    fn atomic_write_replaces_the_file_whole_and_leaves_no_temporary() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("out.pfm");
        std::fs::write(&path, b"old").unwrap();
        write_atomically(&path, b"new contents").unwrap();
        assert_eq!(std::fs::read(&path).unwrap(), b"new contents");
        assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 1);
        let missing = dir.path().join("no/such/dir/out.png");
        let err = write_atomically(&missing, b"x").unwrap_err().to_string();
        assert!(err.contains("does not exist"), "{err}");
    }
}
