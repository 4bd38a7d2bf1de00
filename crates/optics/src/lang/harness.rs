//! The harness's errors in Hungarian: no checkout, a pipeline that could
//! not run to the end. Each is an exhaustive `match` over the harness's
//! kinds.

use validation::checkout::{CheckoutError, Via, ENV, MARKERS};
use validation::pipeline::PipelineError;
use validation::python::{Task, ToolError};
use validation::reference::ReferenceError;
use validation::regenerate::RegenerateError;

use super::render::output_hu;
use crate::error::HarnessKind;
use validation::tradeoff::error::BudgetError;

/// No usable checkout: what named the directory and what it lacks, or
/// where none was found and the advice that a command whose checkout flag
/// is `flag` accepts ([`crate::error::harness::checkout_en`]).
pub fn checkout_hu(error: &CheckoutError, flag: Option<&str>) -> String {
    match error {
        CheckoutError::NotACheckout { via, path, marker } => format!(
            "{} {}: nem a programcsomag munkapéldánya (nincs benne {marker})",
            via_hu(*via, flag),
            path.display()
        ),
        CheckoutError::NotFound { start } => {
            let advice = match flag {
                Some(flag) => format!(
                    "adja meg a {flag} DIR kapcsolót, állítsa be az {ENV}=DIR változót, \
                     vagy futtassa egy munkapéldányon belülről"
                ),
                None => format!(
                    "állítsa be az {ENV}=DIR változót, vagy futtassa egy munkapéldányon belülről"
                ),
            };
            format!(
                "nem található a programcsomag munkapéldánya: nem neveztek meg egyet sem, az \
                 {ENV} változó üres vagy nincs beállítva, és sem {}, sem egy fölötte lévő \
                 könyvtár nem tartalmazza egyszerre ezeket: {}, {}; {advice}",
                start.display(),
                MARKERS[0],
                MARKERS[1]
            )
        }
    }
}

fn via_hu(via: Via, flag: Option<&str>) -> &str {
    match (via, flag) {
        (Via::Explicit, Some(flag)) => flag,
        (Via::Explicit, None) => "a megnevezett könyvtár",
        (Via::Environment, _) => ENV,
        (Via::Search, _) => "a munkakönyvtár",
        (Via::BuildTime, _) => "e fordítás munkapéldánya",
    }
}

/// A pipeline that could not run to the end, led by the flag that sets
/// what it concerns.
pub fn pipeline_hu(error: &PipelineError) -> String {
    let message = match error {
        PipelineError::OutNotADirectory { path } => format!(
            "a(z) {} kimeneti könyvtár létezik, de nem könyvtár",
            path.display()
        ),
        PipelineError::CreateDir { path, source } => format!(
            "a(z) {} könyvtár nem hozható létre: {source}",
            path.display()
        ),
        PipelineError::NoRequirements { path } => format!(
            "{} nem található: a Python-oldal a programcsomag munkapéldányából fut",
            path.display()
        ),
        PipelineError::Write(error) => output_hu(error),
        PipelineError::Reference(error) => reference_hu(error),
        PipelineError::Tool(error) | PipelineError::Regenerate(RegenerateError::Tool(error)) => {
            tool_hu(error)
        }
        PipelineError::Regenerate(RegenerateError::Undecided {
            file,
            status,
            stderr,
        }) => format!(
            "a python-checks/reproduce.py nem tudta eldönteni, egyezik-e {file} ({status}): \
             {stderr}"
        ),
    };
    match crate::error::harness::pipeline_lead(error) {
        Some(lead) => format!("{}: {message}", lead.hu),
        None => message,
    }
}

fn reference_hu(error: &ReferenceError) -> String {
    match error {
        ReferenceError::Io { path, source } => {
            format!("a(z) {} referencia nem olvasható: {source}", path.display())
        }
        ReferenceError::Malformed {
            path,
            field,
            message,
        } => format!(
            "a(z) {} referencia hibás itt: `{field}`: {message}",
            path.display()
        ),
        ReferenceError::Schema {
            path,
            found,
            expected,
        } => format!(
            "a(z) {} referencia sémája `{found}`, a várt séma `{expected}`",
            path.display()
        ),
    }
}

fn tool_hu(error: &ToolError) -> String {
    match error {
        ToolError::Start {
            what,
            program,
            source,
        } => format!("{}: a(z) {program} nem indítható: {source}", task_hu(what)),
        ToolError::Failed {
            what,
            status,
            stderr_tail,
        } => format!("{}: sikertelen ({status}):\n{stderr_tail}", task_hu(what)),
    }
}

