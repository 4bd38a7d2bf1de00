//! The course's formulas exactly as its texts write them, errors included.
//!
//! These exist to be audited, not used: the tests in
//! `tests/source_formulas.rs` compare each against the law it means to
//! state and name every place where it is wrong. The physically based code
//! never calls them; the tracer's course-compatibility mode does, to
//! reproduce what the course's shader computes.
//!
//! Each function keeps its source's own conventions, which differ from the
//! crate's: the incident vector `v` (or `i`) is the ray's direction of
//! travel, pointing *towards* the surface, and the unit normal `n` points
//! back towards the side the ray comes from. Source files are named by their
//! prefix in `shared/seeds/`: `000` (GLSL tutorial), `001` (slides,
//! "realistic scenes"), `003` (textbook chapter).

#[allow(unused_imports)]
use num_traits::{Float, FloatConst, One, Zero};

use crate::{Real, Vector3};

/// `000`, `vec3 Fresnel(vec3 F0, float cosTheta)`:
/// `F0 + (1 − F0) · cosθ⁵`.
///
/// **Wrong**: Schlick's term is `(1 − cos θ)⁵`. As written, a mirror
/// reflects everything at normal incidence (`F = 1`) and only `F0` at
/// grazing incidence: the Fresnel effect backwards. See
/// [`crate::fresnel::schlick`].
#[inline]
pub fn fresnel_000_glsl<T: Real>(f0: T, cos_theta: T) -> T {
    f0 + (T::one() - f0) * cos_theta.powi(5)
}

/// `003`, the `refract` implementation:
/// `V / ns + N (cosa / ns − √disc)`, `disc = 1 − (1 − cosa²) / ns²`,
/// `cosa = −V·N`, returning the zero vector when `disc < 0`.
///
/// Correct as a formula (it is Snell's law with `ns = n_t / n_i`), but it
/// encodes total internal reflection as a zero-length "direction".
#[inline]
pub fn refract_003_code<V: Vector3>(v: V, n: V, ns: V::Scalar) -> V {
    let one = V::Scalar::one();
    let cosa = -v.dot(n);
    let disc = one - (one - cosa * cosa) / ns / ns;
    if disc < V::Scalar::zero() {
        return V::new(V::Scalar::zero(), V::Scalar::zero(), V::Scalar::zero());
    }
    v * (one / ns) + n * (cosa / ns - disc.sqrt())
}

/// `003`, the boxed result of the refraction derivation:
/// `v / n + N (cos(α / n) − √(1 − (1 − cos²α) / n²))`.
///
/// **Wrong**: the first term in the bracket must be `cos(α) / n`, as the
/// chapter's own code has it; `cos(α / n)` takes the cosine of a shrunken
/// angle. The result is neither unit length nor on Snell's cone.
#[inline]
pub fn refract_003_boxed<V: Vector3>(v: V, n: V, eta: V::Scalar) -> V {
    let one = V::Scalar::one();
    let cos_alpha = -v.dot(n);
    let alpha = cos_alpha.acos();
    v * (one / eta)
        + n * ((alpha / eta).cos() - (one - (one - cos_alpha * cos_alpha) / (eta * eta)).sqrt())
}

/// `003`, the tangent used in the refraction derivation:
/// `N⊥ = (v + N) / sin α`, "since `|v + N| = sin α`".
///
/// **Wrong**: the component of `v` perpendicular to `N` is `v + N cos α`,
/// whose length is `sin α`; `|v + N| = √(2 − 2 cos α)`. As written `N⊥` is
/// neither perpendicular to `N` nor of unit length (except at α = 90°).
#[inline]
pub fn tangent_003<V: Vector3>(v: V, n: V) -> V {
    let cos_alpha = -v.dot(n);
    let sin_alpha = (V::Scalar::one() - cos_alpha * cos_alpha).sqrt();
    (v + n) * (V::Scalar::one() / sin_alpha)
}

/// `001`, the slide formula `t = r i + (w − k) n` with `r = n₁/n₂`,
/// `w = −(i·n) r`, `k = √(1 + (w − r)(w + r))`.
///
/// Correct (Akenine-Möller and Haines' form of Snell's law:
/// `(w − r)(w + r) = −r² sin²θ_i`, so `k = cos θ_t`). Under total internal
/// reflection the root is of a negative number and the result is NaN: the
/// slide does not say what to do there.
#[inline]
pub fn refract_001_slide<V: Vector3>(i: V, n: V, r: V::Scalar) -> V {
    let w = -i.dot(n) * r;
    let k = (V::Scalar::one() + (w - r) * (w + r)).sqrt();
    i * r + n * (w - k)
}

/// `001`, the Cg `refract(I, N, etaRatio)`:
/// `T = etaRatio I + (etaRatio cosI − √|cosT2|) N`, multiplied by
/// `cosT2 > 0`.
///
/// Correct where it refracts; under total internal reflection it returns the
/// zero vector, and the `abs` inside the root hides the negative
/// discriminant instead of reporting it.
#[inline]
pub fn refract_001_cg<V: Vector3>(i: V, n: V, eta_ratio: V::Scalar) -> V {
    let one = V::Scalar::one();
    let cos_i = -i.dot(n);
    let cos_t2 = one - eta_ratio * eta_ratio * (one - cos_i * cos_i);
    let t = i * eta_ratio + n * (eta_ratio * cos_i - cos_t2.abs().sqrt());
    t * if cos_t2 > V::Scalar::zero() {
        one
    } else {
        V::Scalar::zero()
    }
}

/// `001`, the empirical Fresnel approximation: `bias + scale · x^power`,
/// with `x` written two ways in the source (see the methods).
///
/// An empirical curve, not a law: with `bias = F0`, `scale = 1 − F0`,
/// `power = 5` and the vertex program's `x` it is Schlick's approximation.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct EmpiricalFresnel<T> {
    /// The reflectance at normal incidence the curve starts from.
    pub bias: T,
    /// How much the curve rises towards grazing incidence.
    pub scale: T,
    /// How sharply it rises.
    pub power: T,
}

impl<T: Real> EmpiricalFresnel<T> {
    /// The slide: `max(0, min(1, bias + scale (0 + I·N)^power))`.
    ///
    /// **Wrong**: with `I` pointing towards the surface `I·N = −cos θ ≤ 0`,
    /// and a negative base to a fractional power is NaN, which the clamps
    /// turn into whatever min/max make of NaN (`f64::min` here: 1); an odd
    /// power gives `bias − scale cos^power θ`, never above the bias; an even
    /// one is largest at normal incidence instead of at grazing. The vertex
    /// program on the next slide has `1 + dot(I, N)`, which is what is
    /// meant: see [`EmpiricalFresnel::vertex_program`].
    #[inline]
    pub fn slide<V: Vector3<Scalar = T>>(&self, i: V, n: V) -> T {
        let f = self.bias + self.scale * (T::zero() + i.dot(n)).powf(self.power);
        f.min(T::one()).max(T::zero())
    }

    /// The vertex program `C7E5v_dispersion`:
    /// `bias + scale · (1 + dot(I, N))^power`, unclamped.
    ///
    /// Unlike the slide it does not clamp into `[0, 1]`, so `bias + scale > 1`
    /// gives a reflectance above 1 at grazing incidence.
    #[inline]
    pub fn vertex_program<V: Vector3<Scalar = T>>(&self, i: V, n: V) -> T {
        self.bias + self.scale * (T::one() + i.dot(n)).powf(self.power)
    }
}
