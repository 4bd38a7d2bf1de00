//! The photon a caustic map holds: where it came to rest and what it carries.

use glam::Vec3;

/// A photon at rest on a rough surface after at least one specular bounce.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Photon {
    /// Where it landed, m.
    pub point: Vec3,
    /// The unit direction it came from.
    pub towards_source: Vec3,
    /// Its flux, W per channel.
    pub flux: Vec3,
    /// The object it landed on.
    pub object: u32,
    /// The mirrors and glass it met on its way, at least 1.
    pub bounces: u32,
}
