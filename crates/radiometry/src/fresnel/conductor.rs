//! The exact Fresnel equations for a conductor, of complex index
//! `n + i·kappa`, lit from the dielectric side.

use num_complex::Complex;

#[allow(unused_imports)]
use num_traits::{Float, FloatConst, One, Zero};

use super::algebra::{fraction, sqr};
use crate::compensated::{self, TwoPart};
use crate::snell::clamp_unit;
use crate::Real;

/// The wide precision of the tier `T`.
type Wide<T> = <T as Real>::Wide;

/// Reflectance of a conductor, per polarisation.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ConductorFresnel<T> {
    /// Reflectance of s-polarised light, `|r_s|²`.
    pub r_s: T,
    /// Reflectance of p-polarised light, `|r_p|²`.
    pub r_p: T,
}

impl<T: Real> ConductorFresnel<T> {
    /// NaN in both polarisations: input that describes no conductor.
    #[inline]
    fn undefined() -> Self {
        Self {
            r_s: T::nan(),
            r_p: T::nan(),
        }
    }

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
#[inline(always)]
pub fn conductor_polarized<T: Real>(cos_i: T, n: T, kappa: T) -> ConductorFresnel<T> {
    match Conductor::new(n, kappa) {
        Some(conductor) => conductor.polarized(cos_i),
        None => ConductorFresnel::undefined(),
    }
}

/// A conductor of complex index `n + i·kappa`, lit from a dielectric of
/// index 1, with the parts of the exact law that do not depend on the
/// angle computed once: a material evaluated at many angles (a surface of
/// a render) builds it once and asks [`Conductor::polarized`] at each.
/// [`conductor_polarized`] is the same law in one call.
///
/// ```
/// use radiometry::fresnel::{conductor_polarized, Conductor};
/// let gold_red = Conductor::new(0.17_f32, 3.1).unwrap();
/// assert_eq!(gold_red.polarized(0.6), conductor_polarized(0.6, 0.17, 3.1));
/// assert!(Conductor::new(0.17_f32, -1.0).is_none()); // κ < 0 absorbs negatively
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Conductor<T: Real> {
    /// The real part of `η² − 1`, unevaluated.
    contrast: TwoPart<Wide<T>>,
    /// The real part of `η² + 1`, unevaluated: Brewster's factor is
    /// `c² (η² + 1) − 1`.
    brewster: TwoPart<Wide<T>>,
    /// `η²`.
    eta2: Complex<Wide<T>>,
    /// `|η² − 1|`; zero for an index-matched medium, which reflects nothing.
    abs_eta2_m1: Wide<T>,
    /// `2 n κ`, the imaginary part of `η²`.
    two_nk: Wide<T>,
}

impl<T: Real> Conductor<T> {
    /// The conductor of index `n + i·kappa`; `None` for `n ≤ 0`,
    /// `kappa < 0` or either not finite (NaN included).
    #[inline(always)]
    pub fn new(n: T, kappa: T) -> Option<Self> {
        let valid = n > T::zero() && n.is_finite() && kappa >= T::zero() && kappa.is_finite();
        if !valid {
            return None;
        }
        // In the tier's wide precision; what its exact products spare is
        // decided per tier.
        let exact = T::PRODUCTS_EXACT_IN_WIDE;
        let (n, kappa) = (n.widen(), kappa.widen());
        let one = Wide::<T>::one();
        let two_nk = (n + n) * kappa;
        let contrast = compensated::squares_plus(n, kappa, -one, exact);
        // η² itself, summed afresh rather than as (η² − 1) + 1, which would
        // lose the digits of a small η² (n = 1e-3: six of its sixteen).
        let eta2_re = compensated::squares_plus(n, kappa, Wide::<T>::zero(), exact).value();
        Some(Self {
            contrast,
            brewster: compensated::squares_plus(n, kappa, one, exact),
            eta2: Complex::new(eta2_re, two_nk),
            abs_eta2_m1: T::wide_hypotenuse(contrast.value(), two_nk),
            two_nk,
        })
    }

    /// Reflectance per polarisation at `cos_i` (its sign is ignored: light
    /// arrives from the dielectric side); NaN for a NaN cosine.
    #[inline(always)]
    pub fn polarized(&self, cos_i: T) -> ConductorFresnel<T> {
        self.polarized_on::<false>(cos_i)
    }

