//! The outcome of one check: what was compared with what, within which
//! tolerance, the worst disagreements, and the failures and findings.
//!
//! A **failure** is a disagreement the suite is responsible for: one of its
//! laws beyond the stated tolerance of a reference. A **finding** is a
//! disagreement between two references (Mitsuba's float32 evaluation against
//! the exact value, say) that the suite reports without failing for it.
//!
//! What a check says to a reader (its title, its reference, the gist of
//! its findings) it says in English and in Hungarian, both given where
//! the check is declared; `report.json` carries the English.

use errata::Words;
use radiometry::Real;
use serde::{Serialize, Serializer};

/// One check's result, as it appears in `report.json`.
#[derive(Clone, Debug, Serialize)]
pub struct Check {
    /// A stable identifier, `group.reference.law`, e.g. `laws.mitsuba.fresnel`.
    pub id: String,
    /// What is compared, in words.
    #[serde(serialize_with = "english")]
    pub title: Words,
    /// The reference the law is compared with, and its version.
    #[serde(serialize_with = "english")]
    pub reference: Words,
    /// The tolerance and why it is that.
    #[serde(serialize_with = "english")]
    pub tolerance: Words,
    /// The number of cases compared.
    pub cases: usize,
    /// The worst disagreements measured, one per quantity.
    pub metrics: Vec<Metric>,
    /// Cases beyond tolerance, each naming the case and the numbers.
    pub failures: Vec<String>,
    /// Each of [`Check::failures`] in Hungarian, where the check gave it
    /// ([`Check::fail_in_both`]); not part of `report.json`.
    #[serde(skip)]
    failures_hu: Vec<Option<String>>,
    /// Disagreements between references, reported and not counted as
    /// failures, each in English and in Hungarian.
    #[serde(serialize_with = "english_each")]
    pub findings: Vec<Words>,
    /// The findings in one plain sentence, the worst of them named, for a
    /// reader who will not read them all; set by the check that found them.
    #[serde(
        skip_serializing_if = "Option::is_none",
        serialize_with = "english_if_any"
    )]
    pub gist: Option<Words>,
}

/// A text as `report.json` carries it: its English.
fn english<S: Serializer>(words: &Words, serializer: S) -> Result<S::Ok, S::Error> {
    serializer.serialize_str(&words.en)
}

fn english_each<S: Serializer>(words: &[Words], serializer: S) -> Result<S::Ok, S::Error> {
    serializer.collect_seq(words.iter().map(|w| &w.en))
}

fn english_if_any<S: Serializer>(words: &Option<Words>, serializer: S) -> Result<S::Ok, S::Error> {
    match words {
        Some(words) => english(words, serializer),
        None => serializer.serialize_none(),
    }
}

/// `[English, Hungarian]` as [`Words`].
fn words([en, hu]: [&str; 2]) -> Words {
    Words {
        en: en.to_owned(),
        hu: hu.to_owned(),
    }
}

/// The worst value of one measured quantity and where it occurred.
#[derive(Clone, Debug, Serialize, PartialEq)]
pub struct Metric {
    /// What is measured, with its unit (`|ours − exact| in f32 ulps`).
    pub name: String,
    /// [`Metric::name`] in Hungarian, where the check gave it
    /// ([`Check::measure_in_both`]); not part of `report.json`.
    #[serde(skip)]
    pub name_hu: Option<String>,
    /// The worst value over the cases.
    pub worst: f64,
    /// The label of the case where it occurred (empty when no case was compared).
    pub at: String,
}

impl Check {
    /// A check with no cases compared yet; its `title`, `reference` and
    /// `tolerance` in English and in Hungarian.
    pub fn new(id: &str, title: [&str; 2], reference: [&str; 2], tolerance: [&str; 2]) -> Self {
        Self {
            id: id.to_owned(),
            title: words(title),
            reference: words(reference),
            tolerance: words(tolerance),
            cases: 0,
            metrics: Vec::new(),
            failures: Vec::new(),
            failures_hu: Vec::new(),
            findings: Vec::new(),
            gist: None,
        }
    }

    /// Whether every case was within tolerance.
    pub fn passed(&self) -> bool {
        self.failures.is_empty() && self.cases > 0
    }

    /// Records `value` for the quantity `name` at case `at`, keeping the worst.
    /// NaN counts as worse than any number.
    pub fn measure(&mut self, name: &str, value: f64, at: &str) {
        self.measure_at(name, value, || at.to_owned());
    }

