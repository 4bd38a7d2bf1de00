//! Welch's two-sample t-test, for comparing Monte Carlo estimates: the
//! Student t distribution's tail through the regularised incomplete beta
//! function.
//!
//! The suite's renders are compared with Mitsuba's per pixel; each pixel is
//! one test, so the comparison corrects for their number (see
//! [`crate::renders`]).

/// One side of a comparison: the mean of `count` independent samples and
/// their unbiased sample variance.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sample {
    /// Mean of the samples.
    pub mean: f64,
    /// Unbiased variance of one sample (divided by `count − 1`).
    pub variance: f64,
    /// Number of samples, at least 2.
    pub count: f64,
}

/// The outcome of Welch's test.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Welch {
    /// `(mean_a − mean_b) / sqrt(var_a/n_a + var_b/n_b)`.
    pub t: f64,
    /// Welch–Satterthwaite degrees of freedom.
    pub dof: f64,
    /// Two-sided p-value: the probability of a `|t|` at least this large if
    /// the means are equal.
    pub p: f64,
}

/// Welch's t-test of equal means (Welch, *Biometrika* 34, 1947), or `None`
/// when both variances are zero (no randomness: compare the means directly).
pub fn welch(a: Sample, b: Sample) -> Option<Welch> {
    let (sa, sb) = (a.variance / a.count, b.variance / b.count);
    let se2 = sa + sb;
    if !(se2 > 0.0) {
        return None;
    }
    let t = (a.mean - b.mean) / se2.sqrt();
    let dof = se2 * se2 / (sa * sa / (a.count - 1.0) + sb * sb / (b.count - 1.0));
    Some(Welch {
        t,
        dof,
        p: student_t_two_sided(t, dof),
    })
}

/// `P(|T| ≥ |t|)` for Student's t with `dof` degrees of freedom:
/// `I_{dof/(dof + t²)}(dof/2, 1/2)` (Abramowitz and Stegun 26.7.1 with 26.5.27).
pub fn student_t_two_sided(t: f64, dof: f64) -> f64 {
    if t.is_nan() || !(dof > 0.0) {
        return f64::NAN;
    }
    if t.is_infinite() {
        return 0.0;
    }
    regularized_incomplete_beta(dof / (dof + t * t), dof / 2.0, 0.5)
}

/// The `|t|` whose two-sided p-value is `p` under Student's t with `dof`
/// degrees of freedom: the inverse of [`student_t_two_sided`], by bisection
/// (the p-value falls monotonically in `|t|`) to a relative 1e-12. `None`
/// unless `0 < p < 1` and `dof > 0`.
pub fn student_t_critical(p: f64, dof: f64) -> Option<f64> {
    if !(p > 0.0 && p < 1.0 && dof > 0.0) {
        return None;
    }
    let mut high = 1.0;
    while student_t_two_sided(high, dof) > p {
        high *= 2.0;
        if high > 1e300 {
            return None;
        }
    }
    let mut low = 0.0;
    while high - low > 1e-12 * high {
        let mid = 0.5 * (low + high);
        if student_t_two_sided(mid, dof) > p {
            low = mid;
        } else {
            high = mid;
        }
    }
    Some(high)
}

/// `I_x(a, b)`, by the continued fraction of Abramowitz and Stegun 26.5.8,
/// evaluated with the modified Lentz method (Press et al., *Numerical
/// Recipes*, 3rd ed., §6.4), on the side of `x` where it converges fast.
pub fn regularized_incomplete_beta(x: f64, a: f64, b: f64) -> f64 {
    if x <= 0.0 {
        return 0.0;
    }
    if x >= 1.0 {
        return 1.0;
    }
    let ln_front = ln_gamma(a + b) - ln_gamma(a) - ln_gamma(b) + a * x.ln() + b * (1.0 - x).ln();
    if x < (a + 1.0) / (a + b + 2.0) {
        ln_front.exp() * beta_fraction(x, a, b) / a
    } else {
        1.0 - ln_front.exp() * beta_fraction(1.0 - x, b, a) / b
    }
}

fn beta_fraction(x: f64, a: f64, b: f64) -> f64 {
    const TINY: f64 = 1e-300;
    let mut c = 1.0;
    let mut d = 1.0 - (a + b) * x / (a + 1.0);
    if d.abs() < TINY {
        d = TINY;
    }
    d = 1.0 / d;
    let mut h = d;
    for m in 1..=10_000 {
        let m = m as f64;
        let m2 = 2.0 * m;
        for numerator in [
            m * (b - m) * x / ((a + m2 - 1.0) * (a + m2)),
            -(a + m) * (a + b + m) * x / ((a + m2) * (a + m2 + 1.0)),
        ] {
            d = 1.0 + numerator * d;
            if d.abs() < TINY {
                d = TINY;
            }
            c = 1.0 + numerator / c;
            if c.abs() < TINY {
                c = TINY;
            }
            d = 1.0 / d;
            h *= d * c;
        }
        if (d * c - 1.0).abs() < 1e-15 {
            break;
        }
    }
    h
}

