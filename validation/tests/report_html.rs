//! `report.html` as a reader gets it: every number of `report.json` read
//! back out of the page, and the page opened in a real browser (headless
//! Chromium), which must show no console error or broken image and let no
//! element reach past the window at 1400 and at 400 pixels wide.
//!
//! The browser tests skip, saying so, where no Chromium is installed
//! (`apt-get install chromium`; `CHROMIUM=/path` names another).

mod page;
use page::{english_left_in, number_marks, words};

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::process::Command;

use record::Lang;
use validation::check::Check;
use validation::report::{to_html, to_json, Report, WorstDeltaE};
use validation::speed::Timing;
use validation::tradeoff::findings::{Findings, Shortcut};

/// A report with a check in every area and the awkward content real ones
/// carry: a JSON request as the place of a worst value, long names, a
/// failure, findings, a figure.
fn sample() -> (Report, Vec<String>) {
    let mut report = Report::new(true, "optics validate --quick");
    let mut laws = check(
        "laws.mitsuba.random",
        1000,
        &[
            (
                "fresnel R: |ours − f64 law| (f32 ulps)",
                0.94903221167624,
                r#"case 720: {"law":"fresnel","cos_i":-0.4081333875656128,"eta":0.8534522652626038}"#,
            ),
            (
                "fresnel R: |Mitsuba − f64 law|",
                3.5504471460057196e-7,
                "case 756",
            ),
        ],
    );
    laws.find([
        "Mitsuba R at eta=1.0001 outside cos=0.01: 7.180912792682648e-2, exact 7.178980365261572e-2 (off by 1.93e-5, 2594 f32 ulps)".into(),
        "a Mitsuba R értéke itt: eta=1.0001 kívül cos=0.01: 7.180912792682648e-2, a pontos 7.178980365261572e-2 (eltérés 1.93e-5, 2594 f32 ulps)".into(),
    ]);
    let mpmath = check(
        "laws.mpmath.fresnel_dielectric",
        400,
        &[
            (
                "f64 R_s (ulps)",
                3.748045487603745,
                "glass inside critical-1e-12rad",
            ),
            (
                "f64 R_s (relative)",
                4.3436967647709994e-16,
                "eta=1-1e-12 outside cos=0.9",
            ),
        ],
    );
    let mut render = check(
        "renders.mitsuba.kaleidoscope_lit.path",
        230_400,
        &[
            ("|t|", 3.47751983589165, "pixel (232, 85) R"),
            ("masked edge pixels", 104.0, ""),
        ],
    );
    render.fail_in_both([
        "pixel (1, 2) R: t = 99".into(),
        "képpont (1, 2) R: t = 99".into(),
    ]);
    let colour = check(
        "colour.colour-science.tables",
        471,
        &[("|ours − colour-science|", 0.0, "x̄(360 nm)")],
    );
    let light = check(
        "full_light.tracer.kaleidoscope_lit.photon.all_the_light",
        3,
        &[("photon / ptracer", 1.0012345678901234, "")],
    );
    let metals = check(
        "colour.colour-science.metals",
        20,
        &[("reflectance: max |ours − exact|", 7.77e-16, "gold 60°")],
    );
    let flip = check(
        "images.flip.nvidia",
        6,
        &[("mean: |ours − NVIDIA|", 3.258e-6, "noise pair")],
    );
    let techniques = check(
        "techniques.refraction.cheap",
        360,
        &[(
            "into water, c = 1: angle from Snell's law (°)",
            10.63,
            "60°",
        )],
    );
    report.checks = vec![
        laws, mpmath, metals, colour, render, flip, light, techniques,
    ];
    report.metal_delta_e = vec![WorstDeltaE {
        metal: "gold".into(),
        method: "course RGB n, κ (seed 000)".into(),
        delta_e_2000: 5.257051672420828,
        at_angle_deg: 0.0,
    }];
    report.speed = ["spectral: 85 wavelengths", "course RGB: 3 wavelengths"]
        .iter()
        .zip([15220.5761, 437.50055])
        .map(|(method, ns)| Timing {
            method: (*method).into(),
            ns_per_colour: ns,
            iterations: 20_000,
            optimised: true,
        })
        .collect();
    // The findings as the command writes them: those of its rows.
    let mut record: validation::tradeoff::record::Record =
        serde_json::from_str(TRADEOFF).expect("the sample record");
    record.findings = Some(validation::tradeoff::findings::Findings::of(&record));
    report.tradeoffs = vec![record];
    report.checks.push(validation::tradeoff::checks::check(
        Path::new("docs/tradeoffs/gold_spheres-lambert.json"),
        &Ok(report.tradeoffs[0].clone()),
    ));
    // Stand-in words (not the library's prose), to show the page escapes them.
    report.tradeoff_words = report
        .tradeoffs
        .iter()
        .filter_map(|r| Some((r.stem(), wording(r.findings.as_ref()?).join(" "))))
        .collect();
    report.summarise();
    (
        report,
        vec![
            "figures/render_kaleidoscope_lit_path.png".to_owned(),
            "figures/tradeoff_gold_spheres-lambert.png".to_owned(),
        ],
    )
}

