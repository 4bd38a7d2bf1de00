//! The exact Fresnel equations for a dielectric interface, seen from either
//! side.
//!
//! # How the exact equations are evaluated
//!
//! The textbook form `r_s = (cos θ_i − η cos θ_t) / (cos θ_i + η cos θ_t)`
//! cancels catastrophically twice: in `1 − sin²θ_t` near the critical angle,
//! and in the numerator when `η → 1` or near Brewster's angle. Here both are
//! removed algebraically. For light going from index `n_i` into `n_t`, with
//! `c = cos θ_i`, `a = n_i c` and `s = n_t cos θ_t = √(n_t² − n_i² + a²)`:
//!
//! ```text
//! r_s = (n_i² − n_t²) / (a + s)²                          T_s = 4 a s / (a + s)²
//! r_p = (n_t² − n_i²)(c²(n_t² + n_i²) − n_i²) / (n_t² c + n_i s)²
//!                                                     T_p = 4 a s n_t² / (n_t² c + n_i s)²
//! ```
//!
//! (multiply numerator and denominator of each textbook amplitude by its
//! denominator, and use Snell's law for `s²`). One of `n_i`, `n_t` is exactly
//! 1 and the other is `eta`, so light from the inside never pays for a
//! rounded `1 / eta`. The two sums that can still cancel, `s²` and the
//! Brewster factor `c²(n_t² + n_i²) − n_i²`, are summed in twice the working
//! precision. `T` is computed directly rather than as `1 − R`, so it keeps
//! its relative accuracy where it is small (near the critical angle and at
//! grazing incidence). The workspace test `fresnel_reference` measures the
//! result against 50-digit values, extremes included: within one ulp or so
//! in `f32`, rounded once from `f64`; in `f64` a few ulps, but `R_p`, the
//! square of a ratio of about six roundings that nothing cancels, reaches
//! 10.9 ulps (at `cos θ_i = 0.76528…`, `η = 1.70205…`; bound 12).
//!
//! The sign of the amplitudes is not exposed: only powers are returned.

#[allow(unused_imports)]
use num_traits::{Float, FloatConst, One, Zero};

use super::algebra::{fraction, sqr};
use crate::compensated;
use crate::snell::Incidence;
use crate::specular::{refract_resolved, Refraction};
use crate::{Real, Vector3};

/// Reflectance and transmittance of a dielectric interface, per
/// polarisation, with what the law decided on the way: the side and indices
/// ([`DielectricFresnel::incidence`]) and whether light is transmitted
/// ([`DielectricFresnel::cos_t`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DielectricFresnel<T> {
    /// Reflectance of s-polarised light (electric field perpendicular to the
    /// plane of incidence), `|r_s|²`.
    pub r_s: T,
    /// Reflectance of p-polarised light (field in the plane of incidence).
    pub r_p: T,
    /// Transmittance of s-polarised light, `1 − r_s`, computed directly.
    pub t_s: T,
    /// Transmittance of p-polarised light, `1 − r_p`, computed directly.
    pub t_p: T,
    /// `cos θ_t ≥ 0`, or `None` under total internal reflection.
    pub cos_t: Option<T>,
    /// The side, the indices `n_i`, `n_t` and `|cos θ_i|` the law was
    /// evaluated at; NaN throughout for input that describes no interface.
    pub incidence: Incidence<T>,
}

impl<T: Real> DielectricFresnel<T> {
    /// Unpolarised reflectance, `(R_s + R_p) / 2`.
    #[inline]
    pub fn reflectance(&self) -> T {
        (self.r_s + self.r_p) * T::lit(0.5)
    }

    /// Unpolarised transmittance, `(T_s + T_p) / 2 = 1 − R`.
    #[inline]
    pub fn transmittance(&self) -> T {
        (self.t_s + self.t_p) * T::lit(0.5)
    }

    /// Whether Snell's law has no solution and all light is reflected.
    #[inline]
    pub fn is_total_internal_reflection(&self) -> bool {
        self.cos_t.is_none()
    }

    /// The effective relative index along the path, `n_t / n_i`, read from
    /// [`DielectricFresnel::incidence`].
    #[inline]
    pub fn eta_path(&self) -> T {
        self.incidence.eta_path()
    }

