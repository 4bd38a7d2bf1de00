//! The findings of a sweep ([`Findings`]) in words, English or Hungarian:
//! the paragraph under each scene's table in `docs/tradeoffs.md` and the
//! lines after the terminal's table. Every number is the record's; the
//! decisions (what is worth it, what is seen) are the findings'.

mod light;

use super::findings::{
    Findings, MetalRgb, RgbOutcome, Schlick, Shortcut, TimingNoise, GRAZING_COS,
};
use super::mitsuba::SecondTruth;
use super::verdict::{Verdict, JUST_NOTICEABLE, WORTH_IT};
use light::{bounces, light};

use record::{say, Lang};

/// The sentences, in the order a reader asks: what to take, what not,
/// what each integrator and bounce misses, Schlick, local against
/// Whitted, the metals' colour.
pub fn sentences(f: &Findings, lang: Lang) -> Vec<String> {
    let mut out: Vec<String> = f.timing_noise.iter().map(|t| timing(t, lang)).collect();
    out.push(shortcuts(f, lang));
    out.extend(seen(f, lang));
    out.extend(no_gain(f, lang));
    out.extend(upgrades(f, lang));
    out.extend(f.light_left_out.as_ref().map(|l| light(l, lang)));
    out.extend(f.bounces.as_ref().map(|b| bounces(b, lang)));
    out.extend(f.schlick.as_ref().map(|s| schlick(s, lang)));
    out.extend(f.local_against_whitted.as_ref().map(|l| {
        if l.indistinguishable {
            say!(
                lang,
                "Local and Whitted are indistinguishable here: ΔE p99 {:.2} between their renders (≤ {}).",
                "A lokális és a Whitted-modell itt megkülönböztethetetlen: képeik között ΔE p99 {:.2} (≤ {}).",
                l.delta_e_p99,
                JUST_NOTICEABLE
            )
        } else {
            say!(
                lang,
                "Whitted can be told from local here: ΔE p99 {:.2} between their renders.",
                "A Whitted-modell itt elválik a lokálistól: képeik között ΔE p99 {:.2}.",
                l.delta_e_p99
            )
        }
    }));
    if !f.metals.is_empty() {
        out.push(metals(&f.metals, lang));
    }
    out.extend(f.mitsuba.as_ref().map(|m| second_truth(m, lang)));
    out
}

/// The truth and the scene's own settings against Mitsuba's light tracer,
/// and whether the two truths rank the settings alike.
fn second_truth(m: &SecondTruth, lang: Lang) -> String {
    let noise = if m.within_noise {
        lang.pick("within the noise", "a zajon belül")
    } else {
        lang.pick(
            "beyond the noise: the two truths differ",
            "a zajon túl: a két referencia eltér",
        )
    };
    let ranking = if m.discordant == 0 {
        say!(
            lang,
            "ranked by relative RMSE, the settings stand in the same order under both truths",
            "relatív RMSE szerint a beállítások sorrendje mindkét referenciával azonos"
        )
    } else {
        say!(
            lang,
            "ranked by relative RMSE, {} of {} pairs of settings stand the other way under Mitsuba's",
            "relatív RMSE szerint a(z) {1} beállításpárból {0} fordítva áll a Mitsubáéval",
            m.discordant,
            m.pairs
        )
    };
    say!(
        lang,
        "Against Mitsuba's light tracer, on the {} pixels that see a diffuse surface at {}×{}, the truth carries {:.4} ± {:.4} of its light ({}) and the scene's own settings {:.4}; {}.",
        "A Mitsuba fénykövetőjével szemben, a {1}×{2}-es kép {0} diffúz felületet látó képpontján a referencia annak fényéből {3:.4} ± {4:.4} részt hordoz ({5}), a jelenet saját beállításai {6:.4} részt; {7}.",
        m.pixels,
        m.size[0],
        m.size[1],
        m.truth[0],
        m.truth[1],
        noise,
        m.own[0],
        ranking
    )
}

