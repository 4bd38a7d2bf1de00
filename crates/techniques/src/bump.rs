//! Bump mapping (Blinn 1978; `001`, "Felületi egyenetlenség leképezés"): a
//! height field `h(u, v)`, metres, bends a surface's shading normal by its
//! slopes `b_u = ∂h/∂u`, `b_v = ∂h/∂v`, taken by finite differences as the
//! slides take them from a height texture ("the difference of neighbouring
//! columns gives the slope in u, of neighbouring rows the slope in v"). The
//! surface itself does not move: its silhouette, its shadows and the
//! shadows its bumps would cast on it are those of the smooth surface.
//!
//! The surface `P(u, v)` with unit normal `n̂ = N / |N|`, `N = P_u × P_v`,
//! displaced by `h` along `n̂`, has tangents `P_u + b_u n̂ + h n̂_u` and
//! `P_v + b_v n̂ + h n̂_v`. Blinn drops the `h n̂_u`, `h n̂_v` terms (small
//! where the bumps are small against the surface's radius of curvature,
//! and zero on a plane); the cross product of what is left is
//!
//! ```text
//! N' = N + b_u (n̂ × P_v) − b_v (n̂ × P_u)        (b_u b_v n̂ × n̂ = 0)
//! ```
//!
//! and divided by `|N|`, [`perturbed_normal`]'s form,
//! `n' = normalize(n̂ + (b_u (n̂ × P_v) − b_v (n̂ × P_u)) / |P_u × P_v|)`.
//! The two vectors `n̂ × P_v` and `n̂ × P_u` lie in the tangent plane: they
//! are the slides' "two vectors perpendicular to the normal" that `b_u`
//! and `b_v` scale. On a plane the formula is exact: `h = a u` on the plane
//! `z = 0` (`P_u = x̂`, `P_v = ŷ`) gives `(−a, 0, 1)`, the normal of
//! `z = a x`.
//!
//! ```
//! use glam::DVec3;
//! use techniques::bump::{on_plane, perturbed_normal, slopes, HeightField, STEP};
//!
//! // A height rising 0.5 m per metre along u tilts the plane's normal
//! // by atan(0.5) = 26.57° away from the rise.
//! let field = HeightField::slope(0.5, 0.0).unwrap();
//! let at = on_plane(DVec3::ZERO, DVec3::Z, DVec3::new(2.0, 3.0, 0.0));
//! let b = slopes(&field, at.u, at.v, STEP);
//! let n = perturbed_normal(at.normal, &at.tangents, b).unwrap();
//! let tilted = (at.tangents.p_u * -0.5 + at.normal).normalize();
//! assert!((n - tilted).length() < 1e-12);
//! assert!((n.angle_between(at.normal).to_degrees() - 26.565).abs() < 1e-3);
//! ```
//!
//! Conventions: `(u, v)` are the surface's own parameters (metres along a
//! plane's tangents; the latitude–longitude texture coordinates
//! `(φ / 2π, θ / π)` on a sphere, see [`on_sphere`]); heights are metres
//! along the outward normal; slopes are metres of height per unit of `u`
//! or `v`.

use std::f64::consts::{PI, TAU};
use std::fmt;

use glam::DVec3;

/// The finite-difference step the tracer uses, in units of `u` and `v`:
/// `2⁻¹²`, exact in binary, so that `u ± STEP` and the division by
/// `2 STEP` add no rounding of their own beyond that of `u ± STEP`. A
/// central difference is off by `STEP² h‴ / 6`: for the sine of the
/// shortest period allowed ([`MIN_PERIOD`]) that is 2.6 % of its slope,
/// for the period of 1/16 of the bumped sphere 0.10 ‰.
pub const STEP: f64 = 1.0 / 4096.0;

/// The shortest sine period accepted, 16 steps: a shorter one would be
/// sampled by the finite differences too coarsely to follow its slopes.
pub const MIN_PERIOD: f64 = 16.0 * STEP;

/// The steepest slope accepted, metres per unit of `u` or `v`: a million,
/// a normal within a microradian of the tangent plane on a unit-speed
/// parametrisation; beyond it the bent normal says nothing more.
pub const MAX_SLOPE: f64 = 1e6;

/// A height field `h(u, v)`, metres. Build it with [`HeightField::slope`]
/// or [`HeightField::sine`], which check its parameters (finite, a period
/// of at least [`MIN_PERIOD`], slopes of at most [`MAX_SLOPE`]); the
/// variants are public to be matched on.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum HeightField {
    /// `h = 0`: the surface as it is.
    Flat,
    /// `h = du · u + dv · v`: a plane tilt, the same slopes everywhere.
    Slope {
        /// `∂h/∂u`.
        du: f64,
        /// `∂h/∂v`.
        dv: f64,
    },
    /// `h = amplitude · sin(2π u / period) · sin(2π v / period)`: a grid of
    /// bumps and dimples, `period` apart along each parameter.
    Sine {
        /// The height of a bump, metres (negative swaps bumps and dimples).
        amplitude: f64,
        /// The period along `u` and along `v`, at least [`MIN_PERIOD`].
        period: f64,
    },
}

