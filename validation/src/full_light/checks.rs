//! The checks of all the light: Mitsuba's two full-light estimates against
//! each other, the missing share per scene, and a tracer render against the
//! estimate it claims to match.

use super::estimates::{Estimate, Region};
use super::reference::DecodedLight;
use super::statistics::{share, RegionMean};
use super::thresholds::{
    missing_share_tolerance, tolerance_text, ALPHA, FINDING_RELATIVE, POWER, TOLERANCE_RELATIVE,
};
use crate::case_words;
use crate::check::Check;

/// A tracer render as the checks read it: per-pixel mean and unbiased
/// variance of one sample (`3 · width · height` each, RGB) over `samples`
/// independent samples per pixel.
#[derive(Clone, Copy, Debug)]
pub struct TracerRender<'a> {
    /// Per-pixel mean.
    pub mean: &'a [f64],
    /// Per-pixel variance of one sample.
    pub variance: &'a [f64],
    /// Samples per pixel.
    pub samples: u32,
}

const CHANNEL: [&str; 3] = ["R", "G", "B"];

/// Whether an object of the scene is a mirror, a conductor or glass.
pub(super) fn has_delta_surface(scene: &tracer::scene::Scene) -> bool {
    scene
        .objects
        .iter()
        .any(|o| scene.materials[o.material() as usize].is_specular())
}

/// A region's mean over the channels' sum, from an estimate's passes.
fn summed(decoded: &DecodedLight, estimate: Estimate, region: Region) -> Option<RegionMean> {
    let passes = decoded.passes.get(&(estimate, region))?;
    Some(RegionMean::from_passes(
        passes.iter().map(|p| p.iter().sum()),
    ))
}

fn per_channel(
    decoded: &DecodedLight,
    estimate: Estimate,
    region: Region,
    c: usize,
) -> Option<RegionMean> {
    let passes = decoded.passes.get(&(estimate, region))?;
    Some(RegionMean::from_passes(passes.iter().map(|p| p[c])))
}

/// The light tracer against the area lights on the `diffuse` region: two
/// independent estimates of all the light, which must agree within their
/// noise (Welch's t on the channels' sum, p ≥ α). `None` where the camera
/// sees no diffuse surface directly.
pub fn check_independent(name: &str, decoded: &DecodedLight) -> Option<Check> {
    let ptracer = summed(decoded, Estimate::Ptracer, Region::Diffuse)?;
    let area = summed(decoded, Estimate::Area, Region::Diffuse)?;
    let mut check = Check::new(
        &format!("full_light.mitsuba.{name}.independent"),
        [
            &format!("{name}: Mitsuba's light tracer against its path tracer with area lights, where the camera sees a diffuse surface"),
            &format!("{name}: a Mitsuba fénykövetője az útkövetőjéhez mérve felületi fényforrásokkal, ahol a kamera diffúz felületet lát"),
        ],
        [
            "Mitsuba 3 ptracer and path (scalar_rgb), mitsuba_full_light.json",
            "a Mitsuba 3 fénykövetője ('ptracer') és útkövetője ('path', scalar_rgb), mitsuba_full_light.json",
        ],
        [&format!("Welch's t on the region's mean per pass (R + G + B): fails when p < α = {ALPHA}"), &format!("Welch-féle t a tartomány átlagára menetenként (R + G + B): hibás, ha p < α = {ALPHA}")],
    );
    check.cases = 1;
    let detectable = ptracer.detectable_difference(area, ALPHA, POWER) / area.0.mean;
    check.measure_in_both(
        [
            &format!("smallest detectable difference (power {POWER}), share of all the light"),
            &format!(
                "a legkisebb kimutatható eltérés (próbaerő {POWER}), az összes fény arányában"
            ),
        ],
        detectable,
        "",
    );
    check.measure_in_both(
        ["ptracer / area", "fénykövetés / felületi fények"],
        ptracer.0.mean / area.0.mean,
        "",
    );
    if let Some(w) = ptracer.welch(area) {
        check.measure_in_both(["|t|", "|t|"], w.t.abs(), "");
        if w.p < ALPHA {
            check.fail(format!(
                "ptracer {:.6} ± {:.6}, area {:.6} ± {:.6}: t = {:.2}, p = {:.2e} < {ALPHA}",
                ptracer.0.mean,
                ptracer.standard_error(),
                area.0.mean,
                area.standard_error(),
                w.t,
                w.p
            ));
        }
    }
    Some(check)
}

