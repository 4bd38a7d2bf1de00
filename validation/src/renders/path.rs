//! Path against path: Monte Carlo renders compared per pixel and channel by
//! Welch's t-test, Bonferroni-corrected, a rejection explained by Mitsuba's
//! own ray offsets recorded as a finding about the reference.

mod judge;
mod measures;
mod sides;

use super::common::{summarise_failures, Compared, ALPHA, MITSUBA_RAY_EPSILON};
use super::figure::triptych;
use super::image_mean;
use super::reference::Decoded;
use crate::check::Check;
use crate::compare::{TOLERANCE_ABSOLUTE, TOLERANCE_RELATIVE};
use judge::{judge_deterministic, judge_tests};
use measures::{record_metrics, record_power};
use sides::{split, Moved, Sides, Split, Verdicts};

/// The tracer's per-pixel mean and per-sample variance with its secondary
/// rays started by Mitsuba's rule ([`MITSUBA_RAY_EPSILON`]); asked
/// for only when a rejection is left that the measured offset sensitivity
/// does not explain.
pub type UnderMitsubaOffsets<'a> = &'a dyn Fn() -> Result<(Vec<f64>, Vec<f64>), String>;

/// Path against path: Welch's t per pixel and channel, Bonferroni-corrected,
/// over every pixel of Mitsuba's box-filtered render (no edge is masked:
/// both sides integrate the same pixel).
pub fn compare_path(
    name: &str,
    reference: &Decoded,
    mitsuba_samples: u32,
    ours: (&[f64], &[f64]),
    our_samples: u32,
    under_mitsuba_offsets: UnderMitsubaOffsets,
) -> Option<Compared> {
    let mitsuba = reference.path.as_ref()?;
    let scene = &mitsuba.scene;
    let sides = Sides::new(ours, our_samples, mitsuba, mitsuba_samples);
    let mut check = new_check(name);
    if ours.0.len() != mitsuba.mean.len() {
        check.fail(format!(
            "the render has {} values, the reference {}",
            ours.0.len(),
            mitsuba.mean.len()
        ));
    }
    let Split {
        tests,
        deterministic,
        sum,
        compared,
    } = split(&mut check, &sides);
    let mut heat = vec![f64::NAN; mitsuba.mean.len()];
    let moved = Moved::new();
    let moved_render = || moved.get_or_init(under_mitsuba_offsets);
    let verdicts = judge_tests(&mut check, &sides, &tests, &mut heat, &moved_render);
    let kept: Vec<bool> = verdicts.explained.iter().map(|&e| !e).collect();
    let image = image_mean::judge(
        &mut check,
        image_mean::Side {
            mean: ours.0,
            variance: ours.1,
            samples: our_samples,
        },
        image_mean::Side {
            mean: &mitsuba.mean,
            variance: &mitsuba.variance,
            samples: mitsuba_samples,
        },
        &kept,
        verdicts.threshold,
        &|| moved_render().as_ref().ok().cloned(),
    );
    judge_deterministic(&mut check, &sides, &deterministic, &mut heat);
    check.cases = compared / 3;
    record_metrics(&mut check, &sides, &tests, &verdicts, deterministic.len());
    let pixels = (scene.width * scene.height) as f64;
    check.measure_in_both(
        [
            "compared pixel fraction",
            "összehasonlított képpontok aránya",
        ],
        compared as f64 / 3.0 / pixels,
        "",
    );
    record_power(
        &mut check,
        &sides,
        (&tests, &deterministic),
        verdicts.threshold,
        image.least_shift,
    );
    check.measure_in_both(
        [
            "mean |mean ours − mean Mitsuba|, W/(sr m²)",
            "|miénk átlaga − Mitsuba átlaga| átlaga, W/(sr m²)",
        ],
        sum / compared.max(1) as f64,
        "",
    );
    record_findings(&mut check, name, &verdicts);
    summarise_failures(&mut check);
    let figure = triptych(name, "path", scene, ours.0, &mitsuba.mean, &heat);
    Some(Compared { check, figure })
}

