//! Test-only switches that undo one of the reader's fixes on the current
//! thread, so that the fuzz target (`crates/tracer/tests/fuzz_scenes.rs`)
//! can show it finds the case each fix handles: a target that passes with a
//! fix undone would pass without the fix. Off unless a test turns one on.

use std::cell::Cell;

/// A fix of the scene reader, undone.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Fault {
    /// Text after the scene's JSON value is ignored.
    TrailingTextIgnored,
    /// Structs read from arrays and choices from objects, as serde would.
    ShapesUnchecked,
    /// Products of scene numbers not bounded within `f32`.
    RadianceUnbounded,
}

thread_local! {
    static UNDONE: Cell<Option<Fault>> = const { Cell::new(None) };
}

/// Runs `f` with `fault`'s fix undone on this thread.
pub fn with<T>(fault: Fault, f: impl FnOnce() -> T) -> T {
    UNDONE.with(|u| u.set(Some(fault)));
    let out = f();
    UNDONE.with(|u| u.set(None));
    out
}

/// Whether `fault`'s fix is undone on this thread.
pub(crate) fn undone(fault: Fault) -> bool {
    UNDONE.with(|u| u.get()) == Some(fault)
}
