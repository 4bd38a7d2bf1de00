//! The checks' false-alarm rate, power and allowances.

/// Family-wise false-alarm rate of each check: one correct render in a
/// hundred may fail by chance.
pub const ALPHA: f64 = 0.01;

/// The power the checks state their smallest detectable difference at.
pub const POWER: f64 = 0.8;

/// Relative difference of a region's mean that a tracer render may show
/// against Mitsuba's at the same pixel positions without failing, whatever
/// the samples: float32 differences of intersections and ray offsets, as
/// the per-pixel render comparison allows ([`crate::compare::TOLERANCE_RELATIVE`]).
/// Against the box-filtered estimates the allowance adds what the filter
/// moves that region's mean, measured per scene, region and channel as
/// `|path − path_centres|` (up to 3 % on `gold_spheres`, whose gold
/// spheres show sub-pixel images of the green one).
pub const TOLERANCE_RELATIVE: f64 = 1e-3;

/// A significant difference beyond the allowance but within this much more
/// (relative) is reported as a finding, not a failure: the tracer's `path`
/// and Mitsuba's, through the same pixel centres, differ by 2.5 × 10⁻³ to
/// 3.5 × 10⁻³ on `inside_water`'s surface pixels (t = −3.8 to −6.2 at 512
/// samples per pixel, `FL_SAMPLES=512 cargo test -p validation --test
/// full_light the_tracers_path`), a difference the per-pixel comparison of
/// `mitsuba_renders.json` cannot resolve and which is not yet explained
/// (the camera looks out of the water, where rays near Snell's window are
/// the most sensitive to where a ray starts). A missed light path is
/// larger: 5 % of the light on `webgl_seven_spheres`, the least.
pub const FINDING_RELATIVE: f64 = 5e-3;