    /// The refracted ray of `wi` about `n`, the vectors whose `dot(n, wi)`
    /// this law was evaluated at, from the side and `cos θ_t` the law
    /// decided ([`refract_resolved`]); `None` under total internal
    /// reflection.
    #[inline]
    pub fn refraction<V: Vector3<Scalar = T>>(&self, wi: V, n: V) -> Option<Refraction<V>> {
        let cos_t = self.cos_t?;
        Some(refract_resolved(wi, n, &self.incidence, cos_t))
    }

    #[inline]
    fn all(value: T, cos_t: Option<T>, incidence: Incidence<T>) -> Self {
        let other = T::one() - value;
        Self {
            r_s: value,
            r_p: value,
            t_s: other,
            t_p: other,
            cos_t,
            incidence,
        }
    }
}

/// The exact Fresnel equations for a dielectric interface, per polarisation,
/// valid from either side: the sign of `cos_i` says which (crate
/// conventions), `eta = n_inside / n_outside`.
///
/// Special cases, each exact: index-matched (`eta = 1`) reflects nothing;
/// total internal reflection reflects everything; grazing incidence
/// (`cos_i = 0`, `eta ≠ 1`) reflects everything. NaN in, or `eta` not positive
/// and finite, gives NaN in every field.
///
/// ```
/// use radiometry::fresnel::dielectric_polarized;
/// // At Brewster's angle (tan θ_B = 1.5) p-polarised light is not reflected.
/// let cos_b = 1.5_f64.atan().cos();
/// let f = dielectric_polarized(cos_b, 1.5);
/// assert!(f.r_p < 1e-30 && (f.r_s - 0.1479).abs() < 1e-4);
/// // From inside, beyond the critical angle: total internal reflection.
/// let tir = dielectric_polarized(-0.5_f64, 1.5);
/// assert!(tir.is_total_internal_reflection() && tir.incidence.from_inside);
/// ```
#[inline(always)]
pub fn dielectric_polarized<T: Real>(cos_i: T, eta: T) -> DielectricFresnel<T> {
    polarized_on::<T, false>(cos_i, eta)
}

/// [`dielectric_polarized`] compiled for a path that fuses a multiply-add
/// (`FUSED`) or not: the same law and the same bits, its exact product
/// errors taken by the path's quickest means (`compensated::exact_error`).
#[inline(always)]
pub(super) fn polarized_on<T: Real, const FUSED: bool>(cos_i: T, eta: T) -> DielectricFresnel<T> {
    // The law is evaluated whatever the input and the answer for input that
    // describes no interface chosen after it: no branch, so a loop over
    // many cosines vectorises.
    let (incidence, valid) = Incidence::resolve_unchecked(cos_i, eta);
    let law = resolved_on::<T, FUSED>(&incidence);
    if valid {
        law
    } else {
        DielectricFresnel::all(T::nan(), None, Incidence::undefined())
    }
}

/// [`dielectric_polarized`] at an incidence already resolved, for a caller
/// that evaluates several laws at one incidence and decides its side once.
///
/// ```
/// use radiometry::fresnel::{dielectric_polarized, dielectric_resolved};
/// use radiometry::snell::Incidence;
/// let incidence = Incidence::resolve(-0.9_f64, 1.5).unwrap();
/// assert_eq!(dielectric_resolved(&incidence), dielectric_polarized(-0.9, 1.5));
/// ```
#[inline(always)]
pub fn dielectric_resolved<T: Real>(incidence: &Incidence<T>) -> DielectricFresnel<T> {
    resolved_on::<T, false>(incidence)
}

