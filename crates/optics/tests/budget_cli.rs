//! `optics render --tolerance T --metric M`: on course scenes at a small
//! size, for several tolerances and seeds, the error the render reaches
//! against the ground truth stays within T, and the settings chosen cost
//! no more rays than the scene's own where those are predicted within T;
//! bad budgets are refused by name with nothing written.
#![cfg(feature = "harness")]

use std::path::Path;
use std::process::{Command, Output};

use serde_json::Value;

fn optics(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_optics"))
        .args(args)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .expect("the optics binary runs")
}

fn scene(name: &str) -> String {
    format!(
        "{}/../tracer/scenes/{name}.json",
        env!("CARGO_MANIFEST_DIR")
    )
}

/// `optics --json render` of `name` at 16×12 under a budget, its truth
/// cached in `dir`.
fn budget(name: &str, dir: &Path, png: &str, extra: &[&str]) -> Output {
    budget_with_truth(name, dir, png, "512", extra)
}

/// [`budget`] with the truth rendered at `truth_spp`.
fn budget_with_truth(name: &str, dir: &Path, png: &str, truth_spp: &str, extra: &[&str]) -> Output {
    let (path, out) = (scene(name), dir.join(png));
    let cache = dir.join("truth");
    let mut args = vec![
        "--json",
        "render",
        &path,
        "-o",
        out.to_str().unwrap(),
        "--width",
        "16",
        "--height",
        "12",
        "--truth-cache",
        cache.to_str().unwrap(),
        "--truth-spp",
        truth_spp,
        // The caustic map's photons, fewer than the scenes' 10⁵: every
        // candidate of the pilot builds its own map.
        "--photons",
        "2000",
    ];
    args.extend_from_slice(extra);
    optics(&args)
}

fn record(output: &Output) -> Value {
    assert!(
        output.status.success(),
        "{}",
        String::from_utf8_lossy(&output.stderr)
    );
    serde_json::from_slice(&output.stdout).unwrap()
}

/// The bound a prediction puts on `metric`: the relative RMSE's own
/// field, or a displayed measure's simulated `bound`.
fn bound(prediction: &Value, metric: &str) -> f64 {
    let field = if metric == "rel_rmse" {
        "rel_rmse"
    } else {
        "bound"
    };
    prediction[field].as_f64().unwrap()
}

/// What the budgets over seeds came to.
#[derive(Default)]
struct Tally {
    /// Budgets that rendered.
    rendered: usize,
    /// Budgets answered "cannot reach T".
    unreachable: usize,
    /// Renders whose error exceeded their prediction.
    over_prediction: usize,
    /// Renders whose error exceeded their tolerance.
    over_tolerance: usize,
    /// Choices that cast fewer rays than the scene's own settings, where
    /// those were predicted within T.
    cheaper: usize,
}

/// Budgets `metric` at each of `tolerances` with seeds 1 to 3 on three
/// scenes (glass and its caustics, gold mirrors as Lambert, water seen
/// from inside) at 16×12, verified against their truth: each prediction
/// within T, and where the scene's own settings are predicted within T,
/// no more rays than they cast. Prints each budget (`--nocapture`).
fn over_seeds(metric: &str, tolerances: &[&str]) -> Tally {
    let dir = tempfile::tempdir().unwrap();
    let mut tally = Tally::default();
    // gold_spheres's course_rough reflects more than it receives: budgeted
    // with the sweep's Lambert stand-in, as `docs/tradeoffs/make` measures it.
    for (name, lambert) in [
        ("glass_spheres", false),
        ("gold_spheres", true),
        ("inside_water", false),
    ] {
        for &tolerance in tolerances {
            for seed in ["1", "2", "3"] {
                let mut flags = vec![
                    "--tolerance",
                    tolerance,
                    "--metric",
                    metric,
                    "--verify",
                    "--seed",
                    seed,
                ];
                if lambert {
                    flags.push("--lambert");
                }
                let output = budget(name, dir.path(), "b.png", &flags);
                if !output.status.success() {
                    // The other promise: "cannot reach T; the best is …".
                    let json: Value = serde_json::from_slice(&output.stdout).unwrap();
                    assert_eq!(json["error"]["kind"], "budget.unreachable", "{json}");
                    let text = String::from_utf8_lossy(&output.stderr);
                    assert!(text.contains(&format!("cannot reach {metric} ")), "{text}");
                    println!("{name} {metric} T {tolerance} seed {seed}: cannot reach it");
                    tally.unreachable += 1;
                    continue;
                }
                let details = record(&output)["details"].clone();
                let t: f64 = tolerance.parse().unwrap();
                let achieved = details["verified"][metric].as_f64().unwrap();
                let predicted = bound(&details["predicted"], metric);
                println!(
                    "{name} {metric} T {t} seed {seed}: achieved {achieved:.4}, predicted {predicted:.4}"
                );
                assert!(predicted <= t, "{name} {t}: predicted {predicted}");
                tally.rendered += 1;
                tally.over_tolerance += usize::from(achieved > t);
                tally.over_prediction += usize::from(achieved > predicted);
                let rays = details["predicted"]["rays"].as_f64().unwrap();
                let own = &details["scene"];
                if bound(own, metric) <= t {
                    let own_rays = own["rays"].as_f64().unwrap();
                    assert!(
                        rays <= own_rays,
                        "{name} {t}: {rays} rays against the scene's {own_rays}"
                    );
                    tally.cheaper += usize::from(rays < own_rays);
                }
            }
        }
    }
    println!(
        "{metric}: {} answered unreachable; of the {} rendered {} above their prediction, {} above T, {} cheaper than the scene's own settings",
        tally.unreachable, tally.rendered, tally.over_prediction, tally.over_tolerance, tally.cheaper
    );
    tally
}

