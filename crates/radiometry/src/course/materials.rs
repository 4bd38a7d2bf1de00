//! The course's materials as its texts give them, and the shader's F0 of
//! them.

use crate::Real;

/// `000` lines 1385–1386 (again 1843–1844): the course's gold, `n` per
/// RGB channel. Paired with [`GOLD_000_KAPPA`], a complex index
/// `n + iκ` per channel, the three-wavelength shortcut the course takes.
pub const GOLD_000_N: [f64; 3] = [0.17, 0.35, 1.5];
/// `000` lines 1386 and 1844: the course's gold, `κ` per RGB channel.
pub const GOLD_000_KAPPA: [f64; 3] = [3.1, 2.7, 1.9];

/// GLSL's `pow(x, y)` as GPU compilers commonly lower it, `exp2(y · log2 x)`.
///
/// The specification defines `pow` only for `x > 0`, and for `x = 0` with
/// `y > 0` ("Results are undefined if x < 0", GLSL ES 1.00 §8.2); this
/// lowering gives NaN for every `x < 0`, whatever `y`, and `0` for `x = 0`,
/// `y > 0`. A compiler may instead fold a constant `pow(x, 2.0)` into
/// `x * x`, which is defined everywhere: what a shader that feeds `pow` a
/// negative base shows depends on the GPU.
#[inline]
pub fn glsl_pow<T: Real>(x: T, y: T) -> T {
    (y * x.log2()).exp2()
}

/// `000` lines 1241–1247 (again at 1402–1408 and 1860–1866),
/// `getMaterialF0`: per channel
/// `(pow(n − 1, 2) + pow(k, 2)) / (pow(n + 1, 2) + pow(k, 2))`, with `pow`
/// lowered as [`glsl_pow`].
///
/// The formula is [`crate::fresnel::f0`]; the code is **wrong** for the
/// course's own gold, `n = (0.17, 0.35, 1.5)` (lines 1385, 1843): `n − 1 < 0`
/// in red and green, where GLSL leaves `pow` undefined. Lowered as here,
/// F0 is NaN in those channels, and so is every mirror weight it enters;
/// where the compiler folds `pow(x, 2.0)` into `x * x` it is right.
/// `(n − 1.0) * (n − 1.0)` would be defined on every GPU.
#[inline]
pub fn f0_000_glsl<T: Real>(n: T, k: T) -> T {
    let two = T::one() + T::one();
    (glsl_pow(n - T::one(), two) + glsl_pow(k, two))
        / (glsl_pow(n + T::one(), two) + glsl_pow(k, two))
}
