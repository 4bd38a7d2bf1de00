//! What the `f32` tier costs: every law the tracer evaluates in `f32`,
//! against the same law in `f64` at the same inputs (each `f32` input is
//! exact in `f64`, so the difference is the `f32` evaluation's own error; the
//! `f64` laws are within a few `f64` ulps of 50-digit references, see
//! `tests/fresnel_reference.rs`).
//!
//! Run `cargo test -p radiometry --test precision_tiers -- --nocapture` for
//! the table of worst differences; each test fails above a bound stated
//! beside it. `ε` is `f32::EPSILON` (1.19e-7).

use glam::{DVec3, Vec3};
use radiometry::brdf::{BlinnPhong, BlinnPhongReciprocal, Brdf, Lambert};
use radiometry::fresnel::{conductor, dielectric_polarized, f0, schlick};
use radiometry::radiance::point_irradiance;
use radiometry::specular::{reflect, refract};
use radiometry::Real;

const EPS: f64 = f32::EPSILON as f64;

/// The table of worst differences, printed and settled against its section
/// of `docs/results.md`.
fn settle(section: &str, rows: &[&Worst]) {
    let mut table = String::from("| law | worst \\|f32 − f64\\| | at |\n|---|---|---|\n");
    for w in rows {
        table += &w.row();
    }
    println!("{table}");
    results::assert_settled(&results::Section::deterministic(
        section,
        "cargo test -p radiometry --test precision_tiers",
        &table,
    ));
}

/// The worst value of one measured difference and where it occurred.
struct Worst {
    law: &'static str,
    unit: &'static str,
    value: f64,
    at: String,
}

impl Worst {
    fn new(law: &'static str, unit: &'static str) -> Self {
        Self {
            law,
            unit,
            value: 0.0,
            at: String::new(),
        }
    }

    fn record(&mut self, value: f64, at: impl FnOnce() -> String) {
        let value = if value.is_nan() { f64::INFINITY } else { value };
        if value > self.value {
            self.value = value;
            self.at = at();
        }
    }

    fn row(&self) -> String {
        let value = if self.unit == "relative" {
            format!("{:.1e}", self.value)
        } else {
            format!("{:.2}", self.value)
        };
        format!("| {} | {value} {} | {} |\n", self.law, self.unit, self.at)
    }
}

/// Cosines over both sides, 4001 of them, exact in `f32`, with the grazing
/// ones the uniform grid misses.
fn cosines() -> Vec<f32> {
    let mut c: Vec<f32> = (0..=4000).map(|k| -1.0 + k as f32 / 2000.0).collect();
    c.extend([1e-3f32, 1e-6, 1e-30, -1e-3, -1e-6, -1e-30]);
    c
}

/// Unit directions spread over the sphere (a Fibonacci lattice), in `f32`.
fn sphere(count: usize) -> Vec<Vec3> {
    let golden = std::f32::consts::PI * (3.0 - 5f32.sqrt());
    (0..count)
        .map(|k| {
            let z = 1.0 - 2.0 * (k as f32 + 0.5) / count as f32;
            let r = (1.0 - z * z).max(0.0).sqrt();
            let phi = golden * k as f32;
            Vec3::new(r * phi.cos(), r * phi.sin(), z).normalize()
        })
        .collect()
}

const INDICES: [f32; 5] = [1.333, 1.5, 2.42, 1.0 / 1.5, 1.0001];