/// The band of the run's timing noise, from renders of the scene's own
/// work.
fn timing(t: &TimingNoise, lang: Lang) -> String {
    let example = t.labels.first().map_or("", String::as_str);
    let renders = match t.labels.len() {
        1 => say!(lang, "one setting, `{}`", "egy beállítás, `{}`", example),
        n => say!(
            lang,
            "{} settings, such as `{}`",
            "{} beállítás, például `{}`",
            n,
            example
        ),
    };
    // A band whose ends print alike is one number, not "0.95× to 0.95×".
    let [low, high] = t.ratios.map(|r| format!("{r:.2}"));
    let band = if low == high {
        say!(lang, "{}×", "{}-szeresét", low)
    } else {
        say!(lang, "{}× to {}×", "{}–{}-szeresét", low, high)
    };
    say!(
        lang,
        "Renders of the scene's own work (as many rays, the same image: {}) took {} its time: this run's timing noise, so no time ratio inside that band is counted a saving or a cost.",
        "A jelenet saját munkáját végző képek (ugyanannyi sugár, ugyanaz a kép: {}) az idő {} vették: ez a futás időmérési zaja, így e sávon belüli időarány sem megtakarításnak, sem költségnek nem számít.",
        renders,
        band
    )
}

/// `label` (r× the time, ΔE p99 d).
fn item(s: &Shortcut, lang: Lang) -> String {
    say!(
        lang,
        "`{}` ({:.2}× the time, ΔE p99 {:.2})",
        "`{}` (az idő {:.2}-szerese, ΔE p99 {:.2})",
        s.label,
        s.time_ratio,
        s.delta_e_p99
    )
}

fn shortcuts(f: &Findings, lang: Lang) -> String {
    if f.worth_it.is_empty() {
        return say!(
            lang,
            "No shortcut here is both unseen (ΔE p99 ≤ {} against the scene's own render) and at most {}× its time, below the timing noise.",
            "Itt egyetlen rövidítés sem láthatatlan (ΔE p99 ≤ {} a jelenet saját képéhez képest) és egyben legfeljebb {}-szeres idejű, az időmérési zaj alatt.",
            JUST_NOTICEABLE,
            WORTH_IT
        );
    }
    let list: Vec<String> = f.worth_it.iter().map(|s| item(s, lang)).collect();
    say!(
        lang,
        "Worth it here (unseen against the scene's own render, at most {}× its time): {}.",
        "Itt megéri (a jelenet saját képéhez képest nem látszik, legfeljebb {}-szeres idő): {}.",
        WORTH_IT,
        list.join("; ")
    )
}

/// The faster settings that are seen: the least seen and the fastest.
fn seen(f: &Findings, lang: Lang) -> Option<String> {
    let fastest = f.seen.first()?;
    let least = f
        .seen
        .iter()
        .min_by(|a, b| a.delta_e_p99.total_cmp(&b.delta_e_p99))?;
    Some(if least == fastest {
        say!(
            lang,
            "Faster but seen ({}): {}.",
            "Gyorsabb, de látszik ({}): {}.",
            f.seen.len(),
            item(fastest, lang)
        )
    } else {
        say!(
            lang,
            "Faster but seen ({}): the least seen is {}, the fastest {}.",
            "Gyorsabb, de látszik ({}): a legkevésbé látható {}, a leggyorsabb {}.",
            f.seen.len(),
            item(least, lang),
            item(fastest, lang)
        )
    })
}

fn no_gain(f: &Findings, lang: Lang) -> Option<String> {
    if f.no_gain.is_empty() {
        return None;
    }
    let list: Vec<String> = f.no_gain.iter().map(|s| item(s, lang)).collect();
    Some(say!(
        lang,
        "Dearer and unseen, time that buys nothing visible: {}.",
        "Drágább és nem látszik, az idő semmi láthatót nem vesz: {}.",
        list.join("; ")
    ))
}

/// The cheapest and the nearest of the settings nearer the truth.
fn upgrades(f: &Findings, lang: Lang) -> Option<String> {
    let cheapest = f.upgrades.first()?;
    let nearest = f
        .upgrades
        .iter()
        .min_by(|a, b| a.rel_rmse.total_cmp(&b.rel_rmse))?;
    let one = |u: &crate::tradeoff::findings::Upgrade| {
        say!(
            lang,
            "`{}` at {:.2}× the time reaches {:.4} and ΔE p99 {:.2}",
            "`{}` az idő {:.2}-szereséért {:.4}-et és ΔE p99 {:.2}-t ér el",
            u.label,
            u.time_ratio,
            u.rel_rmse,
            u.delta_e_p99
        )
    };
    let list = if cheapest == nearest {
        one(cheapest)
    } else {
        format!("{}; {}", one(cheapest), one(nearest))
    };
    Some(say!(
        lang,
        "Nearer the truth than the scene's own settings (relative RMSE {:.4}, ΔE p99 {:.2}): {}.",
        "Közelebb a referenciához, mint a jelenet saját beállításai (relatív RMSE {:.4}, ΔE p99 {:.2}): {}.",
        f.own.rel_rmse,
        f.own.delta_e_p99,
        list
    ))
}

