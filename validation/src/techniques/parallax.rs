//! Environment mapping against ray tracing, as checks: the slides'
//! captured map ([`super::envmap_vs_traced`]) against the traced mirror
//! as the surroundings move away, and two mirrors side by side, which the
//! map cannot show in each other.

use super::envmap_vs_traced::{log_log_slope, one_sphere, Comparison, Resolution, Surroundings};
use super::figure::strip;
use crate::check::Check;
use crate::renders::RenderFigure;
use crate::tradeoff::measure::Errors;

/// The checks' sizes: 48 × 48 pixels (the pair 96 × 48), a cube of 48²
/// texels a face; the sweep's exponents are stated at this size, where
/// the pixel grid quantises the bands along sharp edges.
pub const RESOLUTION: Resolution = Resolution {
    image: 48,
    cube: 48,
};

/// One sweep: the surroundings, the distances (mirror radii, doubling),
/// and the expected exponent of the relative RMSE `∝ d^p` with its band.
#[derive(Clone, Copy, Debug)]
pub struct Sweep {
    /// What surrounds the mirror.
    pub surroundings: Surroundings,
    /// Distances, each twice the last.
    pub distances: [f64; 4],
    /// The expected exponent: `−1` where the error is the parallax angle
    /// times a smooth gradient; `−1/2` where it lives in bands along sharp
    /// edges, whose area goes as `1/d` and the RMSE as its root.
    pub exponent: f64,
    /// How far the fitted exponent may be from it.
    pub within: f64,
}

/// The two sweeps of `techniques.envmap.distance`.
pub const SWEEPS: [Sweep; 2] = [
    Sweep {
        surroundings: Surroundings::Sky,
        distances: [6.0, 12.0, 24.0, 48.0],
        exponent: -1.0,
        within: 0.15,
    },
    Sweep {
        surroundings: Surroundings::Objects,
        distances: [2.0, 4.0, 8.0, 16.0],
        exponent: -0.5,
        within: 0.25,
    },
];

/// A distance sweep measured: the distances and the errors there.
#[derive(Clone, Debug, serde::Serialize)]
pub struct DistanceCurve {
    /// The surroundings, in words.
    pub label: String,
    /// Distance of the surroundings, mirror radii.
    pub distance: Vec<f64>,
    /// Relative RMSE of linear radiance over the mirror's pixels.
    pub rel_rmse: Vec<f64>,
    /// Mean ΔE2000 of the displayed images over the mirror's pixels.
    pub delta_e_mean: Vec<f64>,
    /// The least-squares exponent of the relative RMSE.
    pub fitted_exponent: f64,
}

/// Each distance's relative RMSE of the sweep named `[name, name_hu]`.
fn record_rmse(check: &mut Check, [name, name_hu]: [&str; 2], rows: &[(f64, Errors)]) {
    for (d, e) in rows {
        let at = format!("{name}, d = {d}");
        check.measure_in_both(
            [
                &format!("{name}: relative RMSE at d = {d}"),
                &format!("{name_hu}: relatív négyzetes középhiba d = {d} esetén"),
            ],
            e.rel_rmse,
            &at,
        );
    }
}

/// A sweep's surroundings ([`label`]) in Hungarian.
fn label_hu(name: &str) -> &str {
    match name {
        "objects" => "tárgyak",
        "sky" => "égbolt",
        other => other,
    }
}

/// What each sweep of [`SWEEPS`] is held to, in English and in Hungarian.
fn distance_tolerance() -> [String; 2] {
    let each = |s: &Sweep| {
        let name = label(s.surroundings);
        [
            format!(
                "{name}: falls at every doubling of d (relative RMSE and mean ΔE2000), RMSE ∝ d^p \
                 with p = {} ± {}",
                s.exponent, s.within
            ),
            format!(
                "{}: csökken d minden duplázásánál (relatív négyzetes középhiba és ΔE2000 átlag), \
                 középhiba ∝ d^p, p = {} ± {}",
                label_hu(name),
                s.exponent,
                s.within
            ),
        ]
    };
    let all: Vec<[String; 2]> = SWEEPS.iter().map(each).collect();
    [0, 1].map(|k| {
        all.iter()
            .map(|t| t[k].as_str())
            .collect::<Vec<_>>()
            .join("; ")
    })
}

