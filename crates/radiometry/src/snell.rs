//! Snell's law, `n_i sin θ_i = n_t sin θ_t`, and the angles it singles out:
//! the critical angle of total internal reflection and Brewster's angle.
//! Angles in radians; indices of refraction are unitless.
//!
//! Functions on signed cosines follow the crate convention,
//! `eta = n_inside / n_outside`, and read the side from the sign of `cos_i`;
//! they resolve it once, through [`Incidence::resolve`]. Functions on angles
//! in `[0, π/2]` have no side to read and take the index along the path,
//! `eta_path = n_t / n_i` (light goes from medium i into medium t), as the
//! crate conventions state.
//!
//! Sources: Snell's law as the course states it (`003`, "Snellius-Descartes
//! törvény"; `001`, `n₁ sin θ₁ = n₂ sin θ₂`); Born & Wolf, *Principles of
//! Optics*, §1.5 (refraction, total internal reflection, Brewster's angle).
//!
//! ```
//! use radiometry::snell;
//!
//! // The course's quiz: light leaving a medium of index 10 into air.
//! let theta_c = snell::critical_angle(1.0_f64 / 10.0).unwrap();
//! assert!((theta_c.to_degrees() - 5.739).abs() < 1e-3);
//! // Entering a denser medium there is no critical angle.
//! assert!(snell::critical_angle(1.5_f64).is_none());
//! ```

#[allow(unused_imports)]
use num_traits::{Float, FloatConst, One, Zero};

use crate::compensated;
use crate::Real;

/// The incident side of an interface, resolved from the sign of `cos_i`.
///
/// The indices are kept apart rather than as their ratio: one of `n_i`,
/// `n_t` is exactly 1 and the other is `eta`, so light from the inside never
/// pays for a rounded `1 / eta`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Incidence<T> {
    /// `|cos θ_i|`, clamped into `[0, 1]`: the unsigned cosine of
    /// incidence (the signed one, `cos_i`, said which side this is).
    pub abs_cos_i: T,
    /// The (relative) index of the medium the light comes from: 1 from the
    /// outside, `eta` from the inside.
    pub n_i: T,
    /// The (relative) index of the medium the light goes into: `eta` from the
    /// outside, 1 from the inside.
    pub n_t: T,
    /// Whether the light arrives from the inside (`cos_i < 0`).
    pub from_inside: bool,
    /// `sin θ_i` as measured from the directions, where it says more than
    /// the cosine: near normal incidence (`|cos θ_i| ≥ 1/√2`, θ_i ≤ π/4),
    /// where the cosine is flat and one of its ulps spans many of θ's, so
    /// `1 − cos²θ_i` keeps few of `sin²θ_i`'s digits. Set only by
    /// [`Incidence::resolve_measured`]; `None` where the cosine is all that
    /// was given or is the better of the two. Snell's discriminant is taken
    /// from it when present.
    pub sin_i: Option<T>,
}

/// Snell's law decided at one incidence: `d = n_t² cos²θ_t` in the tier's
/// wide precision, and whether light is transmitted (`d ≥ 0`; under total
/// internal reflection it is not).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Snell<W> {
    pub(crate) discriminant: W,
    pub(crate) transmits: bool,
}

impl<T: Real> Incidence<T> {
    /// Resolves the side from the sign of `cos_i`, for an interface of
    /// relative index `eta = n_inside / n_outside`; `None` for input that
    /// describes no interface: a NaN cosine, or an `eta` that is not positive
    /// and finite. This is the one place the laws of signed cosines check
    /// their input.
    ///
    /// `cos_i` is clamped into `[-1, 1]`, absorbing the rounding of a dot
    /// product of unit vectors.
    ///
    /// ```
    /// use radiometry::snell::Incidence;
    /// let inside = Incidence::resolve(-0.5_f64, 1.5).unwrap();
    /// assert!(inside.from_inside && (inside.n_i, inside.n_t) == (1.5, 1.0));
    /// assert_eq!(Incidence::resolve(0.5_f64, -1.5), None);
    /// ```
    #[inline]
    pub fn resolve(cos_i: T, eta: T) -> Option<Self> {
        let (incidence, valid) = Self::resolve_unchecked(cos_i, eta);
        valid.then_some(incidence)
    }

