//! The rasteriser-side techniques of `001` (the `techniques` crate)
//! against the answers they stand in for: N-BK7's Sellmeier index against
//! Schott's data sheet, the traced prism against the analytic minimum
//! deviation, the slides' cheap refraction and fitted empirical Fresnel
//! form against the exact laws, and the projected shadow against the
//! tracer's own ray–plane intersection. Their measured errors are the
//! report's numbers for the techniques.

pub mod dispersion;
mod envmap;
mod glass;
mod shadow;
mod shortcuts;

use serde::Serialize;
use techniques::dispersion::Sellmeier;

use crate::check::Check;
pub use envmap::{check_envmap, sphere_round_trip, ENVMAP_ROUND_TRIP};
pub use glass::{
    check_dispersion_render, check_prism, check_sellmeier, DATA_SHEET_ABS, FLAT_SPECTRUM_RELATIVE,
    N_BK7_DATA_SHEET, PRISM_ABS,
};
pub use shadow::check_projected_shadow;
pub use shortcuts::{check_cheap_refraction, check_empirical_fresnel};

/// The techniques' curves, for the report's figure (`techniques.png`):
/// what their checks measured, one value per degree.
#[derive(Clone, Debug, Default, Serialize)]
pub struct TechniqueCurves {
    /// The cheap refraction's angle from Snell's law, per medium and
    /// constant.
    pub refraction: Vec<RefractionCurve>,
    /// The fitted empirical Fresnel form beside the exact law and Schlick.
    pub fresnel_fits: Vec<FitCurve>,
}

/// One medium and constant of the cheap refraction.
#[derive(Clone, Debug, Serialize)]
pub struct RefractionCurve {
    /// Medium and constant, in words.
    pub label: String,
    /// Angle of incidence, degrees.
    pub angle_deg: Vec<f64>,
    /// The angle between the cheap and the exact ray, degrees.
    pub error_deg: Vec<f64>,
}

/// One interface's reflectance by the exact law, the fitted form and
/// Schlick.
#[derive(Clone, Debug, Serialize)]
pub struct FitCurve {
    /// The interface.
    pub label: String,
    /// Angle of incidence, degrees.
    pub angle_deg: Vec<f64>,
    /// The exact law.
    pub exact: Vec<f64>,
    /// The fitted form, clamped as the slide clamps it.
    pub fitted: Vec<f64>,
    /// Schlick's approximation.
    pub schlick: Vec<f64>,
    /// The fitted parameters `(bias, scale, power)`.
    pub form: [f64; 3],
}

/// The interfaces whose fits the figure draws.
const DRAWN_FITS: [&str; 3] = ["glass", "water", "gold G"];

/// Every technique's check, and the curves they measured; `glass` the
/// dispersing glass (N-BK7 in the suite; a parameter so that a wrong one
/// can be shown to be caught).
pub fn check_all(glass: &Sellmeier) -> (Vec<Check>, TechniqueCurves) {
    let mut curves = TechniqueCurves::default();
    let checks = vec![
        check_envmap(),
        check_sellmeier(glass),
        check_prism(glass),
        check_dispersion_render(dispersion::three_etas),
        check_cheap_refraction(&mut curves.refraction),
        check_empirical_fresnel(&mut curves.fresnel_fits),
        check_projected_shadow(),
    ];
    (checks, curves)
}
