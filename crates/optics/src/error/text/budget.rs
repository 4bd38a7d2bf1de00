//! `optics render --tolerance` that cannot render within its tolerance,
//! in both languages: one exhaustive `match` over the budget's kinds, and
//! one over what a candidate that misses would need.

use record::{say, Lang};
use validation::tradeoff::budget::{written, Need};
use validation::tradeoff::error::BudgetError;

/// A budget refused, in `lang`.
pub(super) fn budget(error: &BudgetError, lang: Lang) -> String {
    match error {
        BudgetError::Unreachable {
            metric,
            tolerance,
            best,
            settings,
            top_spp,
            need,
        } => {
            let tolerance = written(*tolerance);
            let need = need_text(*need, *top_spp, lang);
            say!(
                lang,
                "--tolerance {tolerance}: cannot reach {metric} {tolerance}; the best is {metric} ≤ {best:.4}, with {settings}; {need}",
                "--tolerance {tolerance}: a(z) {metric} {tolerance} nem érhető el; a legjobb {metric} ≤ {best:.4}, ezzel: {settings}; {need}"
            )
        }
        BudgetError::PilotNoisy { pilot_spp } => say!(
            lang,
            "--pilot-spp {pilot_spp}: the pilot cannot tell the light on the surfaces from its noise (its energy, three standard deviations down, is not above 0), so no relative error can be predicted; the scene may be black, or its light may grow with depth (course_rough's albedo π kd above 1: give --lambert to measure it with the stand-in `optics tradeoff --lambert` uses); try more pilot samples",
            "--pilot-spp {pilot_spp}: a próba nem tudja elválasztani a felületek fényét a zajától (energiája három szórásnyival lejjebb nem nagyobb 0-nál), így relatív hiba nem becsülhető; a jelenet lehet fekete, vagy fénye nőhet a mélységgel (a course_rough π kd albedója 1 fölött: a --lambert az `optics tradeoff --lambert` helyettesítőjével mér); próbálj több próbamintát"
        ),
        BudgetError::EnergyGain { material, gain } => say!(
            lang,
            "--lambert: material \"{material}\" reflects {gain:.2} times the light it receives (course_rough's albedo π kd), so its light grows with every bounce, no ground truth converges and no error can be bounded; give --lambert to budget the scene with the stand-in `optics tradeoff --lambert` uses",
            "--lambert: a(z) \"{material}\" anyag {gain:.2}-szer annyi fényt ver vissza, mint amennyit kap (a course_rough π kd albedója), így fénye minden visszaverődéssel nő, nincs konvergáló referencia és a hiba nem korlátozható; a --lambert az `optics tradeoff --lambert` helyettesítőjével számol"
        ),
    }
}

/// What the best candidate would need to reach the tolerance, given the
/// most samples per pixel the budget renders (`None`: it renders none).
fn need_text(need: Need, top_spp: Option<u32>, lang: Lang) -> String {
    match (need, top_spp) {
        (Need::Samples { spp }, Some(top)) => say!(
            lang,
            "it would need 2^{} = {spp} spp (a power of two, as the budget renders), past the most it renders, {top} spp",
            "2^{} = {spp} minta kellene képpontonként (kettőhatvány, ahogy a költségvetés renderel), több, mint a legtöbb, amennyivel renderel, {top}",
            spp.trailing_zeros()
        ),
        (Need::Capped { spp }, _) => say!(
            lang,
            "more samples cannot reach it: its noise stops falling past {spp} spp, where its caustic map has its most photons",
            "több minta sem éri el: a zaja {spp} minta fölött már nem csökken, ott a kausztikus térkép fotonjai a legtöbbek"
        ),
        (Need::Floor, _) => say!(
            lang,
            "no number of samples reaches it: its floor, the bias with the pilot's noise and the ground truth's, is above it (more --pilot-spp lowers the pilot's part)",
            "semennyi minta nem éri el: már az alsó határa, a torzítás a próba és a referencia zajával együtt, fölötte van (több --pilot-spp a próba részét csökkenti)"
        ),
        (Need::Never | Need::Samples { .. }, _) => say!(
            lang,
            "no number of samples reaches it: the bias alone is above it",
            "semennyi minta nem éri el: már a torzítás maga fölötte van"
        ),
    }
}
