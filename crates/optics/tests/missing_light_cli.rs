//! `optics inspect` names the light the chosen integrator misses: each
//! chain delta light → mirrors or glass → rough surface, in both languages,
//! and the share of the light Mitsuba's path tracer misses where the
//! checkout's reference (`mitsuba_full_light.json`) measured the scene.

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

fn inspect(name: &str, extra: &[&str]) -> Output {
    let path = scene(name);
    let mut args = vec!["inspect", &path, "--width", "16", "--height", "12"];
    args.extend_from_slice(extra);
    optics(&args)
}

#[test]
fn inspect_names_the_chain_from_the_light_through_the_mirror_to_the_rough_surface() {
    let out = inspect("kaleidoscope_lit", &[]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let report = String::from_utf8_lossy(&out.stdout);
    assert!(
        report.contains("light the whitted integrator does not compute: point light 0 → conductor 'gold' → course_rough 'green'"),
        "{report}"
    );
    #[cfg(feature = "harness")]
    assert!(
        report.contains("measured by Mitsuba (mitsuba_full_light.json")
            && report.contains("this integrator misses at least as much"),
        "{report}"
    );
    let out = inspect("kaleidoscope_lit", &["--lang", "hu"]);
    let report = String::from_utf8_lossy(&out.stdout);
    assert!(
        report.contains("0 pontfény → vezető 'gold' → érdes (a kurzusé) 'green'"),
        "{report}"
    );
}

#[test]
fn inspect_says_what_each_integrator_does_with_the_chain() {
    for (integrator, says) in [
        ("path", "light the path integrator does not compute"),
        (
            "photon",
            "light the photon integrator computes by its caustic photon map",
        ),
    ] {
        let out = inspect("kaleidoscope_lit", &["--integrator", integrator]);
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        let report = String::from_utf8_lossy(&out.stdout);
        assert!(report.contains(says), "{integrator}: {report}");
        #[cfg(feature = "harness")]
        {
            let verdict = match integrator {
                "path" => "the tracer's path misses the same share",
                _ => "the photon integrator computes this light on the diffuse surfaces",
            };
            assert!(report.contains(verdict), "{integrator}: {report}");
            assert!(
                !report.contains("at least as much"),
                "{integrator}: {report}"
            );
        }
    }
}

#[test]
fn inspect_names_no_chain_where_there_is_no_mirror_or_glass() {
    let out = inspect("shadow", &[]);
    assert!(out.status.success());
    let report = String::from_utf8_lossy(&out.stdout);
    assert!(!report.contains("does not compute"), "{report}");
}

#[test]
fn the_json_record_carries_the_chains_and_the_measured_share() {
    let path = scene("glass_spheres");
    let out = optics(&[
        "--json",
        "inspect",
        &path,
        "--width",
        "16",
        "--height",
        "12",
        "--integrator",
        "path",
        "--spp",
        "1",
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let record: Value = serde_json::from_slice(&out.stdout).unwrap();
    let missing = &record["details"]["missing_light"];
    let chains = missing["chains"].as_array().unwrap();
    assert_eq!(chains.len(), 6, "{chains:?}");
    assert!(chains
        .iter()
        .any(|c| c["via"] == serde_json::json!(["glass"]) && c["to"] == "floor"));
    #[cfg(feature = "harness")]
    {
        let share = missing["measured"]["surface"]["share"].as_f64().unwrap();
        // The caustics under the glass balls: a few percent of the light.
        assert!(share > 0.01 && share < 0.5, "{share}");
    }
}

/// `--measure` renders the scene as written with path and photon and
/// states the share path misses, with its standard error, in either
/// language; without it the record holds no such measurement.
#[cfg(feature = "harness")]
#[test]
fn inspect_measure_states_the_share_path_misses_on_the_scene_itself() {
    let path = scene("gold_spheres");
    let args = [
        "--json",
        "inspect",
        &path,
        "--width",
        "32",
        "--height",
        "24",
        "--integrator",
        "path",
        "--spp",
        "8",
    ];
    let record = |extra: &[&str]| -> Value {
        let out = optics(&[&args[..], extra].concat());
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        serde_json::from_slice(&out.stdout).unwrap()
    };
    assert!(record(&[])["details"]["missing_light"]["measured_here"].is_null());
    let here = record(&["--measure"])["details"]["missing_light"]["measured_here"].clone();
    let diffuse = &here["diffuse"];
    let (share, se) = (
        diffuse["share"].as_f64().unwrap(),
        diffuse["standard_error"].as_f64().unwrap(),
    );
    // A share with its noise (that it is well above its noise on this
    // scene is `validation`'s `path_misses_the_gold_spheres_caustic`).
    assert!(se > 0.0 && share.abs() < 1.0, "{here}");
    assert_eq!(here["passes"], 4);
    let out = optics(&[&args[1..], &["--measure", "--lang", "hu"]].concat());
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(text.contains("a photon által talált fény"), "{text}");
}