/// Words for a sweep's findings, standing in for the command's prose: a
/// sentence on the scene's own settings and one per shortcut judged, with
/// Markdown's code spans and characters the page must escape.
fn wording(findings: &Findings) -> Vec<String> {
    let mut sentences = vec![format!(
        "The scene's own settings are {:.3} <relative RMSE> from the truth.",
        findings.own.rel_rmse
    )];
    sentences.extend(shortcuts(findings).map(|s| {
        format!(
            "`{}` takes {:.2}× the time & is ΔE p99 {:.2} from them.",
            s.label, s.time_ratio, s.delta_e_p99
        )
    }));
    sentences
}

/// The shortcuts the findings judge: worth it, seen, or no gain.
fn shortcuts(findings: &Findings) -> impl Iterator<Item = &Shortcut> {
    findings
        .worth_it
        .iter()
        .chain(&findings.seen)
        .chain(&findings.no_gain)
}

/// A trade-off record of two settings, as `optics tradeoff` writes one.
const TRADEOFF: &str = r#"{"schema": "optics.tradeoff", "version": 2,
  "scene": "crates/tracer/scenes/gold_spheres.json", "lambert": true, "width": 80, "height": 60,
  "machine": "a machine, 2 threads", "date": "2026-12-04", "load": "load average 0.5",
  "command": "optics tradeoff crates/tracer/scenes/gold_spheres.json --lambert",
  "truth": {"spp": 64, "noise_relative": 3.56e-5},
  "points": [
    {"axis": "scene", "label": "scene: whitted, max_depth 63, fresnel exact",
     "settings": {"integrator": "whitted", "max_depth": 63, "fresnel": "exact"},
     "seconds_median": 0.000250786, "seconds": [0.000262, 0.000250786, 0.000249],
     "rays": 5304.0,
     "errors": {"rel_rmse": 0.1796523927533933, "delta_e_mean": 2.06, "delta_e_p99": 28.047669109095697, "flip_mean": 0.0678083591684686, "light": 0.9623574712545723},
     "against_scene": {"rel_rmse": 0.0, "delta_e_mean": 0.0, "delta_e_p99": 0.0, "flip_mean": 0.0},
     "pareto": ["delta_e_mean", "delta_e_p99", "flip_mean"]},
    {"axis": "fresnel", "label": "fresnel schlick-rarer",
     "settings": {"integrator": "whitted", "max_depth": 63, "fresnel": "schlick-rarer"},
     "seconds_median": 0.0002, "seconds": [0.0002], "rays": 5304.0,
     "errors": {"rel_rmse": 0.1791, "delta_e_mean": 2.26, "delta_e_p99": 28.05, "flip_mean": 0.072},
     "against_scene": {"rel_rmse": 0.01, "delta_e_mean": 0.1, "delta_e_p99": 1.21, "flip_mean": 0.01},
     "pareto": ["rel_rmse", "delta_e_mean", "delta_e_p99", "flip_mean"], "verdict": "trade"}
  ]}"#;