/// The mapped mirror against the traced one over each sweep of
/// [`SWEEPS`], made by `compare` ([`one_sphere`] in the suite; a
/// parameter, so that a wrong map can be shown to be caught): the error
/// must fall at every doubling of the distance by both measures, and the
/// relative RMSE at the sweep's exponent within its band.
pub fn check_distance(
    compare: fn(Surroundings, f64, Resolution) -> Comparison,
    curves: &mut Vec<DistanceCurve>,
    figures: &mut Vec<RenderFigure>,
) -> Check {
    let mut check = Check::new(
        "techniques.envmap.distance",
        [
            "Environment mapping against ray tracing: a mirror sphere's error as its surroundings move away",
            "Környezetleképzés a sugárkövetéshez mérve: egy tükörgömb hibája, ahogy a környezete távolodik",
        ],
        [
            "the same mirror traced among the same surroundings (Whitted); the map captured from its centre by the tracer (cube, 48² a face), 48 × 48 pixels",
            "ugyanaz a tükör ugyanabban a környezetben követve (Whitted); a térképet a sugárkövető a középpontjából rögzíti (kocka, lapja 48²), 48 × 48 képpont",
        ],
        distance_tolerance().each_ref().map(String::as_str),
    );
    for sweep in SWEEPS {
        let name = label(sweep.surroundings);
        let name_hu = label_hu(name);
        let rows: Vec<(f64, Errors)> = sweep
            .distances
            .iter()
            .map(|&d| {
                let c = compare(sweep.surroundings, d, RESOLUTION);
                if d == sweep.distances[0] {
                    figures.push(strip(
                        &format!("techniques_envmap_{name}_d{d}.png"),
                        &c.mapped,
                        &c.traced,
                        4,
                    ));
                }
                (d, c.errors)
            })
            .collect();
        check.cases += rows.len();
        record_rmse(&mut check, [name, name_hu], &rows);
        for pair in rows.windows(2) {
            let ((d0, e0), (d1, e1)) = (pair[0], pair[1]);
            if !(e1.rel_rmse < e0.rel_rmse && e1.delta_e_mean < e0.delta_e_mean) {
                check.fail(format!(
                    "{name}: from d = {d0} to {d1} the error does not fall (RMSE {:.4} → {:.4}, ΔE {:.3} → {:.3})",
                    e0.rel_rmse, e1.rel_rmse, e0.delta_e_mean, e1.delta_e_mean
                ));
            }
        }
        let points: Vec<(f64, f64)> = rows.iter().map(|(d, e)| (*d, e.rel_rmse)).collect();
        let slope = log_log_slope(&points);
        let exponent = [
            format!("{name}: fitted exponent of the RMSE"),
            format!("{name_hu}: a középhiba illesztett kitevője"),
        ];
        check.measure_in_both([&exponent[0], &exponent[1]], slope, "");
        if !((slope - sweep.exponent).abs() <= sweep.within) {
            check.fail(format!(
                "{name}: the RMSE falls as d^{slope:.3}, not d^({} ± {})",
                sweep.exponent, sweep.within
            ));
        }
        curves.push(DistanceCurve {
            label: name.to_owned(),
            distance: rows.iter().map(|r| r.0).collect(),
            rel_rmse: rows.iter().map(|r| r.1.rel_rmse).collect(),
            delta_e_mean: rows.iter().map(|r| r.1.delta_e_mean).collect(),
            fitted_exponent: slope,
        });
    }
    check
}

/// Where the pair is measured: surroundings far enough (mirror radii)
/// that a lone mirror's error is small.
pub const PAIR_DISTANCE: f64 = 32.0;

/// How many times a lone mirror's relative RMSE the pair's must exceed.
pub const PAIR_RATIO: f64 = 5.0;

