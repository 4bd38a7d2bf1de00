//! The report's document: its schema, its contents and their JSON form.

use std::collections::BTreeMap;
use std::path::Path;

use serde::Serialize;

use crate::check::Check;
use crate::metals::MetalColour;
use crate::reference::ReferenceError;
use crate::renders::RenderFigure;
use crate::speed::Timing;
use crate::tradeoff::prose::sentences;
use record::Lang;

/// The schema of `report.json`.
pub const REPORT_SCHEMA: &str = "validation-report/2";

/// `report.json`: every check, its data for the figures, and the references used.
#[derive(Clone, Debug, Serialize)]
pub struct Report {
    /// [`REPORT_SCHEMA`].
    pub schema: &'static str,
    /// Whether this was the reduced set.
    pub quick: bool,
    /// The command line that produced the report.
    pub command: String,
    /// Counts of checks, passes, failures and findings.
    pub summary: Summary,
    /// The reference files read, by name: their description fields.
    pub references: BTreeMap<String, ReferenceInfo>,
    /// Every check.
    pub checks: Vec<Check>,
    /// Reflectance against angle per material: exact, both Schlick forms, Mitsuba.
    pub fresnel_curves: Vec<FresnelCurve>,
    /// Each metal's reflectance spectrum at each angle: exact and Schlick.
    pub metal_spectra: Vec<MetalSpectrum>,
    /// Every metal colour by every method.
    pub metal_colours: Vec<MetalColour>,
    /// The worst CIEDE2000 of each shortcut per metal.
    pub metal_delta_e: Vec<WorstDeltaE>,
    /// Time per metal colour by method.
    pub speed: Vec<Timing>,
    /// The techniques' measured curves: the cheap refraction's error, the
    /// fitted empirical Fresnel forms.
    pub technique_curves: crate::techniques::TechniqueCurves,
    /// The speed/accuracy trade-off records read (`docs/tradeoffs`), one a
    /// scene.
    pub tradeoffs: Vec<crate::tradeoff::record::Record>,
    /// Each trade-off record's findings in words, by the record's stem
    /// ([`Report::word_tradeoffs`]); not part of `report.json`, which
    /// carries the findings themselves.
    #[serde(skip)]
    pub tradeoff_words: BTreeMap<String, String>,
    /// The render triptychs (ours | Mitsuba | difference), written as PNG
    /// by the command beside the report; not part of `report.json`.
    #[serde(skip)]
    pub render_figures: Vec<RenderFigure>,
}

/// Counts over the checks.
#[derive(Clone, Debug, Default, Serialize)]
pub struct Summary {
    /// Checks run.
    pub checks: usize,
    /// Checks within tolerance.
    pub passed: usize,
    /// Checks with failures.
    pub failed: usize,
    /// Findings about the references.
    pub findings: usize,
}

/// The self-description of a reference file.
#[derive(Clone, Debug, Default, Serialize, serde::Deserialize)]
pub struct ReferenceInfo {
    /// Its schema.
    pub schema: String,
    /// The script that wrote it.
    #[serde(default)]
    pub generator: String,
    /// The command that regenerates it.
    #[serde(default)]
    pub regenerate: String,
    /// What it holds.
    #[serde(default)]
    pub description: String,
}

/// One material's reflectance curves, one value per degree.
#[derive(Clone, Debug, Serialize)]
pub struct FresnelCurve {
    /// Material and side.
    pub label: String,
    /// Angle of incidence, degrees.
    pub angle_deg: Vec<f64>,
    /// The exact law (the radiometry crate, f64).
    pub exact: Vec<f64>,
    /// Schlick's approximation in its incident form, `cos θ_i` and
    /// `F0(n, κ)` from either side, as the course uses it.
    #[serde(rename = "schlick-incident")]
    pub schlick_incident: Vec<f64>,
    /// Schlick's approximation in its rarer-medium form: `cos θ_t` from
    /// inside a dielectric, 1 past the critical angle; at a conductor the
    /// incident form.
    #[serde(rename = "schlick-rarer")]
    pub schlick_rarer: Vec<f64>,
    /// Mitsuba 3 (float32).
    pub mitsuba: Vec<f64>,
}

/// One metal's reflectance spectrum at one angle, on the CIE grid.
#[derive(Clone, Debug, Serialize)]
pub struct MetalSpectrum {
    /// The metal.
    pub metal: String,
    /// Angle of incidence, degrees.
    pub angle_deg: f64,
    /// Wavelengths, nm.
    pub wavelength_nm: Vec<f64>,
    /// The exact conductor law at the measured `n, κ`.
    pub exact: Vec<f64>,
    /// Schlick's approximation from the spectral F0.
    pub schlick: Vec<f64>,
}