/// A check of `cases` cases with its worst values `(quantity, value, at)`.
fn check(id: &str, cases: usize, worst: &[(&str, f64, &str)]) -> Check {
    let mut check = Check::new(
        id,
        [&format!("the check {id}"), &format!("az ellenőrzés: {id}")],
        ["a reference", "egy referencia"],
        ["a tolerance", "egy tűrés"],
    );
    check.cases = cases;
    for (name, value, at) in worst {
        check.measure(name, *value, at);
    }
    check
}

/// Every number the page carries, by where `report.json` holds it (a JSON
/// pointer, `data-json`) with its value in full (`data-value`); the page
/// shows each in one place.
fn numbers_in(html: &str) -> BTreeMap<String, f64> {
    let attribute = |tag: &str, name: &str| {
        let start = tag.find(&format!("{name}=\""))? + name.len() + 2;
        let len = tag[start..].find('"')?;
        Some(unescape(&tag[start..start + len]))
    };
    let mut found = BTreeMap::new();
    for tag in html.split('<').skip(1) {
        let tag = &tag[..tag.find('>').unwrap_or(tag.len())];
        let (Some(pointer), Some(value)) =
            (attribute(tag, "data-json"), attribute(tag, "data-value"))
        else {
            continue;
        };
        let value: f64 = value.parse().expect("a number in data-value");
        assert!(
            found.insert(pointer.clone(), value).is_none(),
            "{pointer} shown twice"
        );
    }
    found
}

/// Every number the page quotes again (`data-quote`: a card's headline),
/// with the value it shows.
fn quotes_in(html: &str) -> Vec<(String, f64)> {
    html.split("data-quote=\"")
        .skip(1)
        .map(|rest| {
            let pointer = unescape(&rest[..rest.find('"').expect("its end")]);
            let value = rest.split("data-value=\"").nth(1).expect("its value");
            let value = value[..value.find('"').expect("its end")]
                .parse()
                .expect("a number");
            (pointer, value)
        })
        .collect()
}

fn unescape(text: &str) -> String {
    text.replace("&quot;", "\"")
        .replace("&lt;", "<")
        .replace("&gt;", ">")
        .replace("&amp;", "&")
}

/// Every number of `report.json` that the page shows as a number: the
/// summary's counts, each check's cases and worst values, the metals'
/// worst colour errors and the timings (the figures' data are drawn, not
/// tabled), by JSON pointer.
fn numbers_of(json: &str) -> BTreeMap<String, f64> {
    let report: serde_json::Value = serde_json::from_str(json).expect("report.json");
    let mut found = BTreeMap::new();
    let mut take = |pointer: String| {
        let value = report
            .pointer(&pointer)
            .and_then(serde_json::Value::as_f64)
            .unwrap_or_else(|| panic!("no number at {pointer}"));
        found.insert(pointer, value);
    };
    for field in ["checks", "passed", "failed", "findings"] {
        take(format!("/summary/{field}"));
    }
    for (i, check) in report["checks"]
        .as_array()
        .expect("checks")
        .iter()
        .enumerate()
    {
        take(format!("/checks/{i}/cases"));
        for j in 0..check["metrics"].as_array().expect("metrics").len() {
            take(format!("/checks/{i}/metrics/{j}/worst"));
        }
    }
    for k in 0..report["metal_delta_e"]
        .as_array()
        .expect("metal_delta_e")
        .len()
    {
        take(format!("/metal_delta_e/{k}/delta_e_2000"));
        take(format!("/metal_delta_e/{k}/at_angle_deg"));
    }
    for (k, record) in report["tradeoffs"]
        .as_array()
        .expect("tradeoffs")
        .iter()
        .enumerate()
    {
        for (i, point) in record["points"]
            .as_array()
            .expect("points")
            .iter()
            .enumerate()
        {
            for field in [
                "seconds_median",
                "errors/rel_rmse",
                "errors/delta_e_mean",
                "errors/delta_e_p99",
                "errors/flip_mean",
                "against_scene/delta_e_p99",
            ] {
                take(format!("/tradeoffs/{k}/points/{i}/{field}"));
            }
            if point["errors"].get("light").is_some() {
                take(format!("/tradeoffs/{k}/points/{i}/errors/light"));
            }
            // The range of the timed renders: the fastest and the slowest.
            let seconds: Vec<f64> = point["seconds"]
                .as_array()
                .expect("seconds")
                .iter()
                .map(|s| s.as_f64().expect("a time"))
                .collect();
            if seconds.len() > 1 {
                let by_time = |a: &(usize, &f64), b: &(usize, &f64)| a.1.total_cmp(b.1);
                for (j, _) in [
                    seconds.iter().enumerate().min_by(by_time),
                    seconds.iter().enumerate().max_by(by_time),
                ]
                .into_iter()
                .flatten()
                {
                    take(format!("/tradeoffs/{k}/points/{i}/seconds/{j}"));
                }
            }
        }
    }
    for k in 0..report["speed"].as_array().expect("speed").len() {
        take(format!("/speed/{k}/ns_per_colour"));
        take(format!("/speed/{k}/iterations"));
    }
    found
}

