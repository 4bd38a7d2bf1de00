//! The latitude–longitude map: a direction's spherical angles `(ρ, φ)`,
//! radians, scaled to texture coordinates `(u, v)` in `[0, 1]`.
//!
//! The slides' convention (`001`, lines 27–54):
//!
//! - `ρ = arccos(−r_z)` in `[0, π]` (the slides' "latitude"; a polar angle
//!   measured from `−z`, the viewing direction of OpenGL's eye space), so
//!   `ρ = 0` at `r = (0, 0, −1)` and `ρ = π` at `(0, 0, 1)`;
//! - `φ` the angle of `(r_x, r_y)` from `+x` towards `+y`, over the full
//!   circle `[0, 2π)` (the slides' "longitude");
//! - `u = φ / 2π` follows the longitude and `v = ρ / π` the latitude.
//!
//! Two departures from the slides' text, each for a reason:
//!
//! - `φ` is `atan2(r_y, r_x)`, wrapped into `[0, 2π)`. The slides write
//!   `arctan(r_y / r_x)`, which covers only `(−π/2, π/2)` and gives `r` and
//!   its half turn about the `z` axis the same `φ`: half of the map is
//!   never looked up (an erratum; `docs/errata.md`).
//! - `ρ` is `atan2(√(r_x² + r_y²), −r_z)`, the same angle for a unit `r`.
//!   `arccos` has an infinite slope at ±1: near the poles a rounding of
//!   `r_z` by one unit in the last place moves `ρ` by about 1e-8 rad, and
//!   `arccos(−r_z)` of `r = (1e-9, 0, −1)` normalised is 0, not 1e-9.
//!
//! Seams, decided once: the seam `φ = 0` belongs to `u = 0` (so `u < 1`;
//! `u = 1` is accepted back as the same meridian); at the poles, where `φ`
//! has no value, `u = 0`. The slides' `[0, 1)` holds for `u` only: `v`
//! reaches 1 at `r = (0, 0, 1)`, as `ρ` reaches `π`.

use std::f64::consts::{PI, TAU};

use super::direction::Direction;
use super::texel::{unit_square, TexelError};

/// A texel of the latitude–longitude map, with the angles it came from.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LatLong {
    u: f64,
    v: f64,
    pole: bool,
}

impl LatLong {
    /// The texel `r` is looked up at.
    pub fn from_direction(r: Direction) -> Self {
        let r = r.get();
        let across = r.x.hypot(r.y);
        let rho = across.atan2(-r.z);
        let pole = across == 0.0;
        let phi = if pole {
            0.0 // a pole: every φ names it; u = 0 by decision
        } else {
            let phi = r.y.atan2(r.x);
            if phi < 0.0 {
                phi + TAU
            } else {
                phi
            }
        };
        let u = phi / TAU;
        // −1e-300 rad wraps to 2π itself, and φ just below 2π may round to
        // u = 1: both are the seam, which belongs to u = 0. `+ 0.0` turns
        // the `−0` of `atan2(−0, x)` into 0.
        let u = if u >= 1.0 { 0.0 } else { u + 0.0 };
        Self {
            u,
            v: rho / PI,
            pole,
        }
    }

    /// The texel at `(u, v)`, each in `[0, 1]`.
    pub fn from_uv(u: f64, v: f64) -> Result<Self, TexelError> {
        let (u, v) = unit_square(u, v)?;
        let pole = v == 0.0 || v == 1.0;
        Ok(Self { u, v, pole })
    }

    /// Whether the texel is a pole, `r = (0, 0, ∓1)`, where every `φ`
    /// names the same direction and `u` is 0 by decision (or, given back,
    /// whatever it was given).
    pub fn is_pole(&self) -> bool {
        self.pole
    }

    /// `u = φ / 2π`, in `[0, 1)` when computed from a direction.
    pub fn u(&self) -> f64 {
        self.u
    }

    /// `v = ρ / π`, in `[0, 1]`.
    pub fn v(&self) -> f64 {
        self.v
    }

    /// The longitude `φ = 2π u`, radians.
    pub fn phi(&self) -> f64 {
        TAU * self.u
    }

    /// The slides' latitude `ρ = π v`, radians from `−z`.
    pub fn rho(&self) -> f64 {
        PI * self.v
    }

    /// The direction stored at this texel:
    /// `(sin ρ cos φ, sin ρ sin φ, −cos ρ)`, the inverse of
    /// [`LatLong::from_direction`].
    pub fn direction(&self) -> Direction {
        let (sin_rho, cos_rho) = self.rho().sin_cos();
        let (sin_phi, cos_phi) = self.phi().sin_cos();
        Direction::from_built(glam::DVec3::new(
            sin_rho * cos_phi,
            sin_rho * sin_phi,
            -cos_rho,
        ))
    }
}
