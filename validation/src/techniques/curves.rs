//! The curves the techniques' checks measure, for the report's figure.

use serde::Serialize;

use super::parallax::DistanceCurve;

/// The techniques' curves, for the report's figure (`techniques.png`):
/// what their checks measured, one value per degree.
#[derive(Clone, Debug, Default, Serialize)]
pub struct TechniqueCurves {
    /// The cheap refraction's angle from Snell's law, per medium and
    /// constant.
    pub refraction: Vec<RefractionCurve>,
    /// The fitted empirical Fresnel form beside the exact law and Schlick.
    pub fresnel_fits: Vec<FitCurve>,
    /// The environment-mapped mirror's error against the traced one as
    /// its surroundings move away.
    pub envmap_distance: Vec<DistanceCurve>,
}

impl TechniqueCurves {
    /// Appends `part`'s curves after these.
    pub fn absorb(&mut self, part: TechniqueCurves) {
        let TechniqueCurves {
            refraction,
            fresnel_fits,
            envmap_distance,
        } = part;
        self.refraction.extend(refraction);
        self.fresnel_fits.extend(fresnel_fits);
        self.envmap_distance.extend(envmap_distance);
    }
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
pub(super) const DRAWN_FITS: [&str; 3] = ["glass", "water", "gold G"];
