//! The harness: every kind of check, run beside one another against one
//! directory of references, gathered into one [`Report`] in their order
//! ([`schedule`]).
//!
//! A kind of check ([`CheckKind`]) reads the references it needs, appends its
//! [`Check`](crate::check::Check)s and its figure data to the report, and says how many steps it
//! takes for the progress display. Adding a kind (the renders against
//! Mitsuba, say) is one more implementation in [`standard_kinds`].

use crate::colorimetry::{self, Colorimetry, ColourLaws};
pub use crate::context::{Context, Samples};
use crate::flip;
use crate::full_light::{self, FullLight, FullLightChecks};
use crate::laws::{self, Laws, Laws64, MitsubaLaws};
use crate::metals::{self, MetalLaws, MetalsReference};
use crate::mpmath::{self, FresnelMpmath};
use crate::reference::ReferenceError;
use crate::renders::{self, MitsubaRenders, RenderChecks};
use crate::report::{FresnelCurve, MetalSpectrum, Report, WorstDeltaE};
use crate::speed;
use crate::tradeoff;
use radiometry::spectrum::{self, SAMPLES};

/// The laws against the 50-digit references, Mitsuba and the exact values:
/// the `f32` laws and the `f64` ones.
pub struct LawChecks(pub Laws, pub Laws64);

impl CheckKind for LawChecks {
    fn name(&self) -> &'static str {
        "laws against Mitsuba 3 and mpmath"
    }

    fn name_hu(&self) -> &'static str {
        "a törvények a Mitsuba 3-hoz és az mpmath-hoz mérve"
    }

    fn feeds_figures(&self) -> bool {
        true // the Fresnel curves
    }

    fn run(&self, context: &Context, report: &mut Report) -> Result<(), ReferenceError> {
        let exact = FresnelMpmath::load(&context.reference_dir)?;
        report.note_reference(&context.reference_dir, mpmath::FILE)?;
        report
            .checks
            .push(mpmath::check_dielectric(&self.0, &self.1, &exact));
        report
            .checks
            .push(mpmath::check_conductor(&self.0, &self.1, &exact));
        report
            .checks
            .push(mpmath::check_angles(&self.0, &self.1, &exact));
        let (random, sets) = mpmath::random::FresnelRandom::load(&context.reference_dir)?;
        report.note_reference(&context.reference_dir, mpmath::random::FILE)?;
        report.checks.extend(mpmath::random::check_random(
            &self.0, &self.1, &random, &sets,
        ));
        let reference = MitsubaLaws::load(&context.reference_dir)?;
        report.note_reference(&context.reference_dir, laws::FILE)?;
        report.checks.extend(laws::check_all(&self.0, &reference));
        report.fresnel_curves = fresnel_curves(&reference);
        Ok(())
    }
}

/// The exact law and both forms of Schlick's beside Mitsuba's curves, per
/// material.
pub fn fresnel_curves(reference: &MitsubaLaws) -> Vec<FresnelCurve> {
    use radiometry::fresnel;
    reference
        .curves
        .iter()
        .map(|curve| {
            let f0 = fresnel::f0(curve.n, curve.kappa);
            let dielectric = curve.kappa == 0.0;
            let exact = |c: f64| {
                if dielectric {
                    fresnel::dielectric(c, curve.n)
                } else {
                    fresnel::conductor(c, curve.n, curve.kappa)
                }
            };
            // A conductor is lit from outside, where both forms take cos θi.
            let incident = |c: f64| {
                if dielectric {
                    fresnel::schlick_dielectric_incident(c, curve.n)
                } else {
                    fresnel::schlick(c, f0)
                }
            };
            let rarer = |c: f64| {
                if dielectric {
                    fresnel::schlick_dielectric(c, curve.n)
                } else {
                    fresnel::schlick(c, f0)
                }
            };
            FresnelCurve {
                label: curve.label.clone(),
                angle_deg: curve
                    .cos_i
                    .iter()
                    .map(|c| c.abs().acos().to_degrees())
                    .collect(),
                exact: curve.cos_i.iter().map(|&c| exact(c)).collect(),
                schlick_incident: curve.cos_i.iter().map(|&c| incident(c)).collect(),
                schlick_rarer: curve.cos_i.iter().map(|&c| rarer(c)).collect(),
                mitsuba: curve.mitsuba_f.clone(),
            }
        })
        .collect()
}

/// The colorimetry against colour-science.
pub struct ColourChecks(pub ColourLaws);

