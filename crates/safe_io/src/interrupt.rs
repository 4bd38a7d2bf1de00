//! SIGINT and SIGTERM while files are written: the temporaries removed,
//! a commit already under way finished, and the process ended by the
//! signal.
//!
//! The writer ([`crate::atomic`]) registers each temporary file here while
//! it exists, and renames a set of files into place while holding the
//! registry's lock. On the first registration a thread starts that waits
//! for SIGINT or SIGTERM. When one comes it takes the lock (so a commit
//! under way completes first), removes every temporary still registered,
//! and ends the process by the signal's default action, so that the parent
//! sees the signal (a shell: exit status 130 or 143). A writer that finds a
//! signal pending when it releases the lock stops there, and leaves the end
//! to that thread.
//!
//! SIGKILL and power loss cannot be handled: after them a temporary
//! (`.tmp…`) or a commit's backup of the previous file may remain beside
//! the destination, under a name of its own; the destination itself is
//! always either whole or absent.
//!
//! **Test hook** (only with the `test-hooks` feature, which the tests turn
//! on). With `TRACER_TEST_PAUSE=mid-stage` the writer pauses
//! after the first temporary of a set is written and before the next is
//! begun; with `TRACER_TEST_PAUSE=before-commit`, once its temporaries are
//! complete and before the first rename;
//! with `TRACER_TEST_PAUSE=mid-commit`, between the renames of a set of
//! several files, until a signal is pending. Each pause is announced on
//! stderr as `tracer: paused <point>`, and, with the hook set, the signal's
//! thread says in which phase the signal arrived, so that a test can
//! interrupt the writer at a known point instead of a guessed moment. A
//! pause with no signal ends after a minute.

use std::path::PathBuf;
use std::sync::atomic::{AtomicBool, AtomicU8, Ordering};
use std::sync::{Mutex, MutexGuard, Once, PoisonError};

/// The environment variable of the test hook.
pub const PAUSE_VARIABLE: &str = "TRACER_TEST_PAUSE";

static TEMPORARIES: Mutex<Vec<PathBuf>> = Mutex::new(Vec::new());
static PENDING: AtomicBool = AtomicBool::new(false);
static PHASE: AtomicU8 = AtomicU8::new(Phase::Idle as u8);
static INSTALL: Once = Once::new();

/// What the writer is doing, as the signal's thread reports it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[repr(u8)]
pub(crate) enum Phase {
    /// Not writing.
    Idle,
    /// Writing temporaries.
    Staging,
    /// Every temporary complete, nothing renamed yet.
    Staged,
    /// Renaming into place.
    Committing,
}

impl Phase {
    fn name(self) -> &'static str {
        match self {
            Phase::Idle => "idle",
            Phase::Staging => "staging",
            Phase::Staged => "staged",
            Phase::Committing => "committing",
        }
    }
}

/// Where the test hook can pause the writer.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum PausePoint {
    /// One temporary of a set written, the next not yet begun.
    MidStage,
    /// Temporaries complete, before the first rename.
    BeforeCommit,
    /// Between two renames of one set.
    MidCommit,
}

impl PausePoint {
    fn name(self) -> &'static str {
        match self {
            PausePoint::MidStage => "mid-stage",
            PausePoint::BeforeCommit => "before-commit",
            PausePoint::MidCommit => "mid-commit",
        }
    }
}

/// The registry of temporaries, locked; a signal waits until it is
/// released.
pub(crate) struct Registry {
    guard: Option<MutexGuard<'static, Vec<PathBuf>>>,
}

/// Locks the registry, starting the signal's thread on first use.
pub(crate) fn lock() -> Registry {
    INSTALL.call_once(install);
    Registry {
        guard: Some(TEMPORARIES.lock().unwrap_or_else(PoisonError::into_inner)),
    }
}

impl Registry {
    /// Registers a temporary file, removed on a signal.
    pub(crate) fn add(&mut self, path: PathBuf) {
        if let Some(paths) = &mut self.guard {
            paths.push(path);
        }
    }

    /// Forgets a temporary that was renamed into place or removed.
    pub(crate) fn forget(&mut self, path: &std::path::Path) {
        if let Some(paths) = &mut self.guard {
            paths.retain(|p| p != path);
        }
    }
}

impl Drop for Registry {
    fn drop(&mut self) {
        drop(self.guard.take());
        // A signal is being handled: its thread ends the process.
        while PENDING.load(Ordering::SeqCst) {
            std::thread::park();
        }
    }
}

/// Records what the writer is doing.
pub(crate) fn set_phase(phase: Phase) {
    PHASE.store(phase as u8, Ordering::SeqCst);
}

fn phase() -> Phase {
    match PHASE.load(Ordering::SeqCst) {
        1 => Phase::Staging,
        2 => Phase::Staged,
        3 => Phase::Committing,
        _ => Phase::Idle,
    }
}

/// The pause the test hook asks for: [`PAUSE_VARIABLE`]'s value, read
/// only in a build with the `test-hooks` feature (the tests turn it on
/// through their dev-dependencies; a shipped build reads no variable and
/// never pauses).
fn hooked() -> Option<String> {
    #[cfg(feature = "test-hooks")]
    return test_hook_variable();
    #[cfg(not(feature = "test-hooks"))]
    None
}

/// [`PAUSE_VARIABLE`]'s value: a function of its own, never inlined, so
/// that `.ci/no-fault-switches` can tell a build that has the hook.
#[cfg(feature = "test-hooks")]
#[inline(never)]
fn test_hook_variable() -> Option<String> {
    std::env::var(PAUSE_VARIABLE).ok()
}

/// The test hook: pauses at `point` when asked to (see the module's docs).
pub(crate) fn pause(point: PausePoint) {
    if hooked().as_deref() != Some(point.name()) {
        return;
    }
    eprintln!("tracer: paused {}", point.name());
    for _ in 0..6000 {
        if point == PausePoint::MidCommit && PENDING.load(Ordering::SeqCst) {
            return;
        }
        std::thread::sleep(std::time::Duration::from_millis(10));
    }
}

#[cfg(unix)]
fn install() {
    use signal_hook::consts::{SIGINT, SIGTERM};
    let Ok(mut signals) = signal_hook::iterator::Signals::new([SIGINT, SIGTERM]) else {
        return;
    };
    // Without the thread the signals keep their default action, which is
    // what a failure to start it leaves.
    let _ = std::thread::Builder::new()
        .name("tracer-signals".into())
        .spawn(move || {
            if let Some(signal) = signals.forever().next() {
                end_by(signal);
            }
        });
}

#[cfg(not(unix))]
fn install() {}

/// Removes the temporaries once no commit is under way, and ends the
/// process by `signal`.
#[cfg(unix)]
fn end_by(signal: i32) {
    PENDING.store(true, Ordering::SeqCst);
    let arrived = phase();
    let paths = TEMPORARIES.lock().unwrap_or_else(PoisonError::into_inner);
    for path in paths.iter() {
        let _ = std::fs::remove_file(path);
    }
    if hooked().is_some() {
        eprintln!(
            "tracer: signal {signal} while {}: {} temporaries removed",
            arrived.name(),
            paths.len()
        );
    }
    let _ = signal_hook::low_level::emulate_default_handler(signal);
    std::process::exit(128 + signal);
}
