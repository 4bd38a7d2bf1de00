//! The slides' empirical Fresnel form, `max(0, min(1, bias + scale (1 + I·N)^power))`
//! (unitless reflectance), fitted by least squares to the exact Fresnel law
//! of a material and measured beside Schlick's approximation.
//!
//! The form is the one of the vertex program `C7E5v_dispersion` (`001`
//! line 508), `1 + dot(I, N)`, clamped as the slide (line 467) clamps it; the
//! slide's own `0 + I·N` is an erratum (`docs/errata.md`). Its arithmetic is
//! [`radiometry::course::EmpiricalFresnel::vertex_program`]; the exact laws
//! are [`radiometry::fresnel::dielectric`] and
//! [`radiometry::fresnel::conductor`], Schlick is [`radiometry::fresnel::schlick`].
//! None is re-derived here: this module only chooses the parameters.
//!
//! Light arrives from the outside (air, index 1), `cos_i = dot(n, wi)` in
//! `[0, 1]` as in radiometry's conventions; in the slides' terms
//! `I = −wi`, so `1 + I·N = 1 − cos_i`.
//!
//! # The fit
//!
//! Least squares over an [`AngleGrid`], uniform in the incidence angle
//! (by default every 0.1° from 0° to 90°). For a fixed `power` the form is
//! linear in `bias` and `scale`, which are then solved in closed form; the
//! residual is minimised over `power` by a scan of [`POWER_SCAN`] followed
//! by a golden-section search between the best scanned power's neighbours.
//! The result is deterministic and does not depend on a starting guess.
//!
//! The fit minimises the unclamped form's squared error; the errors it
//! reports are those of the clamped form. The exact reflectance lies in
//! `[0, 1]`, so clamping can only bring the form closer to it: the clamped
//! errors are never larger. Schlick's curve is the form with `bias = F0`,
//! `scale = 1 − F0`, `power = 5`, so on the grid the fitted RMS can be no
//! larger than Schlick's; its worst-case error can (glass, see the tests).

use glam::DVec3;
use radiometry::course::EmpiricalFresnel;
use radiometry::fresnel;

/// A smooth interface lit from the outside (index 1), whose exact
/// reflectance the form is fitted to.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Interface {
    /// A dielectric of relative index `eta = n_inside / n_outside`.
    Dielectric {
        /// `n_inside / n_outside`.
        eta: f64,
    },
    /// A conductor of complex index `n + i·kappa`.
    Conductor {
        /// The real part of the index.
        n: f64,
        /// The extinction coefficient, `kappa ≥ 0`.
        kappa: f64,
    },
}

impl Interface {
    /// The exact unpolarised reflectance at `cos_i`.
    pub fn reflectance(&self, cos_i: f64) -> f64 {
        match *self {
            Self::Dielectric { eta } => fresnel::dielectric(cos_i, eta),
            Self::Conductor { n, kappa } => fresnel::conductor(cos_i, n, kappa),
        }
    }

    /// The normal-incidence reflectance `F0`.
    pub fn f0(&self) -> f64 {
        match *self {
            Self::Dielectric { eta } => fresnel::f0(eta, 0.0),
            Self::Conductor { n, kappa } => fresnel::f0(n, kappa),
        }
    }

    /// Schlick's approximation with this interface's `F0`.
    pub fn schlick(&self, cos_i: f64) -> f64 {
        fresnel::schlick(cos_i, self.f0())
    }
}

/// Glass, `eta = 1.5`.
pub const GLASS: Interface = Interface::Dielectric { eta: 1.5 };
/// Water, `eta = 1.33` (the suite's `inside_water.json`).
pub const WATER: Interface = Interface::Dielectric { eta: 1.33 };

const fn rgb(n: [f64; 3], kappa: [f64; 3]) -> [Interface; 3] {
    [
        Interface::Conductor {
            n: n[0],
            kappa: kappa[0],
        },
        Interface::Conductor {
            n: n[1],
            kappa: kappa[1],
        },
        Interface::Conductor {
            n: n[2],
            kappa: kappa[2],
        },
    ]
}

/// The course's gold (`000` lines 1385–1386, the scene `gold_spheres.json`),
/// per R, G, B channel.
pub const GOLD: [Interface; 3] = rgb([0.17, 0.35, 1.5], [3.1, 2.7, 1.9]);
/// The suite's silver (`webgl_seven_spheres.json`), per R, G, B channel.
pub const SILVER: [Interface; 3] = rgb([0.155, 0.117, 0.138], [3.6, 3.04, 2.52]);
/// The suite's copper (`inside_water.json`), per R, G, B channel.
pub const COPPER: [Interface; 3] = rgb([0.2, 0.924, 1.102], [3.912, 2.452, 2.142]);