/// `ln Γ(x)` for `x > 0`, Lanczos' approximation with g = 7, n = 9
/// (relative error below 1e-15 for positive arguments).
pub fn ln_gamma(x: f64) -> f64 {
    const G: f64 = 7.0;
    const C: [f64; 9] = [
        0.999_999_999_999_809_9,
        676.520_368_121_885_1,
        -1_259.139_216_722_402_8,
        771.323_428_777_653_1,
        -176.615_029_162_140_6,
        12.507_343_278_686_905,
        -0.138_571_095_265_720_12,
        9.984_369_578_019_572e-6,
        1.505_632_735_149_311_6e-7,
    ];
    if x < 0.5 {
        // Reflection: Γ(x) Γ(1 − x) = π / sin(πx).
        return (std::f64::consts::PI / (std::f64::consts::PI * x).sin()).ln() - ln_gamma(1.0 - x);
    }
    let x = x - 1.0;
    let mut sum = C[0];
    for (i, c) in C.iter().enumerate().skip(1) {
        sum += c / (x + i as f64);
    }
    let t = x + G + 0.5;
    0.5 * (2.0 * std::f64::consts::PI).ln() + (x + 0.5) * t.ln() - t + sum.ln()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ln_gamma_matches_factorials() {
        // Γ(n) = (n − 1)!; Γ(1/2) = √π. Tolerance: Lanczos' 1e-15 relative, a few roundings.
        for (x, exact) in [
            (1.0, 1.0_f64),
            (5.0, 24.0),
            (11.0, 3_628_800.0),
            (0.5, std::f64::consts::PI.sqrt()),
        ] {
            assert!((ln_gamma(x) - exact.ln()).abs() < 1e-13, "ln Γ({x})");
        }
    }

    /// The same printed critical values, from the p-value back (printed to
    /// 3 or 4 digits: within 5e-4 relative); and the round trip to 1e-9.
    #[test]
    fn student_t_critical_values_match_printed_tables() {
        for (t, dof, p) in [
            (12.706, 1.0, 0.05),
            (2.228, 10.0, 0.05),
            (3.169, 10.0, 0.01),
            (2.042, 30.0, 0.05),
            (1.96, 1e9, 0.05),
        ] {
            let got = student_t_critical(p, dof).unwrap();
            assert!(
                (got - t).abs() <= 5e-4 * t,
                "t({p}, {dof}) = {got}, printed {t}"
            );
        }
        for (p, dof) in [(1e-8, 63.0), (4e-8, 120.5), (0.3, 2.0)] {
            let t = student_t_critical(p, dof).unwrap();
            let back = student_t_two_sided(t, dof);
            assert!((back - p).abs() <= 1e-9 * p, "p {p} dof {dof}: {back}");
        }
        assert_eq!(student_t_critical(0.0, 5.0), None);
        assert_eq!(student_t_critical(0.5, 0.0), None);
    }

    #[test]
    fn student_t_tails_match_printed_tables() {
        // Critical values of Student's t (two-sided), e.g. Abramowitz and
        // Stegun table 26.10 and any statistics text; printed to 3 or 4
        // digits, so the p-value is compared within what that rounding moves it.
        for (t, dof, p, tol) in [
            (12.706, 1.0, 0.05, 1e-4),
            (2.228, 10.0, 0.05, 1e-4),
            (3.169, 10.0, 0.01, 1e-4),
            (2.042, 30.0, 0.05, 1e-4),
            (1.96, 1e9, 0.05, 1e-4),
            (0.0, 7.0, 1.0, 1e-15),
        ] {
            let got = student_t_two_sided(t, dof);
            assert!((got - p).abs() < tol, "t = {t}, dof = {dof}: {got}");
        }
    }

    #[test]
    fn student_t_far_tail_matches_the_normal_limit() {
        // With 10⁹ degrees of freedom t is normal: P(|Z| ≥ 5) = 5.733e-7
        // (erfc(5/√2)); 1e-3 relative covers the O(1/dof) difference and the
        // printed digits.
        let p = student_t_two_sided(5.0, 1e9);
        assert!((p / 5.733_031e-7 - 1.0).abs() < 1e-3, "{p}");
    }

    #[test]
    fn welch_needs_some_variance() {
        let fixed = Sample {
            mean: 1.0,
            variance: 0.0,
            count: 10.0,
        };
        assert_eq!(welch(fixed, fixed), None);
        let noisy = Sample {
            variance: 1.0,
            ..fixed
        };
        let w = welch(noisy, fixed).unwrap();
        assert_eq!(w.t, 0.0);
        assert!((w.dof - 9.0).abs() < 1e-12, "one noisy side: its own n − 1");
    }
}