/// The relative RMSE at T 0.1 and 0.2, and 1, where the scenes' own
/// Whitted settings come within reach; three seeds: each of the 27
/// renders reaches a relative RMSE within its tolerance. Each prediction
/// takes its four estimated sums at 3 standard deviations up, so where
/// they are near normal it fails at most 4 × 0.13 % of the time; a bias
/// from paths too rare for the pilot to meet (a deep bounce between the
/// gold mirrors) is what can still exceed it, so the renders are held to
/// T with a stated confidence: at least 25 of the 27 (93 %), where a
/// budget the predictor cannot meet answers "cannot reach T" instead (the
/// bound is conservative: inside_water at T 0.1, seed 2, is one; at most
/// a third may be, so that the test holds renders to T). Observed once:
/// gold_spheres (as Lambert) at T 0.2, seed 2, rendered at 1 spp,
/// reached 0.2135 against a prediction of 0.1908, one sample's tail (the
/// gold mirrors' path-traced light on the floor) heavier than the
/// pilot's halves of 4 show; no candidate is now predicted below a
/// half's samples, and it reaches 0.0544 ≤ 0.1343 at 4 spp. Where the
/// scene's own settings are predicted within T, the choice casts no more
/// rays than they would, and at least once fewer.
#[test]
fn the_achieved_error_stays_within_the_tolerance_over_seeds() {
    let tally = over_seeds("rel_rmse", &["0.1", "0.2", "1"]);
    assert!(
        tally.over_tolerance <= 2,
        "{} of 27 renders above their tolerance",
        tally.over_tolerance
    );
    assert!(
        tally.unreachable <= 9,
        "{} of 27 budgets unreachable",
        tally.unreachable
    );
    assert!(
        tally.cheaper > 0,
        "the budget never undercut the scene's own settings"
    );
}

/// The displayed image's measures, each at two tolerances the three
/// scenes reach at 16×12 (mean ΔE2000 5 and 10, its 99th percentile 30
/// and 60, ꟻLIP 0.1 and 0.2), seeds 1 to 3: 18 budgets per measure. Each
/// bound is the largest of 8 simulated renders plus 3 deviations of
/// their spread, so the renders are held to T with a stated confidence:
/// at least 17 of the 18 rendered (94 %), at most a third answering
/// "cannot reach T"; where the scene's own settings are predicted within
/// T, the choice casts no more rays than they would.
#[test]
fn the_displayed_measures_stay_within_the_tolerance_over_seeds() {
    for (metric, tolerances) in [
        ("delta_e_mean", ["5", "10"]),
        ("delta_e_p99", ["30", "60"]),
        ("flip_mean", ["0.1", "0.2"]),
    ] {
        let tally = over_seeds(metric, &tolerances);
        assert!(
            tally.over_tolerance <= 1,
            "{metric}: {} of {} renders above their tolerance",
            tally.over_tolerance,
            tally.rendered
        );
        assert!(
            tally.unreachable <= 6,
            "{metric}: {} of 18 budgets unreachable",
            tally.unreachable
        );
    }
}