/// Every material of the suite the form is fitted to, named, one channel a
/// line.
pub const SUITE: [(&str, Interface); 11] = [
    ("glass", GLASS),
    ("water", WATER),
    ("gold R", GOLD[0]),
    ("gold G", GOLD[1]),
    ("gold B", GOLD[2]),
    ("silver R", SILVER[0]),
    ("silver G", SILVER[1]),
    ("silver B", SILVER[2]),
    ("copper R", COPPER[0]),
    ("copper G", COPPER[1]),
    ("copper B", COPPER[2]),
];

/// Incidence angles uniform in `θ` from 0° to 90°, both ends included.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct AngleGrid {
    intervals: usize,
}

impl AngleGrid {
    /// Every 0.1°: 901 angles.
    pub const TENTH_OF_A_DEGREE: Self = Self { intervals: 900 };

    /// `intervals + 1` angles, `None` for fewer than two intervals (a fit
    /// of three parameters needs at least three angles).
    pub fn new(intervals: usize) -> Option<Self> {
        (intervals >= 2).then_some(Self { intervals })
    }

    /// The cosines of the angles, from normal (1) to grazing incidence.
    pub fn cosines(&self) -> impl Iterator<Item = f64> + '_ {
        let step = std::f64::consts::FRAC_PI_2 / self.intervals as f64;
        (0..=self.intervals).map(move |k| (k as f64 * step).cos())
    }
}

/// The slides' form at `cos_i`: the vertex program's arithmetic for the
/// incident direction of travel `I = −wi`, clamped into `[0, 1]` as the
/// slide writes it.
pub fn reflectance(form: &EmpiricalFresnel<f64>, cos_i: f64) -> f64 {
    unclamped(form, cos_i).clamp(0.0, 1.0)
}

/// The vertex program's arithmetic, unclamped: what the fit minimises.
fn unclamped(form: &EmpiricalFresnel<f64>, cos_i: f64) -> f64 {
    let sin_i = (1.0 - cos_i * cos_i).max(0.0).sqrt();
    let travelling = DVec3::new(sin_i, 0.0, -cos_i);
    form.vertex_program(travelling, DVec3::Z)
}

/// How far a curve lies from the exact law over a grid.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Errors {
    /// The root mean square of the difference.
    pub rms: f64,
    /// The largest absolute difference.
    pub max: f64,
}

/// The errors of `curve` against `exact` over `grid`.
pub fn errors(curve: impl Fn(f64) -> f64, exact: impl Fn(f64) -> f64, grid: &AngleGrid) -> Errors {
    let (mut squares, mut max, mut count) = (0.0, 0.0f64, 0usize);
    for cos_i in grid.cosines() {
        let e = curve(cos_i) - exact(cos_i);
        squares += e * e;
        max = max.max(e.abs());
        count += 1;
    }
    Errors {
        rms: (squares / count as f64).sqrt(),
        max,
    }
}

/// The powers scanned before the golden-section search,
/// `first + step · k` for `k` in `0..count`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PowerScan {
    /// The first power.
    pub first: f64,
    /// The step between powers.
    pub step: f64,
    /// How many powers.
    pub count: usize,
}

/// 0.05 to 30 in steps of 0.05: Schlick's 5 and the metals' fitted 5 to
/// 15 well inside.
pub const POWER_SCAN: PowerScan = PowerScan {
    first: 0.05,
    step: 0.05,
    count: 600,
};

/// The golden-section search stops when its bracket is narrower than this.
pub const POWER_TOLERANCE: f64 = 1e-9;

/// A least-squares fit of the form and its errors against the data.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Fit {
    /// The fitted parameters.
    pub form: EmpiricalFresnel<f64>,
    /// The clamped form's errors against the data fitted.
    pub errors: Errors,
}

/// Why no fit was made.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum FitError {
    /// The data has a NaN or infinite value.
    NotFinite,
    /// The best scanned power is the first or last of [`POWER_SCAN`]: the
    /// least-squares power lies at or beyond the range searched (also when
    /// the data is flat and no power fits better than another).
    PowerNotBracketed {
        /// The best power scanned.
        power: f64,
    },
}

