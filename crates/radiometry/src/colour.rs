//! Colour from CIE 1931 tristimulus values: linear and encoded sRGB, CIELAB,
//! and the CIEDE2000 colour difference. XYZ is unitless with `Y = 1` for the
//! white; sRGB components are in `[0, 1]` inside the gamut; `L*` is in
//! `[0, 100]`; a ΔE00 of about 1 is a just-noticeable difference.
//!
//! | function | model | source |
//! |---|---|---|
//! | [`xyz_to_linear_srgb`], [`linear_srgb_to_xyz`] | sRGB primaries, D65 white | IEC 61966-2-1:1999, §5.2 (the standard's four-decimal matrix) |
//! | [`srgb_encode`], [`srgb_decode`] | the sRGB transfer function | IEC 61966-2-1:1999, §5.2 |
//! | [`xyz_to_lab`] | CIE 1976 L\*a\*b\* | CIE 15:2004, §8.2.1 |
//! | [`delta_e_2000`] | CIEDE2000 | CIE 142-2001; G. Sharma, W. Wu, E. N. Dalal, *Color Res. Appl.* 30(1), 2005 |
//!
//! ```
//! use radiometry::colour::{delta_e_2000, d65_white, xyz_to_lab, Lab};
//! // The white is L* = 100 with no colour.
//! let white = xyz_to_lab(d65_white(), d65_white());
//! assert!((white.l - 100.0).abs() < 1e-12 && white.a.abs() < 1e-12 && white.b.abs() < 1e-12);
//! // Sharma et al. (2005), table 1, pair 1.
//! let de = delta_e_2000(Lab::new(50.0, 2.6772, -79.7751), Lab::new(50.0, 0.0, -82.7485));
//! assert!((de - 2.0425).abs() < 5e-5);
//! ```

/// CIE 1931 tristimulus values.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Xyz {
    /// X.
    pub x: f64,
    /// Y, the luminance factor (1 for the white).
    pub y: f64,
    /// Z.
    pub z: f64,
}

/// CIE 1976 L\*a\*b\* coordinates.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Lab {
    /// Lightness `L*`, 0 (black) to 100 (the white).
    pub l: f64,
    /// Green (−) to red (+), `a*`.
    pub a: f64,
    /// Blue (−) to yellow (+), `b*`.
    pub b: f64,
}

impl Lab {
    /// `L*, a*, b*`.
    pub const fn new(l: f64, a: f64, b: f64) -> Self {
        Self { l, a, b }
    }
}

/// XYZ (D65 white, `Y = 1`) to linear sRGB, IEC 61966-2-1:1999 eq. (5).
pub const XYZ_TO_LINEAR_SRGB: [[f64; 3]; 3] = [
    [3.2406, -1.5372, -0.4986],
    [-0.9689, 1.8758, 0.0415],
    [0.0557, -0.2040, 1.0570],
];

/// The chromaticity `(x, y)` of the D65 white point as sRGB defines it
/// (IEC 61966-2-1:1999) and colour-science's `CCS_ILLUMINANTS` gives it:
/// CIE 15:2004 table T.3's `(0.31272, 0.32903)` to four decimals. The
/// white of [`crate::spectrum::reflectance_to_xyz`], summed over the CIE
/// grid, lies between the two, `(0.31271, 0.32901)`; CIELAB of a perfect
/// reflector against this white is `(100, 0.0016, 0.0054)`:
///
/// ```
/// use radiometry::colour::{d65_white, xyz_to_lab};
/// use radiometry::spectrum::{reflectance_to_xyz, SAMPLES};
/// let white = xyz_to_lab(reflectance_to_xyz(&[1.0; SAMPLES]), d65_white());
/// assert!((white.l - 100.0).abs() < 1e-12);
/// assert!((white.a - 0.0016).abs() < 1e-4 && (white.b - 0.0054).abs() < 1e-4);
/// ```
pub const D65_WHITE_XY: (f64, f64) = (0.3127, 0.3290);

/// The tristimulus values of chromaticity `(x, y)` at luminance `Y = 1`.
#[inline]
pub fn xy_to_xyz(x: f64, y: f64) -> Xyz {
    Xyz {
        x: x / y,
        y: 1.0,
        z: (1.0 - x - y) / y,
    }
}

/// The D65 white point, `Y = 1`: the white of sRGB and of CIELAB here.
#[inline]
pub fn d65_white() -> Xyz {
    xy_to_xyz(D65_WHITE_XY.0, D65_WHITE_XY.1)
}

fn apply(m: &[[f64; 3]; 3], v: [f64; 3]) -> [f64; 3] {
    core::array::from_fn(|r| m[r][0] * v[0] + m[r][1] * v[1] + m[r][2] * v[2])
}

/// Linear sRGB `[R, G, B]` of `xyz`; components outside `[0, 1]` are out of
/// gamut and kept as they are.
#[inline]
pub fn xyz_to_linear_srgb(xyz: Xyz) -> [f64; 3] {
    apply(&XYZ_TO_LINEAR_SRGB, [xyz.x, xyz.y, xyz.z])
}

