//! Whitted against Whitted: deterministic renders compared per pixel, away
//! from the edges the reference masks, by [`crate::compare::tolerance`].

use tracer::render::Image;

use super::common::{flatten, pixel_label, summarise_failures, Compared, ALPHA};
use super::figure::triptych;
use super::reference::Decoded;
use crate::check::Check;
use crate::compare::{tolerance, Tolerance, TOLERANCE_ABSOLUTE, TOLERANCE_RELATIVE};

// What a Whitted render measures, in English and in Hungarian.
const DIFFERENCE: [&str; 2] = [
    "|ours − Mitsuba|, W/(sr m²)",
    "|miénk − Mitsuba|, W/(sr m²)",
];
const SCORE: [&str; 2] = ["|ours − Mitsuba| / tolerance", "|miénk − Mitsuba| / tűrés"];
const MASKED: [&str; 2] = ["masked edge pixels", "maszkolt élképpontok"];
const MASKED_SHARE: [&str; 2] = ["masked pixel fraction", "maszkolt képpontok aránya"];
const MEAN: [&str; 2] = [
    "mean |ours − Mitsuba|, W/(sr m²)",
    "átlagos |miénk − Mitsuba|, W/(sr m²)",
];

/// Whitted against Whitted, per pixel away from edges.
pub fn compare_whitted(name: &str, reference: &Decoded, ours: &Image) -> Compared {
    let scene = &reference.scene;
    let mut check = Check::new(
        &format!("renders.mitsuba.{name}.whitted"),
        [
            &format!("{name}: the tracer's whitted against a Whitted integrator on Mitsuba's primitives, per pixel"),
            &format!("{name}: a sugárkövető Whitted-féle képe egy Whitted-integrátorhoz mérve a Mitsuba primitívjein, képpontonként"),
        ],
        [
            "Mitsuba 3 (scalar_rgb, float32): ray_intersect, fresnel_conductor, reflect (mitsuba_renders.json)",
            "Mitsuba 3 (scalar_rgb, float32): ray_intersect, fresnel_conductor, 'reflect' (mitsuba_renders.json)",
        ],
        [&format!(
            "|ours − Mitsuba| ≤ {TOLERANCE_ABSOLUTE:e} + {TOLERANCE_RELATIVE:e} · |Mitsuba| per channel, \
             edge pixels masked: both float32, different intersections and ray offsets; the s = 100 lobe \
             and mirror chains amplify them"
        ), &format!("|miénk − Mitsuba| ≤ {TOLERANCE_ABSOLUTE:e} + {TOLERANCE_RELATIVE:e} · |Mitsuba| csatornánként, az élképpontok maszkolva: mindkettő float32, eltérő metszéspontokkal és sugáreltolásokkal; az s = 100 lebeny és a tükörláncok felnagyítják ezeket")],
    );
    let ours = flatten(ours);
    if ours.len() != reference.whitted.len() {
        check.fail(format!(
            "the render has {} values, the reference {}",
            ours.len(),
            reference.whitted.len()
        ));
    }
    let verdicts = tolerance::radiance(
        &ours,
        &reference.whitted,
        None,
        Tolerance::RENDERS,
        ALPHA,
        Some(&reference.edges),
    );
    let masked = reference.edges.iter().filter(|&&e| e).count();
    let (mut sum, mut compared) = (0.0, 0usize);
    for i in (0..verdicts.score.len()).filter(|&i| verdicts.compared[i]) {
        let d = verdicts.difference[i].abs();
        sum += d;
        compared += 1;
        let at = || pixel_label(scene.width, i);
        check.measure_at_in_both(DIFFERENCE, d, at);
        check.measure_at_in_both(SCORE, verdicts.score[i], at);
        if verdicts.disagrees(i) {
            check.fail(format!(
                "{}: ours {:.7}, Mitsuba {:.7}, difference {d:.3e}",
                at(),
                ours[i],
                reference.whitted[i]
            ));
        }
    }
    check.cases = compared / 3;
    let masked_share = masked as f64 / reference.edges.len().max(1) as f64;
    check.measure_in_both(MASKED, masked as f64, "");
    check.measure_in_both(MASKED_SHARE, masked_share, "");
    check.measure_in_both(MEAN, sum / compared.max(1) as f64, "");
    summarise_failures(&mut check);
    let figure = triptych(
        name,
        "whitted",
        scene,
        &ours,
        &reference.whitted,
        &verdicts.score,
    );
    Compared { check, figure }
}
