//! Mitsuba's renders as the sweep's second truth: where the scene is one
//! that `mitsuba_full_light.json` measured, at a size that maps onto the
//! reference's exactly, each setting's renders are box-averaged down to
//! the reference's size and held against Mitsuba's estimate of all the
//! light ([`crate::tradeoff::mitsuba`], which says what is measured
//! and why); elsewhere the record says why not.

use std::path::Path;

use crate::checkout::Checkout;
use crate::full_light::{FullLight, FILE};
use crate::tradeoff::mitsuba::{
    against, box_downsample, measure, reference_for, AgainstMitsuba, MitsubaTruth, NoReference,
    Reference,
};
use glam::DVec3;
use tracer::render::Image;
use tracer::scene::Scene;

use record::{say, Lang};

/// Mitsuba's truth for one sweep, gathered as its points are measured.
pub struct Second {
    reference: Result<Reference, NoReference>,
    /// Each point's label and renders at the reference's size.
    points: Vec<(String, Vec<Vec<DVec3>>)>,
}

impl Second {
    /// The reference for `scene` (as the sweep renders it, at its size),
    /// read from `file`'s stem and the reference of `checkout` (or why
    /// there is none: the checkout not found), or why none.
    pub fn new(scene: &Scene, file: &Path, checkout: Result<&Checkout, &str>) -> Self {
        let name = file
            .file_stem()
            .map_or_else(String::new, |s| s.to_string_lossy().into_owned());
        let reference = checkout
            .map_err(|e| NoReference::Unreadable(e.to_owned()))
            .and_then(|c| {
                let dir = c.reference_dir();
                let full =
                    FullLight::load(&dir).map_err(|e| NoReference::Unreadable(e.to_string()))?;
                reference_for(scene, &name, &full, &dir.join(FILE))
            });
        Second {
            reference,
            points: Vec::new(),
        }
    }

    /// Keeps the point's renders, box-averaged to the reference's size.
    pub fn add(&mut self, label: &str, images: &[Image]) {
        if let Ok(reference) = &self.reference {
            let small = images
                .iter()
                .map(|image| box_downsample(image, reference.factor))
                .collect();
            self.points.push((label.to_owned(), small));
        }
    }

    /// Every point and the truth against the reference, or why none; the
    /// reason kept typed for the table's words.
    pub fn finish(self, truth: &Image) -> (MitsubaTruth, Option<NoReference>) {
        match self.reference {
            Err(why) => (MitsubaTruth::NoReference(english(&why)), Some(why)),
            Ok(reference) => {
                let truth = box_downsample(truth, reference.factor);
                let points = self
                    .points
                    .iter()
                    .map(|(label, images)| against(label, images, &truth, &reference))
                    .collect();
                (
                    MitsubaTruth::Measured(measure(&reference, &truth, points)),
                    None,
                )
            }
        }
    }
}

/// A reason in English, as the record keeps it, with the flag that
/// measures a scene as Mitsuba did.
fn english(why: &NoReference) -> String {
    match why {
        NoReference::NotLambert => {
            "Mitsuba measured course_rough as Lambert: --lambert measures the scene so".to_owned()
        }
        _ => why.to_string(),
    }
}

/// A reason in Hungarian (the record keeps the English).
fn hungarian(why: &NoReference) -> String {
    match why {
        NoReference::Unreadable(detail) => format!("{FILE} nem olvasható: {detail}"),
        NoReference::Excluded { scene, why } => format!("{FILE} kihagyja: {scene}: {why}"),
        NoReference::NotMeasured { scene } => format!("{FILE} nem mérte: {scene}"),
        NoReference::SizeDoesNotMap {
            width,
            height,
            reference: (w, h),
        } => format!("{width}×{height} nem egész k·{w} × k·{h} többszöröse a referencia méretének"),
        NoReference::NotLambert => {
            "a Mitsuba a course_rough anyagot Lambertként mérte: a --lambert így mér".to_owned()
        }
        NoReference::SceneDiffers {
            backgrounds: Some((ours, theirs)),
            ..
        } => format!(
            "a jelenet nem az, amelyet a Mitsuba mért: háttere, {ours:?}, megvilágítja, a Mitsubáé {theirs:?} volt"
        ),
        NoReference::SceneDiffers { part, .. } => {
            format!("a jelenet nem az, amelyet a Mitsuba mért: eltér: {part}")
        }
        NoReference::NoRegion => {
            "a kamera nem lát diffúz felületet, ahol a Mitsuba fénykövetője az összes fényt adja"
                .to_owned()
        }
    }
}