/// Every physically based course scene the sweep covers, with the flags
/// `docs/tradeoffs/make` gives it (`--lambert` where course_rough's albedo
/// π kd exceeds 1), budgeted once per metric at 16×12 with `--verify`
/// against its matching truth (256 spp): the error reached stays within
/// T and within the prediction. T is a loose 0.5 for the relative RMSE,
/// 10 for mean ΔE2000, 60 for its 99th percentile, 0.2 for ꟻLIP;
/// kaleidoscope_lit's 2, 15, 100 and 0.3, for its mirrors' deep paths
/// leave only the truth's full depth within 0.5 and 1, its caustic map
/// then grown with 128 or 64 times the pilot's samples (40 s and 12 s
/// here, against 7 s at 2), and its pilot's noise between the mirrors
/// keeps the 99th percentile's bound above 80 (ꟻLIP 0.2 takes 512 spp,
/// 40 s). At 8×6 its pilot (and blinn_phong's) cannot bound the energy at
/// 8 samples.
#[test]
fn every_course_scene_of_the_sweep_is_budgeted_within_its_prediction() {
    let dir = tempfile::tempdir().unwrap();
    let loose = ["0.5", "10", "60", "0.2"];
    let scenes = [
        ("shadow", true, loose),
        ("blinn_phong", true, loose),
        ("diffuse", true, loose),
        ("gold_spheres", true, loose),
        ("kaleidoscope_lit", true, ["2", "15", "100", "0.3"]),
        ("webgl_seven_spheres", true, loose),
        ("glass_spheres", false, loose),
        ("inside_water", false, loose),
    ];
    let metrics = ["rel_rmse", "delta_e_mean", "delta_e_p99", "flip_mean"];
    for (name, lambert, tolerances) in scenes {
        for (metric, tolerance) in metrics.into_iter().zip(tolerances) {
            let mut flags = vec!["--tolerance", tolerance, "--metric", metric, "--verify"];
            if lambert {
                flags.push("--lambert");
            }
            let output = budget_with_truth(name, dir.path(), "s.png", "256", &flags);
            let details = record(&output)["details"].clone();
            let achieved = details["verified"][metric].as_f64().unwrap();
            let predicted = bound(&details["predicted"], metric);
            let t: f64 = tolerance.parse().unwrap();
            println!("{name} {metric} T {t}: achieved {achieved:.4}, predicted {predicted:.4}");
            assert_eq!(details["lambert"].as_bool().unwrap_or(false), lambert);
            assert!(predicted <= t, "{name} {metric}: predicted {predicted}");
            assert!(achieved <= t, "{name} {metric}: achieved {achieved}");
            assert!(
                achieved <= predicted,
                "{name} {metric}: achieved {achieved} over its prediction {predicted}"
            );
        }
    }
}

/// What the text says: the choice, the terms of its prediction, the
/// scene's own settings, and the verification.
#[test]
fn the_budget_says_what_it_chose_and_why() {
    let dir = tempfile::tempdir().unwrap();
    let path = scene("glass_spheres");
    let out = dir.path().join("g.png");
    let cache = dir.path().join("truth");
    let output = optics(&[
        "render",
        &path,
        "-o",
        out.to_str().unwrap(),
        "--width",
        "16",
        "--height",
        "12",
        "--tolerance",
        "0.1",
        "--metric",
        "rel_rmse",
        "--verify",
        "--truth-spp",
        "256",
        "--truth-cache",
        cache.to_str().unwrap(),
        "--photons",
        "2000",
    ]);
    assert!(
        output.status.success(),
        "{}",
        String::from_utf8_lossy(&output.stderr)
    );
    let text = String::from_utf8(output.stdout).unwrap();
    for words in [
        "pilot:",
        "chosen:",
        "bias ≤",
        "the scene's own settings",
        "verified against the ground truth",
    ] {
        assert!(text.contains(words), "{words:?} missing from {text}");
    }
    assert!(out.exists() && out.with_extension("pfm").exists());
}

