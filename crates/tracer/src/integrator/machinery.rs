//! What a render actually runs, chosen from what its scene needs.

use crate::scene::{Scene, Settings};
use crate::trap::Trap;

/// What a render actually runs: the scene's needs (see [`crate::needs`])
/// decide which parts are switched on. Switching a part on that the scene
/// does not need never changes the image, only its cost.
#[derive(Clone, Debug, PartialEq)]
pub struct Machinery {
    /// Cast shadow rays (off when no object can block a light).
    pub shadow_rays: bool,
    /// Which lights are evaluated (off: a light that delivers nothing).
    pub lights: Vec<bool>,
    /// Samples per pixel actually taken (1 when every path is deterministic).
    pub spp: u32,
    /// The mirror tube whose held rays end a camera path (`path` and
    /// `photon`; see [`crate::trap`]): the rest of such a path adds nothing.
    pub trap: Option<Trap>,
}

impl Machinery {
    /// Everything on: the reference against which skipping is measured.
    pub fn everything(scene: &Scene, settings: &Settings) -> Self {
        Machinery {
            shadow_rays: true,
            lights: vec![true; scene.lights.len()],
            spp: settings.spp,
            trap: None,
        }
    }
}
