//! Test-only switches that undo one of the reader's fixes, or leave one law
//! out of the tracer, on the current thread, so that a check can show it
//! finds the case: the fuzz target (`crates/tracer/tests/fuzz_scenes.rs`)
//! each fix of the reader, the harness's render comparison
//! (`validation/tests/renders_vs_mitsuba.rs`) the law. A check that passes
//! with the fix undone would pass without it. Off unless a test turns one
//! on. A render reads the switch once, on the thread that starts it, so it
//! holds for every row whichever thread traces it.
//!
//! The switches exist only with the cargo feature `faults`, which the
//! tests turn on through their dev-dependencies: a build without it (the
//! shipped binary) has no switch, and every check below is `false`.

#[cfg(feature = "faults")]
use std::cell::Cell;

/// A fix of the scene reader, undone.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
// Without the feature only the reader's checks name their fault; the
// tracer's are read through a pattern and planted by no one.
#[cfg_attr(not(feature = "faults"), allow(dead_code))]
pub enum Fault {
    /// Text after the scene's JSON value is ignored.
    TrailingTextIgnored,
    /// Structs read from arrays and choices from objects, as serde would.
    ShapesUnchecked,
    /// Products of scene numbers not bounded within `f32`.
    RadianceUnbounded,
    /// Radiance carried across a dielectric interface without its `1/η²`
    /// (`radiometry::radiance::across_interface`): the transmittance alone.
    RadianceNotScaledAcrossInterfaces,
    /// Photons keep their flux at mirrors and glass: no Fresnel factor.
    PhotonsUnweightedAtMirrors,
    /// Environment images taken whatever their size: a lat-long map of
    /// any aspect, cube faces neither square nor of one side (each then
    /// read by the first face's side).
    EnvironmentSizeUnchecked,
    /// Photons that reach a rough surface straight from the light are put
    /// in the caustic map too, so the direct light is counted twice.
    PhotonsStoredBeforeAnyMirror,
}

#[cfg(feature = "faults")]
thread_local! {
    static UNDONE: Cell<Option<Fault>> = const { Cell::new(None) };
}

/// Runs `f` with `fault`'s fix undone on this thread.
#[cfg(feature = "faults")]
pub fn with<T>(fault: Fault, f: impl FnOnce() -> T) -> T {
    UNDONE.with(|u| u.set(Some(fault)));
    let out = f();
    UNDONE.with(|u| u.set(None));
    out
}

/// Whether `fault`'s fix is undone on this thread.
#[cfg(feature = "faults")]
pub(crate) fn undone(fault: Fault) -> bool {
    current() == Some(fault)
}

/// No fix is undone: without the feature `faults` no switch exists. Always
/// inlined, so that even an unoptimised build holds no symbol of this
/// module (`.ci/no-fault-switches`).
#[cfg(not(feature = "faults"))]
#[inline(always)]
pub(crate) const fn undone(_: Fault) -> bool {
    false
}

/// The fault planted on this thread, if any.
#[cfg(feature = "faults")]
pub(crate) fn current() -> Option<Fault> {
    UNDONE.with(|u| u.get())
}

/// No fault: without the feature `faults` no switch exists (inlined as
/// [`undone`] is).
#[cfg(not(feature = "faults"))]
#[inline(always)]
pub(crate) const fn current() -> Option<Fault> {
    None
}
