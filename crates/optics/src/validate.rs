//! `optics validate`: the cross-check harness's command. Sets up the Python
//! environment the references come from, runs every check (the `validation`
//! crate), and writes `report.json`, `report.html` and the figures.

use std::io::IsTerminal;
use std::path::{Path, PathBuf};
use std::process::Command;

use anyhow::{bail, Context as _};
use serde_json::json;
use validation::exchange;
use validation::laws::Laws;
use validation::mpmath::Laws64;
use validation::report::{to_html, to_json, write_atomically};
use validation::suite::{self, Context};
use validation::Check;

use crate::lang::say;
use crate::Ui;

#[derive(clap::Args, Debug)]
#[command(after_help = "Examples:
  optics validate                      regenerate the references with the pinned tools, check
  optics validate --quick              the committed references, no regeneration (CI runs this)
  optics validate --quick --no-python  no Python at all: no set-up, no figures
  optics --json validate --quick --out /tmp/validation

Writes report.json, report.html and figures/*.png into --out. On first use the
Python environment (--venv, pinned by python-checks/requirements.txt) is
created; that downloads Mitsuba 3, colour-science and matplotlib once.
Exit status 1 when any check fails.")]
pub struct ValidateArgs {
    /// Run the reduced set: check against the committed references instead of
    /// regenerating them.
    #[arg(long)]
    pub quick: bool,
    /// Directory for report.json, report.html and figures/ (created if
    /// missing) [default: validation/out in the checkout].
    #[arg(long, value_name = "DIR")]
    pub out: Option<PathBuf>,
    /// The Python virtual environment, created if missing [default: .venv in
    /// the checkout].
    #[arg(long, value_name = "DIR")]
    pub venv: Option<PathBuf>,
    /// The Python 3 interpreter that creates the environment.
    #[arg(long, value_name = "PATH", default_value = "python3")]
    pub python: PathBuf,
    /// Use no Python: check against the committed references, draw no figures.
    #[arg(long)]
    pub no_python: bool,
    /// Seed of the random cases evaluated by Mitsuba.
    #[arg(long, default_value_t = 1)]
    pub seed: u64,
}

/// The reference generators and the files each writes, in the order the
/// full run regenerates them.
/// Each generator and its outputs.
const GENERATORS: [(&str, &[&str]); 5] = [
    ("fresnel_mpmath.py", &["fresnel_mpmath.json"]),
    ("mitsuba_laws.py", &["mitsuba_laws.json"]),
    ("colorimetry.py", &["colorimetry.json", "cie_tables.rs"]),
    ("metals.py", &["metals.json"]),
    ("mitsuba_render.py", &["mitsuba_renders.json"]),
];

pub fn run(args: &ValidateArgs, ui: &Ui) -> anyhow::Result<()> {
    let lang = ui.lang;
    let root = validation::repo_root();
    let scripts = root.join("python-checks");
    let out = args
        .out
        .clone()
        .unwrap_or_else(|| root.join("validation/out"));
    if out.exists() && !out.is_dir() {
        bail!("--out {}: exists and is not a directory", out.display());
    }
    std::fs::create_dir_all(&out)
        .with_context(|| format!("--out {}: cannot create the directory", out.display()))?;
    // The command as typed, by the program's name rather than its build path.
    let command_line = std::iter::once("optics".to_owned())
        .chain(std::env::args().skip(1))
        .collect::<Vec<_>>()
        .join(" ");

    let python = if args.no_python {
        None
    } else {
        if !scripts.join("requirements.txt").is_file() {
            bail!(
                "{} not found: optics validate runs from a checkout of the suite (or use --no-python)",
                scripts.join("requirements.txt").display()
            );
        }
        let venv = args.venv.clone().unwrap_or_else(|| root.join(".venv"));
        Some(ensure_environment(&args.python, &venv, &scripts, ui)?)
    };

    let mut extra_checks = Vec::new();
    let reference_dir = match (&python, args.quick) {
        (Some(python), false) => {
            let fresh = out.join("reference");
            std::fs::create_dir_all(&fresh)
                .with_context(|| format!("cannot create {}", fresh.display()))?;
            note(
                ui,
                &say!(
                    lang,
                    "regenerating the references with the pinned tools",
                    "a referenciák újragenerálása a rögzített eszközökkel"
                ),
            );
            extra_checks.push(regenerate(python, &scripts, &fresh)?);
            fresh
        }
        _ => validation::reference::committed_dir(),
    };

    let context = Context {
        reference_dir,
        quick: args.quick,
    };
    let kinds = suite::standard_kinds();
    let bar = (std::io::stderr().is_terminal() && !ui.json).then(|| {
        let bar = indicatif::ProgressBar::new(kinds.len() as u64);
        bar.set_style(
            indicatif::ProgressStyle::with_template("{bar:30} {pos}/{len} {msg}")
                .unwrap_or_else(|_| indicatif::ProgressStyle::default_bar()),
        );
        bar
    });
    let mut report = suite::run(&kinds, &context, &command_line, |i, name| match &bar {
        Some(bar) => {
            bar.set_position(i as u64);
            bar.set_message(name.to_owned());
        }
        None => note(ui, &format!("[{}/{}] {name}", i + 1, kinds.len())),
    })?;
    if let Some(bar) = &bar {
        bar.finish_and_clear();
    }
    if let Some(python) = &python {
        let count = if args.quick { 300 } else { 3000 };
        note(
            ui,
            &say!(
                lang,
                "evaluating {} random cases with Mitsuba",
                "{} véletlen eset kiértékelése a Mitsubával",
                3 * count
            ),
        );
        extra_checks.push(random_cases(python, &scripts, &out, args.seed, count)?);
    }
    report.checks.splice(0..0, extra_checks);
    report.summarise();
    write_atomically(&out, "report.json", to_json(&report).as_bytes())
        .with_context(|| format!("writing {}", out.join("report.json").display()))?;

    let figures = match &python {
        Some(python) => {
            note(ui, &say!(lang, "drawing the figures", "az ábrák rajzolása"));
            match draw_figures(python, &scripts, &out) {
                Ok(figures) => figures,
                Err(error) => {
                    let mut check = Check::new(
                        "report.figures",
                        "The report's figures, drawn by python-checks/plot_report.py",
                        "matplotlib",
                        "the script succeeds",
                    );
                    check.cases = 1;
                    check.fail(format!("{error:#}"));
                    report.checks.push(check);
                    report.summarise();
                    write_atomically(&out, "report.json", to_json(&report).as_bytes())?;
                    Vec::new()
                }
            }
        }
        None => Vec::new(),
    };
    let mut figures = figures;
    figures.extend(write_render_figures(&out, &report)?);
    write_atomically(&out, "report.html", to_html(&report, &figures).as_bytes())
        .with_context(|| format!("writing {}", out.join("report.html").display()))?;

    let s = &report.summary;
    if ui.json {
        let record = json!({
            "passed": report.passed(),
            "summary": s,
            "report_json": out.join("report.json"),
            "report_html": out.join("report.html"),
            "figures": figures,
            "failed_checks": report.checks.iter().filter(|c| !c.passed()).map(|c| &c.id).collect::<Vec<_>>(),
        });
        println!("{record}");
        if !report.passed() {
            // The record above is the whole answer; the status says it failed.
            std::process::exit(1);
        }
        return Ok(());
    }
    for check in &report.checks {
        let mark = if check.passed() { "pass" } else { "FAIL" };
        println!(
            "{mark}  {} ({} cases, {} findings)",
            check.id,
            check.cases,
            check.findings.len()
        );
        for failure in check.failures.iter().take(5) {
            println!("      {failure}");
        }
    }
    if let [spectral, rgb] = report.speed.as_slice() {
        println!(
            "{}",
            say!(
                lang,
                "gold's colour: {:.2} µs from 85 wavelengths, {:.2} µs from three ({:.1}×{})",
                "az arany színe: {:.2} µs 85 hullámhosszból, {:.2} µs háromból ({:.1}×{})",
                spectral.ns_per_colour / 1e3,
                rgb.ns_per_colour / 1e3,
                spectral.ns_per_colour / rgb.ns_per_colour,
                if spectral.optimised {
                    ""
                } else {
                    lang.pick(", unoptimised build", ", optimalizálatlan fordítás")
                }
            )
        );
    }
    println!(
        "{}",
        say!(
            lang,
            "{} checks: {} passed, {} failed; {} findings about the references. Report: {}",
            "{} ellenőrzés: {} sikeres, {} sikertelen; {} megállapítás a referenciákról. Jelentés: {}",
            s.checks,
            s.passed,
            s.failed,
            s.findings,
            out.join("report.html").display()
        )
    );
    if !report.passed() {
        bail!("{} of {} checks failed", s.failed, s.checks);
    }
    Ok(())
}

/// A progress message on stderr (never on stdout, which carries the result).
fn note(ui: &Ui, message: &str) {
    if !ui.json {
        eprintln!("optics validate: {message}");
    }
}

/// Runs `command`, naming it in the error if it cannot start or fails;
/// returns its stdout.
fn run_tool(mut command: Command, what: &str) -> anyhow::Result<String> {
    let output = command
        .output()
        .with_context(|| format!("{what}: cannot run {:?}", command.get_program()))?;
    if !output.status.success() {
        let stderr = String::from_utf8_lossy(&output.stderr);
        let tail: Vec<_> = stderr.lines().rev().take(8).collect();
        bail!(
            "{what} failed ({}):\n{}",
            output.status,
            tail.into_iter().rev().collect::<Vec<_>>().join("\n")
        );
    }
    Ok(String::from_utf8_lossy(&output.stdout).into_owned())
}

/// The environment's interpreter, after creating the environment and
/// installing the pinned requirements if needed.
fn ensure_environment(
    python: &Path,
    venv: &Path,
    scripts: &Path,
    ui: &Ui,
) -> anyhow::Result<PathBuf> {
    let lang = ui.lang;
    let interpreter = venv.join("bin/python");
    let requirements = scripts.join("requirements.txt");
    if !interpreter.is_file() {
        note(ui, &say!(lang,
            "setting up the Python environment in {} (first run: installs Mitsuba 3, colour-science, matplotlib, mpmath; a few minutes)",
            "a Python-környezet létrehozása itt: {} (első futás: Mitsuba 3, colour-science, matplotlib, mpmath telepítése; néhány perc)",
            venv.display()));
        let mut create = Command::new(python);
        create.arg("-m").arg("venv").arg(venv);
        run_tool(create, &format!("creating the virtual environment with `{} -m venv` (is Python 3 installed? --python names another interpreter; --no-python skips Python)", python.display()))?;
    } else if pins_satisfied(&interpreter, &requirements)? {
        return Ok(interpreter);
    }
    note(
        ui,
        &say!(
            lang,
            "installing the pinned requirements ({})",
            "a rögzített csomagok telepítése ({})",
            requirements.display()
        ),
    );
    let mut install = Command::new(&interpreter);
    install
        .args([
            "-m",
            "pip",
            "install",
            "--quiet",
            "--disable-pip-version-check",
            "-r",
        ])
        .arg(&requirements);
    run_tool(
        install,
        "installing python-checks/requirements.txt with pip",
    )?;
    Ok(interpreter)
}

/// Whether every `name==version` pin is installed at that version.
fn pins_satisfied(interpreter: &Path, requirements: &Path) -> anyhow::Result<bool> {
    const CHECK: &str = "import sys, importlib.metadata as m\n\
        bad = []\n\
        for line in open(sys.argv[1], encoding='utf-8'):\n\
        \x20   line = line.split('#')[0].strip()\n\
        \x20   if '==' in line:\n\
        \x20       name, want = line.split('==')\n\
        \x20       try:\n\
        \x20           have = m.version(name)\n\
        \x20       except m.PackageNotFoundError:\n\
        \x20           have = None\n\
        \x20       if have != want:\n\
        \x20           bad.append(f'{name} {have} (pinned {want})')\n\
        print('\\n'.join(bad))\n";
    let mut check = Command::new(interpreter);
    check.arg("-c").arg(CHECK).arg(requirements);
    Ok(run_tool(check, "checking the installed Python packages")?
        .trim()
        .is_empty())
}

/// Regenerates every reference into `fresh` and checks that each reproduces
/// the committed one, by the rule of `python-checks/reproduce.py` (byte for
/// byte, but for the files written through colour-science's BLAS products).
fn regenerate(python: &Path, scripts: &Path, fresh: &Path) -> anyhow::Result<Check> {
    let committed = validation::reference::committed_dir();
    let tables = validation::repo_root().join("crates/radiometry/src/cie_tables.rs");
    let mut check = Check::new(
        "references.regenerated",
        "Every committed reference regenerates with the pinned tools",
        "python-checks/ generators in the pinned environment",
        "the rule of python-checks/reproduce.py: byte-identical, but for the files written \
         through colour-science's BLAS products, whose numbers may move within its stated \
         tolerance",
    );
    for (script, outputs) in GENERATORS {
        let mut command = Command::new(python);
        command.arg("-W").arg("ignore").arg(scripts.join(script));
        for name in outputs {
            command.arg(fresh.join(name));
        }
        run_tool(command, &format!("python-checks/{script}"))?;
        for name in outputs {
            check.cases += 1;
            let old = if name.ends_with(".rs") {
                tables.clone()
            } else {
                committed.join(name)
            };
            // Both must exist: two missing files are not a reproduction.
            if !(old.is_file() && fresh.join(name).is_file()) {
                check.fail(format!("{} or its regeneration is missing", old.display()));
                continue;
            }
            let output = Command::new(python)
                .arg(scripts.join("reproduce.py"))
                .arg(&old)
                .arg(fresh.join(name))
                .output()
                .context("python-checks/reproduce.py: cannot run it")?;
            let said = String::from_utf8_lossy(&output.stdout)
                .trim()
                .replace('\n', "; ");
            // 0: reproduces; 1: differs (stdout says where); anything else: it could not tell.
            match output.status.code() {
                Some(0) => {}
                Some(1) => check.fail(format!(
                    "{} differs from what python-checks/{script} writes now ({said}): regenerate and commit it",
                    old.display()
                )),
                _ => bail!(
                    "python-checks/reproduce.py could not compare {} ({}): {}",
                    old.display(),
                    output.status,
                    String::from_utf8_lossy(&output.stderr).trim()
                ),
            }
        }
    }
    Ok(check)
}

/// Exports `count` random cases of each law, has Mitsuba evaluate them, and
/// compares (`validation::exchange`).
fn random_cases(
    python: &Path,
    scripts: &Path,
    out: &Path,
    seed: u64,
    count: usize,
) -> anyhow::Result<Check> {
    let dir = out.join("exchange");
    std::fs::create_dir_all(&dir).with_context(|| format!("cannot create {}", dir.display()))?;
    let cases = exchange::random_cases(seed, count);
    write_atomically(
        &dir,
        "cases.json",
        serde_json::to_string(&cases)?.as_bytes(),
    )
    .with_context(|| format!("writing {}", dir.join("cases.json").display()))?;
    let mut command = Command::new(python);
    command
        .arg(scripts.join("mitsuba_eval.py"))
        .arg(dir.join("cases.json"))
        .arg(dir.join("results.json"));
    run_tool(command, "python-checks/mitsuba_eval.py")?;
    let results: exchange::ResultsFile =
        validation::reference::load(&dir, "results.json", exchange::RESULTS_SCHEMA)?;
    Ok(exchange::check_random(
        &Laws::radiometry(),
        &Laws64::radiometry(),
        &cases,
        &results,
    ))
}

/// Writes the render triptychs (ours | Mitsuba | difference) as PNG under
/// `out/figures/`; their names, relative to `out`.
fn write_render_figures(out: &Path, report: &suite::Report) -> anyhow::Result<Vec<String>> {
    let dir = out.join("figures");
    std::fs::create_dir_all(&dir).with_context(|| format!("cannot create {}", dir.display()))?;
    let mut names = Vec::new();
    for figure in &report.render_figures {
        let path = dir.join(&figure.file);
        tracer::output::write_png(&path, &figure.image)
            .with_context(|| format!("writing {}", path.display()))?;
        names.push(format!("figures/{}", figure.file));
    }
    Ok(names)
}

/// Runs the figure script on `out/report.json`; the figure file names,
/// relative to `out`.
fn draw_figures(python: &Path, scripts: &Path, out: &Path) -> anyhow::Result<Vec<String>> {
    let figures = out.join("figures");
    let mut command = Command::new(python);
    command
        .arg(scripts.join("plot_report.py"))
        .arg(out.join("report.json"))
        .arg(&figures);
    let listed = run_tool(command, "python-checks/plot_report.py")?;
    Ok(listed
        .lines()
        .map(|name| format!("figures/{}", name.trim()))
        .collect())
}