/// The XYZ of linear sRGB: the exact inverse of [`XYZ_TO_LINEAR_SRGB`]
/// (rather than the standard's separately rounded forward matrix), so that
/// a colour survives the round trip.
pub fn linear_srgb_to_xyz(rgb: [f64; 3]) -> Xyz {
    let m = XYZ_TO_LINEAR_SRGB;
    let cofactor = |r: usize, c: usize| {
        let (r0, r1) = ((r + 1) % 3, (r + 2) % 3);
        let (c0, c1) = ((c + 1) % 3, (c + 2) % 3);
        m[r0][c0] * m[r1][c1] - m[r0][c1] * m[r1][c0]
    };
    let det = m[0][0] * cofactor(0, 0) + m[0][1] * cofactor(0, 1) + m[0][2] * cofactor(0, 2);
    // inverse[i][j] = cofactor(j, i) / det
    let inverse: [[f64; 3]; 3] =
        core::array::from_fn(|i| core::array::from_fn(|j| cofactor(j, i) / det));
    let [x, y, z] = apply(&inverse, rgb);
    Xyz { x, y, z }
}

/// The sRGB transfer function (encoding): linear `[0, 1]` to the stored
/// value, `12.92 L` up to `L = 0.0031308` and `1.055 L^(1/2.4) − 0.055` above.
#[inline]
pub fn srgb_encode(linear: f64) -> f64 {
    if linear <= 0.0031308 {
        12.92 * linear
    } else {
        1.055 * linear.powf(1.0 / 2.4) - 0.055
    }
}

/// The inverse of [`srgb_encode`].
#[inline]
pub fn srgb_decode(encoded: f64) -> f64 {
    if encoded <= 0.04045 {
        encoded / 12.92
    } else {
        ((encoded + 0.055) / 1.055).powf(2.4)
    }
}

/// CIELAB of `xyz` relative to the white `white` (CIE 15:2004 §8.2.1, with
/// the exact rational constants `ε = (6/29)³`, `κ = (29/3)³`).
pub fn xyz_to_lab(xyz: Xyz, white: Xyz) -> Lab {
    const EPSILON: f64 = 216.0 / 24389.0;
    const KAPPA: f64 = 24389.0 / 27.0;
    let f = |t: f64| {
        if t > EPSILON {
            t.cbrt()
        } else {
            (KAPPA * t + 16.0) / 116.0
        }
    };
    let (fx, fy, fz) = (f(xyz.x / white.x), f(xyz.y / white.y), f(xyz.z / white.z));
    Lab {
        l: 116.0 * fy - 16.0,
        a: 500.0 * (fx - fy),
        b: 200.0 * (fy - fz),
    }
}