/// Fresnel reflectance and transmittance: within 8 `f32` ulps of the `f64`
/// value, the bound the 50-digit check holds the `f32` tier to (its sums run
/// in `f64`, so only a handful of final roundings remain). The relative
/// difference is reported too, and is bounded by the same reasoning by 16 ε
/// where the value is not subnormal.
#[test]
fn f32_fresnel_is_within_8_f32_ulps_of_f64() {
    let mut r = Worst::new("dielectric R", "f32 ulps");
    let mut t = Worst::new("dielectric T", "f32 ulps");
    let mut rel = Worst::new("dielectric R and T", "relative");
    for eta in INDICES {
        for c in cosines() {
            let (f32_, f64_) = (
                dielectric_polarized(c, eta),
                dielectric_polarized(f64::from(c), f64::from(eta)),
            );
            let at = || format!("eta {eta}, cos {c:e}");
            for (worst, a, b) in [
                (&mut r, f32_.reflectance(), f64_.reflectance()),
                (&mut t, f32_.transmittance(), f64_.transmittance()),
            ] {
                let diff = (f64::from(a) - b).abs();
                worst.record(diff / f32::ulp_at(b), at);
                if b >= f64::from(f32::MIN_POSITIVE) {
                    rel.record(diff / b, at);
                }
            }
        }
    }
    let mut metal = Worst::new("conductor R (gold RGB, silver, aluminium)", "f32 ulps");
    let metals = [
        (0.17f32, 3.1f32),
        (0.35, 2.7),
        (1.5, 1.9),
        (0.15, 3.6),
        (1.2, 7.0),
    ];
    let mut schlick_diff = Worst::new("Schlick, F0 from (n, κ)", "f32 ulps");
    for (n, kappa) in metals {
        for c in cosines().into_iter().filter(|&c| c >= 0.0) {
            let exact = conductor(f64::from(c), f64::from(n), f64::from(kappa));
            let diff = (f64::from(conductor(c, n, kappa)) - exact).abs();
            metal.record(diff / f32::ulp_at(exact), || {
                format!("n {n}, κ {kappa}, cos {c:e}")
            });
            let s64 = schlick(f64::from(c), f0(f64::from(n), f64::from(kappa)));
            let s32 = schlick(c, f0(n, kappa));
            schlick_diff.record((f64::from(s32) - s64).abs() / f32::ulp_at(s64), || {
                format!("n {n}, κ {kappa}, cos {c:e}")
            });
        }
    }
    for w in [&r, &t, &metal, &schlick_diff] {
        assert!(
            w.value <= 8.0,
            "{}: {} {} at {}",
            w.law,
            w.value,
            w.unit,
            w.at
        );
    }
    assert!(rel.value <= 16.0 * EPS, "{} at {}", rel.value, rel.at);
    settle("f32-fresnel", &[&r, &t, &rel, &metal, &schlick_diff]);
}

/// Mirror and refracted directions, component by component, in units of ε.
/// Reflection: `2(w·n)n − w` rounds a few times on unit-sized terms: 4 ε.
/// Refraction: the tangential part scales by `n_i/n_t` (up to 1.5 here),
/// a few roundings each: 8 ε (1 + 1/η_path). The normal part is
/// `cos θ_t = √d / n_t`, and the discriminant `d` is good to about an ε of
/// its terms (the dot product `cos θ_i` it is built from is rounded in
/// `f32`), so `√d` errs by about ε/√d: 2 ε / cos θ_t, which grows without
/// bound at the critical angle. A perturbation of ε in `d` moves `√d` by at
/// most √ε, so the bound is capped at 2√ε.
#[test]
fn f32_directions_are_within_rounding_of_f64() {
    let mut mirror = Worst::new("reflect, per component", "ε");
    let mut bent = Worst::new("refract, per component", "ε");
    let mut bent_vs_bound = Worst::new("refract, error / bound", "of the bound");
    let normals = sphere(37);
    for (k, w) in sphere(2000).into_iter().enumerate() {
        let n = normals[k % normals.len()];
        let (w64, n64) = (w.as_dvec3(), n.as_dvec3());
        let diff = |a: Vec3, b: DVec3| (a.as_dvec3() - b).abs().max_element() / EPS;
        mirror.record(diff(reflect(w, n), reflect(w64, n64)), || {
            format!("w {w}, n {n}")
        });
        for eta in INDICES {
            let (t32, t64) = (refract(w, n, eta), refract(w64, n64, f64::from(eta)));
            assert_eq!(
                t32.is_some(),
                t64.is_some(),
                "the tiers disagree on total internal reflection: w {w}, n {n}, eta {eta}"
            );
            if let (Some(t32), Some(t64)) = (t32, t64) {
                let err = diff(t32.direction, t64.direction);
                let bound =
                    (8.0 * (1.0 + 1.0 / t64.eta_path) + 2.0 / t64.cos_t).min(2.0 / EPS.sqrt());
                let at = || format!("w {w}, n {n}, eta {eta}, cos_t {:e}", t64.cos_t);
                bent.record(err, at);
                bent_vs_bound.record(err / bound, at);
            }
        }
    }
    assert!(mirror.value <= 4.0, "{} ε at {}", mirror.value, mirror.at);
    assert!(
        bent_vs_bound.value <= 1.0,
        "{} of the bound at {}",
        bent_vs_bound.value,
        bent_vs_bound.at
    );
    settle("f32-directions", &[&mirror, &bent, &bent_vs_bound]);
}

