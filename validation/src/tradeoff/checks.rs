//! `optics validate`'s checks of the committed trade-off records: each is
//! the current version, its every measure is a value the measure can take,
//! its truth converged, and the fronts, verdicts and findings it carries
//! are the ones its own numbers give. The records' numbers themselves are the
//! renderer's measured trade, shown in the report beside these checks.

use std::path::{Path, PathBuf};

use super::findings::Findings;
use super::pareto;
use super::record::{Point, Record};
use super::schema::{MEASURES, SCHEMA, SCHEMA_VERSION};
use super::verdict::Verdict;
use crate::check::Check;
use crate::reference::{parse, ReferenceError};

/// Where the records are, relative to the checkout.
pub const DIR: &str = "docs/tradeoffs";

/// The command that writes them.
pub const REGENERATE: &str = "docs/tradeoffs/make";

/// A truth whose relative noise exceeds this has not converged: the
/// errors measured against it are its noise as much as the setting's.
pub const UNCONVERGED: f64 = 0.01;

/// A record file and what reading it gave.
pub type Read = (PathBuf, Result<Record, ReferenceError>);

/// The records under `dir`, by file name, in name order, each read as
/// this version reads it ([`super::record::upgrade`]).
///
/// # Errors
///
/// A file that cannot be read; a record that is not `optics.tradeoff`
/// JSON is returned as its error, per file, for its check to report.
pub fn read(dir: &Path) -> Result<Vec<Read>, ReferenceError> {
    let io = |source| ReferenceError::Io {
        path: dir.to_owned(),
        source,
    };
    let mut files: Vec<PathBuf> = std::fs::read_dir(dir)
        .map_err(io)?
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|x| x == "json"))
        .collect();
    files.sort();
    files
        .into_iter()
        .map(|path| {
            let text = std::fs::read_to_string(&path).map_err(|source| ReferenceError::Io {
                path: path.clone(),
                source,
            })?;
            let record = parse(&path, &super::record::upgrade(&text), SCHEMA);
            Ok((path, record))
        })
        .collect()
}

/// The check that fails where `dir` holds no record.
pub fn none(dir: &Path) -> Check {
    let mut none = Check::new(
        "tradeoff.records",
        [
            "The speed/accuracy trade-off records",
            "A sebesség és a pontosság cseréjének feljegyzései",
        ],
        [DIR, DIR],
        [
            "one record a lit course scene",
            "kurzusjelenetenként egy feljegyzés",
        ],
    );
    none.cases = 1;
    none.fail(format!(
        "no record in {}: write them with `{REGENERATE}`",
        dir.display()
    ));
    none
}

/// The check of one record, `file` named in it.
pub fn check(file: &Path, record: &Result<Record, ReferenceError>) -> Check {
    let mut check = announced(file);
    let record = match record {
        Ok(record) => record,
        Err(e) => {
            check.cases = 1;
            check.fail(format!("{e}: regenerate with `{REGENERATE}`"));
            return check;
        }
    };
    check.cases = record.points.len();
    current_and_converged(&mut check, record);
    let Some(base) = record.points.first() else {
        check.fail("no setting measured".into());
        return check;
    };
    for point in &record.points {
        physical(&mut check, point);
    }
    fronts(&mut check, &record.points);
    verdicts(&mut check, base, &record.points[1..]);
    against_mitsuba(&mut check, record);
    findings(&mut check, record);
    shortcuts(&mut check, base, &record.points[1..]);
    check
}

/// The check of the record `file`, named and described, nothing yet
/// found.
fn announced(file: &Path) -> Check {
    let stem = file
        .file_stem()
        .map_or_else(String::new, |s| s.to_string_lossy().into_owned());
    Check::new(
        &format!("tradeoff.{stem}"),
        [
            &format!("{stem}: the speed/accuracy trade of every shortcut the scene allows, as recorded"),
            &format!("{stem}: a jelenet minden megengedett rövidítésének sebesség–pontosság cseréje, ahogy feljegyezték"),
        ],
        [
            &format!("{}, written by `{REGENERATE}`", file.display()),
            &format!("{}, a `{REGENERATE}` írta", file.display()),
        ],
        [&format!(
            "schema {SCHEMA} version {SCHEMA_VERSION}; every measure finite, ≥ 0 and ꟻLIP ≤ 1; \
             the truth's relative noise ≤ {UNCONVERGED}; the fronts, verdicts and findings recorded \
             are those the recorded times and errors give; against Mitsuba's truth, where recorded, \
             every setting's light and relative RMSE finite and ≥ 0 and the ranking the one they give, \
             or a reason why there is no reference"
        ), &format!("séma: {SCHEMA}, {SCHEMA_VERSION}. változat; minden mérték véges, ≥ 0, és a ꟻLIP ≤ 1; a pontos kép relatív zaja ≤ {UNCONVERGED}; a feljegyzett frontok, ítéletek és megállapítások azok, amelyeket a feljegyzett idők és hibák adnak; a Mitsuba pontos képéhez mérve, ahol feljegyezték, minden beállítás fénye és relatív négyzetes középhibája véges és ≥ 0, és a sorrend az, amit ezek adnak, vagy indok, miért nincs referencia")],
    )
}

