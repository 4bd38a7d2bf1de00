//! Shared helpers for the workspace-level tests: loading the committed
//! reference data in `validation/reference/` and measuring errors in ulps.

use std::path::PathBuf;

/// The path of a file under `validation/reference/`.
pub fn reference_path(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../validation/reference")
        .join(name)
}

/// Reads and parses a committed reference file, naming it on failure.
pub fn load_reference<T: serde::de::DeserializeOwned>(name: &str) -> T {
    let path = reference_path(name);
    let text = std::fs::read_to_string(&path)
        .unwrap_or_else(|e| panic!("reading {}: {e}", path.display()));
    serde_json::from_str(&text).unwrap_or_else(|e| panic!("parsing {}: {e}", path.display()))
}

/// A reference value carried as an unevaluated sum `hi + lo` of two doubles
/// (about 32 significant digits), as the reference generators write it.
#[derive(Clone, Copy, Debug, serde::Deserialize)]
pub struct Exact(pub f64, pub f64);

/// The floating-point formats whose accuracy is measured.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Precision {
    /// IEEE binary32: 24-bit significand.
    F32,
    /// IEEE binary64: 53-bit significand.
    F64,
}

impl Precision {
    /// The spacing of floats of this precision at `x` (the unit in the last
    /// place), down to the smallest subnormal.
    pub fn ulp(self, x: f64) -> f64 {
        let x = x.abs();
        match self {
            Precision::F64 => x.next_up() - x,
            Precision::F32 => {
                // The binary exponent of x, from its bits (x > 0 normal) or 0.
                let exponent = ((x.to_bits() >> 52) & 0x7ff) as i32 - 1023;
                2f64.powi((exponent - 23).max(-149))
            }
        }
    }
}

impl Exact {
    /// The error of `computed` in ulps of the exact value at `precision`.
    /// `computed − hi` is exact (Sterbenz) when the two are close, so the
    /// error is resolved far below one ulp.
    pub fn ulps(self, computed: f64, precision: Precision) -> f64 {
        ((computed - self.0) - self.1).abs() / precision.ulp(self.0)
    }

    /// The relative error of `computed`; the absolute error where the exact
    /// value is 0.
    pub fn relative(self, computed: f64) -> f64 {
        let err = ((computed - self.0) - self.1).abs();
        if self.0 == 0.0 {
            err
        } else {
            err / self.0.abs()
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ulp_is_the_float_spacing() {
        assert_eq!(Precision::F64.ulp(1.0), f64::EPSILON);
        assert_eq!(Precision::F64.ulp(0.75), f64::EPSILON / 2.0);
        assert_eq!(Precision::F32.ulp(1.0), f32::EPSILON as f64);
        assert_eq!(Precision::F32.ulp(1.0 - 1e-9), f32::EPSILON as f64 / 2.0);
        assert_eq!(Precision::F64.ulp(1e-310), 2f64.powi(-1074));
        assert_eq!(Precision::F64.ulp(0.04), 2f64.powi(-57)); // 0.04 lies in [2⁻⁵, 2⁻⁴)
    }

    #[test]
    fn ulps_resolve_below_one_ulp() {
        let third = Exact(1.0 / 3.0, 0.0); // taken as exact
        assert_eq!(third.ulps(1.0 / 3.0, Precision::F64), 0.0);
        let next = f64::from_bits((1.0f64 / 3.0).to_bits() + 1);
        assert_eq!(third.ulps(next, Precision::F64), 1.0);
    }
}
