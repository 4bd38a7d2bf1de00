//! The Fresnel equations: the fraction of light power reflected (and
//! transmitted) by a smooth interface, for dielectrics and conductors, with
//! the course's approximations beside them. All results are unitless
//! fractions in `[0, 1]`.
//!
//! | function | law | source |
//! |---|---|---|
//! | [`dielectric_polarized`], [`dielectric`], [`dielectric_transmittance`] | exact, real index, either side | Born & Wolf, *Principles of Optics*, §1.5.2 |
//! | [`conductor_polarized`], [`conductor`] | exact, complex index `n + i·kappa` | Born & Wolf §14.2; pbrt-v4 §9.5 |
//! | [`f0`] | normal-incidence reflectance `((n−1)² + κ²) / ((n+1)² + κ²)` | course text `003`, Born & Wolf §14.2 eq. 15 |
//! | [`schlick`], [`schlick_dielectric`] | Schlick's approximation | C. Schlick, *Computer Graphics Forum* 13(3), 1994 |
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
//! result against 50-digit values: a few ulps in `f64` and `f32` across the
//! grid, extremes included.
//!
//! The sign of the amplitudes is not exposed: only powers are returned.

use num_complex::Complex;

#[allow(unused_imports)]
use num_traits::{Float, FloatConst, One, Zero};

use crate::compensated;
use crate::snell::{clamp_unit, Incidence};
use crate::Real;

/// Normal-incidence reflectance `F0 = ((n − 1)² + κ²) / ((n + 1)² + κ²)` of
/// an interface from a medium of index 1 into one of index `n + i·kappa`.
///
/// For a dielectric (`kappa = 0`) this is `((η − 1) / (η + 1))²` for either
/// direction of travel. NaN for `n ≤ 0` or `kappa < 0`.
///
/// ```
/// use radiometry::fresnel::{f0, f0_rgb};
/// // Glass: 4 %.
/// assert!((f0(1.5_f64, 0.0) - 0.04).abs() < 1e-16);
/// // The course's gold, n = (0.17, 0.35, 1.5), κ = (3.1, 2.7, 1.9): yellow.
/// let gold = f0_rgb([0.17_f64, 0.35, 1.5], [3.1, 2.7, 1.9]);
/// let expected = [0.938064, 0.846365, 0.391481];
/// for (got, want) in gold.iter().zip(expected) {
///     assert!((got - want).abs() < 1e-6);
/// }
/// ```
#[inline]
pub fn f0<T: Real>(n: T, kappa: T) -> T {
    if !(n > T::zero() && kappa >= T::zero()) {
        return T::nan();
    }
    let k2 = kappa * kappa;
    let below = (n - T::one()) * (n - T::one()) + k2;
    let above = (n + T::one()) * (n + T::one()) + k2;
    below / above
}

/// Schlick's approximation `F ≈ F0 + (1 − F0)(1 − cos θ)⁵`, as the course
/// uses it for dielectrics and metals alike (`003`, boxed formula).
///
/// `cos_i` is the cosine of the angle on the side the light arrives from;
/// its sign is ignored. For light leaving a denser dielectric this is the
/// wrong angle: see [`schlick_dielectric`].
///
/// ```
/// use radiometry::fresnel::schlick;
/// assert_eq!(schlick(1.0_f64, 0.04), 0.04); // exact at normal incidence
/// assert_eq!(schlick(0.0_f64, 0.04), 1.0); // and at grazing incidence
/// ```
#[inline]
pub fn schlick<T: Real>(cos_i: T, f0: T) -> T {
    let c = clamp_unit(cos_i.abs());
    // 1 − c is exact for c in [1/2, 1] (Sterbenz), where it matters most.
    f0 + (T::one() - f0) * (T::one() - c).powi(5)
}