/// The record of this build's version, and its truth converged.
fn current_and_converged(check: &mut Check, record: &Record) {
    if record.version != SCHEMA_VERSION {
        check.fail(format!(
            "written as version {}, this build reads {SCHEMA_VERSION}: regenerate with `{REGENERATE}`",
            record.version
        ));
    }
    if !(record.truth.noise_relative <= UNCONVERGED) {
        check.fail(format!(
            "the truth ({} spp) has relative noise {:.3e} > {UNCONVERGED}: not converged",
            record.truth.spp, record.truth.noise_relative
        ));
    }
    check.measure_in_both(
        ["the truth's relative noise", "a pontos kép relatív zaja"],
        record.truth.noise_relative,
        "",
    );
}

/// The record's Mitsuba truth held to what it must be, and its floor
/// measured where there is one.
fn against_mitsuba(check: &mut Check, record: &Record) {
    let labels: Vec<&str> = record.points.iter().map(|p| p.label.as_str()).collect();
    for failure in super::mitsuba::hold(record.mitsuba.as_ref(), &labels) {
        check.fail(failure);
    }
    if let Some(super::mitsuba::MitsubaTruth::Measured(m)) = &record.mitsuba {
        check.measure_in_both(
            [
                "our truth's light against Mitsuba's, the floor",
                "pontos képünk fénye a Mitsubáéhoz mérve, a padló",
            ],
            m.floor.light,
            &m.estimate,
        );
        check.measure_in_both(
            [
                "our truth's relative RMSE against Mitsuba's, the floor",
                "pontos képünk relatív négyzetes középhibája a Mitsubáéhoz mérve, a padló",
            ],
            m.floor.rel_rmse,
            &m.estimate,
        );
    }
}

/// The findings recorded against those the record's rows give.
fn findings(check: &mut Check, record: &Record) {
    match &record.findings {
        Some(recorded) if *recorded == Findings::of(record) => {}
        Some(_) => {
            check.fail("the findings recorded are not those its rows give: regenerate".to_owned())
        }
        None => check.fail(format!(
            "no findings: written before they were recorded; regenerate with `{REGENERATE}`"
        )),
    }
}

/// What the record says of the scene's own settings `base` and of the
/// `shortcuts`, measured for the report.
fn shortcuts(check: &mut Check, base: &Point, shortcuts: &[Point]) {
    check.measure_in_both(
        [
            "the scene's own settings: relative RMSE from all the light",
            "a jelenet saját beállításai: relatív négyzetes középhiba az összes fényhez",
        ],
        base.errors.rel_rmse,
        &base.label,
    );
    for p in shortcuts {
        check.measure_in_both(
            [
                "a shortcut's ΔE p99 against the scene's own",
                "egy rövidítés ΔE p99-e a jelenet sajátjához mérve",
            ],
            p.against_scene.delta_e_p99,
            &p.label,
        );
    }
    let worth = shortcuts
        .iter()
        .filter(|p| p.verdict == Some(Verdict::WorthIt))
        .count();
    check.measure_in_both(
        [
            "shortcuts worth taking (not seen, faster)",
            "megérő rövidítések (nem látható, gyorsabb)",
        ],
        worth as f64,
        "",
    );
}

/// Every measure of `point` a value the measure can take.
fn physical(check: &mut Check, point: &Point) {
    for (against, errors) in [("truth", &point.errors), ("scene", &point.against_scene)] {
        for name in MEASURES {
            let value = errors.get(name);
            let top = if name == "flip_mean" {
                1.0
            } else {
                f64::INFINITY
            };
            if !(value >= 0.0 && value <= top && value.is_finite()) {
                check.fail(format!(
                    "`{}`: {name} against the {against} is {value}, outside [0, {top}]",
                    point.label
                ));
            }
        }
    }
    if !(point.seconds_median > 0.0 && point.seconds_median.is_finite()) {
        check.fail(format!(
            "`{}`: seconds_median is {}",
            point.label, point.seconds_median
        ));
    }
    if !(point.rays > 0.0 && point.rays.is_finite()) {
        check.fail(format!("`{}`: rays is {}", point.label, point.rays));
    }
}

/// The fronts recorded against the fronts of the recorded numbers.
fn fronts(check: &mut Check, points: &[Point]) {
    for name in MEASURES {
        let xy: Vec<(f64, f64)> = points
            .iter()
            .map(|p| (p.seconds_median, p.errors.get(name)))
            .collect();
        let on = pareto::front(&xy);
        for (i, p) in points.iter().enumerate() {
            let recorded = p.pareto.iter().any(|m| m == name);
            if recorded != on.contains(&i) {
                check.fail(format!(
                    "`{}`: recorded {} the {name} front, but its numbers put it {}",
                    p.label,
                    if recorded { "on" } else { "off" },
                    if recorded { "off" } else { "on" }
                ));
            }
        }
    }
}

/// The verdicts recorded against the rule applied to the recorded numbers.
fn verdicts(check: &mut Check, base: &Point, shortcuts: &[Point]) {
    for p in shortcuts {
        let rule = Verdict::of(
            p.against_scene.delta_e_p99,
            p.seconds_median,
            base.seconds_median,
        );
        if p.verdict != Some(rule) {
            check.fail(format!(
                "`{}`: recorded verdict {:?}, but its numbers give {rule:?}",
                p.label, p.verdict
            ));
        }
    }
}
