//! The result record every subcommand prints: as text for people, or with
//! `--json` as one JSON object with stable fields for scripts, documented
//! in `docs/cli.md` ("The JSON record").
//!
//! [`Record`] is the one definition of that object for every `--json`
//! output: the law evaluators', the quiz's, `optics batch`'s lines, and
//! `render`'s, `inspect`'s and `validate`'s, all built the same way
//! ([`Record::new`], then [`Record::input`]/[`Record::inputs_from`],
//! [`Record::step`], [`Record::set_answer`], [`Record::detail`]/
//! [`Record::details_from`], [`Record::note`]) and printed by
//! the front end (`optics`'s `Ui::show`, or `Ui::show_steps`, whose text
//! is the steps alone). A failure prints the front end's error object
//! instead.
//!
//! Whether the working is wanted ([`Steps`]) is decided once by the caller
//! (`optics batch --no-steps`, a request's `"steps"`) and handed to the law,
//! which gives it to its record ([`Record::with_steps`]); each step is a
//! closure, so a record whose working is skipped never formats it.

use crate::lang::Lang;
use serde::ser::SerializeMap;
use serde::{Serialize, Serializer};
use serde_json::{Map, Value};
use std::borrow::Cow;

/// The answer to one evaluation.
#[derive(Clone, Debug, Serialize)]
#[serde(untagged)]
pub enum Answer {
    /// A number in the record's unit.
    Number(f64),
    /// A direction or an RGB triple, `[x, y, z]`.
    Vector([f64; 3]),
    /// No value exists (a ray totally reflected has no refracted direction).
    None,
    /// Several answers, in order (a whole quiz, the files a render wrote).
    List(Vec<Value>),
    /// Named answers (what a scene needs).
    Object(Map<String, Value>),
    /// Yes or no (whether every check of the harness passed).
    Verdict(bool),
}

/// Whether a record's working is written: every subcommand wants it; `optics
/// batch` skips it for `--no-steps` or a request's `"steps": false`, and the
/// record's `steps` is then `[]`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Steps {
    /// The working is written, line by line.
    #[default]
    Wanted,
    /// The working is left out; `steps` stays `[]`.
    Skipped,
}

impl Steps {
    /// `true` is [`Steps::Wanted`], as a request's `"steps"` says it.
    pub fn from_wanted(wanted: bool) -> Self {
        if wanted {
            Steps::Wanted
        } else {
            Steps::Skipped
        }
    }
}

/// One evaluation: what was asked, the answer with its unit, and the working.
///
/// The JSON fields `law`, `inputs`, `answer`, `unit`, `steps` are always
/// present; `details` and `notes` only when there is something in them.
#[derive(Clone, Debug, Serialize)]
pub struct Record {
    /// The law or exercise evaluated, as named in `optics batch`.
    pub law: &'static str,
    /// A one-line heading in the chosen language (text output only).
    #[serde(skip)]
    pub title: String,
    /// The inputs as given (directions before normalisation).
    pub inputs: Fields,
    /// The answer: a number, a vector `[x, y, z]`, `null` when none exists,
    /// or a list.
    pub answer: Answer,
    /// How the answer reads for people, when a bare number would say less
    /// (`0.0277778 (2.78 %)`); text output only.
    #[serde(skip)]
    pub answer_text: Option<String>,
    /// The answer's unit: `"1"` for dimensionless, `"W/(sr m^2)"`, `"deg"`.
    pub unit: &'static str,
    /// The working, one line each: formula, substitution, result; empty
    /// when [`Steps::Skipped`].
    pub steps: Vec<String>,
    /// Whether [`Record::step`] writes its line.
    #[serde(skip)]
    wanted: Steps,
    /// Further named results (R_s, R_p, T, …), machine-readable.
    #[serde(skip_serializing_if = "Fields::is_empty")]
    pub details: Fields,
    /// Remarks: normalised inputs, disagreements with a printed answer.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub notes: Vec<String>,
}

impl Record {
    /// A record of `law` with its heading and the answer's unit, no inputs
    /// yet, the answer [`Answer::None`] and the working wanted.
    pub fn new(law: &'static str, title: String, unit: &'static str) -> Self {
        Self {
            law,
            title,
            inputs: Fields::default(),
            answer: Answer::None,
            answer_text: None,
            unit,
            steps: Vec::new(),
            wanted: Steps::Wanted,
            details: Fields::default(),
            notes: Vec::new(),
        }
    }

    /// The record with its working written or skipped, as the caller
    /// decided.
    pub fn with_steps(mut self, steps: Steps) -> Self {
        self.wanted = steps;
        self
    }