    /// [`Check::measure`] with the quantity named in English and in
    /// Hungarian, `[en, hu]`; the English names it in [`Check::worst`].
    pub fn measure_in_both(&mut self, names: [&str; 2], value: f64, at: &str) {
        self.measure_at_in_both(names, value, || at.to_owned());
    }

    /// [`Check::measure`] with the case named by `at`, called only when the
    /// value is a new worst: for a measure taken at every pixel.
    pub fn measure_at(&mut self, name: &str, value: f64, at: impl FnOnce() -> String) {
        self.record(name, None, value, at);
    }

    /// [`Check::measure_at`] with the quantity named in English and in
    /// Hungarian, `[en, hu]`.
    pub fn measure_at_in_both(
        &mut self,
        [en, hu]: [&str; 2],
        value: f64,
        at: impl FnOnce() -> String,
    ) {
        self.record(en, Some(hu), value, at);
    }

    fn record(&mut self, name: &str, hu: Option<&str>, value: f64, at: impl FnOnce() -> String) {
        let value = if value.is_nan() { f64::INFINITY } else { value };
        match self.metrics.iter_mut().find(|m| m.name == name) {
            Some(m) if value > m.worst => {
                m.worst = value;
                m.at = at();
            }
            Some(_) => {}
            None => self.metrics.push(Metric {
                name: name.to_owned(),
                name_hu: hu.map(str::to_owned),
                worst: value,
                at: at(),
            }),
        }
    }

    /// The worst value recorded for `name`, if any.
    pub fn worst(&self, name: &str) -> Option<&Metric> {
        self.metrics.iter().find(|m| m.name == name)
    }

    /// Records a failure, in English only.
    pub fn fail(&mut self, message: String) {
        self.failures.push(message);
        self.failures_hu.push(None);
    }

    /// Records a failure, `[English, Hungarian]`.
    pub fn fail_in_both(&mut self, [en, hu]: [String; 2]) {
        self.failures.push(en);
        self.failures_hu.push(Some(hu));
    }

    /// The failure `i` in Hungarian, where the check gave it.
    pub fn failure_hu(&self, i: usize) -> Option<&str> {
        self.failures_hu.get(i)?.as_deref()
    }

    /// Keeps the first `shown` failures and puts `rest` after them,
    /// `[English, Hungarian]`.
    pub fn keep_failures(&mut self, shown: usize, rest: [String; 2]) {
        self.failures.truncate(shown);
        self.failures_hu.truncate(shown);
        self.fail_in_both(rest);
    }

    /// Records a finding, `[English, Hungarian]`.
    pub fn find(&mut self, [en, hu]: [String; 2]) {
        self.findings.push(Words { en, hu });
    }

    /// Sums the findings up in one plain sentence, `gist`, in English and
    /// in Hungarian, where there are any (a check without findings keeps
    /// none).
    pub fn sum_up(&mut self, gist: impl FnOnce(&Self) -> [String; 2]) {
        if !self.findings.is_empty() {
            let [en, hu] = gist(self);
            self.gist = Some(Words { en, hu });
        }
    }
}

/// `|computed − exact|` in `f32` ulps of `exact` ([`Real::ulp_at`]);
/// infinite if `computed` is NaN.
pub fn ulps_f32(computed: f64, exact: f64) -> f64 {
    let err = (computed - exact).abs();
    if err.is_nan() {
        f64::INFINITY
    } else {
        err / f32::ulp_at(exact)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ulps_f32_counts_in_float32_spacing() {
        assert_eq!(ulps_f32(1.0 + f32::EPSILON as f64, 1.0), 1.0);
        assert_eq!(ulps_f32(0.75 + f32::EPSILON as f64, 0.75), 2.0);
        assert!(ulps_f32(f64::NAN, 1.0).is_infinite());
    }

    #[test]
    fn measure_keeps_the_worst_and_where() {
        let mut check = Check::new("t", ["t", "t"], ["t", "t"], ["t", "t"]);
        check.measure("err", 1.0, "a");
        check.measure("err", 3.0, "b");
        check.measure("err", 2.0, "c");
        check.measure("err", f64::NAN, "d");
        assert_eq!(check.worst("err").unwrap().at, "d");
        assert!(check.worst("err").unwrap().worst.is_infinite());
    }

    #[test]
    fn a_check_without_cases_does_not_pass() {
        assert!(!Check::new("t", ["t", "t"], ["t", "t"], ["t", "t"]).passed());
    }
}