    /// [`Incidence::resolve`] without the early return, for a law that
    /// computes its general case whatever the input and chooses after it,
    /// so that a loop over many cosines has no branch: the incidence (of
    /// NaNs or meaningless where the input describes no interface), and
    /// whether the input describes one.
    #[inline(always)]
    pub(crate) fn resolve_unchecked(cos_i: T, eta: T) -> (Self, bool) {
        let valid = !cos_i.is_nan() && eta > T::zero() && eta.is_finite();
        let from_inside = cos_i < T::zero();
        let (n_i, n_t) = if from_inside {
            (eta, T::one())
        } else {
            (T::one(), eta)
        };
        let incidence = Self {
            abs_cos_i: clamp_unit(cos_i.abs()),
            n_i,
            n_t,
            from_inside,
            sin_i: None,
        };
        (incidence, valid)
    }

    /// [`Incidence::resolve`] for a caller that can also measure `sin θ_i`
    /// (from the directions, `|n × (n × ω_i)|`, or from the angle): `sin_i` is
    /// called, and kept, only near normal incidence (`|cos θ_i| ≥ 1/√2`),
    /// where it determines Snell's discriminant `n_t² − (n_i sin θ_i)²` to
    /// more digits than the cosine does. This is the one place that choice
    /// is made.
    ///
    /// ```
    /// use radiometry::snell::Incidence;
    /// // Near normal incidence the sine is kept; at 60° the cosine suffices.
    /// let near = Incidence::resolve_measured(0.999_f64, 1.5, || 0.0447).unwrap();
    /// assert_eq!(near.sin_i, Some(0.0447));
    /// assert_eq!(Incidence::resolve_measured(0.5_f64, 1.5, || 0.866).unwrap().sin_i, None);
    /// ```
    #[inline]
    pub fn resolve_measured(cos_i: T, eta: T, sin_i: impl FnOnce() -> T) -> Option<Self> {
        let mut incidence = Self::resolve(cos_i, eta)?;
        if incidence.abs_cos_i >= T::FRAC_1_SQRT_2() {
            incidence.sin_i = Some(clamp_unit(sin_i()));
        }
        Some(incidence)
    }

    /// The relative index along the path, `n_t / n_i` (rounded once).
    #[inline]
    pub fn eta_path(&self) -> T {
        self.n_t / self.n_i
    }

    /// `n_t² cos²θ_t = n_t² − n_i² sin²θ_i`, computed without cancellation,
    /// in the tier's wide precision ([`Real::Wide`]). Negative exactly when
    /// Snell's law has no real solution (total internal reflection).
    /// `FUSED`: whether the path this is compiled into fuses a
    /// multiply-add, for the exact errors of the products
    /// (`compensated::exact_error`; the same value either way).
    #[inline(always)]
    pub(crate) fn discriminant<const FUSED: bool>(&self) -> T::Wide {
        let exact = T::PRODUCTS_EXACT_IN_WIDE;
        let (n_t, n_i) = (self.n_t.widen(), self.n_i.widen());
        match self.sin_i {
            Some(sin_i) => {
                compensated::snell_discriminant_from_sine(n_t, n_i, sin_i.widen(), exact)
            }
            None => compensated::snell_discriminant::<_, FUSED>(
                &self.index_squares(),
                self.from_inside,
                self.abs_cos_i.widen(),
                exact,
            ),
        }
    }

    /// The squares of the interface's index, `η²` and `η² ± 1`, in the
    /// tier's wide precision: what the laws take at every angle. They
    /// depend only on the material, so a loop over many cosines of one
    /// material computes them once.
    #[inline(always)]
    pub(crate) fn index_squares(&self) -> compensated::IndexSquares<T::Wide> {
        // One of the two indices is 1 and the other is η.
        let eta = if self.from_inside { self.n_i } else { self.n_t };
        compensated::IndexSquares::of(eta.widen(), T::PRODUCTS_EXACT_IN_WIDE)
    }