/// The worst colour error of one shortcut for one metal.
#[derive(Clone, Debug, Serialize)]
pub struct WorstDeltaE {
    /// The metal.
    pub metal: String,
    /// The shortcut.
    pub method: String,
    /// Its worst CIEDE2000 over the angles.
    pub delta_e_2000: f64,
    /// Where.
    pub at_angle_deg: f64,
}

impl Report {
    /// An empty report.
    pub fn new(quick: bool, command: &str) -> Self {
        Self {
            schema: REPORT_SCHEMA,
            quick,
            command: command.to_owned(),
            summary: Summary::default(),
            references: BTreeMap::new(),
            checks: Vec::new(),
            fresnel_curves: Vec::new(),
            metal_spectra: Vec::new(),
            metal_colours: Vec::new(),
            metal_delta_e: Vec::new(),
            speed: Vec::new(),
            technique_curves: Default::default(),
            tradeoffs: Vec::new(),
            tradeoff_words: BTreeMap::new(),
            render_figures: Vec::new(),
        }
    }

    /// Records the description fields of reference `name` in `dir`.
    pub fn note_reference(&mut self, dir: &Path, name: &str) -> Result<(), ReferenceError> {
        let path = dir.join(name);
        let text = std::fs::read_to_string(&path).map_err(|source| ReferenceError::Io {
            path: path.clone(),
            source,
        })?;
        let info: ReferenceInfo = crate::reference::parse_any(&path, &text)?;
        self.references.insert(name.to_owned(), info);
        Ok(())
    }

    /// A report of the same run holding only what the figures draw
    /// (`python-checks/plot_report.py` reads these fields and no others).
    pub fn figure_data(&self) -> Report {
        Report {
            fresnel_curves: self.fresnel_curves.clone(),
            metal_spectra: self.metal_spectra.clone(),
            metal_colours: self.metal_colours.clone(),
            metal_delta_e: self.metal_delta_e.clone(),
            technique_curves: self.technique_curves.clone(),
            ..Report::new(self.quick, &self.command)
        }
    }

    /// Appends `part`, a report of the same run holding one kind of check's
    /// results, after what this one holds: what running that kind into
    /// this report would have appended.
    pub fn absorb(&mut self, part: Report) {
        // Every field named, so that a new one cannot be left out.
        let Report {
            schema: _,
            quick: _,
            command: _,
            summary: _,
            references,
            checks,
            fresnel_curves,
            metal_spectra,
            metal_colours,
            metal_delta_e,
            speed,
            technique_curves,
            tradeoffs,
            tradeoff_words,
            render_figures,
        } = part;
        self.references.extend(references);
        self.checks.extend(checks);
        self.fresnel_curves.extend(fresnel_curves);
        self.metal_spectra.extend(metal_spectra);
        self.metal_colours.extend(metal_colours);
        self.metal_delta_e.extend(metal_delta_e);
        self.speed.extend(speed);
        self.technique_curves.absorb(technique_curves);
        self.tradeoffs.extend(tradeoffs);
        self.tradeoff_words.extend(tradeoff_words);
        self.render_figures.extend(render_figures);
    }

    /// Words each trade-off record's findings into
    /// [`Report::tradeoff_words`] in the report's language, English
    /// ([`crate::tradeoff::prose::sentences`]), one paragraph a record: the
    /// paragraph under each scene's table in `docs/tradeoffs.md`. A record
    /// without findings gets none.
    pub fn word_tradeoffs(&mut self) {
        self.tradeoff_words = self
            .tradeoffs
            .iter()
            .filter_map(|r| {
                let findings = r.findings.as_ref()?;
                Some((r.stem(), sentences(findings, Lang::En).join(" ")))
            })
            .collect();
    }

    /// Recounts [`Report::summary`] from the checks.
    pub fn summarise(&mut self) {
        let passed = self.checks.iter().filter(|c| c.passed()).count();
        self.summary = Summary {
            checks: self.checks.len(),
            passed,
            failed: self.checks.len() - passed,
            findings: self.checks.iter().map(|c| c.findings.len()).sum(),
        };
    }

    /// Whether every check passed.
    pub fn passed(&self) -> bool {
        self.checks.iter().all(Check::passed)
    }
}

/// `report.json`, pretty-printed. Non-finite numbers (which JSON cannot hold)
/// are written as `null`.
pub fn to_json(report: &Report) -> String {
    let mut text = serde_json::to_string_pretty(report).expect("a report always serialises");
    text.push('\n');
    text
}