/// A parameter of a height field, named as the scene schema names it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Parameter {
    /// [`HeightField::Sine`]'s `amplitude`.
    Amplitude,
    /// [`HeightField::Sine`]'s `period`.
    Period,
    /// [`HeightField::Slope`]'s `du`.
    Du,
    /// [`HeightField::Slope`]'s `dv`.
    Dv,
}

impl Parameter {
    /// The parameter's name in a scene file.
    pub fn name(self) -> &'static str {
        match self {
            Parameter::Amplitude => "amplitude",
            Parameter::Period => "period",
            Parameter::Du => "du",
            Parameter::Dv => "dv",
        }
    }
}

/// Why a height field could not be made.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum FieldError {
    /// A parameter that is NaN or infinite.
    NotFinite {
        /// Which.
        parameter: Parameter,
        /// The value given.
        value: f64,
    },
    /// A sine period shorter than [`MIN_PERIOD`] (or not positive).
    PeriodTooShort {
        /// The period given.
        period: f64,
    },
    /// A steepest slope beyond [`MAX_SLOPE`]: `|du|`, `|dv|`, or the
    /// sine's `2π |amplitude| / period`.
    TooSteep {
        /// The parameter that makes it so.
        parameter: Parameter,
        /// The steepest slope, metres per unit of `u` or `v`.
        slope: f64,
    },
}

impl FieldError {
    /// The parameter refused.
    pub fn parameter(&self) -> Parameter {
        match *self {
            FieldError::NotFinite { parameter, .. } | FieldError::TooSteep { parameter, .. } => {
                parameter
            }
            FieldError::PeriodTooShort { .. } => Parameter::Period,
        }
    }
}

impl fmt::Display for FieldError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            FieldError::NotFinite { value, .. } => write!(f, "must be finite, got {value}"),
            FieldError::PeriodTooShort { period } => write!(
                f,
                "must be at least {MIN_PERIOD} (16 finite-difference steps), got {period}"
            ),
            FieldError::TooSteep { slope, .. } => write!(
                f,
                "makes a slope of {slope:e}, steeper than the {MAX_SLOPE:e} accepted"
            ),
        }
    }
}

impl std::error::Error for FieldError {}

fn finite(parameter: Parameter, value: f64) -> Result<f64, FieldError> {
    if value.is_finite() {
        Ok(value)
    } else {
        Err(FieldError::NotFinite { parameter, value })
    }
}

fn not_too_steep(parameter: Parameter, slope: f64) -> Result<(), FieldError> {
    if slope <= MAX_SLOPE {
        Ok(())
    } else {
        Err(FieldError::TooSteep { parameter, slope })
    }
}

impl HeightField {
    /// The tilt `h = du · u + dv · v`.
    pub fn slope(du: f64, dv: f64) -> Result<Self, FieldError> {
        for (parameter, value) in [(Parameter::Du, du), (Parameter::Dv, dv)] {
            not_too_steep(parameter, finite(parameter, value)?.abs())?;
        }
        Ok(HeightField::Slope { du, dv })
    }

    /// The bumps `h = amplitude · sin(2π u / period) · sin(2π v / period)`.
    pub fn sine(amplitude: f64, period: f64) -> Result<Self, FieldError> {
        finite(Parameter::Amplitude, amplitude)?;
        finite(Parameter::Period, period)?;
        // Finite by now, so `<` also refuses no NaN by accident.
        if period < MIN_PERIOD {
            return Err(FieldError::PeriodTooShort { period });
        }
        not_too_steep(Parameter::Amplitude, TAU * amplitude.abs() / period)?;
        Ok(HeightField::Sine { amplitude, period })
    }

    /// The height at `(u, v)`, metres.
    pub fn height(&self, u: f64, v: f64) -> f64 {
        match *self {
            HeightField::Flat => 0.0,
            HeightField::Slope { du, dv } => du * u + dv * v,
            HeightField::Sine { amplitude, period } => {
                amplitude * (TAU * u / period).sin() * (TAU * v / period).sin()
            }
        }
    }
}

/// The slopes of a height field at a point, metres per unit of `u`, `v`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Slopes {
    /// `b_u ≈ ∂h/∂u`.
    pub b_u: f64,
    /// `b_v ≈ ∂h/∂v`.
    pub b_v: f64,
}