/// [`dielectric_resolved`] on a path that fuses a multiply-add or not, as
/// [`polarized_on`].
#[inline(always)]
fn resolved_on<T: Real, const FUSED: bool>(incidence: &Incidence<T>) -> DielectricFresnel<T> {
    // Evaluated in the tier's wide precision and rounded once at the end:
    // for `f32`, whose products are exact in `f64`, that leaves one rounding
    // per result.
    let exact = T::PRODUCTS_EXACT_IN_WIDE;
    let [c, n_i] = [incidence.abs_cos_i, incidence.n_i].map(T::widen);
    let squares = incidence.index_squares();
    let inside = incidence.from_inside;
    let contrast = squares.contrast(inside).value(); // n_t² − n_i²
                                                     // d = s² with s = n_t cos θ_t; Snell's law decides whether light goes on.
    let snell = incidence.snell::<FUSED>();
    let d = snell.discriminant;
    // The general case is computed whatever the outcome and the special
    // cases are chosen after it, so that a loop over many cosines has no
    // branch and vectorises; `max` keeps the square root of a negative `d`
    // (whose result is not chosen) out of the way.
    let s = d.max(T::Wide::zero()).sqrt();
    // The side's indices as products chosen per angle, not as `n_i`, `n_t`
    // widened per angle: one of the two is 1, and the other's products
    // are taken whatever the side.
    let eta = squares.eta();
    let pick = |times_eta: T::Wide, alone: T::Wide| if inside { times_eta } else { alone };
    let a = pick(eta * c, c); // n_i cos θ_i
    let n_i_s = pick(eta * s, s);

    // T = 4 a s / w² is evaluated as 4c · (n_i s / w²): at grazing incidence
    // a = n_i c, or the product 4 a s, would underflow before the division.
    let four_c = T::Wide::lit(4.0) * c;

    // (a + s)² as a² + 2as + s² with s² = d exactly as computed: at grazing
    // incidence this makes r_s = (n_i² − n_t²)/d = −1 to the last bit.
    // (n_t² c + n_i s)² likewise with n_i² d for (n_i s)²: exact at grazing.
    //
    // A tier whose products are exact in the wide precision (`f32`)
    // squares the sums as they are, in two operations where the expanded
    // forms take nine: its result is rounded once more, to a precision
    // 2^29 coarser, which takes r_s and r_p to −1 at grazing incidence all
    // the same (`s² = d` to within an `f64` ulp), and the few `f64`
    // roundings of the squares and of `wide_quotients` lie as far below it.
    let n_t2 = squares.transmitted(inside);
    let b = pick(c, n_t2 * c);
    let (ws2, wp2) = if exact {
        (sqr(a + s), sqr(b + n_i_s))
    } else {
        (
            a * a + (a + a) * s + d,
            b * b + (b + b) * n_i_s + n_i * n_i * d,
        )
    };
    let brewster = compensated::brewster_factor::<_, FUSED>(&squares, inside, c, exact);

    let [amp_s, amp_p] = T::wide_quotients_sharing(contrast, ws2, brewster, wp2);
    let [t_s, t_p] = T::wide_quotients(n_i * s, ws2, n_i * n_t2 * s, wp2);
    let (r_s, r_p) = (sqr(amp_s), sqr(amp_p));
    let (t_s, t_p) = (four_c * t_s, four_c * t_p);

    // Clamped after rounding, in the tier's own lanes (twice as many as
    // the wide tier's for `f32`): the same value as clamping before, for
    // any `x`, as rounding is monotonic and keeps 1.
    let narrow = |x| fraction(T::narrow(x));
    let general = DielectricFresnel {
        r_s: narrow(r_s),
        r_p: narrow(r_p),
        t_s: narrow(t_s),
        t_p: narrow(t_p),
        cos_t: Some(incidence.cos_from_root(s)),
        incidence: *incidence,
    };
    // Chosen by value, not by branch (each case is cheap to have computed).
    if contrast == T::Wide::zero() {
        // Index-matched (n_t = n_i): nothing reflects, θ_t = θ_i.
        DielectricFresnel::all(T::zero(), incidence.cos_transmitted(), *incidence)
    } else if !snell.transmits {
        DielectricFresnel::all(T::one(), None, *incidence)
    } else {
        general
    }
}

/// Unpolarised reflectance of a dielectric interface, exact, from either
/// side. See [`dielectric_polarized`] for the conventions and special cases.
///
/// ```
/// use radiometry::fresnel::dielectric;
/// assert!((dielectric(1.0_f64, 1.5) - 0.04).abs() < 1e-16);
/// assert!((dielectric(-1.0_f64, 1.5) - 0.04).abs() < 1e-16); // symmetric at normal incidence
/// assert_eq!(dielectric(0.3_f64, 1.0), 0.0); // index-matched: nothing reflects
/// ```
#[inline(always)]
pub fn dielectric<T: Real>(cos_i: T, eta: T) -> T {
    dielectric_polarized(cos_i, eta).reflectance()
}

/// Unpolarised transmittance `1 − R` of a dielectric interface, computed
/// directly so that it stays accurate where it is small.
#[inline]
pub fn dielectric_transmittance<T: Real>(cos_i: T, eta: T) -> T {
    dielectric_polarized(cos_i, eta).transmittance()
}

/// [`dielectric`] per channel with a per-channel index: chromatic dispersion.
#[inline]
pub fn dielectric_rgb<T: Real>(cos_i: T, eta: [T; 3]) -> [T; 3] {
    eta.map(|eta| dielectric(cos_i, eta))
}