/// BRDFs and the point light, relative. The half vector and the cosines carry
/// a few ε; `x^shine` multiplies a relative error of `x` by `shine`, and the
/// course's division by `cos θ_i` adds that cosine's error relative to
/// itself. Bound: (8 + 2·shine) ε relative to the value, plus for the course
/// form 2ε / cos θ_i. Lambert is a constant: exact rounding of albedo/π, ε.
/// The point light's `I cos θ / r²`: 8 ε relative to `I / r²` (the cosine is
/// an absolute quantity: relative to its own value it is unbounded at grazing).
#[test]
fn f32_brdfs_and_lights_are_within_rounding_of_f64() {
    let mut lambert = Worst::new("Lambert", "ε relative");
    let mut blinn = Worst::new("Blinn-Phong (course), error / bound", "of the bound");
    let mut reciprocal = Worst::new("Blinn-Phong reciprocal, error / bound", "of the bound");
    let mut light = Worst::new("point light irradiance", "ε of I/r²");
    let dirs: Vec<Vec3> = sphere(400).into_iter().filter(|d| d.z > 1e-3).collect();
    let n = Vec3::Z;
    for shine in [1.0f32, 10.0, 100.0] {
        let course = BlinnPhong {
            kd: 0.2f32,
            ks: 0.7,
            shine,
        };
        let fixed = BlinnPhongReciprocal {
            kd: 0.2f32,
            ks: 0.7,
            shine,
        };
        let (course64, fixed64) = (
            BlinnPhong {
                kd: 0.2f32 as f64,
                ks: 0.7f32 as f64,
                shine: shine as f64,
            },
            BlinnPhongReciprocal {
                kd: 0.2f32 as f64,
                ks: 0.7f32 as f64,
                shine: shine as f64,
            },
        );
        let bound = (8.0 + 2.0 * shine as f64) * EPS;
        for (i, &a) in dirs.iter().enumerate() {
            for &b in dirs.iter().skip(i % 7).step_by(7) {
                let (a64, b64) = (a.as_dvec3(), b.as_dvec3());
                let at = || format!("shine {shine}, wi {a}, wo {b}");
                let v64 = course64.eval(DVec3::Z, a64, b64);
                let err = (f64::from(course.eval(n, a, b)) - v64).abs() / v64;
                blinn.record(err / (bound + 2.0 * EPS / a64.z), at);
                let v64 = fixed64.eval(DVec3::Z, a64, b64);
                let err = (f64::from(fixed.eval(n, a, b)) - v64).abs() / v64;
                reciprocal.record(err / bound, at);
            }
        }
    }
    for albedo in [0.1f32, 0.8, 1.0] {
        let (white, white64) = (
            Lambert { albedo },
            Lambert {
                albedo: f64::from(albedo),
            },
        );
        for (i, &a) in dirs.iter().enumerate() {
            for &b in dirs.iter().skip(i % 7).step_by(7) {
                let v64 = white64.eval(DVec3::Z, a.as_dvec3(), b.as_dvec3());
                let err = (f64::from(white.eval(n, a, b)) - v64).abs() / v64;
                lambert.record(err / EPS, || format!("albedo {albedo} (any directions)"));
            }
        }
    }
    let lamp = Vec3::new(0.3, -0.2, 2.0);
    for (k, p) in sphere(500).into_iter().enumerate() {
        let point = p * (1.0 + k as f32 / 100.0);
        let (s32, s64) = (
            point_irradiance(100.0f32, lamp, point, n),
            point_irradiance(100.0, lamp.as_dvec3(), point.as_dvec3(), DVec3::Z),
        );
        if let (Some(s32), Some(s64)) = (s32, s64) {
            let scale = 100.0 / (s64.distance * s64.distance);
            light.record(
                (f64::from(s32.irradiance) - s64.irradiance).abs() / scale / EPS,
                || format!("point {point}"),
            );
        }
    }
    assert!(lambert.value <= 1.0, "{}", lambert.value);
    assert!(
        blinn.value <= 1.0,
        "{} of the bound at {}",
        blinn.value,
        blinn.at
    );
    assert!(
        reciprocal.value <= 1.0,
        "{} of the bound at {}",
        reciprocal.value,
        reciprocal.at
    );
    assert!(light.value <= 8.0, "{} ε at {}", light.value, light.at);
    settle("f32-brdfs-lights", &[&lambert, &blinn, &reciprocal, &light]);
}