fn new_check(name: &str) -> Check {
    Check::new(
        &format!("renders.mitsuba.{name}.path"),
        [
            &format!("{name}: the tracer's path against Mitsuba's path integrator, per-pixel Welch t-test"),
            &format!("{name}: a sugárkövető útkövetése a Mitsuba útkövető integrátorához mérve, képpontonkénti Welch-féle t-próba"),
        ],
        [
            "Mitsuba 3 path integrator through mi.render (scalar_rgb), box filter (mitsuba_renders.json)",
            "a Mitsuba 3 útkövető integrátora ('path') az mi.render útján (scalar_rgb), dobozszűrővel (mitsuba_renders.json)",
        ],
        [&format!(
            "a pixel-channel fails when p < α/m, α = {ALPHA} over the m t-tests (Bonferroni: one correct \
             render in {:.0} fails by chance), and its means differ by more than the Whitted tolerance \
             {TOLERANCE_ABSOLUTE:e} + {TOLERANCE_RELATIVE:e} · |Mitsuba| (float32 differences, which no \
             number of samples removes); every pixel, both sides box filtered",
            1.0 / ALPHA
        ), &format!("egy képpont-csatorna hibás, ha p < α/m, α = {ALPHA} az m t-próbán (Bonferroni: {:.0} helyes képből egy véletlenül elbukik), és átlagai jobban eltérnek a Whitted-féle tűrésnél, {TOLERANCE_ABSOLUTE:e} + {TOLERANCE_RELATIVE:e} · |Mitsuba| (float32-eltérések, amelyeket semennyi minta nem tüntet el); minden képpont, mindkét oldal dobozszűrővel", 1.0 / ALPHA)],
    )
}

/// The findings of a comparison whose rejections Mitsuba's ray offsets
/// explain, an example of each, and the check's summary.
fn record_findings(check: &mut Check, name: &str, verdicts: &Verdicts) {
    if let Some([en, hu]) = &verdicts.offset_example {
        let n = verdicts.offset_findings;
        check.find([
            format!(
                "{n} pixel-channels differ significantly from Mitsuba's path integrator, each by \
                 less than Mitsuba's own ray offsets (RayEpsilon ≈ 8.9e-5 relative) move it; e.g. {en}"
            ),
            format!(
                "{n} képpont-színcsatorna szignifikánsan eltér a Mitsuba útkövető integrátorától, \
                 mindegyik kevesebbel, mint amennyivel a Mitsuba saját sugáreltolásai (RayEpsilon ≈ 8.9e-5 \
                 relatív) elmozdítják; például {hu}"
            ),
        ]);
    }
    if let Some([en, hu]) = &verdicts.rule_example {
        let n = verdicts.rule_findings;
        check.find([
            format!(
                "{n} pixel-channels differ significantly from Mitsuba's path integrator, and agree with it \
                 when the tracer starts its secondary rays as Mitsuba does, {MITSUBA_RAY_EPSILON:.3e} (1 + max |p_i|) off the \
                 surface: Mitsuba's offsets move this light; e.g. {en}"
            ),
            format!(
                "{n} képpont-színcsatorna szignifikánsan eltér a Mitsuba útkövető integrátorától, és egyezik \
                 vele, ha a sugárkövető a Mitsubához hasonlóan {MITSUBA_RAY_EPSILON:.3e} (1 + max |p_i|) távolságra \
                 indítja a másodlagos sugarait a felülettől: ezt a fényt a Mitsuba sugáreltolásai mozdítják el; például {hu}"
            ),
        ]);
    }
    check.sum_up(|c| {
        let pixels = verdicts.offset_findings + verdicts.rule_findings;
        let means = c
            .findings
            .iter()
            .filter(|f| f.en.starts_with("the image's mean"))
            .count();
        [
            format!(
                "In {name}, Mitsuba's path render departs from ours only where its own ray offsets \
                 move light: {pixels} pixel-channels and {means} of the image's mean channels, each \
                 explained by those offsets."
            ),
            format!(
                "A `{name}` jelenetben a Mitsuba útkövetéses képe csak ott tér el a miénktől, ahol \
                 a saját sugáreltolásai fényt mozdítanak el: {pixels} képpont-csatorna és a kép \
                 {means} átlagos csatornája, mindegyiket ezek az eltolások magyarázzák."
            ),
        ]
    });
}