    /// The answer, with how it reads for people when a bare number would say
    /// less.
    pub fn set_answer(&mut self, answer: Answer, text: Option<String>) -> &mut Self {
        self.answer = answer;
        self.answer_text = text;
        self
    }

    /// Every field of `value` as an input (a settings struct, a map); a value
    /// that is not a JSON object goes in whole, under `"value"`.
    pub fn inputs_from(&mut self, value: impl Serialize) -> &mut Self {
        fields_into(&mut self.inputs, value);
        self
    }

    /// Every field of `value` as a detail; a value that is not a JSON object
    /// goes in whole, under `"value"`.
    pub fn details_from(&mut self, value: impl Serialize) -> &mut Self {
        fields_into(&mut self.details, value);
        self
    }

    /// Sets the input `name` to `value`, as given.
    pub fn input(&mut self, name: &'static str, value: impl Serialize) -> &mut Self {
        self.inputs.insert(Cow::Borrowed(name), json(value));
        self
    }

    /// Sets the detail `name` to `value`.
    pub fn detail(&mut self, name: &'static str, value: impl Serialize) -> &mut Self {
        self.details.insert(Cow::Borrowed(name), json(value));
        self
    }

    /// A line of the working, formatted only when the working is wanted.
    pub fn step(&mut self, line: impl FnOnce() -> String) -> &mut Self {
        if self.wanted == Steps::Wanted {
            self.steps.push(line());
        }
        self
    }

    /// A remark, always written.
    pub fn note(&mut self, line: String) -> &mut Self {
        self.notes.push(line);
        self
    }

    /// The record as people read it.
    pub fn to_text(&self, lang: Lang) -> String {
        let mut out = format!("{}\n", self.title);
        for step in &self.steps {
            out.push_str(&format!("  {step}\n"));
        }
        let label = lang.pick("answer", "eredmény");
        let answer = match (&self.answer_text, &self.answer) {
            (Some(text), _) => text.clone(),
            (None, Answer::Number(x)) => format!("{}{}", number(*x), unit_text(self.unit)),
            (None, Answer::Vector(v)) => vector(*v),
            (None, Answer::None) => lang.pick("none", "nincs").to_owned(),
            (None, Answer::List(items)) => items
                .iter()
                .map(|item| match item {
                    Value::String(s) => s.clone(),
                    Value::Bool(b) => lang
                        .pick(&b.to_string(), if *b { "igaz" } else { "hamis" })
                        .to_owned(),
                    other => other.to_string(),
                })
                .collect::<Vec<_>>()
                .join(", "),
            (None, Answer::Object(fields)) => fields
                .iter()
                .map(|(name, value)| format!("{name} = {value}"))
                .collect::<Vec<_>>()
                .join(", "),
            (None, Answer::Verdict(yes)) => lang
                .pick(
                    if *yes { "yes" } else { "no" },
                    if *yes { "igen" } else { "nem" },
                )
                .to_owned(),
        };
        out.push_str(&format!("{label}: {}\n", answer.trim_end()));
        for note in &self.notes {
            out.push_str(&format!("{} {note}\n", lang.pick("note:", "megjegyzés:")));
        }
        out
    }
}

fn json(value: impl Serialize) -> Value {
    // Serialising plain numbers, strings and arrays cannot fail; a NaN would
    // become null, but inputs are validated finite before they get here.
    serde_json::to_value(value).unwrap_or(Value::Null)
}

fn fields_into(fields: &mut Fields, value: impl Serialize) {
    match json(value) {
        Value::Object(map) => {
            for (name, value) in map {
                fields.insert(Cow::Owned(name), value);
            }
        }
        other => fields.insert(Cow::Borrowed("value"), other),
    }
}

/// A record's named values (its `inputs`, its `details`), written as one
/// JSON object with the names in byte order, as `serde_json`'s own map
/// writes them. A record has a handful, so a sorted list serves, and the
/// laws' names (`&'static str`) are never copied.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Fields(Vec<(Cow<'static, str>, Value)>);

impl Fields {
    /// Sets `name` to `value`, replacing the value it had.
    pub fn insert(&mut self, name: Cow<'static, str>, value: Value) {
        // A law sets a handful: room for them at once, not grown by doubling.
        self.0.reserve(if self.0.is_empty() { 8 } else { 1 });
        match self.0.binary_search_by(|(n, _)| byte_order(n, &name)) {
            Ok(i) => self.0[i].1 = value,
            Err(i) => self.0.insert(i, (name, value)),
        }
    }

    /// The value of `name`, if set.
    pub fn get(&self, name: &str) -> Option<&Value> {
        let i = self.0.binary_search_by(|(n, _)| byte_order(n, name)).ok()?;
        Some(&self.0[i].1)
    }