#[test]
fn the_page_carries_every_number_of_report_json() {
    let (report, figures) = sample();
    let html = to_html(&report, &figures, Lang::En);
    let json = to_json(&report);
    assert_eq!(numbers_in(&html), numbers_of(&json));
    let quotes = quotes_in(&html);
    // The two laws' cards quote their worst ulps; the metals', ꟻLIP's,
    // the techniques' and the trade-off's cards their headline quantity
    // (the sample's colour, render and light checks measure others).
    assert_eq!(
        quotes.len(),
        6,
        "the cards quote their headlines: {quotes:?}"
    );
    for (pointer, value) in quotes {
        assert_eq!(numbers_of(&json).get(&pointer), Some(&value), "{pointer}");
    }
    // 4 counts, 9 checks' cases, 8 + 3 + 4 worst values, 2 of the metal,
    // 4 timings, 2 × 6 of the trade-off's settings, the first's light and
    // the range of its three timed renders.
    assert_eq!(numbers_of(&json).len(), 49);
}

#[test]
fn a_page_with_a_row_dropped_is_caught() {
    let (report, figures) = sample();
    let html = to_html(&report, &figures, Lang::En);
    let row = html.find("<tr><td><span class=pass>").expect("a row");
    let end = row + html[row..].find("</tr>").expect("its end") + "</tr>".len();
    let dropped = format!("{}{}", &html[..row], &html[end..]);
    assert_ne!(numbers_in(&dropped), numbers_of(&to_json(&report)));
}

#[test]
fn a_page_with_a_timing_or_a_count_dropped_is_caught() {
    let (report, figures) = sample();
    let html = to_html(&report, &figures, Lang::En);
    let json = numbers_of(&to_json(&report));
    for pointer in [
        "/speed/1/ns_per_colour",
        "/summary/findings",
        "/metal_delta_e/0/at_angle_deg",
    ] {
        let cell = html
            .find(&format!("data-json=\"{pointer}\""))
            .expect(pointer);
        let dropped = html.replacen(&html[cell..cell + 12], "data-gone", 1);
        assert_ne!(numbers_in(&dropped), json, "{pointer}");
    }
}

#[test]
fn a_page_showing_a_wrong_number_is_caught() {
    let (report, figures) = sample();
    let html = to_html(&report, &figures, Lang::En).replacen(
        "data-value=\"5.257051672420828e0\"",
        "data-value=\"5.26e0\"",
        1,
    );
    assert_ne!(numbers_in(&html), numbers_of(&to_json(&report)));
}

#[test]
fn report_json_names_its_schema_and_version() {
    let (report, _) = sample();
    let json: serde_json::Value = serde_json::from_str(&to_json(&report)).unwrap();
    assert_eq!(json["schema"], "validation-report/2");
}

