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
//! "realistic scenes"), `002` (WebGL tracer), `003` (textbook chapter).
//!
//! Where a shader's control flow, not a formula, is what the text gets
//! wrong, the step is written out in [`shader_steps`].

#[allow(unused_imports)]
use num_traits::{Float, FloatConst, One, Zero};

use crate::{Real, Vector3};

mod materials;
pub mod shader_steps;
pub use materials::{f0_000_glsl, glsl_pow, GOLD_000_KAPPA, GOLD_000_N};
pub use shader_steps::{
    intersect_mirrors_000, reflection_loop_002, rough_hit_000, shade_002, Hit002, MirrorHit000,
};

/// `000` lines 1249, 1410, 1868, `vec3 Fresnel(vec3 F0, float cosTheta)`:
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

/// `003` line 175, boxed: `R = v + 2 N cos(α)`, with `cos α = −v·N`.
///
/// Correct: the law of reflection, the same vector as
/// [`crate::specular::reflect`]`(−v, N)`. It is even in `N`, so the
/// chapter's warning (line 190) that `N` must point to the side `v` comes
/// from matters for the Fresnel factor, not for this direction.
#[inline]
pub fn reflect_003_boxed<V: Vector3>(v: V, n: V) -> V {
    let cos_alpha = -v.dot(n);
    v + n * (cos_alpha + cos_alpha)
}

/// `003` lines 183–185, the code: `vec3 reflect(vec3 V, vec3 N) { return V
/// - N * dot(N, V) * 2; }`.
///
/// Correct: the boxed formula [`reflect_003_boxed`] with `cos α` expanded.
#[inline]
pub fn reflect_003_code<V: Vector3>(v: V, n: V) -> V {
    let two = V::Scalar::one() + V::Scalar::one();
    v - n * n.dot(v) * two
}

/// `001` line 40 `r = e − 2(n·e)n` (environment mapping, `e` the unit
/// vector from the eye to the surface), line 73 `R = I − 2N(N·I)` and the
/// Cg `reflect(I, N)` of lines 76–79, `I - 2.0 * N * dot(N, I)`: one
/// expression written three times (line 163 repeats it for the mirrored
/// eye).
///
/// Correct: the law of reflection, [`crate::specular::reflect`]`(−I, N)`.
/// The same expression as [`reflect_003_code`], its factors in another
/// order; kept apart because each transcribes its own source.
#[inline]
pub fn reflect_001<V: Vector3>(i: V, n: V) -> V {
    let two = V::Scalar::one() + V::Scalar::one();
    i - n * two * n.dot(i)
}

/// `003` lines 195–203, `vec3 Fresnel(vec3 V, vec3 N)`: per channel,
/// `F0 = ((n − 1)² + κ²) / ((n + 1)² + κ²)` and
/// `F0 + (1 − F0) (1 − cosa)⁵` with `cosa = −V·N`; `ior` and `kappa` are
/// the globals `n` and `kappa` of the listing.
///
/// Correct: Schlick's approximation with the conductor `F0`,
/// [`crate::fresnel::schlick`]`(cosa, `[`crate::fresnel::f0`]`(n, κ))` per
/// channel. The listing writes three minus signs as `–` (U+2013), which no
/// C or GLSL compiler accepts; they are read as minus here. It trusts the
/// caller to orient `N` towards `v` (line 190): with `N` on the other side
/// `cosa < 0` and `(1 − cosa)⁵ > 1`, a "reflectance" above 1, where the
/// crate's `schlick` takes `|cos θ|`.
#[inline]
pub fn fresnel_003_code<V: Vector3>(
    v: V,
    n: V,
    ior: [V::Scalar; 3],
    kappa: [V::Scalar; 3],
) -> [V::Scalar; 3] {
    let one = V::Scalar::one();
    let cosa = -v.dot(n);
    core::array::from_fn(|ch| {
        let (n, k) = (ior[ch], kappa[ch]);
        let f0 = ((n - one) * (n - one) + k * k) / ((n + one) * (n + one) + k * k);
        f0 + (one - f0) * (one - cosa).powi(5)
    })
}

/// `003` line 95, Snell's law for angles:
/// `n = sin θin / sin θ ⟹ θ = arcsin(sin θin / n)`, with `n = n_t / n_i`
/// (line 98: the material's index, light arriving from air). `001` line 373
/// writes the same law as `n₁ sin θ₁ = n₂ sin θ₂`.
///
/// Correct where light refracts: [`crate::snell::transmitted_angle`]. It has
/// no guard for total internal reflection: going from a denser medium
/// (`n < 1`) beyond the critical angle `asin(n)`, `sin θin / n > 1` and the
/// arcsine is NaN. The chapter treats total internal reflection only in its
/// refraction-vector code (lines 249, 268).
#[inline]
pub fn refraction_angle_003<T: Real>(theta_in: T, n: T) -> T {
    (theta_in.sin() / n).asin()
}