    /// `cos θ_t ≥ 0` on the far side, or `None` under total internal
    /// reflection (`sin θ_t` would exceed 1).
    ///
    /// Snell's law is decided for a resolved incidence in `Incidence::snell`:
    /// this, the exact Fresnel law, Schlick's working and
    /// [`crate::specular::refract`] all take `cos θ_t` (or its absence)
    /// from it.
    #[inline(always)]
    pub fn cos_transmitted(&self) -> Option<T> {
        if self.n_i == self.n_t {
            // Index-matched: the light goes straight on, θ_t = θ_i exactly
            // (√ of the rounded cos² would lose bits once cos² underflows).
            return Some(self.abs_cos_i);
        }
        let snell = self.snell::<false>();
        snell
            .transmits
            .then(|| self.cos_from_root(snell.discriminant.sqrt()))
    }

    /// Snell's decision with the discriminant it is made from, for the
    /// exact Fresnel law, which needs the discriminant itself. Index-matched
    /// interfaces are [`Incidence::cos_transmitted`]'s to special-case.
    /// `FUSED` as for [`Incidence::discriminant`].
    #[inline(always)]
    pub(crate) fn snell<const FUSED: bool>(&self) -> Snell<T::Wide> {
        let discriminant = self.discriminant::<FUSED>();
        Snell {
            discriminant,
            // `!(d < 0)` would let NaN through; `d >= 0` does not.
            transmits: discriminant >= T::Wide::zero(),
        }
    }

    /// `cos θ_t` from `s = √d = n_t cos θ_t` in the wide precision, clamped
    /// against rounding and rounded once to the tier.
    #[inline(always)]
    pub(crate) fn cos_from_root(&self, s: T::Wide) -> T {
        T::narrow(clamp_unit(s / self.n_t.widen()))
    }

    /// Snell's sine, `sin θ_t = n_i sin θ_i / n_t`, with
    /// `sin θ_i = √((1 − |cos θ_i|)(1 + |cos θ_i|))`: greater than 1 under
    /// total internal reflection, where it says by how far no refracted ray
    /// exists. For narration; whether light is transmitted is decided by
    /// [`Incidence::cos_transmitted`], whose discriminant keeps the digits
    /// this form loses near the critical angle.
    ///
    /// ```
    /// use radiometry::snell::Incidence;
    /// // From inside glass at 60°: sin θ_t = 1.5 · √3/2 ≈ 1.299 > 1.
    /// let inside = Incidence::resolve(-0.5_f64, 1.5).unwrap();
    /// assert!((inside.sin_transmitted() - 1.5 * 0.75_f64.sqrt()).abs() < 1e-15);
    /// ```
    #[inline]
    pub fn sin_transmitted(&self) -> T {
        let c = self.abs_cos_i;
        let sin_i = self
            .sin_i
            .unwrap_or_else(|| ((T::one() - c) * (T::one() + c)).sqrt());
        self.n_i * sin_i / self.n_t
    }

    /// An incidence of NaNs, for laws that return numbers on input that
    /// describes no interface.
    #[inline]
    pub(crate) fn undefined() -> Self {
        Self {
            abs_cos_i: T::nan(),
            n_i: T::nan(),
            n_t: T::nan(),
            from_inside: false,
            sin_i: None,
        }
    }
}

/// `cos θ_t ≥ 0` for light with signed cosine `cos_i` at an interface of
/// relative index `eta = n_inside / n_outside`, or `None` when no refracted
/// ray exists: under total internal reflection, and for input that describes
/// no interface (a NaN cosine, `eta` not positive and finite).
///
/// Accurate to a few ulps also within 1e-12 rad of the critical angle, where
/// `1 − sin²θ_t` cancels: the discriminant is summed in twice the precision.
///
/// ```
/// use radiometry::snell::cos_transmitted;
/// // Normal incidence goes straight through.
/// assert_eq!(cos_transmitted(1.0_f64, 1.5), Some(1.0));
/// // From inside glass, beyond the critical angle (41.8°), nothing transmits.
/// let cos_60deg = 0.5_f64;
/// assert_eq!(cos_transmitted(-cos_60deg, 1.5), None);
/// ```
#[inline]
pub fn cos_transmitted<T: Real>(cos_i: T, eta: T) -> Option<T> {
    Incidence::resolve(cos_i, eta)?.cos_transmitted()
}

