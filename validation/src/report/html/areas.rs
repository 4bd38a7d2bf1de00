//! The areas of `report.html`, in the order of its first screen, and the
//! checks and figures each claims.

use crate::check::Check;
use crate::report::document::Report;

/// The areas of the report, in the order of its first screen: a title, the
/// check ids it gathers (by prefix; the first area that claims a check
/// keeps it), the figures that say it best (file-name prefixes), and its
/// card's headline: what its worst number means, and whose defect it is.
const AREAS: [Area; 9] = [
    Area {
        key: "mpmath",
        title: [
            "Laws against 50-digit mpmath",
            "A törvények az 50 jegyű mpmath-hoz mérve",
        ],
        checks: &["laws.mpmath."],
        figures: &["fresnel_errors"],
        headline: Some(Headline {
            quantity: None,
            says: [
                "Our Fresnel laws stay within {} ulps of the 50-digit exact values, \
                 in f64 and in f32: the suite's own rounding.",
                "Fresnel-egyenleteink f64-ben és f32-ben is legfeljebb {} ulp-re térnek el \
                 az 50 jegyű pontos értékektől: ez a csomag saját kerekítése.",
            ],
        }),
    },
    Area {
        key: "mitsuba-laws",
        title: [
            "Laws against Mitsuba 3",
            "A törvények a Mitsuba 3-hoz mérve",
        ],
        checks: &["laws.mitsuba."],
        figures: &["fresnel_curves"],
        headline: Some(Headline {
            quantity: None,
            says: [
                "Our float32 Fresnel laws lie within {} ulps of the exact law on every case \
                 Mitsuba 3 was given; where Mitsuba's own float32 departs, the findings below say.",
                "Float32 Fresnel-egyenleteink a Mitsuba 3-nak adott minden esetben legfeljebb {} \
                 ulp-re térnek el a pontos törvénytől; ahol a Mitsuba saját float32 számítása tér \
                 el, azt a lenti megállapítások mondják el.",
            ],
        }),
    },
    Area {
        key: "metals",
        title: ["Metals: spectra and colour", "Fémek: spektrum és szín"],
        checks: &["colour.colour-science.metals"],
        figures: &["metal_swatches", "metal_delta_e", "metal_spectra"],
        headline: Some(Headline {
            quantity: Some("reflectance: max |ours − exact|"),
            says: [
                "Our metal reflectance spectra agree with the exact law to {}, rounding alone; \
                 what the course's shortcuts do to the colours, the table below shows.",
                "Fémjeink visszaverődési spektruma legfeljebb {} eltéréssel egyezik a pontos \
                 törvénnyel, ez csak kerekítés; hogy a kurzus rövidítései mit tesznek a \
                 színekkel, az alábbi táblázat mutatja.",
            ],
        }),
    },
    Area {
        key: "colour",
        title: [
            "Colour against colour-science",
            "A színek a colour-science-hez mérve",
        ],
        checks: &["colour."],
        figures: &[],
        headline: Some(Headline {
            quantity: Some("CIELAB: max |ours − colour-science|"),
            says: [
                "Our colours agree with colour-science to {} in CIELAB: rounding, \
                 no defect on either side.",
                "Színeink CIELAB-ban legfeljebb {} eltéréssel egyeznek a colour-science \
                 színeivel: kerekítés, egyik oldal sem hibás.",
            ],
        }),
    },
    Area {
        key: "renders",
        title: [
            "Renders against Mitsuba 3",
            "A renderelt képek a Mitsuba 3-hoz mérve",
        ],
        checks: &["renders."],
        figures: &["render_kaleidoscope_lit_path", "render_"],
        headline: Some(Headline {
            quantity: Some("|ours − Mitsuba| / tolerance"),
            says: [
                "Our Whitted renders differ from Mitsuba 3's by at most {} of what a pixel may \
                 differ (1 would fail): neither renderer is at fault.",
                "Whitted-féle képeink képpontonként legfeljebb a megengedett eltérés {} részével \
                 térnek el a Mitsuba 3 képeitől (1 már hiba volna): egyik sugárkövető sem hibás.",
            ],
        }),
    },
    Area {
        key: "images",
        title: [
            "ꟻLIP against NVIDIA's evaluator",
            "A ꟻLIP az NVIDIA kiértékelőjéhez mérve",
        ],
        checks: &["images."],
        figures: &[],
        headline: Some(Headline {
            quantity: Some("mean: |ours − NVIDIA|"),
            says: [
                "Our ꟻLIP agrees with NVIDIA's evaluator to {} in the mean: rounding, \
                 no defect on either side.",
                "A ꟻLIP-ünk átlaga legfeljebb {} eltéréssel egyezik az NVIDIA kiértékelőjéével: \
                 kerekítés, egyik oldal sem hibás.",
            ],
        }),
    },
    Area {
        key: "full-light",
        title: ["All the light", "Az összes fény"],
        checks: &["full_light."],
        figures: &[],
        headline: Some(Headline {
            quantity: Some("Mitsuba path's missing share, surface"),
            says: [
                "Path tracing misses up to {} of the light on a surface in these scenes, the \
                 light that arrives by way of a mirror: Mitsuba's and ours alike, a limit of the \
                 method rather than a defect of either.",
                "Az útkövetés ezekben a jelenetekben egy felület fényének legfeljebb {} részét \
                 nem találja meg, a tükrön át érkező fényt: a Mitsubáé és a miénk egyaránt; \
                 a módszer korlátja, egyikük sem hibás.",
            ],
        }),
    },
    Area {
        key: "techniques",
        title: [
            "The slides' techniques against the exact answers",
            "A diák technikái a pontos válaszokhoz mérve",
        ],
        checks: &["techniques."],
        figures: &["techniques"],
        headline: Some(Headline {
            quantity: Some("into water, c = 1: angle from Snell's law (°)"),
            says: [
                "The slides' cheap refraction bends light into water up to {}° away from \
                 Snell's law: the course texts' error, as the errata say.",
                "A diák olcsó fénytörése a vízbe lépő fényt legfeljebb {}°-kal téríti el a \
                 Snellius–Descartes-törvény szerinti iránytól: a kurzus szövegének hibája, \
                 ahogy a hibajegyzék is mondja.",
            ],
        }),
    },
    Area {
        key: "tradeoff",
        title: [
            "The speed/accuracy trade, whole renders",
            "A sebesség és a pontosság cseréje, teljes képeken",
        ],
        checks: &["tradeoff."],
        figures: &["tradeoff_kaleidoscope_lit", "tradeoff_"],
        headline: Some(Headline {
            quantity: Some("the scene's own settings: relative RMSE from all the light"),
            says: [
                "A scene rendered with its own settings (Whitted) is off by up to {} relative \
                 RMSE from all the light: what a Whitted tracer leaves out, not a defect.",
                "A saját beállításaival (Whitted) készült kép relatív négyzetes középhibája a \
                 összes fényhez képest legfeljebb {}: ennyit hagy ki a Whitted-féle \
                 sugárkövetés, ez nem hiba.",
            ],
        }),
    },
];

/// One area of the report.
pub(super) struct Area {
    pub(super) key: &'static str,
    /// In English and in Hungarian.
    pub(super) title: [&'static str; 2],
    pub(super) checks: &'static [&'static str],
    pub(super) figures: &'static [&'static str],
    pub(super) headline: Option<Headline>,
}

/// A card's headline: one sentence in English and in Hungarian, `{}` where
/// the area's worst value of `quantity` goes (`None`: its worst Fresnel
/// error in ulps).
pub(super) struct Headline {
    pub(super) quantity: Option<&'static str>,
    pub(super) says: [&'static str; 2],
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
            title: ["Other checks", "Egyéb ellenőrzések"],
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
