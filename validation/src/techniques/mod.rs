//! The rasteriser-side techniques of `001` (the `techniques` crate)
//! against the answers they stand in for: N-BK7's Sellmeier index against
//! Schott's data sheet, the traced prism against the analytic minimum
//! deviation, the slides' cheap refraction and fitted empirical Fresnel
//! form against the exact laws, and the projected shadow against the
//! tracer's own ray–plane intersection; and, rendered beside the traced
//! truth, the environment-mapped mirror as its surroundings move away and
//! beside another mirror, bump mapping's silhouettes and shadows, planar
//! reflections and projected shadows. Their measured errors are the
//! report's numbers for the techniques, their pictures its figures.

mod bump_render;
mod curves;
pub mod dispersion;
mod envmap;
pub mod envmap_vs_traced;
pub mod figure;
mod glass;
pub mod glass_shortcuts;
pub mod parallax;
pub mod planar_reflection;
pub mod planar_shadow;
mod shadow;
mod shortcuts;

use techniques::dispersion::Sellmeier;
use techniques::planar;

use crate::check::Check;
use crate::renders::RenderFigure;
pub use bump_render::render as render_with_hits;
pub use bump_render::{bump_scene, check_bump_render, CHANGED_SHARE};
pub use curves::{FitCurve, RefractionCurve, TechniqueCurves};
pub use envmap::{check_envmap, sphere_round_trip, ENVMAP_ROUND_TRIP};
pub use glass::{
    check_dispersion_render, check_prism, check_sellmeier, DATA_SHEET_ABS, FLAT_SPECTRUM_RELATIVE,
    N_BK7_DATA_SHEET, PRISM_ABS,
};
pub use glass_shortcuts::{
    check_cheap_refraction_render, check_empirical_fresnel_render, fitted_form, glass_scene,
    CHEAP_REFRACTION,
};
pub use parallax::{check_distance, check_self_reflection, DistanceCurve};
pub use planar_reflection::{check_planar_reflection, floor_matrix, mirror_scene};
pub use planar_shadow::{check_planar_shadow, shadow_scene};
pub use shadow::check_projected_shadow;
pub use shortcuts::{check_cheap_refraction, check_empirical_fresnel};

/// The sizes of the planar scenes' renders, pixels.
pub const PLANAR_SIZE: (u32, u32) = (160, 120);

/// Every technique's check, the curves they measured, and their pictures
/// (shortcut | truth | difference) appended to `figures`; `glass` the
/// dispersing glass (N-BK7 in the suite; a parameter so that a wrong one
/// can be shown to be caught).
pub fn check_all(
    glass: &Sellmeier,
    figures: &mut Vec<RenderFigure>,
) -> (Vec<Check>, TechniqueCurves) {
    let mut curves = TechniqueCurves::default();
    let (w, h) = PLANAR_SIZE;
    let checks = vec![
        check_envmap(),
        check_sellmeier(glass),
        check_prism(glass),
        check_dispersion_render(dispersion::three_etas),
        check_cheap_refraction(&mut curves.refraction),
        check_empirical_fresnel(&mut curves.fresnel_fits),
        check_projected_shadow(),
        check_distance(
            envmap_vs_traced::one_sphere,
            &mut curves.envmap_distance,
            figures,
        ),
        check_self_reflection(envmap_vs_traced::two_spheres, figures),
        check_bump_render(&bump_scene(), bump_render::render, figures),
        check_planar_reflection(&mirror_scene(w, h), floor_matrix(), figures),
        check_planar_shadow(&shadow_scene(w, h), planar::shadow_matrix, figures),
        check_cheap_refraction_render(CHEAP_REFRACTION, figures),
        check_empirical_fresnel_render(fitted_form(&glass_scene()), figures),
    ];
    (checks, curves)
}