/// The header of the measured sub-table, in words.
fn header(m: &AgainstMitsuba, lang: Lang) -> String {
    say!(
        lang,
        "against Mitsuba's {} (all the light), {} region at {}×{} ({} pixels, each the mean of {}×{} of the sweep's), {} passes of {} spp, max_depth {}: our truth carries {:.4} ± {:.4} of its light, relative RMSE {:.4} (the floor)",
        "a Mitsuba {} becslésével (az összes fény) szemben, {} tartomány {}×{} méretben ({} képpont, mindegyik a mérés {}×{} képpontjának átlaga), {} menet, menetenként {} minta, max_depth {}: saját referenciánk fényének {:.4} ± {:.4} részét hordozza, relatív RMSE {:.4} (az alsó határ)",
        m.estimate,
        m.region,
        m.width,
        m.height,
        m.pixels,
        m.factor,
        m.factor,
        m.passes,
        m.spp,
        m.max_depth,
        m.floor.light,
        m.floor.light_se,
        m.floor.rel_rmse
    )
}

/// Whether the ranking agrees, in words.
fn ranking(m: &AgainstMitsuba, lang: Lang) -> String {
    let r = &m.ranking;
    let pairs = r.concordant + r.discordant.len();
    if r.agrees() {
        return say!(
            lang,
            "ranked by relative RMSE, the settings stand in the same order under both truths ({} pairs)",
            "relatív RMSE szerint a beállítások sorrendje mindkét referenciával azonos ({} pár)",
            pairs
        );
    }
    let swapped: Vec<String> = r
        .discordant
        .iter()
        .map(|[a, b]| format!("{a} / {b}"))
        .collect();
    say!(
        lang,
        "ranked by relative RMSE, {} of {} pairs stand the other way under Mitsuba's truth: {}",
        "relatív RMSE szerint {} pár a(z) {} közül fordított sorrendben áll a Mitsuba referenciájával: {}",
        r.discordant.len(),
        pairs,
        swapped.join("; ")
    )
}

/// The terminal's lines: a short sub-table under the main one.
pub fn table(m: &MitsubaTruth, why: Option<&NoReference>, lang: Lang) -> Vec<String> {
    let m = match m {
        MitsubaTruth::NoReference(english) => {
            let words = match (lang, why) {
                (Lang::Hu, Some(why)) => hungarian(why),
                _ => english.clone(),
            };
            return vec![say!(
                lang,
                "no Mitsuba reference: {}",
                "nincs Mitsuba-referencia: {}",
                words
            )];
        }
        MitsubaTruth::Measured(m) => m,
    };
    let width = m
        .points
        .iter()
        .map(|p| p.label.chars().count())
        .max()
        .unwrap_or(7)
        .max(7);
    let mut lines = vec![
        header(m, lang),
        format!(
            "{:<width$}  {:>17}  {:>13}  {:>11}",
            lang.pick("setting", "beállítás"),
            lang.pick("light vs Mitsuba", "fény / Mitsuba"),
            "RMSE vs Mitsuba",
            lang.pick("RMSE vs ours", "RMSE / saját"),
        ),
    ];
    for p in &m.points {
        lines.push(format!(
            "{:<width$}  {:>17}  {:>15.4}  {:>12.4}",
            p.label,
            format!("{:.4} ± {:.4}", p.light, p.light_se),
            p.rel_rmse,
            p.rel_rmse_truth
        ));
    }
    lines.push(ranking(m, lang));
    lines
}

/// The Markdown sub-table of the scene's section.
pub fn markdown(m: &MitsubaTruth) -> String {
    let m = match m {
        MitsubaTruth::NoReference(why) => return format!("\nNo Mitsuba reference: {why}.\n"),
        MitsubaTruth::Measured(m) => m,
    };
    let mut out = format!(
        "\n**Against Mitsuba's truth**: {}.\n\n",
        header(m, Lang::En)
    );
    out += "| setting | light Σx/ΣM (± se, Mitsuba's passes) | rel. RMSE vs Mitsuba | rel. RMSE vs our truth, same pixels |\n";
    out += "|---|---:|---:|---:|\n";
    for p in &m.points {
        out += &format!(
            "| {} | {:.4} ± {:.4} | {:.4} | {:.4} |\n",
            p.label, p.light, p.light_se, p.rel_rmse, p.rel_rmse_truth
        );
    }
    out += &format!("\n{}.\n", capitalised(&ranking(m, Lang::En)));
    out
}

fn capitalised(text: &str) -> String {
    let mut chars = text.chars();
    chars
        .next()
        .map_or_else(String::new, |c| c.to_uppercase().chain(chars).collect())
}