fn verdict(v: Verdict, lang: Lang) -> &'static str {
    match v {
        Verdict::WorthIt => lang.pick("worth it", "megéri"),
        Verdict::Unseen => lang.pick("not seen, no faster", "nem látszik, nem gyorsabb"),
        Verdict::Trade => lang.pick("faster, seen", "gyorsabb, látszik"),
        Verdict::Worse => lang.pick("seen, no faster", "látszik, nem gyorsabb"),
    }
}

fn schlick(s: &Schlick, lang: Lang) -> String {
    let grazing = match &s.grazing {
        Some(g) => say!(
            lang,
            "over the {} pixels whose centre first meets a mirror or glass at a cosine below {}: ΔE mean {:.2}, p99 {:.2}, relative RMSE {:.4}",
            "azon {} képponton, amelyek középpontja először tükröt vagy üveget ér {} alatti koszinusszal: ΔE átlag {:.2}, p99 {:.2}, relatív RMSE {:.4}",
            g.pixels,
            GRAZING_COS,
            g.delta_e_mean,
            g.delta_e_p99,
            g.rel_rmse
        ),
        None => say!(
            lang,
            "no pixel's centre first meets a mirror or glass at a cosine below {}",
            "egyetlen képpont középpontja sem ér először tükröt vagy üveget {} alatti koszinusszal",
            GRAZING_COS
        ),
    };
    say!(
        lang,
        "Schlick's law for the exact one: {:.2}× the time, ΔE p99 {:.2} against the exact law's render ({}), relative RMSE from the truth {:.4} → {:.4}; {}.",
        "Schlick-közelítés a pontos törvény helyett: az idő {:.2}-szerese, ΔE p99 {:.2} a pontos törvény képéhez képest ({}), relatív RMSE a referenciától {:.4} → {:.4}; {}.",
        s.shortcut.time_ratio,
        s.shortcut.delta_e_p99,
        verdict(s.verdict, lang),
        s.rel_rmse[0],
        s.rel_rmse[1],
        grazing
    )
}

fn metals(metals: &[MetalRgb], lang: Lang) -> String {
    let items: Vec<String> = metals
        .iter()
        .map(|m| match &m.outcome {
            RgbOutcome::Measured { angles_deg, delta_e } => {
                let normal = angles_deg
                    .iter()
                    .position(|&a| a == 0.0)
                    .map_or(f64::NAN, |i| delta_e[i]);
                let (worst, at) = m.outcome.worst().unwrap_or((f64::NAN, f64::NAN));
                let last = angles_deg.last().copied().unwrap_or(f64::NAN);
                if at == 0.0 {
                    say!(
                        lang,
                        "`{}` in three channels is ΔE2000 {:.2} from its measured spectrum at normal incidence, its most over 0°–{}°",
                        "a(z) `{}` három csatornán merőleges beesésnél ΔE2000 {:.2}-re van mért spektrumától, ez a legtöbb 0° és {}° között",
                        m.material,
                        normal,
                        last
                    )
                } else {
                    say!(
                        lang,
                        "`{}` in three channels is ΔE2000 {:.2} from its measured spectrum at normal incidence and {:.2} at {}°, its most over 0°–{}°",
                        "a(z) `{0}` három csatornán merőleges beesésnél ΔE2000 {1:.2}-re van mért spektrumától, {3}°-nál {2:.2}-re, ez a legtöbb 0° és {4}° között",
                        m.material,
                        normal,
                        worst,
                        at,
                        last
                    )
                }
            }
            RgbOutcome::NoReference { detail } => say!(
                lang,
                "`{}` not measured: the harness's metals.json could not be read ({})",
                "a(z) `{}` nincs mérve: a mérőcsomag metals.json fájlja nem olvasható ({})",
                m.material,
                detail
            ),
            RgbOutcome::NoSpectrum => say!(
                lang,
                "`{}` not measured: metals.json has no measured spectrum of that name over 360–780 nm",
                "a(z) `{}` nincs mérve: a metals.json-ban nincs ilyen nevű mért spektrum 360–780 nm-en",
                m.material
            ),
        })
        .collect();
    say!(
        lang,
        "RGB against a spectrum, by the harness's measure (`optics validate`'s metals.*; the image itself has no spectral truth yet): {}.",
        "RGB a spektrummal szemben, a mérőcsomag mércéjével (az `optics validate` metals.* ellenőrzései; magának a képnek még nincs spektrális referenciája): {}.",
        items.join("; ")
    )
}

#[cfg(test)]
mod tests;