/// The `f32` tier's sums run in plain `f64` (its products are exact
/// there): the cosines where they cancel most are the `f32` cosines
/// nearest the critical angle (Snell's discriminant → 0, which T and
/// `cos θ_t` hang on) and nearest Brewster's angle (R_p → 0). Over 4000
/// indices, the 33 `f32` cosines around each angle: R, T, R_s and R_p
/// within 8 `f32` ulps of the `f64` law, whose sums are compensated.
#[test]
fn f32_fresnel_where_its_sums_cancel_is_within_8_f32_ulps_of_f64() {
    let mut worst = 0.0f64;
    let mut at = String::new();
    for k in 0..4000 {
        let eta = 1.0001f32 + k as f32 * (2.0 / 4000.0);
        let (e, e2) = (f64::from(eta), f64::from(eta) * f64::from(eta));
        // From the inside past cos_c = √(1 − 1/η²); from the outside at
        // cos_B = 1/√(1 + η²).
        let angles = [-(1.0 - 1.0 / e2).sqrt(), 1.0 / (1.0 + e2).sqrt()];
        for centre in angles {
            let mut c = centre as f32;
            for _ in 0..16 {
                c = c.next_down();
            }
            for _ in 0..33 {
                let (f32_, f64_) = (
                    dielectric_polarized(c, eta),
                    dielectric_polarized(f64::from(c), e),
                );
                for (a, b) in [
                    (f32_.reflectance(), f64_.reflectance()),
                    (f32_.transmittance(), f64_.transmittance()),
                    (f32_.r_s, f64_.r_s),
                    (f32_.r_p, f64_.r_p),
                ] {
                    // NaN counts as the worst.
                    let ulps = (f64::from(a) - b).abs() / f32::ulp_at(b);
                    let ulps = if ulps.is_nan() { f64::INFINITY } else { ulps };
                    if ulps > worst {
                        worst = ulps;
                        at = format!("eta {eta}, cos {c:e}: {a:e} against {b:e}");
                    }
                }
                c = c.next_up();
            }
        }
    }
    println!("worst {worst:.2} f32 ulps at {at}");
    assert!(worst <= 8.0, "{worst:.2} f32 ulps at {at}");
}