impl CheckKind for ColourChecks {
    fn name(&self) -> &'static str {
        "colorimetry against colour-science"
    }

    fn name_hu(&self) -> &'static str {
        "a színmérés a colour-science-hez mérve"
    }

    fn run(&self, context: &Context, report: &mut Report) -> Result<(), ReferenceError> {
        let reference = Colorimetry::load(&context.reference_dir)?;
        report.note_reference(&context.reference_dir, colorimetry::FILE)?;
        report
            .checks
            .extend(colorimetry::check_all(&self.0, &reference));
        Ok(())
    }
}

/// Metal colours: spectral against colour-science, shortcuts measured, speed timed.
pub struct MetalChecks(pub MetalLaws);

impl CheckKind for MetalChecks {
    fn name(&self) -> &'static str {
        "metal colours and their shortcuts"
    }

    fn name_hu(&self) -> &'static str {
        "a fémek színe és egyszerűsítései"
    }

    fn feeds_figures(&self) -> bool {
        true // the metals' swatches, spectra and ΔE table
    }

    fn run(&self, context: &Context, report: &mut Report) -> Result<(), ReferenceError> {
        let reference = MetalsReference::load(&context.reference_dir)?;
        report.note_reference(&context.reference_dir, metals::FILE)?;
        report
            .checks
            .push(metals::check_spectral_colours(&self.0, &reference));
        let rows = metals::shortcut_colours(&self.0, &reference);
        report.metal_delta_e = metals::worst_delta_e(&rows)
            .into_iter()
            .map(|(metal, method, delta_e_2000, at_angle_deg)| WorstDeltaE {
                metal,
                method,
                delta_e_2000,
                at_angle_deg,
            })
            .collect();
        report.metal_colours = rows;
        report.metal_spectra = metal_spectra(&self.0, &reference);
        Ok(())
    }
}

/// The cost of gold's spectral colour against its three-wavelength one,
/// timed with the wall clock: alone, after every other kind.
pub struct SpeedChecks(pub MetalLaws);

impl CheckKind for SpeedChecks {
    fn name(&self) -> &'static str {
        "the cost of a spectral colour"
    }

    fn name_hu(&self) -> &'static str {
        "a spektrális szín ára"
    }

    fn measures_time(&self) -> bool {
        true
    }

    fn run(&self, context: &Context, report: &mut Report) -> Result<(), ReferenceError> {
        let reference = MetalsReference::load(&context.reference_dir)?;
        let iterations = if context.quick { 20_000 } else { 200_000 };
        if let Some(gold) = reference.metals.iter().find(|m| m.name == "gold") {
            report.speed.extend(
                speed::time_gold(&self.0, gold, iterations)
                    .into_iter()
                    .flatten(),
            );
        }
        Ok(())
    }
}

/// The rasteriser-side techniques of `001` against the answers they
/// stand in for, with N-BK7 (or another glass) as the dispersing glass.
pub struct TechniqueChecks(pub techniques::dispersion::Sellmeier);

impl CheckKind for TechniqueChecks {
    fn name(&self) -> &'static str {
        "the slides' techniques against the exact answers"
    }

    fn name_hu(&self) -> &'static str {
        "a diák technikái a pontos válaszokhoz mérve"
    }

    fn feeds_figures(&self) -> bool {
        true // the cheap refraction's error, the fitted Fresnel forms
    }

    fn run(&self, _context: &Context, report: &mut Report) -> Result<(), ReferenceError> {
        let (checks, curves) = crate::techniques::check_all(&self.0, &mut report.render_figures);
        report.checks.extend(checks);
        report.technique_curves = curves;
        Ok(())
    }
}

/// The committed speed/accuracy trade-off records (`docs/tradeoffs`):
/// each checked, each carried into the report for its section.
pub struct TradeoffChecks;

impl CheckKind for TradeoffChecks {
    fn name(&self) -> &'static str {
        "the speed/accuracy trade, as recorded"
    }

    fn name_hu(&self) -> &'static str {
        "a sebesség és a pontosság cseréje, ahogy rögzítették"
    }

    fn run(&self, context: &Context, report: &mut Report) -> Result<(), ReferenceError> {
        let dir = context.checkout.join(tradeoff::checks::DIR);
        let records = tradeoff::checks::read(&dir)?;
        if records.is_empty() {
            report.checks.push(tradeoff::checks::none(&dir));
        }
        for (file, record) in records {
            report.checks.push(tradeoff::checks::check(&file, &record));
            if let Ok(record) = record {
                report.tradeoffs.push(record);
            }
        }
        Ok(())
    }
}