/// The share of the light Mitsuba's `path` misses, per region and full-light
/// estimate. A scene without delta surfaces misses nothing: there every
/// share must be zero within its noise (Welch's t, p ≥ α / tests).
pub fn check_missing_share(name: &str, decoded: &DecodedLight) -> Check {
    let control = !has_delta_surface(&decoded.scene);
    let mut check = Check::new(
        &format!("full_light.mitsuba.{name}.missing_share"),
        [
            &format!("{name}: the share of the light Mitsuba's path integrator misses, 1 − path / full"),
            &format!("{name}: a fény része, amelyet a Mitsuba útkövető integrátora nem talál meg, 1 − út / teljes"),
        ],
        [
            "Mitsuba 3 ptracer and path with area lights (scalar_rgb), mitsuba_full_light.json",
            "a Mitsuba 3 fénykövetője ('ptracer') és útkövetője ('path') felületi fényforrásokkal (scalar_rgb), mitsuba_full_light.json",
        ],
        missing_share_tolerance(control).each_ref().map(String::as_str),
    );
    let pairs: Vec<(Region, Estimate)> = Region::ALL
        .iter()
        .flat_map(|&r| r.full_light().iter().map(move |&e| (r, e)))
        .filter(|&(r, e)| decoded.passes.contains_key(&(e, r)))
        .collect();
    for &(region, estimate) in &pairs {
        let (Some(path), Some(full)) = (
            summed(decoded, Estimate::Path, region),
            summed(decoded, estimate, region),
        ) else {
            continue;
        };
        check.cases += 1;
        let s = share(path, full);
        let ([region_en, region_hu], [estimate_en, estimate_hu]) =
            (region.names(), estimate.names());
        let at = format!("{region_en} against {estimate_en}");
        let at_hu = format!("{region_hu}; viszonyítás: {estimate_hu}");
        let share_names = [
            format!("missing share, {at}"),
            format!("hiányzó arány, {at_hu}"),
        ];
        check.measure_in_both([&share_names[0], &share_names[1]], s.share, "");
        let error_names = [
            format!("its standard error, {at}"),
            format!("középhibája, {at_hu}"),
        ];
        check.measure_in_both([&error_names[0], &error_names[1]], s.standard_error, "");
        let Some(w) = path.welch(full) else { continue };
        if control && w.p < ALPHA / pairs.len() as f64 {
            check.fail(format!(
                "{at}: a scene without delta surfaces misses {:.4} ± {:.4} of the light (t = {:.2}, p = {:.2e})",
                s.share, s.standard_error, w.t, w.p
            ));
        }
    }
    check
}

/// A tracer render of an integrator that claims all the light (`integrator`
/// names it), against Mitsuba's full-light estimates: per region and
/// channel, Welch's t, failing where p < α / tests and the means differ by
/// more than [`TOLERANCE_RELATIVE`] and what Mitsuba's box filter moves
/// that region's mean. The tracer's `path` fails it
/// wherever a delta light reaches a diffuse surface through a delta surface.
pub fn check_all_the_light(
    name: &str,
    integrator: &str,
    decoded: &DecodedLight,
    ours: TracerRender,
) -> Check {
    check_all_the_light_in(name, integrator, decoded, ours, &Region::ALL)
}

