//! The reference's schema: `fresnel_mpmath.json`'s cases per tier, and
//! the exact values they carry as `hi + lo`, with the error of a computed
//! value counted in ulps of the exact one.

use radiometry::Real;
use serde::Deserialize;

/// A value carried as the unevaluated sum `hi + lo` of two doubles.
#[derive(Clone, Copy, Debug, Deserialize)]
pub struct Exact(pub f64, pub f64);

/// `fresnel_mpmath.json`.
#[derive(Clone, Debug, Deserialize)]
pub struct FresnelMpmath {
    /// mpmath's version.
    pub mpmath_version: String,
    /// Dielectric cases per tier.
    pub dielectric: Tiers<DielectricCase>,
    /// Conductor cases per tier.
    pub conductor: Tiers<ConductorCase>,
    /// The angle laws per tier.
    pub angles: Tiers<AngleCase>,
}

/// Cases whose inputs are exact in `f64`, and in `f32`.
#[derive(Clone, Debug, Deserialize)]
pub struct Tiers<C> {
    /// Inputs exact in `f64`.
    pub f64: Vec<C>,
    /// Inputs exact in `f32`.
    pub f32: Vec<C>,
}

impl<C> Tiers<C> {
    /// Both tiers' cases, each with its tier's name.
    pub fn by_tier(&self) -> [(&'static str, &[C]); 2] {
        [("f64", &self.f64), ("f32", &self.f32)]
    }
}

/// One dielectric case.
#[derive(Clone, Debug, Deserialize)]
pub struct DielectricCase {
    /// Where on the grid.
    pub label: String,
    /// Signed cosine.
    pub cos_i: f64,
    /// `n_inside / n_outside`.
    pub eta: f64,
    /// Total internal reflection.
    pub tir: bool,
    /// Exact R_s.
    pub r_s: Exact,
    /// Exact R_p.
    pub r_p: Exact,
    /// Exact R.
    pub r: Exact,
    /// Exact T = 1 − R.
    pub t: Exact,
    /// The condition number of T at this input: how much a relative change
    /// of the inputs is amplified in T (large where `1 − R` cancels).
    pub cond_t: f64,
}

/// One case of an angle law.
#[derive(Clone, Debug, Deserialize)]
pub struct AngleCase {
    /// Where on the grid.
    pub label: String,
    /// `transmitted_angle`, `critical_angle` or `brewster_angle`.
    pub law: String,
    /// The angle of incidence (radians; `transmitted_angle` only).
    pub theta_i: f64,
    /// The index along the path, `n_t / n_i`.
    pub eta_path: f64,
    /// The exact angle, or `None` where the law has none (total internal
    /// reflection, no critical angle).
    pub value: Option<Exact>,
    /// The relative condition number of the angle over `theta_i` alone,
    /// `|θ_i ∂θ_t/∂θ_i| / θ_t` (`transmitted_angle`; 0 for the others,
    /// whose one input reaches them exact).
    pub cond_theta: f64,
}

/// One conductor case.
#[derive(Clone, Debug, Deserialize)]
pub struct ConductorCase {
    /// Where on the grid.
    pub label: String,
    /// Cosine.
    pub cos_i: f64,
    /// Real index.
    pub n: f64,
    /// Extinction coefficient.
    pub kappa: f64,
    /// Exact R_s.
    pub r_s: Exact,
    /// Exact R_p.
    pub r_p: Exact,
    /// Exact R.
    pub r: Exact,
}

impl FresnelMpmath {
    /// Loads the reference from `dir`.
    pub fn load(dir: &std::path::Path) -> Result<Self, crate::reference::ReferenceError> {
        crate::reference::load(dir, super::FILE, super::SCHEMA)
    }
}

impl Exact {
    /// The spacing of the tier's numbers at the exact value `hi + lo`
    /// ([`Real::ulp_at`]). When `hi` is a power of two and `lo` points
    /// towards zero, the value lies in the binade below, whose spacing is
    /// half that at `hi`.
    pub fn ulp(self, tier: &str) -> f64 {
        let at = if tier == "f32" {
            f32::ulp_at
        } else {
            f64::ulp_at
        };
        let power_of_two = self.0 != 0.0 && self.0.to_bits() & ((1 << 52) - 1) == 0;
        // `lo` pointing towards zero puts the exact value inside |hi|'s binade below.
        let below = power_of_two && self.1 != 0.0 && self.1.signum() != self.0.signum();
        if below {
            at(self.0.abs() * 0.75) // any value of the binade below
        } else {
            at(self.0)
        }
    }

    /// `|got − (hi + lo)|`. `got − hi` is exact (Sterbenz) when the two are
    /// close, so the error resolves below one ulp of either tier.
    pub fn error(self, got: f64) -> f64 {
        ((got - self.0) - self.1).abs()
    }

    /// [`Exact::error`] in ulps of the tier at the exact value
    /// ([`Exact::ulp`]); infinite if `got` is NaN.
    pub fn ulps(self, got: f64, tier: &str) -> f64 {
        let err = self.error(got);
        if err.is_nan() {
            f64::INFINITY
        } else {
            err / self.ulp(tier)
        }
    }
}
