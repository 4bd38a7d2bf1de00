//! The English text of each kind: its `Display`, the one place the
//! suite's own messages are worded in English (their Hungarian is in
//! `crate::lang`).

use std::fmt;

#[cfg(feature = "harness")]
use validation::tradeoff::budget::Need;
#[cfg(feature = "harness")]
use validation::tradeoff::error::BudgetError;

#[cfg(feature = "harness")]
use super::harness::HarnessKind;
use super::kind::ErrorKind;
use super::usage_text;
#[cfg(feature = "harness")]
use super::{compare, harness};

impl fmt::Display for ErrorKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ErrorKind::Domain(error) => write!(f, "{error}"),
            ErrorKind::Usage(error) => write!(f, "{}", usage_text(error)),
            ErrorKind::VectorParts { count } => write!(
                f,
                "expected three comma-separated numbers such as 0,3,4, got {count} part(s)"
            ),
            ErrorKind::VectorComponent { axis, text } => {
                write!(f, "the {axis} component {text:?} is not a number")
            }
            ErrorKind::AngleDegrees { name, value } => {
                write!(f, "{name} must be an angle in [0, 180] degrees, got {value}")
            }
            ErrorKind::CosineOrAngle { cosine, angle } => {
                write!(f, "give exactly one of {cosine} and {angle}")
            }
            ErrorKind::ConductorFromInside {
                name,
                cos_i,
                degrees,
            } => conductor_from_inside(f, name, *cos_i, *degrees),
            ErrorKind::NoCriticalAngle {
                name,
                n,
                name_outside,
                n_outside,
            } => no_critical_angle(f, (name, *n), (name_outside, *n_outside)),
            ErrorKind::EmptyLine => write!(f, "empty line: every line holds one request"),
            ErrorKind::MalformedJson { error, non_finite } => malformed_json(f, error, *non_finite),
            ErrorKind::NotAnObject => write!(f, "a request must be a JSON object"),
            ErrorKind::LawMissing => write!(f, "law: missing; every request names its law"),
            ErrorKind::LawNotString => write!(f, "law: must be a string"),
            ErrorKind::UnknownLaw { law, expected } => write!(
                f,
                "law: unknown law {law:?}, expected one of {}",
                expected.join(", ")
            ),
            ErrorKind::Request { path, message } => match path {
                Some(path) => write!(f, "{path}: {message}"),
                None => write!(f, "{message}"),
            },
            ErrorKind::ReadLine { line, source } => write!(f, "reading line {line}: {source}"),
            ErrorKind::LineTooLong { limit } => write!(
                f,
                "the line is longer than {limit} bytes (a request is an object of a few \
                 numbers): skipped to its end unread"
            ),
            ErrorKind::NotUtf8 { column } => write!(
                f,
                "the line is not UTF-8 text: the byte at column {column} is not"
            ),
            ErrorKind::Overflow { quantity, inputs } => write!(
                f,
                "{quantity} overflows: it grows with {} past the largest finite number (1.8e308); give smaller values",
                inputs.join(", ")
            ),
            ErrorKind::Write(error) => write!(f, "cannot write the output: {error}"),
            ErrorKind::Encode(error) => write!(f, "cannot write the result as JSON: {error}"),
            ErrorKind::Scene { file, error } => {
                let advice = super::render::advice_en(error.kind());
                write!(f, "scene {}: {error}{advice}", file.display())
            }
            ErrorKind::Output(error) => write!(f, "--output: {error}"),
            ErrorKind::Threads(error) => {
                write!(f, "cannot start the render's threads: {error}")
            }
            ErrorKind::RadianceNotFinite { x, y } => write!(
                f,
                "the radiance at pixel ({x}, {y}) is not finite in f32: the paths' gain \
                 exceeds f32 there; nothing was written"
            ),
            #[cfg(feature = "harness")]
            ErrorKind::Harness(kind) => write!(f, "{kind}"),
        }
    }
}