/// [`check_all_the_light`] over `regions` only.
pub fn check_all_the_light_in(
    name: &str,
    integrator: &str,
    decoded: &DecodedLight,
    ours: TracerRender,
    regions: &[Region],
) -> Check {
    let mut check = Check::new(
        &format!("full_light.tracer.{name}.{integrator}.all_the_light"),
        [
            &format!("{name}: the tracer's {integrator} against all the light (Mitsuba's light tracer and area lights)"),
            &format!("{name}: a sugárkövető {integrator} integrátora az összes fényhez mérve (a Mitsuba fénykövetője és felületi fényforrások)"),
        ],
        [
            "Mitsuba 3 ptracer and path with area lights (scalar_rgb), mitsuba_full_light.json",
            "a Mitsuba 3 fénykövetője ('ptracer') és útkövetője ('path') felületi fényforrásokkal (scalar_rgb), mitsuba_full_light.json",
        ],
        tolerance_text().each_ref().map(String::as_str),
    );
    let pairs: Vec<(Region, Estimate)> = regions
        .iter()
        .flat_map(|&r| r.full_light().iter().map(move |&e| (r, e)))
        .collect();
    for &(region, estimate) in &pairs {
        compare(
            &mut check,
            decoded,
            (estimate, region),
            ours,
            3 * pairs.len(),
        );
    }
    check.sum_up(beyond_the_allowance);
    check
}

/// A tracer render of an integrator that, like Mitsuba's `path`, misses the
/// light of delta lights through delta surfaces, against Mitsuba's `path`
/// on the same scene, through the same pixel centres: both must miss the
/// same share.
pub fn check_same_missing_light(
    name: &str,
    integrator: &str,
    decoded: &DecodedLight,
    ours: TracerRender,
) -> Check {
    let mut check = Check::new(
        &format!("full_light.tracer.{name}.{integrator}.missing_share"),
        [
            &format!("{name}: the tracer's {integrator} misses what Mitsuba's path misses"),
            &format!("{name}: a sugárkövető {integrator} integrátora ugyanazt nem találja meg, amit a Mitsuba útkövetője"),
        ],
        [
            "Mitsuba 3 path (scalar_rgb), mitsuba_full_light.json",
            "a Mitsuba 3 útkövetője ('path', scalar_rgb), mitsuba_full_light.json",
        ],
        tolerance_text().each_ref().map(String::as_str),
    );
    for region in Region::ALL {
        let tests = 3 * Region::ALL.len();
        compare(
            &mut check,
            decoded,
            (Estimate::PathCentres, region),
            ours,
            tests,
        );
    }
    if let (Some(path), Some(area)) = (
        summed(decoded, Estimate::Path, Region::Surface),
        summed(decoded, Estimate::Area, Region::Surface),
    ) {
        check.measure_in_both(
            [
                "Mitsuba path's missing share, surface",
                "a Mitsuba útkövetésének hiányzó aránya, felület",
            ],
            share(path, area).share,
            "",
        );
    }
    check.sum_up(beyond_the_allowance);
    check
}

/// The findings of a comparison of region means in one sentence: the
/// largest relative difference, significant but within the finding's
/// margin past the allowance.
fn beyond_the_allowance(check: &Check) -> [String; 2] {
    match check.worst("|ours − Mitsuba| / Mitsuba") {
        Some(m) => {
            let (worst, allowed, more) = (
                100.0 * m.worst,
                100.0 * TOLERANCE_RELATIVE,
                100.0 * FINDING_RELATIVE,
            );
            [
                format!(
                    "Mitsuba's estimate and ours differ significantly by up to {worst:.2} %, at {}: \
                     past the {allowed} % allowance by less than {more} %, so reported, not failed.",
                    m.at
                ),
                format!(
                    "A Mitsuba becslése és a miénk szignifikánsan eltér, legfeljebb {worst:.2} %-kal, \
                     itt: `{}`; a {allowed} %-os engedményt kevesebb mint {more} %-kal lépi túl, \
                     ezért jelentjük, de nem számít kudarcnak.",
                    m.at
                ),
            ]
        }
        None => [
            "Mitsuba's estimate and ours differ significantly.".to_owned(),
            "A Mitsuba becslése és a miénk szignifikánsan eltér.".to_owned(),
        ],
    }
}

