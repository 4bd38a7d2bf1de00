//! Herbie's measure of error (Panchekha, Sanchez-Stern, Wilcox & Tatlock,
//! PLDI 2015): the number of floating-point values of the tier between a
//! law's answer and the correctly rounded exact value, and its bits,
//! `log2(that + 1)`: 0 for a correctly rounded answer, 1 for a neighbour,
//! up to 64 (f64) or 32 (f32) for an answer of the wrong sign or not a number.

use super::reference::Tier;

/// The tier's number `x` as an integer monotonic in `x`, `+0` and `−0` both
/// 0, infinities one past the largest finite number; `None` for NaN.
pub fn ordinal(x: f64, tier: Tier) -> Option<i64> {
    if x.is_nan() {
        return None;
    }
    let magnitude = match tier {
        Tier::F64 => (x.abs().to_bits()) as i64,
        Tier::F32 => i64::from((x.abs() as f32).to_bits()),
    };
    Some(if x < 0.0 { -magnitude } else { magnitude })
}

/// How many numbers of the tier lie between `got` and `rounded` (the
/// correctly rounded exact value), counting one end: 0 when they are equal.
/// A NaN answer is as far as the tier reaches (`2^64 − 1` or `2^32 − 1`).
pub fn ulps_between(got: f64, rounded: f64, tier: Tier) -> u64 {
    match (ordinal(got, tier), ordinal(rounded, tier)) {
        (Some(a), Some(b)) => a.abs_diff(b).min(most(tier)),
        _ => most(tier),
    }
}

/// Herbie's bits of error for `ulps` numbers between answer and exact.
pub fn bits(ulps: u64) -> f64 {
    (ulps as f64 + 1.0).log2()
}

fn most(tier: Tier) -> u64 {
    match tier {
        Tier::F64 => u64::MAX,
        Tier::F32 => u64::from(u32::MAX),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn neighbours_are_one_apart_across_binades_and_zero() {
        let below_one = 1.0 - f64::EPSILON / 2.0;
        assert_eq!(ulps_between(below_one, 1.0, Tier::F64), 1);
        let below_one = f64::from(1.0f32 - f32::EPSILON / 2.0);
        assert_eq!(ulps_between(below_one, 1.0, Tier::F32), 1);
        let tiniest = f64::from(f32::from_bits(1));
        assert_eq!(ulps_between(tiniest, -tiniest, Tier::F32), 2);
        assert_eq!(ulps_between(0.0, -0.0, Tier::F64), 0);
        assert_eq!(ulps_between(f64::from_bits(3), 0.0, Tier::F64), 3);
    }

    #[test]
    fn bits_are_zero_when_correctly_rounded_and_full_for_nan() {
        assert_eq!(bits(0), 0.0);
        assert_eq!(bits(1), 1.0);
        assert_eq!(bits(7), 3.0);
        assert_eq!(bits(ulps_between(f64::NAN, 1.0, Tier::F32)), 32.0);
        assert_eq!(bits(ulps_between(1.0, f64::NAN, Tier::F64)), 64.0);
    }
}