/// The sample's failed check and its verdict in Hungarian: the parts of
/// the page a run without failures (`tests/harness.rs`) never shows.
#[test]
fn a_failing_report_in_hungarian_has_no_english_left() {
    let (report, figures) = sample();
    let [en, hu] = [Lang::En, Lang::Hu].map(|lang| to_html(&report, &figures, lang));
    let names = report
        .checks
        .iter()
        .flat_map(|c| c.id.split('.').map(str::to_owned))
        .collect();
    let left = english_left_in(&hu, &en, &names);
    assert!(left.is_empty(), "English left:\n{}", left.join("\n"));
    let verdict = format!("{} ellenőrzésből 1 HIBÁS.", report.summary.checks);
    assert!(words(&hu).contains(&verdict), "the verdict in Hungarian");
    assert!(hu.contains("<p>Sikertelen esetek (1):</p>"));
    assert_eq!(number_marks(&hu), number_marks(&en));
}

#[test]
fn the_first_screen_gives_the_verdict_and_a_card_per_area() {
    let (report, figures) = sample();
    let html = to_html(&report, &figures, Lang::En);
    let cards = &html[html.find("<div class=cards>").unwrap()..html.find("<h2").unwrap()];
    for title in [
        "Laws against 50-digit mpmath",
        "Laws against Mitsuba 3",
        "Colour against colour-science",
        "Renders against Mitsuba 3",
        "All the light",
        "The speed/accuracy trade, whole renders",
    ] {
        assert!(cards.contains(title), "no card {title}");
    }
    assert!(
        cards.contains("0 of 1 pass"),
        "the failed render check's card"
    );
    // The course texts' card: the errata by class, from their table, the
    // worst three, and where the rest are.
    let course = &cards[cards
        .find("id=course-texts")
        .expect("the course texts' card")..];
    let tally = errata::listing::tally(record::Lang::En);
    assert!(course.contains(&tally), "{tally} not on the card");
    assert_eq!(course.matches("<li>").count(), 3, "the worst three");
    assert!(course.contains("href=\"docs/errata.md\""));
    assert!(words(&html).contains("1 of 9 checks FAIL."));
    assert!(words(&html).contains("8 passed; 1 findings about the references"));
    // Numbers for reading, a request's fields as inputs.
    assert!(html.contains(">3.55e-7<") && html.contains(">0.949<"));
    assert!(html.contains("case 720: cos_i = -0.4081, eta = 0.8535, law = fresnel"));
}

/// The fold of the page for the trade-off record `stem`: from its
/// summary to its end.
fn tradeoff_section<'a>(html: &'a str, stem: &str) -> &'a str {
    let start = html
        .find(&format!("<summary><b>{stem}</b>"))
        .unwrap_or_else(|| panic!("no section for {stem}"));
    let end = start + html[start..].find("</details>").expect("its end");
    &html[start..end]
}

/// Text as the page holds it between tags.
fn escaped(text: &str) -> String {
    text.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
}

#[test]
fn each_swept_scene_shows_its_findings_in_words_its_settings_and_its_plot() {
    let (report, figures) = sample();
    let html = to_html(&report, &figures, Lang::En);
    for record in &report.tradeoffs {
        let section = tradeoff_section(&html, &record.stem());
        let findings = record.findings.as_ref().expect("the sample's findings");
        let sentences = wording(findings);
        assert!(
            sentences.len() > 1,
            "the sample words a setting: {sentences:?}"
        );
        // The paragraph, as a reader sees it: every word, the code spans
        // set as code.
        let paragraph = sentences.join(" ").replace('`', "");
        assert!(
            words(section).contains(&escaped(&paragraph)),
            "{} does not say {paragraph:?}",
            record.stem()
        );
        for shortcut in shortcuts(findings) {
            let code = format!("<code>{}</code>", escaped(&shortcut.label));
            assert!(section.contains(&code), "no {code}");
        }
        // A row per setting, in the record's order.
        let rows: Vec<&str> = section
            .split("<tr><td>")
            .skip(1)
            .map(|row| &row[..row.find("</td>").expect("its first cell")])
            .collect();
        let labels: Vec<String> = record.points.iter().map(|p| escaped(&p.label)).collect();
        assert_eq!(rows, labels, "{}", record.stem());
        // Where and how its times were taken, and its plot.
        for stamp in [&record.command, &record.machine, &record.date, &record.load] {
            assert!(words(section).contains(&escaped(stamp)), "no {stamp}");
        }
        let plot = format!("src=\"figures/tradeoff_{}.png\"", record.stem());
        assert!(section.contains(&plot), "no {plot}");
    }
}