#[cfg(feature = "harness")]
impl fmt::Display for HarnessKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            HarnessKind::Checkout(error) => f.write_str(&harness::checkout_en(error, None)),
            HarnessKind::CheckoutWithFlag(error) => {
                f.write_str(&harness::checkout_en(error, Some(harness::CHECKOUT_FLAG)))
            }
            HarnessKind::Pipeline(error) => match harness::pipeline_lead(error) {
                Some(lead) => write!(f, "{}: {error}", lead.en),
                None => write!(f, "{error}"),
            },
            HarnessKind::ChecksFailed { failed, checks } => {
                write!(f, "{failed} of {checks} checks failed")
            }
            HarnessKind::Compare(error) => compare::english(error, f),
            HarnessKind::TruthIsBlack { file } => write!(
                f,
                "SCENE {}: its physical render is black: no light reaches the camera (a scene without lights shows only the course's ambient term), so there is no light transport to trade",
                file.display()
            ),
            HarnessKind::NoPlotPython { python } => write!(
                f,
                "the Pareto plot needs the checkout's Python environment and there is none at {} (`optics validate` creates it once; --no-plot skips the plot): nothing was written",
                python.display()
            ),
            HarnessKind::Plot(error) => write!(
                f,
                "the Pareto plot cannot be drawn, so nothing was written (--no-plot skips it): {error}"
            ),
            HarnessKind::Budget(BudgetError::Unreachable {
                metric,
                tolerance,
                best,
                settings,
                top_spp,
                need,
            }) => {
                let tolerance = validation::tradeoff::budget::written(*tolerance);
                write!(
                    f,
                    "--tolerance {tolerance}: cannot reach {metric} {tolerance}; the best is {metric} ≤ {best:.4}, with {settings}"
                )?;
                match (need, top_spp) {
                    (Need::Samples { spp }, Some(top)) => write!(
                        f,
                        "; it would need 2^{} = {spp} spp (a power of two, as the budget renders), past the most it renders, {top} spp",
                        spp.trailing_zeros()
                    ),
                    (Need::Capped { spp }, _) => write!(
                        f,
                        "; more samples cannot reach it: its noise stops falling past {spp} spp, where its caustic map has its most photons"
                    ),
                    (Need::Floor, _) => write!(
                        f,
                        "; no number of samples reaches it: its floor, the bias with the pilot's noise and the ground truth's, is above it (more --pilot-spp lowers the pilot's part)"
                    ),
                    _ => write!(
                        f,
                        "; no number of samples reaches it: the bias alone is above it"
                    ),
                }
            }
            HarnessKind::Budget(BudgetError::PilotNoisy { pilot_spp }) => write!(
                f,
                "--pilot-spp {pilot_spp}: the pilot cannot tell the light on the surfaces from its noise (its energy, three standard deviations down, is not above 0), so no relative error can be predicted; the scene may be black, or its light may grow with depth (course_rough's albedo π kd above 1: give --lambert to measure it with the stand-in `optics tradeoff --lambert` uses); try more pilot samples"
            ),
            HarnessKind::Budget(BudgetError::EnergyGain { material, gain }) => write!(
                f,
                "--lambert: material \"{material}\" reflects {gain:.2} times the light it receives (course_rough's albedo π kd), so its light grows with every bounce, no ground truth converges and no error can be bounded; give --lambert to budget the scene with the stand-in `optics tradeoff --lambert` uses"
            ),
            HarnessKind::Jobs(error) => write!(f, "{}", error.named(super::jobs::flag)),
        }
    }
}

/// A line that is not JSON, with why where it spells NaN or an infinity.
fn malformed_json(
    f: &mut fmt::Formatter<'_>,
    error: &serde_json::Error,
    non_finite: bool,
) -> fmt::Result {
    write!(f, "malformed JSON: {error}")?;
    if non_finite {
        write!(f, " ({})", safe_io::json::NON_FINITE_HINT)?;
    }
    Ok(())
}

/// Light from inside a conductor, in the quantity it was given as: an
/// angle in degrees, or a signed cosine.
fn conductor_from_inside(
    f: &mut fmt::Formatter<'_>,
    name: &str,
    cos_i: f64,
    degrees: Option<f64>,
) -> fmt::Result {
    match degrees {
        Some(degrees) => write!(
            f,
            "{name} must be at most 90 degrees for a conductor (kappa > 0): light cannot arrive from inside a metal, got {degrees}"
        ),
        None => write!(
            f,
            "{name} must be ≥ 0 for a conductor (kappa > 0): light cannot arrive from inside a metal, got {cos_i}"
        ),
    }
}

/// A critical angle asked for light going into a denser (or equal) medium.
fn no_critical_angle(
    f: &mut fmt::Formatter<'_>,
    (name, n): (&str, f64),
    (name_outside, n_outside): (&str, f64),
) -> fmt::Result {
    write!(
        f,
        "{name} = {n} is not larger than {name_outside} = {n_outside}: light going into a denser (or equal) medium always refracts, there is no critical angle"
    )
}
