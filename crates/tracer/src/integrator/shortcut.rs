//! A slide's shortcut at glass in place of a law (`Settings::glass_shortcut`),
//! so that the harness can render it beside the traced truth: the side,
//! the indices and whether Snell's law transmits stay the law's decision,
//! handed in from [`super::scatter`]; only the direction or the
//! reflectance the shortcut stands in for is replaced, by the technique's
//! own function (`techniques`), never a copy of it.

use glam::Vec3;
use radiometry::course::refract_001_approx;
use radiometry::snell::Incidence;
use techniques::empirical_fresnel;

use super::Tracer;
use crate::scene::GlassShortcut;

impl Tracer<'_> {
    /// The refracted direction: `exact` (Snell's, for `wo` at the shading
    /// normal `n` and the decided `incidence`), or the cheap form's in its
    /// place.
    pub(super) fn refracted_direction(
        &self,
        wo: Vec3,
        n: Vec3,
        incidence: &Incidence<f32>,
        exact: Vec3,
    ) -> Vec3 {
        let GlassShortcut::CheapRefraction(constant) = self.settings.glass_shortcut else {
            return exact;
        };
        // As the slides apply it: the direction of travel and the normal
        // facing the light (`techniques::refraction::compare`).
        let facing = if incidence.from_inside { -n } else { n };
        let c = constant.value(f64::from(incidence.eta_path())) as f32;
        refract_001_approx(-wo, facing, c)
    }

    /// The empirical form's reflectance where it stands in for the law's:
    /// light from outside the glass that Snell's law transmits; `None`
    /// elsewhere, where the chosen law decides.
    pub(super) fn shortcut_reflectance(&self, incidence: &Incidence<f32>) -> Option<f32> {
        let GlassShortcut::EmpiricalFresnel(form) = self.settings.glass_shortcut else {
            return None;
        };
        if incidence.from_inside || incidence.cos_transmitted().is_none() {
            return None;
        }
        Some(empirical_fresnel::reflectance(&form, f64::from(incidence.abs_cos_i)) as f32)
    }
}