/// The least-squares fit of the form to `exact` over `grid`.
pub fn fit(exact: impl Fn(f64) -> f64, grid: &AngleGrid) -> Result<Fit, FitError> {
    let data: Vec<(f64, f64)> = grid.cosines().map(|c| (c, exact(c))).collect();
    if data.iter().any(|&(_, y)| !y.is_finite()) {
        return Err(FitError::NotFinite);
    }
    let PowerScan { first, step, count } = POWER_SCAN;
    let power_at = |k: usize| first + step * k as f64;
    let best = (0..count)
        .map(|k| (k, linear_fit(&data, power_at(k)).1))
        .min_by(|a, b| a.1.total_cmp(&b.1))
        .map(|(k, _)| k)
        .unwrap_or(0);
    if best == 0 || best + 1 == count {
        return Err(FitError::PowerNotBracketed {
            power: power_at(best),
        });
    }
    let power = golden_section(
        |p| linear_fit(&data, p).1,
        power_at(best - 1),
        power_at(best + 1),
    );
    let (form, _) = linear_fit(&data, power);
    let errors = errors(|c| reflectance(&form, c), &exact, grid);
    Ok(Fit { form, errors })
}

/// For a fixed `power`, the `bias` and `scale` of least squares (the
/// straight-line fit of the data against the form's rising term
/// `(1 + I·N)^power`, in centred sums), and the sum of squared residuals.
fn linear_fit(data: &[(f64, f64)], power: f64) -> (EmpiricalFresnel<f64>, f64) {
    // The rising term, taken from the form itself: bias 0, scale 1.
    let rising = EmpiricalFresnel {
        bias: 0.0,
        scale: 1.0,
        power,
    };
    let phi: Vec<f64> = data.iter().map(|&(c, _)| unclamped(&rising, c)).collect();
    let count = data.len() as f64;
    let phi_mean = phi.iter().sum::<f64>() / count;
    let y_mean = data.iter().map(|&(_, y)| y).sum::<f64>() / count;
    let (mut sxy, mut sxx) = (0.0, 0.0);
    for (&p, &(_, y)) in phi.iter().zip(data) {
        sxy += (p - phi_mean) * (y - y_mean);
        sxx += (p - phi_mean) * (p - phi_mean);
    }
    let scale = if sxx > 0.0 { sxy / sxx } else { 0.0 };
    let bias = y_mean - scale * phi_mean;
    let residual = phi
        .iter()
        .zip(data)
        .map(|(&p, &(_, y))| (bias + scale * p - y).powi(2))
        .sum();
    (EmpiricalFresnel { bias, scale, power }, residual)
}

/// The minimum of `f` on `[lo, hi]`, where `f` has a single minimum, to
/// within [`POWER_TOLERANCE`].
fn golden_section(f: impl Fn(f64) -> f64, mut lo: f64, mut hi: f64) -> f64 {
    let inverse_phi = (5f64.sqrt() - 1.0) / 2.0;
    let (mut a, mut b) = (hi - inverse_phi * (hi - lo), lo + inverse_phi * (hi - lo));
    let (mut fa, mut fb) = (f(a), f(b));
    while hi - lo > POWER_TOLERANCE {
        if fa < fb {
            (hi, b, fb) = (b, a, fa);
            a = hi - inverse_phi * (hi - lo);
            fa = f(a);
        } else {
            (lo, a, fa) = (a, b, fb);
            b = lo + inverse_phi * (hi - lo);
            fb = f(b);
        }
    }
    (lo + hi) / 2.0
}

/// The fitted form and Schlick's approximation, each against the exact law
/// of one interface over one grid.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Comparison {
    /// The least-squares fit of the form.
    pub fit: Fit,
    /// Schlick's errors over the same grid.
    pub schlick: Errors,
}

/// Fits the form to `interface`'s exact reflectance over `grid` and
/// measures Schlick beside it.
///
/// ```
/// use techniques::empirical_fresnel::{compare, AngleGrid, GLASS};
/// let glass = compare(GLASS, &AngleGrid::TENTH_OF_A_DEGREE).unwrap();
/// // Schlick is one member of the form's family: the fit is no worse in RMS.
/// assert!(glass.fit.errors.rms < glass.schlick.rms);
/// assert!((glass.fit.form.power - 4.9555).abs() < 1e-4);
/// ```
pub fn compare(interface: Interface, grid: &AngleGrid) -> Result<Comparison, FitError> {
    let exact = |c| interface.reflectance(c);
    Ok(Comparison {
        fit: fit(exact, grid)?,
        schlick: errors(|c| interface.schlick(c), exact, grid),
    })
}

#[cfg(test)]
mod tests;