// -- in a browser ------------------------------------------------------------

fn chromium() -> Option<PathBuf> {
    if let Some(path) = std::env::var_os("CHROMIUM") {
        return Some(PathBuf::from(path));
    }
    ["chromium", "chromium-browser", "google-chrome"]
        .iter()
        .find_map(|name| {
            std::env::var_os("PATH").and_then(|paths| {
                std::env::split_paths(&paths)
                    .map(|dir| dir.join(name))
                    .find(|p| p.is_file())
            })
        })
}

/// What the probe measured in the page: elements whose box reaches past
/// the window (inside no box that scrolls), images that did not load,
/// errors raised, and the right edge of the widest box against the
/// window's width.
#[derive(Debug, serde::Deserialize)]
struct Probe {
    width: f64,
    scroll: f64,
    wide: Vec<String>,
    broken: Vec<String>,
    errors: Vec<String>,
    /// The bottom of the lowest card, pixels from the top of the page.
    cards: f64,
}

/// The probe, run once the page has loaded, every `<details>` opened. A
/// headless window is at least 500 pixels wide, so a narrower one is had
/// by narrowing the page's root element to `__WIDTH__` pixels.
const PROBE: &str = r#"<script>
window.__errors = [];
addEventListener('error', e => __errors.push(String(e.message || (e.target && e.target.src))), true);
addEventListener('load', () => {
  const cards = Math.max(...[...document.querySelectorAll('.card')].map(c => c.getBoundingClientRect().bottom));
  const width = Math.min(__WIDTH__, document.documentElement.clientWidth);
  document.documentElement.style.width = width + 'px';
  document.querySelectorAll('details').forEach(d => d.open = true);
  const scrolls = e => { for (let p = e.parentElement; p; p = p.parentElement) {
    const o = getComputedStyle(p).overflowX; if (o === 'auto' || o === 'scroll') return true; } return false; };
  const wide = [];
  let scroll = 0;
  for (const e of document.body.querySelectorAll('*')) {
    const r = e.getBoundingClientRect();
    if (r.width === 0 || scrolls(e)) continue;
    scroll = Math.max(scroll, r.right);
    if (r.right > width + 0.5 || r.left < -0.5)
      wide.push(e.tagName + ' ' + Math.round(r.left) + '..' + Math.round(r.right) + ' ' + (e.textContent || '').slice(0, 40));
  }
  const broken = [...document.images].filter(i => !(i.complete && i.naturalWidth > 0)).map(i => i.getAttribute('src'));
  document.body.setAttribute('data-probe', JSON.stringify({width, scroll, wide, broken, errors: __errors, cards}));
});
</script>"#;

/// `html` written beside its figures in a fresh directory, the probe for a
/// window `width` pixels wide put first in its head.
fn page(html: &str, width: u32) -> (tempfile::TempDir, PathBuf) {
    let dir = tempfile::tempdir().unwrap();
    std::fs::create_dir(dir.path().join("figures")).unwrap();
    // The sample's figures, each from a file of the checkout.
    for (figure, source) in [
        (
            "render_kaleidoscope_lit_path.png",
            "crates/tracer/scenes/images/kaleidoscope_lit-path.png",
        ),
        (
            "tradeoff_gold_spheres-lambert.png",
            "docs/tradeoffs/gold_spheres-lambert-pareto.png",
        ),
    ] {
        let source = Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("..")
            .join(source);
        std::fs::copy(source, dir.path().join("figures").join(figure)).unwrap();
    }
    let probe = PROBE.replace("__WIDTH__", &width.to_string());
    let probed = html.replacen("<head>", &format!("<head>{probe}"), 1);
    let path = dir.path().join("report.html");
    std::fs::write(&path, probed).unwrap();
    (dir, path)
}