/// `003` line 90, the radiance split at a smooth surface: reflected
/// `L_in · F(θin)` and refracted `L_in · (1 − F(θin))`, "since their sum
/// must give `L_in`". Returns `(reflected, refracted)`.
///
/// The reflected radiance is right (a mirror keeps the beam's solid angle
/// and its cosine). The refracted one is **wrong as a radiance**: `1 − F` is
/// the fraction of *power* transmitted, and radiance is power per projected
/// area per solid angle. Refraction compresses the beam's solid angle,
/// `n_i² cos θ_i dω_i = n_t² cos θ_t dω_t`, so the transmitted radiance is
/// `(n_t / n_i)² (1 − F) L_in`: [`crate::radiance::across_interface`]. Energy
/// is conserved in power, not in radiance.
#[inline]
pub fn radiance_split_003<T: Real>(l_in: T, f: T) -> (T, T) {
    (l_in * f, l_in * (T::one() - f))
}

/// `003` lines 263–270, the `refract` implementation:
/// `V / ns + N (cosa / ns − √disc)`, `disc = 1 − (1 − cosa²) / ns²`,
/// `cosa = −V·N`, returning the zero vector when `disc < 0`.
///
/// Correct as a formula (it is Snell's law with `ns = n_t / n_i`), but it
/// encodes total internal reflection as a zero-length "direction". Line 265
/// writes `1 – cosa` with `–` (U+2013), read as minus here.
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

/// `003` line 246, the boxed result of the refraction derivation:
/// `v / n + N (cos(α / n) − √(1 − (1 − cos²α) / n²))`.
///
/// **Wrong**: the first term in the bracket must be `cos(α) / n`, as the
/// chapter's own code has it; `cos(α / n)` takes the cosine of a shrunken
/// angle. The tangential part, `sin α / n`, is right; the component along
/// `N` is `−cos α / n + cos(α / n) − cos β` instead of Snell's `−cos β`, so
/// the result is neither unit length nor on Snell's cone (head-on it is
/// `−N / n`). Nor is it what the derivation gives with the chapter's own
/// `N⊥` ([`tangent_003`] in [`refract_003_derivation`]), which is
/// `v / n + N (1 / n − cos β)`: the box is a second, separate error.
#[inline]
pub fn refract_003_boxed<V: Vector3>(v: V, n: V, eta: V::Scalar) -> V {
    let one = V::Scalar::one();
    let cos_alpha = -v.dot(n);
    let alpha = cos_alpha.acos();
    v * (one / eta)
        + n * ((alpha / eta).cos() - (one - (one - cos_alpha * cos_alpha) / (eta * eta)).sqrt())
}

/// `003` line 170 (reflection section), the component of `v` perpendicular
/// to `N`: "`v + N cos(α)`", with `cos α = −v·N`.
///
/// Correct: it removes the normal component `−N cos α` from `v`, and its
/// length is `sin α`. Divided by `sin α` it is the unit tangent the
/// refraction derivation needs, and which [`tangent_003`] gets wrong.
#[inline]
pub fn perpendicular_003<V: Vector3>(v: V, n: V) -> V {
    let cos_alpha = -v.dot(n);
    v + n * cos_alpha
}

/// `003` lines 217 and 240, the refraction derivation before substitution:
/// `T = N⊥ sin β − N cos β` with `cos β = √(1 − sin²α / n²)` and, from
/// Snell's law (line 95), `sin β = sin α / n`; `sin α = √(1 − cos²α)`,
/// `cos α = −v·N`. The tangent `n_perp` is passed in, so that each step of
/// the derivation can be checked on its own.
///
/// Correct with a true unit tangent, `N⊥ = (v + N cos α) / sin α`
/// ([`perpendicular_003`]): it is then Snell's law. With the chapter's
/// `N⊥ = (v + N) / sin α` ([`tangent_003`]) it is
/// `v / n + N (1 / n − cos β)`: the component along `N` is off by
/// `(1 − cos α) / n`. NaN under total internal reflection (the root of a
/// negative number), and at normal incidence for either tangent (`0 / 0`).
#[inline]
pub fn refract_003_derivation<V: Vector3>(v: V, n: V, eta: V::Scalar, n_perp: V) -> V {
    let one = V::Scalar::one();
    let cos_alpha = -v.dot(n);
    let sin2_alpha = one - cos_alpha * cos_alpha;
    let sin_beta = sin2_alpha.sqrt() / eta;
    let cos_beta = (one - sin2_alpha / (eta * eta)).sqrt();
    n_perp * sin_beta - n * cos_beta
}

/// `003` line 223, the tangent used in the refraction derivation:
/// `N⊥ = (v + N) / sin α`, "since `|v + N| = sin α`".
///
/// **Wrong**: the component of `v` perpendicular to `N` is `v + N cos α`
/// (the chapter's own reflection section, line 170: [`perpendicular_003`]),
/// whose length is `sin α`; `|v + N| = √(2 − 2 cos α) = 2 sin(α/2)`. As
/// written `N⊥` has length `1 / cos(α/2)` and `N⊥ · N = tan(α/2)`: it makes
/// `90° − α/2` with `N`, so it is neither perpendicular to `N` nor of unit
/// length at any α in (0°, 90°]; at grazing incidence it is `√2` long and
/// 45° off. At α = 0 it is `0 / 0`.
#[inline]
pub fn tangent_003<V: Vector3>(v: V, n: V) -> V {
    let cos_alpha = -v.dot(n);
    let sin_alpha = (V::Scalar::one() - cos_alpha * cos_alpha).sqrt();
    (v + n) * (V::Scalar::one() / sin_alpha)
}