/// The least mean ΔE2000 where each mirror shows the other: the map
/// shows the other mirror once, without the first in it, where the trace
/// shows the chain of reflections.
pub const SEEING_FLOOR: f64 = 10.0;

/// Two mirrors side by side under the sky at [`PAIR_DISTANCE`], each
/// under its own captured map, against a lone mirror under the same sky:
/// the shortcut's failure, shown. `pair` is [`two_spheres`](super::envmap_vs_traced::two_spheres) in the suite.
pub fn check_self_reflection(
    pair: fn(Surroundings, f64, Resolution) -> Comparison,
    figures: &mut Vec<RenderFigure>,
) -> Check {
    let mut check = Check::new(
        "techniques.envmap.self_reflection",
        [
            "Environment mapping against ray tracing: two mirrors side by side cannot show each other",
            "Környezetleképzés a sugárkövetéshez mérve: két egymás melletti tükör nem mutathatja egymást",
        ],
        [
            "the pair traced (Whitted), each mirror's map captured from its centre; a lone mirror under the same sky",
            "a pár követve (Whitted), mindkét tükör térképe a saját középpontjából rögzítve; egy magányos tükör ugyanazon ég alatt",
        ],
        [&format!(
            "expected to fail as a shortcut: the pair's relative RMSE above {PAIR_RATIO} × a lone \
             mirror's, and a mean ΔE2000 above {SEEING_FLOOR} where each mirror shows the other"
        ), &format!("rövidítésként várhatóan elbukik: a pár relatív négyzetes középhibája nagyobb egy magányos tükörénél {PAIR_RATIO}-szer, és a ΔE2000 átlag {SEEING_FLOOR} fölött, ahol a tükrök egymást mutatják")],
    );
    let lone = one_sphere(Surroundings::Sky, PAIR_DISTANCE, RESOLUTION).errors;
    let c = pair(Surroundings::Sky, PAIR_DISTANCE, RESOLUTION);
    figures.push(strip(
        "techniques_envmap_two_mirrors.png",
        &c.mapped,
        &c.traced,
        4,
    ));
    check.cases = 2;
    let at = format!("sky at d = {PAIR_DISTANCE}");
    check.measure_in_both(
        [
            "one mirror: relative RMSE",
            "egy tükör: relatív négyzetes középhiba",
        ],
        lone.rel_rmse,
        &at,
    );
    check.measure_in_both(
        [
            "two mirrors: relative RMSE",
            "két tükör: relatív négyzetes középhiba",
        ],
        c.errors.rel_rmse,
        &at,
    );
    if !(c.errors.rel_rmse > PAIR_RATIO * lone.rel_rmse) {
        check.fail(format!(
            "the pair's RMSE {:.4} is within {PAIR_RATIO} × a lone mirror's {:.4}",
            c.errors.rel_rmse, lone.rel_rmse
        ));
    }
    match c.split {
        Some(split) if split.seeing_a_mirror_pixels > 0 => {
            let mean = split.seeing_a_mirror.delta_e_mean;
            check.measure_in_both(
                [
                    "where each shows the other: mean ΔE2000",
                    "ahol egymást mutatják: ΔE2000 átlag",
                ],
                mean,
                &format!("{} px", split.seeing_a_mirror_pixels),
            );
            check.measure_in_both(
                ["elsewhere: mean ΔE2000", "máshol: ΔE2000 átlag"],
                split.elsewhere.delta_e_mean,
                &format!("{} px", split.elsewhere_pixels),
            );
            if !(mean > SEEING_FLOOR) {
                check.fail(format!(
                    "where each mirror shows the other the map is off by {mean:.2} ΔE, not above {SEEING_FLOOR}"
                ));
            }
        }
        _ => check.fail("no pixel where a mirror shows the other".into()),
    }
    check
}

fn label(kind: Surroundings) -> &'static str {
    match kind {
        Surroundings::Sky => "sky",
        Surroundings::Objects => "objects",
    }
}