fn open(chromium: &Path, page: &Path, width: u32, screenshot: Option<&Path>) -> Probe {
    let mut command = Command::new(chromium);
    command.args([
        "--headless",
        "--no-sandbox",
        "--disable-gpu",
        "--hide-scrollbars",
        "--virtual-time-budget=5000",
        &format!("--window-size={width},900"),
    ]);
    match screenshot {
        Some(path) => command.arg(format!("--screenshot={}", path.display())),
        None => command.arg("--dump-dom"),
    };
    let url = format!("file://{}", page.display());
    let output = command.arg(&url).output().expect("chromium runs");
    assert!(
        output.status.success(),
        "{}",
        String::from_utf8_lossy(&output.stderr)
    );
    if screenshot.is_some() {
        return open(chromium, page, width, None);
    }
    let dom = String::from_utf8_lossy(&output.stdout);
    let start = dom.find("data-probe=\"").expect("the probe ran") + "data-probe=\"".len();
    let len = dom[start..].find('"').expect("its end");
    serde_json::from_str(&unescape(&dom[start..start + len])).expect("the probe's JSON")
}

fn assert_fits(probe: &Probe, width: u32) {
    assert!(
        probe.errors.is_empty(),
        "{width} px: errors {:?}",
        probe.errors
    );
    assert!(
        probe.broken.is_empty(),
        "{width} px: broken images {:?}",
        probe.broken
    );
    assert!(
        probe.wide.is_empty(),
        "{width} px: past the window: {:#?}",
        probe.wide
    );
    assert!(
        probe.scroll <= probe.width,
        "{width} px: scrolls sideways: {probe:?}"
    );
}

#[test]
fn the_report_fits_the_window_in_a_browser_at_1400_and_400_pixels() {
    let Some(chromium) = chromium() else {
        eprintln!("skipped: no Chromium (apt-get install chromium, or CHROMIUM=/path)");
        return;
    };
    let (report, figures) = sample();
    let html = to_html(&report, &figures, Lang::En);
    let shot = std::env::temp_dir().join("optics-report-first-screen.png");
    let (_wide, path) = page(&html, 1400);
    let probe = open(&chromium, &path, 1400, Some(&shot));
    assert_fits(&probe, 1400);
    // The first screen (1400 × 900) shows the verdict and every card.
    assert!(
        probe.cards <= 900.0,
        "the last card ends at {} px",
        probe.cards
    );
    assert!(
        std::fs::metadata(&shot).is_ok_and(|m| m.len() > 0),
        "no screenshot"
    );
    let (_narrow, path) = page(&html, 400);
    assert_fits(&open(&chromium, &path, 400, None), 400);
}

#[test]
fn the_browser_probe_finds_a_table_too_wide_and_a_broken_image() {
    let Some(chromium) = chromium() else {
        eprintln!("skipped: no Chromium (apt-get install chromium, or CHROMIUM=/path)");
        return;
    };
    let (report, figures) = sample();
    let faulty = to_html(&report, &figures, Lang::En).replacen(
        "<h2",
        "<table><tr><td style=\"white-space:nowrap\">a row far wider than any window, which no box scrolls: \
         xxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxx</td></tr></table>\
         <img src=\"figures/missing.png\" alt=missing><h2",
        1,
    );
    let (_dir, path) = page(&faulty, 400);
    let probe = open(&chromium, &path, 400, None);
    assert!(!probe.wide.is_empty(), "{probe:?}");
    assert_eq!(probe.broken, ["figures/missing.png"], "{probe:?}");
    assert!(probe.scroll > probe.width, "{probe:?}");
}
