//! The scenes that ship with the tracer, as `crates/tracer/scenes/<name>.json`:
//! their one list, `shipped.json` beside this file, which the tracer's
//! tests, benches and examples read through [`course_scenes`] and
//! [`technique_scenes`], and the harness's Python (`python-checks/`) reads
//! as JSON. A scene added to the folder is added to one of its lists, one
//! line; a test (`the_course_scene_list_is_the_scene_folder`) holds the
//! lists and the folder to each other.

use std::sync::LazyLock;

use serde::Deserialize;

/// `shipped.json`, as written.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct Shipped<'a> {
    #[serde(borrow)]
    course: Vec<&'a str>,
    #[serde(borrow)]
    technique: Vec<&'a str>,
}

static SHIPPED: LazyLock<Shipped<'static>> = LazyLock::new(|| {
    // Compiled in, so a malformed list fails every test that reads it, at
    // its first use, rather than any user's input.
    serde_json::from_str(include_str!("shipped.json")).unwrap_or_else(|e| {
        panic!("crates/tracer/src/scene/shipped.json: {e}; expected {{\"course\": [names], \"technique\": [names]}}")
    })
});

/// The course's scenes, in the order the course meets them (then the
/// glass the course leaves out, for its cross-check): the inputs of the
/// tracer's tests, benches and examples and of the harness's render
/// references (`python-checks/mitsuba_render.py`).
pub fn course_scenes() -> &'static [&'static str] {
    &SHIPPED.course
}

/// The scenes that ship beside the course's to show a technique of `001`
/// (`docs/techniques.md`): rendered for the documents and read by the
/// tests, but not among the [`course_scenes`] the harness cross-checks.
pub fn technique_scenes() -> &'static [&'static str] {
    &SHIPPED.technique
}
