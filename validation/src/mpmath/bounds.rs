//! The bounds of the module docs, in ulps of the tier.

/// The bound, in ulps of the tier.
pub const BOUND_ULPS: f64 = 8.0;

/// The dielectric law's `f64` bound, in ulps. Nothing cancels where it is
/// reached: `R_p = (contrast · brewster / (n_t² c + n_i s)²)²` is the square
/// of a ratio of a product of two compensated sums and a sum of three
/// rounded products (`s = √d` among them), about six roundings of order one,
/// doubled by the square. At `cos θi = 0.7652819693198041`,
/// `η = 1.7020537855601314` (the grid's "worst R_p found") `R_p` is 10.9
/// ulps from exact: Snell's discriminant `d`, summed compensated but rounded
/// once to `f64` (here half an ulp off), and `n_t² c` move the denominator
/// by 8 of them, the product `contrast · brewster` the numerator by the
/// rest. It was found among 2·10⁴ random doubles near the random cases'
/// 9.1 ulps, 1 in 4000 of which are past 8; 12 is a tenth above it. The
/// `f32` tier, evaluated in `f64` and rounded once, stays within
/// [`BOUND_ULPS`].
pub const DIELECTRIC_F64_BOUND_ULPS: f64 = 12.0;

/// The dielectric law's bound in `tier` (`"f64"` or `"f32"`).
pub fn dielectric_bound_ulps(tier: &str) -> f64 {
    if tier == "f64" {
        DIELECTRIC_F64_BOUND_ULPS
    } else {
        BOUND_ULPS
    }
}

/// The conductor law's bound, in ulps of the tier. Its `R_p` is the square
/// of a ratio of two `hypot`s, a product and a sum of three rounded terms,
/// each after compensated discriminants, about ten roundings of order one;
/// the square doubles the ratio's relative error. In `f64`, where no
/// product is exact, `R_p` is 11.9 ulps from exact at
/// `cos θi = 0.7915797852215061`, `n = 0.7020224126588795`,
/// `κ = 6.646724002409787` and `R_s` 10.8 ulps at
/// `cos θi = 0.6754425507263279`, `n = 0.18348744872677603`,
/// `κ = 4.060512106629868` (the grid's "worst … found" cases, the worst of
/// 1.9·10⁵ random doubles); the random cases of [`crate::mpmath::random`] reach 10.5. 14
/// is a sixth above the worst found, and a regression costing one digit
/// still fails it.
pub const CONDUCTOR_BOUND_ULPS: f64 = 14.0;
