//! The exact Fresnel equations for a conductor, of complex index
//! `n + i·kappa`, lit from the dielectric side.

use num_complex::Complex;

#[allow(unused_imports)]
use num_traits::{Float, FloatConst, One, Zero};

use super::{fraction, sqr};
use crate::compensated;
use crate::snell::clamp_unit;
use crate::Real;

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
    let abs = |z: Complex<T>| z.re.hypotenuse(z.im);
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
    let t = ((z.re.abs() + z.re.hypotenuse(z.im)) * T::lit(0.5)).sqrt();
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