    /// Whether no value is set.
    pub fn is_empty(&self) -> bool {
        self.0.is_empty()
    }
}

/// The order of `str`, byte by byte: the names are a few bytes long, and
/// compared in place they cost less than a call to compare memory.
fn byte_order(a: &str, b: &str) -> std::cmp::Ordering {
    a.bytes().cmp(b.bytes())
}

impl Serialize for Fields {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        let mut map = serializer.serialize_map(Some(self.0.len()))?;
        for (name, value) in &self.0 {
            map.serialize_entry(name.as_ref(), value)?;
        }
        map.end()
    }
}

/// The unit as it follows a number in text: `2.4 W/(sr m^2)`, `5.74°`.
fn unit_text(unit: &str) -> String {
    match unit {
        "1" | "" => String::new(),
        "deg" => "°".to_owned(),
        other => format!(" {other}"),
    }
}

/// A number for people: six significant digits, no trailing zeros.
pub fn number(x: f64) -> String {
    if x == 0.0 {
        return "0".to_owned(); // also −0, which a reader would take for a sign error
    }
    if !x.is_finite() {
        return format!("{x}");
    }
    let magnitude = x.abs().log10().floor() as i32;
    if !(-4..=6).contains(&magnitude) {
        return format!("{x:.5e}");
    }
    let decimals = (5 - magnitude).max(0) as usize;
    let text = format!("{x:.decimals$}");
    if text.contains('.') {
        text.trim_end_matches('0').trim_end_matches('.').to_owned()
    } else {
        text
    }
}

/// A vector for people: `(x, y, z)` with [`number`]s.
pub fn vector(v: [f64; 3]) -> String {
    format!("({}, {}, {})", number(v[0]), number(v[1]), number(v[2]))
}

/// A fraction as a percentage rounded half-away-from-zero to `decimals`.
pub fn percent(x: f64, decimals: usize) -> String {
    format!("{:.decimals$} %", x * 100.0)
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::json;

    #[test]
    fn numbers_show_six_significant_digits_without_trailing_zeros() {
        assert_eq!(number(0.027777777777777776), "0.0277778");
        assert_eq!(number(2.5), "2.5");
        assert_eq!(number(2.4000000000000004), "2.4");
        assert_eq!(number(5.739170477266787), "5.73917");
        assert_eq!(number(-0.6), "-0.6");
        assert_eq!(number(1e-9), "1.00000e-9");
        assert_eq!(number(0.0), "0");
    }

    #[test]
    fn records_take_inputs_and_details_from_any_serialisable_value() {
        #[derive(Serialize)]
        struct Settings {
            spp: u32,
            seed: u64,
        }
        let mut record = Record::new("render", "Render".into(), "rays/s");
        record
            .inputs_from(Settings { spp: 4, seed: 7 })
            .input("scene", "a.json")
            .details_from(serde_json::json!({ "png": "a.png" }))
            .details_from(3)
            .set_answer(Answer::Number(1e6), None)
            .step(|| "rendered".into());
        let json = serde_json::to_value(&record).unwrap();
        assert_eq!(
            json,
            serde_json::json!({
                "law": "render",
                "inputs": { "spp": 4, "seed": 7, "scene": "a.json" },
                "answer": 1e6,
                "unit": "rays/s",
                "steps": ["rendered"],
                "details": { "png": "a.png", "value": 3 },
            })
        );
    }

    /// The names in byte order and a name set twice keeping its last value,
    /// as `serde_json`'s map writes them: the text is the same.
    #[test]
    fn fields_are_written_as_a_json_map_writes_them() {
        let sets = [
            ("r_s", json!(0.25)),
            ("r_p", json!(1e-300)),
            ("transmittance", json!(0.5)),
            ("cos_t", json!(null)),
            ("total_internal_reflection", json!(false)),
            ("R", json!("upper case sorts first")),
            ("r_s", json!(0.75)),
        ];
        let (mut fields, mut map) = (Fields::default(), Map::new());
        for (name, value) in sets {
            fields.insert(Cow::Owned(name.to_owned()), value.clone());
            map.insert(name.to_owned(), value);
        }
        let written = serde_json::to_string(&fields).unwrap();
        assert_eq!(written, serde_json::to_string(&map).unwrap());
        assert_eq!(fields.get("r_s"), Some(&json!(0.75)));
        assert_eq!(fields.get("kappa"), None);
    }

    #[test]
    fn percentages_round_to_nearest() {
        assert_eq!(percent(0.027777777777777776, 2), "2.78 %");
        assert_eq!(percent(0.04, 1), "4.0 %");
    }
}
