//! The light a sweep's integrators and bounce limits leave out, in words.

use crate::tradeoff::findings::{Bounces, LightLeftOut};
use crate::tradeoff::verdict::JUST_NOTICEABLE;
use record::{say, Lang};

/// A share as a percentage: two decimals, or two significant digits
/// below 1 %.
fn percent(share: f64) -> String {
    let p = 100.0 * share;
    if p == 0.0 || p.abs() >= 1.0 || !p.is_finite() {
        return format!("{p:.2} %");
    }
    let decimals = (1 - p.abs().log10().floor() as i32).clamp(2, 8) as usize;
    format!("{p:.decimals$} %")
}

pub(super) fn light(l: &LightLeftOut, lang: Lang) -> String {
    let photon = l.integrators.iter().any(|i| i.integrator == "photon");
    let items: Vec<String> = l
        .integrators
        .iter()
        .enumerate()
        .map(|(k, i)| {
            let mut notes = Vec::new();
            if k == 0 {
                notes.push(lang.pick("the scene's own", "a jelenet sajátja").to_owned());
            }
            if photon && i.integrator == "path" {
                notes.push(
                    lang.pick("no caustic map", "kausztikus térkép nélkül")
                        .to_owned(),
                );
            }
            if i.within_noise {
                notes.push(lang.pick("within the noise", "a zajon belül").to_owned());
            } else if i.left_out < 0.0 {
                notes.push(
                    lang.pick(
                        "more light than the truth",
                        "több fény, mint a referenciában",
                    )
                    .to_owned(),
                );
            }
            let notes = if notes.is_empty() {
                String::new()
            } else {
                format!(" ({})", notes.join(", "))
            };
            format!("`{}` {}{notes}", i.integrator, percent(i.left_out))
        })
        .collect();
    say!(
        lang,
        "Light left out at the scene's max_depth {}, 1 − Σx/Σt over the surface pixels (the truth's own noise ±{}; within the noise: within two standard deviations of the truth's and the render's own): {}.",
        "A kimaradó fény a jelenet saját max_depth {} korlátjával, 1 − Σx/Σt a felületi képpontokon (a referencia saját zaja ±{}; a zajon belül: a referencia és a kép saját zajának két szórásán belül): {}.",
        l.max_depth,
        percent(l.truth_noise),
        items.join(", ")
    )
}

pub(super) fn bounces(b: &Bounces, lang: Lang) -> String {
    let depths: Vec<String> = b.light.iter().map(|(d, _)| d.to_string()).collect();
    let shares: Vec<String> = b
        .light
        .iter()
        .map(|(_, l)| format!("{:.2}", 100.0 * l))
        .collect();
    let mut text = say!(
        lang,
        "The light carried at max_depth {}: {} % of the truth's.",
        "A max_depth {} mellett átvitt fény: a referencia {} %-a.",
        depths.join(", "),
        shares.join(", ")
    );
    let into = b.steps.iter().find(|s| s.to == b.own);
    let past = b.steps.iter().find(|s| s.from == b.own);
    for step in into.into_iter().chain(past) {
        let seen = step.delta_e_p99.map_or("", |d| {
            if d <= JUST_NOTICEABLE {
                lang.pick("not seen", "nem látszik")
            } else {
                lang.pick("seen", "látszik")
            }
        });
        text += " ";
        text += &say!(
            lang,
            "From {} to {} bounces{}: {} more light, relative RMSE {:.4} → {:.4}, ΔE p99 {:.2} between the two renders ({}).",
            "{} helyett {} pattanás{}: {} több fény, relatív RMSE {:.4} → {:.4}, a két kép között ΔE p99 {:.2} ({}).",
            step.from,
            step.to,
            if step.to == b.own {
                lang.pick(" (the scene's own)", " (a jelenet sajátja)")
            } else {
                ""
            },
            percent(step.light_added),
            step.rel_rmse_from,
            step.rel_rmse_to,
            step.delta_e_p99.unwrap_or(f64::NAN),
            seen
        );
    }
    text += " ";
    text += &match b.enough {
        Some(depth) => say!(
            lang,
            "From max_depth {} on, every render is within ΔE p99 {} of the scene's own.",
            "max_depth {}-től minden kép ΔE p99 {}-en belül van a jelenet sajátjától.",
            depth,
            JUST_NOTICEABLE
        ),
        None => say!(
            lang,
            "A limit deeper than the scene's own {} is still seen.",
            "A jelenet saját {} korlátjánál mélyebb korlát még látszik.",
            b.own
        ),
    };
    text
}