fn task_hu(task: &Task) -> String {
    match task {
        Task::CreateEnvironment { base } => format!(
            "a virtuális környezet létrehozása a(z) `{} -m venv` paranccsal (telepítve van a Python 3?)",
            base.display()
        ),
        Task::InstallRequirements => {
            "a python-checks/requirements.txt telepítése pip-pel".to_owned()
        }
        Task::CheckPins => "a telepített Python-csomagok ellenőrzése".to_owned(),
        Task::Script(script) => script.clone(),
    }
}

/// A failure of the `harness` feature's commands in Hungarian.
pub fn harness_hu(kind: &HarnessKind) -> String {
    match kind {
        HarnessKind::Checkout(error) => checkout_hu(error, None),
        HarnessKind::CheckoutWithFlag(error) => {
            checkout_hu(error, Some(crate::error::harness::CHECKOUT_FLAG))
        }
        HarnessKind::Pipeline(error) => pipeline_hu(error),
        HarnessKind::ChecksFailed { failed, checks } => {
            format!("{checks} ellenőrzésből {failed} sikertelen")
        }
        HarnessKind::Compare(error) => super::compare::compare_hu(error),
        HarnessKind::TruthIsBlack { file } => format!(
            "SCENE {}: fizikai képe fekete: semmi fény nem jut a kamerába (fényforrás nélküli jelenetben csak a kurzus ambiens tagja látszik), így nincs mit fényterjedésben elcserélni",
            file.display()
        ),
        HarnessKind::NoPlotPython { python } => format!(
            "a Pareto-ábrához a munkapéldány Python-környezete kell, de a(z) {} nem létezik (az `optics validate` egyszer létrehozza; a --no-plot kihagyja az ábrát): semmi sem íródott ki",
            python.display()
        ),
        HarnessKind::Plot(error) => format!(
            "a Pareto-ábra nem rajzolható, így semmi sem íródott ki (a --no-plot kihagyja): {}",
            tool_hu(error)
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
            let need = match (need, top_spp) {
                (validation::tradeoff::budget::Need::Samples { spp }, Some(top)) => format!(
                    "2^{} = {spp} minta kellene pixelenként (kettőhatvány, ahogy a költségvetés renderel), több, mint a legtöbb, amennyivel renderel, {top}",
                    spp.trailing_zeros()
                ),
                (validation::tradeoff::budget::Need::Capped { spp }, _) => format!(
                    "több minta sem éri el: a zaja {spp} minta fölött már nem csökken, ott a kausztikus térkép fotonjai a legtöbbek"
                ),
                (validation::tradeoff::budget::Need::Floor, _) => "semennyi minta nem éri el: már az alsó határa, a torzítás a próba és a referencia zajával együtt, fölötte van (több --pilot-spp a próba részét csökkenti)".to_owned(),
                _ => "semennyi minta nem éri el: már a torzítás maga fölötte van".to_owned(),
            };
            format!(
                "--tolerance {tolerance}: a(z) {metric} {tolerance} nem érhető el; a legjobb {metric} ≤ {best:.4}, ezzel: {settings}; {need}"
            )
        }
        HarnessKind::Budget(BudgetError::PilotNoisy { pilot_spp }) => format!(
            "--pilot-spp {pilot_spp}: a próba nem tudja elválasztani a felületek fényét a zajától (energiája három szórásnyival lejjebb nem nagyobb 0-nál), így relatív hiba nem becsülhető; a jelenet lehet fekete, vagy fénye nőhet a mélységgel (a course_rough π kd albedója 1 fölött: a --lambert az `optics tradeoff --lambert` helyettesítőjével mér); próbálj több próbamintát"
        ),
        HarnessKind::Budget(BudgetError::EnergyGain { material, gain }) => format!(
            "--lambert: a(z) \"{material}\" anyag {gain:.2}-szer annyi fényt ver vissza, mint amennyit kap (a course_rough π kd albedója), így fénye minden visszaverődéssel nő, nincs konvergáló referencia és a hiba nem korlátozható; a --lambert az `optics tradeoff --lambert` helyettesítőjével számol"
        ),
        HarnessKind::Jobs(error) => super::jobs::jobs_hu(error),
    }
}