/// Schlick's approximation for a dielectric interface seen from either side,
/// with `F0 = ((η − 1)/(η + 1))²` and the cosine taken in the less dense
/// medium: from the denser side it uses `cos θ_t`, and under total internal
/// reflection it returns exactly 1.
///
/// Schlick (1994) states the approximation in terms of the angle in the
/// rarer medium; applied with `cos θ_i` from inside glass it misses total
/// internal reflection entirely (by up to 0.975 for water, measured by
/// `cargo run --release -p radiometry --example schlick_error`), while with
/// `cos θ_t` it is as close as from the outside.
#[inline]
pub fn schlick_dielectric<T: Real>(cos_i: T, eta: T) -> T {
    let Some(incidence) = Incidence::resolve(cos_i, eta) else {
        return T::nan();
    };
    // F0 is the same from both sides: ((η−1)/(η+1))² = ((1/η−1)/(1/η+1))².
    let f0 = f0(eta, T::zero());
    if incidence.n_t >= incidence.n_i {
        schlick(incidence.cos_i, f0)
    } else {
        match incidence.cos_transmitted() {
            Some(cos_t) => schlick(cos_t, f0),
            None => T::one(),
        }
    }
}

/// Reflectance and transmittance of a dielectric interface, per polarisation.
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
    /// The effective relative index along the path, `n_t / n_i`.
    pub eta_path: T,
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

    fn all(value: T, cos_t: Option<T>, eta_path: T) -> Self {
        let other = T::one() - value;
        Self {
            r_s: value,
            r_p: value,
            t_s: other,
            t_p: other,
            cos_t,
            eta_path,
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
/// assert!(dielectric_polarized(-0.5_f64, 1.5).is_total_internal_reflection());
/// ```
pub fn dielectric_polarized<T: Real>(cos_i: T, eta: T) -> DielectricFresnel<T> {
    let Some(incidence) = Incidence::resolve(cos_i, eta) else {
        return DielectricFresnel::all(T::nan(), None, T::nan());
    };
    let (c, n_i, n_t) = (incidence.cos_i, incidence.n_i, incidence.n_t);
    let contrast = compensated::index_contrast(n_t, T::zero(), n_i); // n_t² − n_i²
    if contrast == T::zero() {
        return DielectricFresnel::all(T::zero(), Some(c), incidence.eta_path());
    }
    let d = incidence.discriminant(); // s² with s = n_t cos θ_t
    if d < T::zero() {
        return DielectricFresnel::all(T::one(), None, incidence.eta_path());
    }
    let s = d.sqrt();
    let a = n_i * c; // n_i cos θ_i

    // T = 4 a s / w² is evaluated as 4c · (n_i s / w²): at grazing incidence
    // a = n_i c, or the product 4 a s, would underflow before the division.
    let four_c = T::lit(4.0) * c;

    // (a + s)² as a² + 2as + s² with s² = d exactly as computed: at grazing
    // incidence this makes r_s = (n_i² − n_t²)/d = −1 to the last bit.
    let ws2 = a * a + (a + a) * s + d;
    let r_s = sqr(contrast / ws2);
    let t_s = four_c * (n_i * s / ws2);

    // (n_t² c + n_i s)² likewise with n_i² d for (n_i s)²: exact at grazing.
    let n_t2 = n_t * n_t;
    let b = n_t2 * c;
    let wp2 = b * b + (b + b) * (n_i * s) + n_i * n_i * d;
    let brewster = compensated::brewster_factor(n_t, T::zero(), n_i, c);
    let r_p = sqr(contrast * brewster / wp2);
    let t_p = four_c * (n_i * n_t2 * s / wp2);

    DielectricFresnel {
        r_s: fraction(r_s),
        r_p: fraction(r_p),
        t_s: fraction(t_s),
        t_p: fraction(t_p),
        cos_t: Some(clamp_unit(s / n_t)),
        eta_path: incidence.eta_path(),
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
#[inline]
pub fn dielectric<T: Real>(cos_i: T, eta: T) -> T {
    dielectric_polarized(cos_i, eta).reflectance()
}

/// Unpolarised transmittance `1 − R` of a dielectric interface, computed
/// directly so that it stays accurate where it is small.
#[inline]
pub fn dielectric_transmittance<T: Real>(cos_i: T, eta: T) -> T {
    dielectric_polarized(cos_i, eta).transmittance()
}

/// Reflectance of a conductor, per polarisation.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ConductorFresnel<T> {
    /// Reflectance of s-polarised light, `|r_s|²`.
    pub r_s: T,
    /// Reflectance of p-polarised light, `|r_p|²`.
    pub r_p: T,
}

impl<T: Real> ConductorFresnel<T> {
    /// Unpolarised reflectance, `(R_s + R_p) / 2`.
    #[inline]
    pub fn reflectance(&self) -> T {
        (self.r_s + self.r_p) * T::lit(0.5)
    }
}

/// The exact Fresnel equations for light arriving from a dielectric of index
/// 1 (relative) onto a medium of complex index `n + i·kappa`, per
/// polarisation.
///
/// `kappa ≥ 0` is the extinction coefficient; `kappa = 0` gives the
/// dielectric law. Light is taken to arrive from the dielectric side, so the
/// sign of `cos_i` is ignored (a conductor's inside is opaque). To use
/// indices relative to a surrounding medium of index `n_o`, pass `n / n_o`
/// and `kappa / n_o`. NaN in, `n ≤ 0`, `kappa < 0` or infinite values give
/// NaN.
///
/// ```
/// use radiometry::fresnel::{conductor, f0};
/// // At normal incidence the exact law reduces to F0, and at grazing incidence to 1.
/// assert!((conductor(1.0_f64, 0.17, 3.1) - f0(0.17, 3.1)).abs() < 1e-15);
/// assert_eq!(conductor(0.0_f64, 0.17, 3.1), 1.0);
/// ```
pub fn conductor_polarized<T: Real>(cos_i: T, n: T, kappa: T) -> ConductorFresnel<T> {
    let valid = n > T::zero() && n.is_finite() && kappa >= T::zero() && kappa.is_finite();
    if cos_i.is_nan() || !valid {
        return ConductorFresnel {
            r_s: T::nan(),
            r_p: T::nan(),
        };
    }
    let c = clamp_unit(cos_i.abs());
    let two_nk = (n + n) * kappa;
    let one = T::one();
    let eta2_m1 = Complex::new(compensated::index_contrast(n, kappa, one), two_nk);
    if eta2_m1.re == T::zero() && eta2_m1.im == T::zero() {
        return ConductorFresnel {
            r_s: T::zero(),
            r_p: T::zero(),
        };
    }
    // s = η cos θ_t = √(η² − 1 + c²), principal branch (Re s ≥ 0).
    let d = Complex::new(compensated::snell_discriminant(n, kappa, one, c), two_nk);
    let s = principal_sqrt(d);
    // η² itself, summed afresh rather than as (η² − 1) + 1, which would lose
    // the digits of a small η² (n = 1e-3: six of its sixteen).
    let eta2 = Complex::new(compensated::index_contrast(n, kappa, T::zero()), two_nk);
    let brewster = Complex::new(
        compensated::brewster_factor(n, kappa, one, c),
        c * c * two_nk,
    );

    // |x + s|² = |x|² + 2 Re(x̄ s) + |s|² with |s|² = |d|: at grazing incidence
    // (x = 0) the ratios below are then |d| / |d| = 1 to the last bit.
    let abs = |z: Complex<T>| z.re.hypot(z.im);
    let two = T::lit(2.0);
    let ws2 = c * c + two * c * s.re + abs(d); // Re s ≥ 0: no cancellation
    let b = eta2 * c;
    let wp2 = b.norm_sqr() + two * (b.re * s.re + b.im * s.im) + abs(d);
    let r_s = sqr(abs(eta2_m1) / ws2);
    let r_p = sqr(abs(eta2_m1) * abs(brewster) / wp2);
    ConductorFresnel {
        r_s: fraction(r_s),
        r_p: fraction(r_p),
    }
}

/// Unpolarised reflectance of a conductor of complex index `n + i·kappa`,
/// exact. See [`conductor_polarized`] for the conventions.
#[inline]
pub fn conductor<T: Real>(cos_i: T, n: T, kappa: T) -> T {
    conductor_polarized(cos_i, n, kappa).reflectance()
}

/// [`f0`] per channel.
#[inline]
pub fn f0_rgb<T: Real>(n: [T; 3], kappa: [T; 3]) -> [T; 3] {
    core::array::from_fn(|ch| f0(n[ch], kappa[ch]))
}

/// [`schlick`] per channel, sharing one angle.
#[inline]
pub fn schlick_rgb<T: Real>(cos_i: T, f0: [T; 3]) -> [T; 3] {
    f0.map(|f0| schlick(cos_i, f0))
}

/// [`conductor`] per channel, sharing one angle: the course's three-wavelength
/// metal.
///
/// ```
/// use radiometry::fresnel::conductor_rgb;
/// let gold = conductor_rgb(1.0_f64, [0.17, 0.35, 1.5], [3.1, 2.7, 1.9]);
/// assert!(gold[0] > gold[1] && gold[1] > gold[2]); // reflects red most: yellow
/// ```
#[inline]
pub fn conductor_rgb<T: Real>(cos_i: T, n: [T; 3], kappa: [T; 3]) -> [T; 3] {
    core::array::from_fn(|ch| conductor(cos_i, n[ch], kappa[ch]))
}

/// [`dielectric`] per channel with a per-channel index: chromatic dispersion.
#[inline]
pub fn dielectric_rgb<T: Real>(cos_i: T, eta: [T; 3]) -> [T; 3] {
    eta.map(|eta| dielectric(cos_i, eta))
}

#[inline]
fn sqr<T: Real>(x: T) -> T {
    x * x
}

/// Clamps a fraction into `[0, 1]` against rounding, keeping NaN.
#[inline]
fn fraction<T: Real>(x: T) -> T {
    if x > T::one() {
        T::one()
    } else {
        x
    }
}

/// Principal square root (`Re ≥ 0`), accurate in both parts.
///
/// `num_complex::Complex::sqrt` goes through polar form, `√r · e^{iθ/2}`; for
/// an argument near the negative real axis `cos(θ/2)` is taken of an angle
/// near π/2 that carries an absolute rounding error, which destroys the
/// relative accuracy of the small real part, the part that decides a metal's
/// reflectance at grazing angles. This is the classic formulation instead
/// (Kahan, "Branch cuts for complex elementary functions", 1987).
fn principal_sqrt<T: Real>(z: Complex<T>) -> Complex<T> {
    if z.re == T::zero() && z.im == T::zero() {
        return Complex::new(T::zero(), z.im);
    }
    let t = ((z.re.abs() + z.re.hypot(z.im)) * T::lit(0.5)).sqrt();
    if z.re >= T::zero() {
        Complex::new(t, z.im / (t + t))
    } else {
        Complex::new(z.im.abs() / (t + t), t.copysign(z.im))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn principal_sqrt_is_accurate_near_the_negative_real_axis() {
        // √(−1 + iδ) = δ/2 + i(1 + δ²/8 + …): the real part is δ/2 to full
        // relative precision.
        let delta = 1e-10_f64;
        let s = principal_sqrt(Complex::new(-1.0, delta));
        assert!(
            (s.re / (delta / 2.0) - 1.0).abs() < 4.0 * f64::EPSILON,
            "{s}"
        );
        assert_eq!(s.im, 1.0);
        // The polar-form square root loses most of those digits.
        let polar = Complex::new(-1.0_f64, delta).sqrt();
        assert!((polar.re / (delta / 2.0) - 1.0).abs() > 1e-8, "{polar}");
    }

    #[test]
    fn principal_sqrt_matches_real_sqrt_on_the_real_axis() {
        assert_eq!(
            principal_sqrt(Complex::new(2.25_f64, 0.0)),
            Complex::new(1.5, 0.0)
        );
        assert_eq!(
            principal_sqrt(Complex::new(-2.25_f64, 0.0)),
            Complex::new(0.0, 1.5)
        );
    }
}