/// Every metal's exact and Schlick reflectance spectra at the reference angles.
pub fn metal_spectra(laws: &MetalLaws, reference: &MetalsReference) -> Vec<MetalSpectrum> {
    let wavelength_nm: Vec<f64> = (0..SAMPLES).map(spectrum::wavelength_nm).collect();
    let mut out = Vec::new();
    for metal in &reference.metals {
        let Some(index) = metal.index_on_grid() else {
            continue;
        };
        for angle in &metal.angles {
            out.push(MetalSpectrum {
                metal: metal.name.clone(),
                angle_deg: angle.angle_deg,
                wavelength_nm: wavelength_nm.clone(),
                exact: laws.spectrum(&index, angle.cos_i).to_vec(),
                schlick: index
                    .iter()
                    .map(|&(n, k)| (laws.schlick)(angle.cos_i, (laws.f0)(n, k)))
                    .collect(),
            });
        }
    }
    out
}

/// The tracer's renders against Mitsuba's, scene by scene.
impl CheckKind for RenderChecks {
    fn name(&self) -> &'static str {
        "renders against Mitsuba 3"
    }

    fn name_hu(&self) -> &'static str {
        "a renderelt képek a Mitsuba 3-hoz mérve"
    }

    fn run(&self, context: &Context, report: &mut Report) -> Result<(), ReferenceError> {
        let reference = MitsubaRenders::load(&context.reference_dir)?;
        report.note_reference(&context.reference_dir, renders::FILE)?;
        self.run_all(
            &reference,
            context,
            &mut report.checks,
            &mut report.render_figures,
        )
    }
}

/// All the light against Mitsuba's light tracer and area lights.
impl CheckKind for FullLightChecks {
    fn name(&self) -> &'static str {
        "all the light against Mitsuba 3"
    }

    fn name_hu(&self) -> &'static str {
        "az összes fény a Mitsuba 3-hoz mérve"
    }

    fn run(&self, context: &Context, report: &mut Report) -> Result<(), ReferenceError> {
        let reference = FullLight::load(&context.reference_dir)?;
        report.note_reference(&context.reference_dir, full_light::FILE)?;
        self.run_all(&reference, context, &mut report.checks)
    }
}

/// The suite's ꟻLIP against NVIDIA's evaluator.
pub struct FlipChecks(pub flip::ErrorMap);

impl CheckKind for FlipChecks {
    fn name(&self) -> &'static str {
        "ꟻLIP against NVIDIA's evaluator"
    }

    fn name_hu(&self) -> &'static str {
        "a ꟻLIP az NVIDIA kiértékelőjéhez mérve"
    }

    fn run(&self, context: &Context, report: &mut Report) -> Result<(), ReferenceError> {
        let reference = flip::FlipReference::load(&context.reference_dir)?;
        report.note_reference(&context.reference_dir, flip::FILE)?;
        report
            .checks
            .push(flip::check_against_nvidia(self.0, &reference));
        Ok(())
    }
}

/// The kinds of check `optics validate` runs, with the radiometry crate's laws.
pub fn standard_kinds() -> Vec<Box<dyn CheckKind>> {
    vec![
        Box::new(LawChecks(Laws::radiometry(), Laws64::radiometry())),
        Box::new(ColourChecks(ColourLaws::radiometry())),
        Box::new(MetalChecks(MetalLaws::radiometry())),
        Box::new(FlipChecks(flip::error_map)),
        Box::new(RenderChecks::tracer()),
        Box::new(FullLightChecks::tracer()),
        Box::new(TechniqueChecks(techniques::dispersion::SELLMEIER_N_BK7)),
        Box::new(TradeoffChecks),
        Box::new(SpeedChecks(MetalLaws::radiometry())),
    ]
}

/// Runs `kinds` ([`schedule::run_merged`]), calling `progress(i, name)`
/// in their order as each is awaited, and returns the summarised report.
pub fn run(
    kinds: &[Box<dyn CheckKind>],
    context: &Context,
    command: &str,
    mut progress: impl FnMut(usize, &str),
) -> Result<Report, ReferenceError> {
    let mut report = Report::new(context.quick, command);
    schedule::run_merged(kinds, context, &mut report, |step| {
        if let Merge::Awaiting { index, names } = step {
            progress(index, names[0]);
        }
        Ok::<(), ReferenceError>(())
    })?;
    report.summarise();
    Ok(report)
}

mod kind;
pub mod schedule;

pub use kind::CheckKind;
use schedule::Merge;