    /// [`Conductor::polarized`] compiled for a path that fuses a
    /// multiply-add (`FUSED`) or not: the same law and the same bits, its
    /// exact product errors taken by the path's quickest means
    /// (`compensated::exact_error`).
    #[inline(always)]
    pub(super) fn polarized_on<const FUSED: bool>(&self, cos_i: T) -> ConductorFresnel<T> {
        // Computed whatever the cosine and a NaN one answered after: no
        // branch, so a loop over many cosines vectorises.
        let exact = T::PRODUCTS_EXACT_IN_WIDE;
        let c = clamp_unit(cos_i.abs()).widen();
        // s = η cos θ_t = √(η² − 1 + c²), principal branch (Re s ≥ 0).
        let d = Complex::new(
            compensated::discriminant_from(self.contrast, c, exact),
            self.two_nk,
        );
        let (u, us) = scaled_root::<T>(d);
        let brewster = Complex::new(
            compensated::brewster_from::<_, FUSED>(self.brewster, c, exact),
            c * c * self.two_nk,
        );

        // |x + s|² = |x|² + 2 Re(x̄ s) + |s|² with |s|² = |d|, each times u:
        // at grazing incidence (x = 0) the ratios below are then
        // u|d| / u|d| = 1 to the last bit.
        let abs = |z: Complex<Wide<T>>| T::wide_hypotenuse(z.re, z.im);
        let two = Wide::<T>::lit(2.0);
        let u_abs_d = u * abs(d);
        let u_ws2 = u * (c * c) + two * c * us.re + u_abs_d; // Re s ≥ 0: no cancellation
        let b = self.eta2 * c;
        let u_wp2 = u * b.norm_sqr() + two * (b.re * us.re + b.im * us.im) + u_abs_d;
        // |η² − 1| / |x + s|² = u |η² − 1| / (u |x + s|²): the scale
        // multiplies the numerator rather than divides the denominator,
        // rounding as often, with one division per amplitude where there
        // were two.
        let u_contrast = u * self.abs_eta2_m1;
        let (r_s, r_p) = if exact {
            // |Brewster|² as summed, without its square root: a tier whose
            // results are rounded once more, to a precision 2^29 coarser,
            // does not see the difference in rounding, and the square
            // root is the slowest step there is.
            let [amp_s, amp_p] = T::wide_quotients(u_contrast, u_ws2, u_contrast, u_wp2);
            (sqr(amp_s), sqr(amp_p) * brewster.norm_sqr())
        } else {
            let [amp_s, amp_p] =
                T::wide_quotients(u_contrast, u_ws2, u_contrast * abs(brewster), u_wp2);
            (sqr(amp_s), sqr(amp_p))
        };
        // Index-matched (η = 1) reflects nothing; chosen here rather than
        // computed, as 0 / ws2 is NaN at grazing incidence (ws2 = 0).
        let zero = Wide::<T>::zero();
        let matched = self.abs_eta2_m1 == zero;
        let narrow = |r| T::narrow(if matched { zero } else { fraction(r) });
        let law = ConductorFresnel {
            r_s: narrow(r_s),
            r_p: narrow(r_p),
        };
        if cos_i.is_nan() {
            ConductorFresnel::undefined()
        } else {
            law
        }
    }

    /// Unpolarised reflectance at `cos_i`, `(R_s + R_p) / 2`.
    #[inline(always)]
    pub fn reflectance(&self, cos_i: T) -> T {
        self.polarized(cos_i).reflectance()
    }
}

/// Unpolarised reflectance of a conductor of complex index `n + i·kappa`,
/// exact. See [`conductor_polarized`] for the conventions.
#[inline(always)]
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

/// The principal square root `s` of `z` (`Re s ≥ 0`) as `(u, u·s)` for a
/// positive `u`, without a division: the laws need `s` only in ratios, so
/// the scale cancels, and a division is the slowest step there is.
///
/// `num_complex::Complex::sqrt` goes through polar form, `√r · e^{iθ/2}`; for
/// an argument near the negative real axis `cos(θ/2)` is taken of an angle
/// near π/2 that carries an absolute rounding error, which destroys the
/// relative accuracy of the small real part, the part that decides a metal's
/// reflectance at grazing angles. This is the classic formulation instead
/// (Kahan, "Branch cuts for complex elementary functions", 1987): with
/// `t = √((|x| + |z|) / 2)`, `s = (t, y / 2t)` for `x ≥ 0` and
/// `(|y| / 2t, ±t)` otherwise; scaled by `u = 2t` both parts are products,
/// and `2t² = |x| + |z|` is used as summed rather than squared back.
#[inline]
fn scaled_root<T: Real>(z: Complex<Wide<T>>) -> (Wide<T>, Complex<Wide<T>>) {
    let zero = Wide::<T>::zero();
    let two_t2 = z.re.abs() + T::wide_hypotenuse(z.re, z.im);
    let t = (two_t2 * Wide::<T>::lit(0.5)).sqrt();
    let u = t + t;
    // Both halves chosen by value, not by branch, so that a loop vectorises.
    let us = if z.re >= zero {
        Complex::new(two_t2, z.im)
    } else {
        Complex::new(z.im.abs(), two_t2.copysign(z.im))
    };
    if z.re == zero && z.im == zero {
        (Wide::<T>::one(), Complex::new(zero, z.im))
    } else {
        (u, us)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn scaled_root_is_accurate_near_the_negative_real_axis() {
        // √(−1 + iδ) = δ/2 + i(1 + δ²/8 + …): the real part is δ/2 to full
        // relative precision.
        let delta = 1e-10_f64;
        let (u, us) = scaled_root::<f64>(Complex::new(-1.0, delta));
        let s = us / u;
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
    fn scaled_root_matches_real_sqrt_on_the_real_axis() {
        for (z, root) in [
            (2.25, Complex::new(1.5, 0.0)),
            (-2.25, Complex::new(0.0, 1.5)),
        ] {
            let (u, us) = scaled_root::<f64>(Complex::new(z, 0.0));
            assert!(u > 0.0);
            assert_eq!(us / u, root, "√{z}");
        }
        assert_eq!(
            scaled_root::<f64>(Complex::new(0.0, 0.0)),
            (1.0, Complex::new(0.0, 0.0))
        );
    }
}