/// The CIEDE2000 colour difference ΔE00 between two CIELAB colours, with the
/// parametric factors `k_L = k_C = k_H = 1`.
///
/// Follows the implementation notes of Sharma, Wu & Dalal (2005), eqs.
/// (1)–(22), including their rules for the hue difference and mean hue when
/// the hues are more than 180° apart or a chroma is zero.
pub fn delta_e_2000(lab1: Lab, lab2: Lab) -> f64 {
    let pow7_25 = 25f64.powi(7);
    let chroma = |lab: Lab| lab.a.hypot(lab.b);
    let c_mean = (chroma(lab1) + chroma(lab2)) / 2.0;
    let g = 0.5 * (1.0 - (c_mean.powi(7) / (c_mean.powi(7) + pow7_25)).sqrt());
    // a′ = (1 + G) a, C′, h′ in degrees in [0, 360).
    let prime = |lab: Lab| {
        let a = (1.0 + g) * lab.a;
        let c = a.hypot(lab.b);
        let h = if a == 0.0 && lab.b == 0.0 {
            0.0
        } else {
            lab.b.atan2(a).to_degrees().rem_euclid(360.0)
        };
        (c, h)
    };
    let ((c1, h1), (c2, h2)) = (prime(lab1), prime(lab2));

    let dl = lab2.l - lab1.l;
    let dc = c2 - c1;
    let chroma_product = c1 * c2;
    let dh_angle = if chroma_product == 0.0 {
        0.0
    } else {
        let d = h2 - h1;
        if d > 180.0 {
            d - 360.0
        } else if d < -180.0 {
            d + 360.0
        } else {
            d
        }
    };
    let dh = 2.0 * chroma_product.sqrt() * (dh_angle.to_radians() / 2.0).sin();

    let l_mean = (lab1.l + lab2.l) / 2.0;
    let c_mean_prime = (c1 + c2) / 2.0;
    let h_mean = if chroma_product == 0.0 {
        h1 + h2
    } else if (h1 - h2).abs() <= 180.0 {
        (h1 + h2) / 2.0
    } else if h1 + h2 < 360.0 {
        (h1 + h2 + 360.0) / 2.0
    } else {
        (h1 + h2 - 360.0) / 2.0
    };
    let cos_deg = |deg: f64| deg.to_radians().cos();
    let t = 1.0 - 0.17 * cos_deg(h_mean - 30.0)
        + 0.24 * cos_deg(2.0 * h_mean)
        + 0.32 * cos_deg(3.0 * h_mean + 6.0)
        - 0.20 * cos_deg(4.0 * h_mean - 63.0);
    let d_theta = 30.0 * (-((h_mean - 275.0) / 25.0).powi(2)).exp();
    let r_c = 2.0 * (c_mean_prime.powi(7) / (c_mean_prime.powi(7) + pow7_25)).sqrt();
    let l50 = (l_mean - 50.0).powi(2);
    let s_l = 1.0 + 0.015 * l50 / (20.0 + l50).sqrt();
    let s_c = 1.0 + 0.045 * c_mean_prime;
    let s_h = 1.0 + 0.015 * c_mean_prime * t;
    let r_t = -(2.0 * d_theta).to_radians().sin() * r_c;
    let (l_term, c_term, h_term) = (dl / s_l, dc / s_c, dh / s_h);
    (l_term * l_term + c_term * c_term + h_term * h_term + r_t * c_term * h_term).sqrt()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn srgb_transfer_round_trips() {
        for x in [0.0, 0.001, 0.0031308, 0.01, 0.2, 0.5, 1.0] {
            assert!((srgb_decode(srgb_encode(x)) - x).abs() < 1e-15, "{x}");
        }
        // Continuous at the knee to the four decimals of the standard's constants.
        assert!((12.92 * 0.0031308 - (1.055 * 0.0031308f64.powf(1.0 / 2.4) - 0.055)).abs() < 1e-7);
    }

    #[test]
    fn srgb_white_is_the_d65_white() {
        // The matrix's rows sum so that D65 maps to R = G = B = 1 within its four decimals.
        for c in xyz_to_linear_srgb(d65_white()) {
            assert!((c - 1.0).abs() < 2e-4, "{c}");
        }
        let back = linear_srgb_to_xyz(xyz_to_linear_srgb(Xyz {
            x: 0.3,
            y: 0.4,
            z: 0.5,
        }));
        assert!(
            (back.x - 0.3).abs() < 1e-15
                && (back.y - 0.4).abs() < 1e-15
                && (back.z - 0.5).abs() < 1e-15
        );
    }

    use proptest::prelude::*;

    /// CIELAB colours inside the region real surfaces reach.
    fn lab_colours() -> impl Strategy<Value = Lab> {
        (0.0..100.0f64, -128.0..128.0f64, -128.0..128.0f64).prop_map(|(l, a, b)| Lab::new(l, a, b))
    }

    proptest! {
        // ΔE00 is a distance-like measure: non-negative, zero on the diagonal
        // and symmetric (Sharma et al. 2005, §3: its hue-mean rules make it so).
        // Symmetry holds to rounding: 1e-12 on values below ~200.
        #[test]
        fn delta_e_2000_is_symmetric_and_non_negative(p in lab_colours(), q in lab_colours()) {
            let (pq, qp) = (delta_e_2000(p, q), delta_e_2000(q, p));
            prop_assert!(pq >= 0.0 && pq.is_finite());
            prop_assert!((pq - qp).abs() <= 1e-12 * pq.max(1.0), "{pq} vs {qp}");
            prop_assert_eq!(delta_e_2000(p, p), 0.0);
        }

        // Lightness alone: with equal a*, b* the difference is the weighted ΔL, which
        // grows with |ΔL| (S_L depends only on the mean lightness).
        #[test]
        fn delta_e_2000_grows_with_the_lightness_difference(l in 10.0..60.0f64, dl in 0.1..20.0f64) {
            let base = Lab::new(l, 10.0, -5.0);
            let near = delta_e_2000(base, Lab::new(l + dl, 10.0, -5.0));
            let far = delta_e_2000(Lab::new(l - 1.0, 10.0, -5.0), Lab::new(l + dl + 1.0, 10.0, -5.0));
            prop_assert!(far > near, "{far} <= {near}");
        }

        // The sRGB transfer function and its inverse undo each other to a few ulps.
        #[test]
        fn srgb_encoding_round_trips(x in 0.0..=1.0f64) {
            prop_assert!((srgb_decode(srgb_encode(x)) - x).abs() <= 4.0 * f64::EPSILON);
        }
    }

    #[test]
    fn delta_e_2000_is_zero_for_equal_colours_and_symmetric() {
        let (p, q) = (
            Lab::new(60.2574, -34.0099, 36.2677),
            Lab::new(60.4626, -34.1751, 39.4387),
        );
        assert_eq!(delta_e_2000(p, p), 0.0);
        assert!((delta_e_2000(p, q) - delta_e_2000(q, p)).abs() < 1e-12);
    }
}
