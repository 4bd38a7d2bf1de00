//! `report.html` as a reader gets it: every number of `report.json` read
//! back out of the page, and the page opened in a real browser (headless
//! Chromium), which must show no console error or broken image and let no
//! element reach past the window at 1400 and at 400 pixels wide.
//!
//! The browser tests skip, saying so, where no Chromium is installed
//! (`apt-get install chromium`; `CHROMIUM=/path` names another).

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::process::Command;

use validation::check::Check;
use validation::report::{to_html, to_json, Report};

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
    laws.find("Mitsuba R at eta=1.0001 outside cos=0.01: 7.180912792682648e-2, exact 7.178980365261572e-2 (off by 1.93e-5, 2594 f32 ulps)".into());
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
    render.fail("pixel (1, 2) R: t = 99".into());
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
    report.checks = vec![laws, mpmath, render, colour, light];
    report.summarise();
    (
        report,
        vec!["figures/render_kaleidoscope_lit_path.png".to_owned()],
    )
}

/// A check of `cases` cases with its worst values `(quantity, value, at)`.
fn check(id: &str, cases: usize, worst: &[(&str, f64, &str)]) -> Check {
    let mut check = Check::new(id, &format!("the check {id}"), "a reference", "a tolerance");
    check.cases = cases;
    for (name, value, at) in worst {
        check.measure(name, *value, at);
    }
    check
}

/// Every `(check, quantity) → value` the page carries in its tables.
fn numbers_in(html: &str) -> BTreeMap<(String, String), f64> {
    let attribute = |cell: &str, name: &str| {
        let start = cell.find(&format!("{name}=\""))? + name.len() + 2;
        let len = cell[start..].find('"')?;
        Some(unescape(&cell[start..start + len]))
    };
    let mut found = BTreeMap::new();
    for cell in html.split("<td ").skip(1) {
        let cell = &cell[..cell.find('>').unwrap_or(cell.len())];
        let (Some(check), Some(metric), Some(value)) = (
            attribute(cell, "data-check"),
            attribute(cell, "data-metric"),
            attribute(cell, "data-value"),
        ) else {
            continue;
        };
        let value: f64 = value.parse().expect("a number in data-value");
        assert!(
            found.insert((check, metric), value).is_none(),
            "a number shown twice"
        );
    }
    found
}

fn unescape(text: &str) -> String {
    text.replace("&quot;", "\"")
        .replace("&lt;", "<")
        .replace("&gt;", ">")
        .replace("&amp;", "&")
}

/// Every `(check, quantity) → value` of `report.json`.
fn numbers_of(json: &str) -> BTreeMap<(String, String), f64> {
    let report: serde_json::Value = serde_json::from_str(json).expect("report.json");
    let mut found = BTreeMap::new();
    for check in report["checks"].as_array().expect("checks") {
        for m in check["metrics"].as_array().expect("metrics") {
            let key = (
                check["id"].as_str().expect("id").to_owned(),
                m["name"].as_str().expect("name").to_owned(),
            );
            found.insert(key, m["worst"].as_f64().expect("a finite worst"));
        }
    }
    found
}

#[test]
fn the_page_carries_every_number_of_report_json() {
    let (report, figures) = sample();
    let html = to_html(&report, &figures);
    let json = to_json(&report);
    assert_eq!(numbers_in(&html), numbers_of(&json));
    assert_eq!(numbers_of(&json).len(), 8);
}

#[test]
fn a_page_with_a_row_dropped_is_caught() {
    let (report, figures) = sample();
    let html = to_html(&report, &figures);
    let row = html.find("<tr><td><span class=pass>").expect("a row");
    let end = row + html[row..].find("</tr>").expect("its end") + "</tr>".len();
    let dropped = format!("{}{}", &html[..row], &html[end..]);
    assert_ne!(numbers_in(&dropped), numbers_of(&to_json(&report)));
}

#[test]
fn report_json_names_its_schema_and_version() {
    let (report, _) = sample();
    let json: serde_json::Value = serde_json::from_str(&to_json(&report)).unwrap();
    assert_eq!(json["schema"], "validation-report/1");
}

#[test]
fn the_first_screen_gives_the_verdict_and_a_card_per_area() {
    let (report, figures) = sample();
    let html = to_html(&report, &figures);
    let cards = &html[html.find("<div class=cards>").unwrap()..html.find("<h2").unwrap()];
    for title in [
        "Laws against 50-digit mpmath",
        "Laws against Mitsuba 3",
        "Colour against colour-science",
        "Renders against Mitsuba 3",
        "All the light",
    ] {
        assert!(cards.contains(title), "no card {title}");
    }
    assert!(
        cards.contains("0 of 1 pass"),
        "the failed render check's card"
    );
    assert!(html.contains("1 of 5 checks FAIL."));
    // Numbers for reading, a request's fields as inputs.
    assert!(html.contains(">3.55e-7<") && html.contains(">0.949<"));
    assert!(html.contains("case 720: cos_i = -0.4081, eta = 0.8535, law = fresnel"));
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
}

/// The probe, run once the page has loaded, every `<details>` opened. A
/// headless window is at least 500 pixels wide, so a narrower one is had
/// by narrowing the page's root element to `__WIDTH__` pixels.
const PROBE: &str = r#"<script>
window.__errors = [];
addEventListener('error', e => __errors.push(String(e.message || (e.target && e.target.src))), true);
addEventListener('load', () => {
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
  document.body.setAttribute('data-probe', JSON.stringify({width, scroll, wide, broken, errors: __errors}));
});
</script>"#;

/// `html` written beside its figure in a fresh directory, the probe for a
/// window `width` pixels wide put first in its head.
fn page(html: &str, width: u32) -> (tempfile::TempDir, PathBuf) {
    let dir = tempfile::tempdir().unwrap();
    std::fs::create_dir(dir.path().join("figures")).unwrap();
    let image = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../crates/tracer/scenes/images/kaleidoscope_lit-path.png");
    std::fs::copy(
        image,
        dir.path().join("figures/render_kaleidoscope_lit_path.png"),
    )
    .unwrap();
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
    let html = to_html(&report, &figures);
    let shot = std::env::temp_dir().join("optics-report-first-screen.png");
    let (_wide, path) = page(&html, 1400);
    assert_fits(&open(&chromium, &path, 1400, Some(&shot)), 1400);
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
    let faulty = to_html(&report, &figures).replacen(
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