/// The slopes of `field` at `(u, v)` by central differences of step
/// `step` (the slides' "neighbouring columns" and "rows", one step either
/// side): `b_u = (h(u + δ, v) − h(u − δ, v)) / 2δ`, likewise `b_v`. Off by
/// `δ² h‴ / 6` plus rounding of about `ε |h| / δ`; exact but for rounding
/// on a linear field, exactly zero on a flat one.
pub fn slopes(field: &HeightField, u: f64, v: f64, step: f64) -> Slopes {
    let h = |u, v| field.height(u, v);
    Slopes {
        b_u: (h(u + step, v) - h(u - step, v)) / (2.0 * step),
        b_v: (h(u, v + step) - h(u, v - step)) / (2.0 * step),
    }
}

/// The surface's derivatives at a point, m per unit of `u` and of `v`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Tangents {
    /// `P_u = ∂P/∂u`.
    pub p_u: DVec3,
    /// `P_v = ∂P/∂v`.
    pub p_v: DVec3,
}

/// The bent normal `normalize(n̂ + (b_u (n̂ × P_v) − b_v (n̂ × P_u)) / |P_u
/// × P_v|)` (Blinn's, see the module's derivation), a unit vector.
///
/// `normal` is the surface's unit normal `n̂`, along `P_u × P_v`. Where both
/// slopes are zero it is handed back as it is, to the bit. `None` where the
/// bend is undefined: the parametrisation is degenerate there (`P_u × P_v`
/// zero or not finite, as at a sphere's poles) or the bent vector has no
/// direction.
pub fn perturbed_normal(normal: DVec3, tangents: &Tangents, slopes: Slopes) -> Option<DVec3> {
    let Slopes { b_u, b_v } = slopes;
    if b_u == 0.0 && b_v == 0.0 {
        return Some(normal);
    }
    let Tangents { p_u, p_v } = *tangents;
    let area = p_u.cross(p_v).length();
    if !area.is_finite() || area <= 0.0 {
        return None;
    }
    let bend = (normal.cross(p_v) * b_u - normal.cross(p_u) * b_v) / area;
    (normal + bend).try_normalize()
}

/// A point of a parametrised surface: its parameters, its unit normal and
/// its tangents.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SurfacePoint {
    /// `u` at the point.
    pub u: f64,
    /// `v` at the point.
    pub v: f64,
    /// The unit normal, along `P_u × P_v`.
    pub normal: DVec3,
    /// `P_u`, `P_v`.
    pub tangents: Tangents,
}

/// `point` on the plane through `origin` with unit normal `normal`:
/// `u`, `v` are metres from `origin` along the unit tangents `P_u` (glam's
/// `any_orthonormal_vector` of the normal) and `P_v = n × P_u`, so that
/// `P_u × P_v = n`.
pub fn on_plane(origin: DVec3, normal: DVec3, point: DVec3) -> SurfacePoint {
    let p_u = normal.any_orthonormal_vector();
    let p_v = normal.cross(p_u);
    let d = point - origin;
    SurfacePoint {
        u: d.dot(p_u),
        v: d.dot(p_v),
        normal,
        tangents: Tangents { p_u, p_v },
    }
}

/// `point` on the sphere of `centre` and `radius` (m), in its
/// latitude–longitude texture coordinates `u = φ / 2π ∈ [0, 1)`, `v = θ /
/// π ∈ [0, 1]`: `θ` from the `+y` pole, `φ` from `+x` towards `+z`, so
/// `P = c + r (sin θ cos φ, cos θ, sin θ sin φ)`, `P_u = 2π ∂P/∂φ`,
/// `P_v = π ∂P/∂θ`, and `P_u × P_v = 2π² r² sin θ n̂` points outwards.
/// At the poles `P_u = 0`: the parametrisation, not the sphere, is
/// degenerate there, and [`perturbed_normal`] says so. `None` where the
/// point coincides with the centre.
pub fn on_sphere(centre: DVec3, radius: f64, point: DVec3) -> Option<SurfacePoint> {
    let n = (point - centre).try_normalize()?;
    let theta = n.x.hypot(n.z).atan2(n.y);
    let phi = n.z.atan2(n.x).rem_euclid(TAU);
    let (sin_t, cos_t) = theta.sin_cos();
    let (sin_p, cos_p) = phi.sin_cos();
    Some(SurfacePoint {
        u: phi / TAU,
        v: theta / PI,
        normal: n,
        tangents: Tangents {
            p_u: DVec3::new(-sin_t * sin_p, 0.0, sin_t * cos_p) * (TAU * radius),
            p_v: DVec3::new(cos_t * cos_p, -sin_t, cos_t * sin_p) * (PI * radius),
        },
    })
}

/// The shading normal at `at` under `field`: the slopes by [`STEP`], the
/// bent normal by [`perturbed_normal`]; the surface's own normal where the
/// bend is undefined (a pole of the sphere's parameters).
pub fn shading_normal(field: &HeightField, at: &SurfacePoint) -> DVec3 {
    let b = slopes(field, at.u, at.v, STEP);
    perturbed_normal(at.normal, &at.tangents, b).unwrap_or(at.normal)
}

#[cfg(test)]
mod tests;