/// The angle of refraction `θ_t` for light meeting the interface at
/// `theta_i` in `[0, π/2]`, with `eta_path = n_t / n_i`: Snell's law
/// `sin θ_i = eta_path · sin θ_t`. `None` under total internal reflection,
/// and for input that describes no refraction (`theta_i` outside
/// `[0, π/2]` or NaN, `eta_path` not positive and finite).
///
/// Snell's discriminant `η² cos²θ_t = η² − sin²θ_i = η² − 1 + cos²θ_i` is
/// summed as if in twice the precision, from whichever of `sin θ_i` and
/// `cos θ_i` the angle determines better (the sine below π/4, the cosine
/// above, where the sine is flat and one of its ulps spans many of θ's), so
/// total internal reflection is decided by the sign of an accurate value, as
/// [`Incidence::cos_transmitted`] decides it from a given cosine. The angle is
/// `atan2(η sin θ_t, η cos θ_t)`, accurate also where `asin` of a sine near 1
/// is not.
///
/// ```
/// use radiometry::snell::transmitted_angle;
/// let theta_t = transmitted_angle(30f64.to_radians(), 1.5).unwrap();
/// assert!((theta_t.sin() * 1.5 - 0.5).abs() < 1e-15);
/// // Leaving glass at 60°, beyond its critical angle: no refraction.
/// assert_eq!(transmitted_angle(60f64.to_radians(), 1.0 / 1.5), None);
/// ```
#[inline]
pub fn transmitted_angle<T: Real>(theta_i: T, eta_path: T) -> Option<T> {
    if !(theta_i >= T::zero() && theta_i <= T::FRAC_PI_2()) {
        return None;
    }
    let (sin_i, cos_i) = theta_i.sin_cos();
    // From the outside of an interface of index eta_path (n_i = 1, n_t =
    // eta_path); resolving it also checks eta_path.
    let incidence = Incidence::resolve_measured(cos_i, eta_path, || sin_i)?;
    let snell = incidence.snell::<false>();
    snell
        .transmits
        .then(|| sin_i.atan2(T::narrow(snell.discriminant.sqrt())))
}

/// The critical angle `θ_c = asin(eta_path)` beyond which light from the
/// denser side is totally reflected, with `eta_path = n_t / n_i`; `None` when
/// `eta_path ≥ 1` (no critical angle going into a denser medium) or it is not
/// positive.
#[inline]
pub fn critical_angle<T: Real>(eta_path: T) -> Option<T> {
    if !(eta_path > T::zero() && eta_path < T::one()) {
        return None;
    }
    // atan2(eta, cos θ_c) keeps full precision as eta → 1, where asin is
    // ill-conditioned; (1 − eta)(1 + eta) avoids the cancellation in 1 − eta².
    let cos_c = ((T::one() - eta_path) * (T::one() + eta_path)).sqrt();
    Some(eta_path.atan2(cos_c))
}

/// Brewster's angle `θ_B = atan(eta_path)`, with `eta_path = n_t / n_i`, at
/// which the p-polarised reflectance vanishes; `None` for an `eta_path` that
/// is not positive and finite.
///
/// ```
/// let theta_b = radiometry::snell::brewster_angle(1.5_f64).unwrap();
/// assert!((theta_b.to_degrees() - 56.31).abs() < 1e-2);
/// ```
#[inline]
pub fn brewster_angle<T: Real>(eta_path: T) -> Option<T> {
    (eta_path > T::zero() && eta_path.is_finite()).then(|| eta_path.atan())
}

/// Clamps into `[-1, 1]`, keeping NaN (unlike `Float::max`/`min`, which drop it).
#[inline]
pub(crate) fn clamp_unit<T: Real>(x: T) -> T {
    if x > T::one() {
        T::one()
    } else if x < -T::one() {
        -T::one()
    } else {
        x
    }
}