/// `003` lines 415–426, `shade(N, V, L, inRad)`, one channel:
/// `inRad · kd · cos θ + inRad · ks · cos^shine δ` with `cos θ = N·L`,
/// `H = normalize(V + L)` and `cos δ = N·H`; zero for `cos θ < 0` ("self
/// shadow"), the diffuse part alone for `cos δ < 0`. Here `V` and `L` point
/// from the surface to the viewer and to the light (the BRDF section, line
/// 293), unlike the `V` of the chapter's reflection code; `kd`, `ks` and
/// `shine` are the listing's globals.
///
/// Right where both directions are above the surface: it is
/// `L_in · f_r · cos θ` with [`crate::brdf::BlinnPhong`], the boxed formula
/// of lines 388–389. **Wrong** below the viewer's horizon: it never looks at
/// `N·V`. A surface seen from behind with the light in front is shaded as if
/// seen from the front, where the BRDF is 0; seen from straight opposite
/// the light (`V = −L`) the half vector is `normalize(0)`, undefined in GLSL
/// and NaN here. Line 357 credits the clamp `cos⁺θ` with hiding a point
/// "seen from inside, from the other side", but `θ` is the light's angle: the
/// clamp hides points the light reaches from behind (the code's comment,
/// "self shadow"), and nothing hides points the viewer sees from behind.
#[inline]
pub fn shade_003_code<V: Vector3>(
    n: V,
    v: V,
    l: V,
    in_rad: V::Scalar,
    kd: V::Scalar,
    ks: V::Scalar,
    shine: V::Scalar,
) -> V::Scalar {
    let zero = V::Scalar::zero();
    let cos_theta = n.dot(l);
    if cos_theta < zero {
        return zero;
    }
    let diffuse_rad = in_rad * kd * cos_theta;
    let sum = v + l;
    let h = sum * (V::Scalar::one() / sum.length());
    let cos_delta = n.dot(h);
    if cos_delta < zero {
        return diffuse_rad;
    }
    diffuse_rad + in_rad * ks * cos_delta.powf(shine)
}

/// `001` lines 380–386, the slide formula `t = r i + (w − k) n` with `r = n₁/n₂`,
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

/// `001` lines 400–409, the Cg `refract(I, N, etaRatio)`:
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

/// `001` lines 390–395, the cheap refraction "for small angles of
/// incidence": `t = −c n + i`, normalised, with `c` "about 1.0 when
/// simulating water".
///
/// An approximation, not a law. In the plane of incidence `t` makes
/// `atan2(sin α, cos α + c)` with `−n`; with `c = 1` that is exactly `α/2`,
/// whatever the index: it refracts like Snell's law for `n₂/n₁ = 2` to
/// first order. Against the exact angle `asin(sin α / η)` its error is
/// `(1/2 − 1/η) α` near normal incidence: water's bending (`α/4` there) is
/// doubled, glass's (`α/3`) overdone by half. The worst error is at
/// `cos²α = (η² − 1)/3`: 10.5° for water (η = 4/3) at 59.4°, 5.7° for glass
/// at 49.8°. The first-order fit is `c = η − 1`, whose error is
/// `(η − 1) α³ / (2η³)` to leading order. Acceptable where only a plausible
/// bend is wanted (a distorted environment look-up), not where the refracted
/// ray is traced on. A zero `−c n + i` (only for `i = c n`) normalises to NaN.
#[inline]
pub fn refract_001_approx<V: Vector3>(i: V, n: V, c: V::Scalar) -> V {
    let t = i - n * c;
    t * (V::Scalar::one() / t.length())
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
    /// The slide (`001` line 467): `max(0, min(1, bias + scale (0 + I·N)^power))`.
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

    /// The vertex program `C7E5v_dispersion` (`001` line 508):
    /// `bias + scale · (1 + dot(I, N))^power`, unclamped.
    ///
    /// Unlike the slide the expression has no clamp, so with
    /// `bias + scale > 1` its arithmetic gives more than 1 at grazing
    /// incidence. The program writes it to `out float reflectionFactor :
    /// COLOR` (`001` line 485), which Cg vertex profiles may clamp into
    /// `[0, 1]`: what the fragment program receives depends on the profile.
    /// This function returns the arithmetic as written, unclamped.
    #[inline]
    pub fn vertex_program<V: Vector3<Scalar = T>>(&self, i: V, n: V) -> T {
        self.bias + self.scale * (T::one() + i.dot(n)).powf(self.power)
    }
}
