//! The areas of `report.html`, in the order of its first screen, and the
//! checks and figures each claims.

use crate::check::Check;
use crate::report::Report;

/// The areas of the report, in the order of its first screen: a title, the
/// check ids it gathers (by prefix; the first area that claims a check
/// keeps it), and the figures that say it best (file-name prefixes).
const AREAS: [Area; 9] = [
    Area {
        key: "mpmath",
        title: "Laws against 50-digit mpmath",
        checks: &["laws.mpmath."],
        figures: &["fresnel_errors"],
        headline: None,
    },
    Area {
        key: "mitsuba-laws",
        title: "Laws against Mitsuba 3",
        checks: &["laws.mitsuba."],
        figures: &["fresnel_curves"],
        headline: None,
    },
    Area {
        key: "metals",
        title: "Metals: spectra and colour",
        checks: &["colour.colour-science.metals"],
        figures: &["metal_swatches", "metal_delta_e", "metal_spectra"],
        headline: Some("reflectance: max |ours − exact|"),
    },
    Area {
        key: "colour",
        title: "Colour against colour-science",
        checks: &["colour."],
        figures: &[],
        headline: Some("CIELAB: max |ours − colour-science|"),
    },
    Area {
        key: "renders",
        title: "Renders against Mitsuba 3",
        checks: &["renders."],
        figures: &["render_kaleidoscope_lit_path", "render_"],
        headline: Some("|ours − Mitsuba| / tolerance"),
    },
    Area {
        key: "images",
        title: "ꟻLIP against NVIDIA's evaluator",
        checks: &["images."],
        figures: &[],
        headline: Some("mean: |ours − NVIDIA|"),
    },
    Area {
        key: "full-light",
        title: "All the light",
        checks: &["full_light."],
        figures: &[],
        headline: Some("Mitsuba path's missing share, surface"),
    },
    Area {
        key: "techniques",
        title: "The slides' techniques against the exact answers",
        checks: &["techniques."],
        figures: &["techniques"],
        headline: Some("into water, c = 1: angle from Snell's law (°)"),
    },
    Area {
        key: "tradeoff",
        title: "The speed/accuracy trade, whole renders",
        checks: &["tradeoff."],
        figures: &["tradeoff_kaleidoscope_lit", "tradeoff_"],
        headline: Some("the scene's own settings: relative RMSE from all the light"),
    },
];

/// One area of the report.
pub(super) struct Area {
    pub(super) key: &'static str,
    pub(super) title: &'static str,
    pub(super) checks: &'static [&'static str],
    pub(super) figures: &'static [&'static str],
    /// The quantity whose worst value heads the card; `None`: the worst
    /// Fresnel error in ulps.
    pub(super) headline: Option<&'static str>,
}

/// An area with the checks and figures it claimed.
pub(super) struct Gathered<'a> {
    pub(super) area: &'static Area,
    /// Each check with its index in [`Report::checks`].
    pub(super) checks: Vec<(usize, &'a Check)>,
    pub(super) figures: Vec<&'a String>,
}

pub(super) fn gather<'a>(report: &'a Report, figures: &'a [String]) -> Vec<Gathered<'a>> {
    let mut areas: Vec<Gathered> = AREAS
        .iter()
        .map(|area| Gathered {
            area,
            checks: Vec::new(),
            figures: Vec::new(),
        })
        .collect();
    let mut other = Vec::new();
    for check in report.checks.iter().enumerate() {
        match areas
            .iter_mut()
            .find(|a| a.area.checks.iter().any(|p| check.1.id.starts_with(p)))
        {
            Some(area) => area.checks.push(check),
            None => other.push(check),
        }
    }
    for area in &mut areas {
        for prefix in area.area.figures {
            let file = |f: &&String| f.rsplit('/').next().unwrap_or(f).starts_with(prefix);
            for f in figures.iter().filter(file) {
                if !area.figures.contains(&f) {
                    area.figures.push(f);
                }
            }
        }
    }
    areas.retain(|a| !a.checks.is_empty());
    if !other.is_empty() {
        static OTHER: Area = Area {
            key: "other",
            title: "Other checks",
            checks: &[],
            figures: &[],
            headline: None,
        };
        areas.push(Gathered {
            area: &OTHER,
            checks: other,
            figures: Vec::new(),
        });
    }
    areas
}
