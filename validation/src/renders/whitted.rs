//! Whitted against Whitted: deterministic renders compared per pixel, away
//! from the edges the reference masks.

use tracer::render::Image;

use super::figure::triptych;
use super::{
    flatten, pixel_label, summarise_failures, tolerance, Compared, Decoded, TOLERANCE_ABSOLUTE,
    TOLERANCE_RELATIVE,
};
use crate::check::Check;

/// Whitted against Whitted, per pixel away from edges.
pub fn compare_whitted(name: &str, reference: &Decoded, ours: &Image) -> Compared {
    let scene = &reference.scene;
    let mut check = Check::new(
        &format!("renders.mitsuba.{name}.whitted"),
        &format!("{name}: the tracer's whitted against a Whitted integrator on Mitsuba's primitives, per pixel"),
        "Mitsuba 3 (scalar_rgb, float32): ray_intersect, fresnel_conductor, reflect (mitsuba_renders.json)",
        &format!(
            "|ours − Mitsuba| ≤ {TOLERANCE_ABSOLUTE:e} + {TOLERANCE_RELATIVE:e} · |Mitsuba| per channel, \
             edge pixels masked: both float32, different intersections and ray offsets; the s = 100 lobe \
             and mirror chains amplify them"
        ),
    );
    let ours = flatten(ours);
    if ours.len() != reference.whitted.len() {
        check.fail(format!(
            "the render has {} values, the reference {}",
            ours.len(),
            reference.whitted.len()
        ));
    }
    let mut heat = vec![f64::NAN; ours.len()];
    let (mut sum, mut compared) = (0.0, 0usize);
    let masked = reference.edges.iter().filter(|&&e| e).count();
    for (i, (&a, &b)) in ours.iter().zip(&reference.whitted).enumerate() {
        if reference.edges[i / 3] {
            continue;
        }
        let d = (a - b).abs();
        heat[i] = d / tolerance(b);
        sum += d;
        compared += 1;
        let at = pixel_label(scene.width, i);
        check.measure("|ours − Mitsuba|, W/(sr m²)", d, &at);
        check.measure("|ours − Mitsuba| / tolerance", heat[i], &at);
        if !(d <= tolerance(b)) {
            check.fail(format!(
                "{at}: ours {a:.7}, Mitsuba {b:.7}, difference {d:.3e}"
            ));
        }
    }
    check.cases = compared / 3;
    check.measure("masked edge pixels", masked as f64, "");
    check.measure(
        "masked pixel fraction",
        masked as f64 / reference.edges.len().max(1) as f64,
        "",
    );
    check.measure(
        "mean |ours − Mitsuba|, W/(sr m²)",
        sum / compared.max(1) as f64,
        "",
    );
    summarise_failures(&mut check);
    let figure = triptych(name, "whitted", scene, &ours, &reference.whitted, &heat);
    Compared { check, figure }
}