/// The largest relative shift of a region's mean by Mitsuba's box filter,
/// over the regions and channels (see [`TOLERANCE_RELATIVE`]).
pub fn box_filter_shift(decoded: &DecodedLight) -> f64 {
    Region::ALL
        .iter()
        .flat_map(|&r| (0..3).map(move |c| (r, c)))
        .map(|(r, c)| filter_shift(decoded, Estimate::Path, r, c))
        .fold(0.0, f64::max)
}

/// What Mitsuba's box filter moves a region's mean in one channel,
/// relative: `|path − path_centres| / path`; zero for the centres themselves.
fn filter_shift(decoded: &DecodedLight, estimate: Estimate, region: Region, c: usize) -> f64 {
    // The estimate compared through the pixel centres has no shift to allow.
    if estimate == Estimate::PathCentres {
        return 0.0;
    }
    match (
        per_channel(decoded, Estimate::Path, region, c),
        per_channel(decoded, Estimate::PathCentres, region, c),
    ) {
        (Some(b), Some(p)) => (b.0.mean - p.0.mean).abs() / b.0.mean.abs(),
        _ => 0.0,
    }
}

fn compare(
    check: &mut Check,
    decoded: &DecodedLight,
    (estimate, region): (Estimate, Region),
    ours: TracerRender,
    tests: usize,
) {
    let threshold = ALPHA / tests as f64;
    for (c, channel) in CHANNEL.iter().enumerate() {
        let Some(reference) = per_channel(decoded, estimate, region, c) else {
            continue;
        };
        let mine = RegionMean::from_pixels(
            ours.mean,
            ours.variance,
            &decoded.masks[&region],
            c,
            ours.samples,
        );
        check.cases += 1;
        let at = format!("{} {channel} against {}", region.name(), estimate.name());
        let relative = (mine.0.mean - reference.0.mean).abs() / reference.0.mean.abs();
        let allowance = TOLERANCE_RELATIVE + filter_shift(decoded, estimate, region, c);
        check.measure_in_both(
            ["|ours − Mitsuba| / Mitsuba", "|miénk − Mitsuba| / Mitsuba"],
            relative,
            &at,
        );
        check.measure_in_both(
            [
                "allowed |ours − Mitsuba| / Mitsuba",
                "megengedett |miénk − Mitsuba| / Mitsuba",
            ],
            allowance,
            &at,
        );
        check.measure_in_both(
            [
                &format!("smallest detectable relative difference (power {POWER})"),
                &format!("a legkisebb kimutatható relatív eltérés (próbaerő {POWER})"),
            ],
            mine.detectable_difference(reference, threshold, POWER) / reference.0.mean.abs(),
            &at,
        );
        let Some(w) = mine.welch(reference) else {
            continue;
        };
        check.measure_in_both(["|t|", "|t|"], w.t.abs(), &at);
        if w.p < threshold && relative > allowance {
            let (ours, theirs) = (mine.0.mean, reference.0.mean);
            let (ours_se, theirs_se) = (mine.standard_error(), reference.standard_error());
            let message = format!(
                "{at}: ours {ours:.6} ± {ours_se:.6}, Mitsuba {theirs:.6} ± {theirs_se:.6} (t = {:.2}, p = {:.2e} < {threshold:.2e}): \
                 ours is {:.4} of it",
                w.t,
                w.p,
                ours / theirs
            );
            if relative <= allowance + FINDING_RELATIVE {
                let at_hu = case_words::in_hungarian(&at);
                check.find([
                    format!("{message}, within {FINDING_RELATIVE} beyond the allowance"),
                    format!(
                        "{at_hu}: a miénk {ours:.6} ± {ours_se:.6}, a Mitsubáé {theirs:.6} ± {theirs_se:.6} (t = {:.2}, p = {:.2e} < {threshold:.2e}): \
                         a miénk annak {:.4}-szerese, legfeljebb {FINDING_RELATIVE} eltéréssel a ráhagyáson túl",
                        w.t,
                        w.p,
                        ours / theirs
                    ),
                ]);
            } else {
                check.fail(message);
            }
        }
    }
}