/// Each bad budget, named: the flag, the exit status, the error's kind,
/// and no image written.
#[test]
fn bad_budgets_are_refused_by_name_with_nothing_written() {
    let dir = tempfile::tempdir().unwrap();
    let cases: [(&str, &[&str], i32, &str, &str); 9] = [
        (
            "a zero tolerance",
            &["--tolerance", "0", "--metric", "rel_rmse"],
            2,
            "usage",
            "--tolerance",
        ),
        (
            "a negative tolerance",
            &["--tolerance=-0.1", "--metric", "rel_rmse"],
            2,
            "usage",
            "--tolerance",
        ),
        (
            "a NaN tolerance",
            &["--tolerance", "NaN", "--metric", "rel_rmse"],
            2,
            "usage",
            "--tolerance",
        ),
        (
            "an infinite tolerance",
            &["--tolerance", "inf", "--metric", "rel_rmse"],
            2,
            "usage",
            "--tolerance",
        ),
        (
            "an unknown metric",
            &["--tolerance", "0.1", "--metric", "psnr"],
            2,
            "usage",
            "--metric",
        ),
        (
            "a tolerance without its metric",
            &["--tolerance", "0.1"],
            2,
            "usage",
            "--metric",
        ),
        (
            "a setting the budget chooses",
            &["--tolerance", "0.1", "--metric", "rel_rmse", "--spp", "4"],
            2,
            "usage",
            "--",
        ),
        (
            "an unreachable budget of a displayed measure",
            &["--tolerance", "1e-3", "--metric", "delta_e_p99"],
            1,
            "budget.unreachable",
            "--tolerance",
        ),
        (
            "an unreachable budget",
            &["--tolerance", "1e-7", "--metric", "rel_rmse"],
            1,
            "budget.unreachable",
            "--tolerance",
        ),
    ];
    for (what, flags, status, kind, field) in cases {
        let output = budget("glass_spheres", dir.path(), "bad.png", flags);
        assert_eq!(
            output.status.code(),
            Some(status),
            "{what}: {}",
            String::from_utf8_lossy(&output.stderr)
        );
        let json: Value = serde_json::from_slice(&output.stdout)
            .unwrap_or_else(|_| panic!("{what}: no JSON error"));
        assert_eq!(json["error"]["kind"], kind, "{what}: {json}");
        let named = json["error"]["field"].as_str().unwrap_or_default();
        assert!(
            named.contains(field),
            "{what}: {json} does not name {field}"
        );
        assert!(
            !dir.path().join("bad.png").exists(),
            "{what}: an image was written"
        );
    }
    let shown = budget(
        "glass_spheres",
        dir.path(),
        "bad.png",
        &["--tolerance", "1e-3", "--metric", "delta_e_p99"],
    );
    let text = String::from_utf8_lossy(&shown.stderr);
    assert!(
        text.contains("cannot reach delta_e_p99 1e-3; the best is delta_e_p99 ≤"),
        "{text}"
    );
    // A displayed measure's floor is more than its bias: the pilot's noise
    // and the truth's are in it too, and the answer says so.
    assert!(
        text.contains("its floor, the bias with the pilot's noise and the ground truth's")
            && !text.contains("the bias alone"),
        "{text}"
    );
    let unreachable = budget(
        "glass_spheres",
        dir.path(),
        "bad.png",
        &["--tolerance", "1e-7", "--metric", "rel_rmse"],
    );
    let text = String::from_utf8_lossy(&unreachable.stderr);
    assert!(
        text.contains("cannot reach rel_rmse 1e-7; the best is rel_rmse ≤"),
        "{text}"
    );
    // The samples it would need, as the budget would render them, or why
    // no samples would do.
    let need = text
        .split("it would need 2^")
        .nth(1)
        .and_then(|rest| rest.split(" = ").nth(1))
        .and_then(|rest| rest.split(" spp").next())
        .and_then(|n| n.parse::<u64>().ok());
    let no_samples = [
        "no number of samples reaches it",
        "its noise stops falling past",
    ]
    .iter()
    .any(|why| text.contains(why));
    assert!(
        need.is_some_and(|n| n.is_power_of_two() && n > 1 << 16) || no_samples,
        "{text}"
    );
    // And what it would render at the most: a power of two.
    let best = text
        .split(" spp,")
        .next()
        .and_then(|head| head.rsplit(' ').next())
        .and_then(|n| n.parse::<u32>().ok());
    assert!(best.is_some_and(u32::is_power_of_two), "{text}");
}

/// A rough material that reflects more than it receives (the course's
/// `π kd` above 1) makes the light grow with depth: no truth converges and
/// no bound holds, so the budget refuses the scene and names `--lambert`
/// before it renders anything (without the refusal, `shadow` at 32 × 24
/// predicted ≤ 0.091 and reached 0.194).
#[test]
fn a_material_that_gains_energy_is_refused_without_lambert() {
    let dir = tempfile::tempdir().unwrap();
    let output = budget(
        "shadow",
        dir.path(),
        "gain.png",
        &["--tolerance", "0.1", "--metric", "rel_rmse"],
    );
    assert_eq!(output.status.code(), Some(1));
    let json: Value = serde_json::from_slice(&output.stdout).expect("a JSON error");
    assert_eq!(json["error"]["kind"], "budget.energy_gain", "{json}");
    assert_eq!(json["error"]["field"], "--lambert", "{json}");
    let text = String::from_utf8_lossy(&output.stderr);
    assert!(
        text.contains("material \"green\" reflects 2.51 times"),
        "{text}"
    );
    assert!(
        !dir.path().join("gain.png").exists(),
        "an image was written"
    );
}
