//! The findings on small synthetic records whose answers are known by
//! construction. Shares and ratios are sums and quotients of a few
//! decimals, so they hold to 1e-12; ΔE and verdicts are copied, exactly.

use super::*;
use crate::tradeoff::record::{Errors, Grazing, Point, Record, Settings, Truth};
use crate::tradeoff::Verdict;

const EXACT: f64 = 1e-12;

/// A point of `axis` with `integrator`, `max_depth` and `fresnel`, taking
/// `seconds`, `rel_rmse` and `light` against the truth and ΔE p99 `seen`
/// against the scene's own; its verdict by the rule against 1 s.
fn point(
    axis: &str,
    settings: (&str, u32, &str),
    seconds: f64,
    rel_rmse: f64,
    light: f64,
    seen: f64,
) -> Point {
    let errors = |rel_rmse: f64, delta_e_p99: f64, light: f64| Errors {
        rel_rmse,
        delta_e_mean: delta_e_p99 / 4.0,
        delta_e_p99,
        flip_mean: 0.1,
        light: Some(light),
        light_noise: None,
    };
    let (integrator, max_depth, fresnel) = settings;
    Point {
        axis: axis.to_owned(),
        label: format!("{axis} {integrator} {max_depth} {fresnel}"),
        settings: Settings {
            integrator: integrator.to_owned(),
            max_depth,
            fresnel: fresnel.to_owned(),
        },
        seconds_median: seconds,
        seconds: vec![seconds],
        rays: 1e4 * seconds,
        errors: errors(rel_rmse, 10.0 * rel_rmse, light),
        against_scene: errors(0.0, seen, 1.0),
        efficiency: None,
        pareto: Vec::new(),
        verdict: (axis != "scene").then(|| Verdict::of(seen, seconds, 1.0)),
        grazing: None,
    }
}

fn record(points: Vec<Point>) -> Record {
    Record {
        schema: super::super::SCHEMA.to_owned(),
        version: super::super::SCHEMA_VERSION,
        scene: "scenes/synthetic.json".to_owned(),
        lambert: false,
        width: 4,
        height: 3,
        machine: "test".to_owned(),
        date: "2026-12-04".to_owned(),
        load: String::new(),
        command: "synthetic".to_owned(),
        truth: Truth {
            spp: 256,
            noise_relative: 1e-6,
            light_noise_relative: Some(2e-4),
        },
        points,
        rgb_against_spectrum: Vec::new(),
        findings: None,
        mitsuba: None,
    }
}

/// The scene's own settings: Whitted, 11 bounces, the exact law, 1 s.
fn own(rel_rmse: f64, light: f64) -> Point {
    point("scene", ("whitted", 11, "exact"), 1.0, rel_rmse, light, 0.0)
}

/// `1 − Σx/Σt` of each integrator, the scene's own first, and the
/// truth's noise on it carried as recorded; a render brighter than the
/// truth leaves out a negative share. Its noise is the truth's and its
/// own in quadrature (2e-4 and 1.5e-4 make 2.5e-4), and a share within
/// two of them (5e-4) is the noise's: 4.99e-4 is, 5.01e-4 is not.
#[test]
fn the_light_left_out_is_one_minus_the_share_rendered() {
    let mut path = point(
        "integrator",
        ("path", 11, "exact"),
        20.0,
        0.05,
        0.96875,
        5.0,
    );
    path.errors.light_noise = Some(1.5e-4);
    let findings = Findings::of(&record(vec![
        own(0.3, 0.75),
        point("integrator", ("local", 11, "exact"), 0.5, 0.9, 0.125, 40.0),
        path.clone(),
        point("integrator", ("course", 11, "exact"), 1.2, 2.0, 1.5, 50.0),
        point("max_depth", ("whitted", 2, "exact"), 0.4, 0.9, 0.5, 9.0),
    ]));
    let light = findings.light_left_out.unwrap();
    assert_eq!(light.truth_noise, 2e-4);
    assert_eq!(light.max_depth, 11);
    let got: Vec<(&str, f64)> = light
        .integrators
        .iter()
        .map(|l| (l.integrator.as_str(), l.left_out))
        .collect();
    let want = [
        ("whitted", 0.25),
        ("local", 0.875),
        ("path", 0.03125),
        ("course", -0.5),
    ];
    assert_eq!(got.len(), want.len(), "{got:?}");
    for ((integrator, left), (w_integrator, w_left)) in got.iter().zip(want) {
        assert_eq!(*integrator, w_integrator);
        assert!((left - w_left).abs() < EXACT, "{integrator}: {left}");
    }
    let noise: Vec<f64> = light.integrators.iter().map(|l| l.noise).collect();
    assert!((noise[0] - 2e-4).abs() < EXACT, "{noise:?}");
    assert!((noise[2] - 2.5e-4).abs() < EXACT, "{noise:?}");
    assert!(!light.integrators[2].within_noise);
    for (share, within) in [(1.0 - 4.99e-4, true), (1.0 - 5.01e-4, false)] {
        path.errors.light = Some(share);
        let findings = Findings::of(&record(vec![own(0.3, 0.75), path.clone()]));
        let left = &findings.light_left_out.unwrap().integrators[1];
        assert_eq!(left.within_noise, within, "{left:?}");
    }
}

/// The step into the scene's own 11 bounces from 10 adds the difference
/// of their shares of the light, and their ΔE p99 apart is depth 10's
/// against the scene's own render; a step between two other depths has
/// no ΔE between them. `enough` is the shallowest depth from which every
/// deeper one is within ΔE p99 1 of the scene's own (4 is, 6 is not).
#[test]
fn the_eleventh_bounce_is_read_against_the_tenth() {
    let findings = Findings::of(&record(vec![
        own(0.30, 0.8125),
        point("max_depth", ("whitted", 4, "exact"), 0.5, 0.40, 0.5, 0.5),
        point("max_depth", ("whitted", 6, "exact"), 0.7, 0.35, 0.625, 1.5),
        point("max_depth", ("whitted", 10, "exact"), 0.9, 0.31, 0.8, 0.75),
        point(
            "max_depth",
            ("whitted", 16, "exact"),
            1.0,
            0.30,
            0.8125,
            0.0,
        ),
    ]));
    let bounces = findings.bounces.unwrap();
    assert_eq!(bounces.own, 11);
    let pairs: Vec<(u32, u32)> = bounces.steps.iter().map(|s| (s.from, s.to)).collect();
    assert_eq!(pairs, [(4, 6), (6, 10), (10, 11), (11, 16)]);
    let into_own = &bounces.steps[2];
    assert!((into_own.light_added - 0.0125).abs() < EXACT);
    assert_eq!((into_own.rel_rmse_from, into_own.rel_rmse_to), (0.31, 0.30));
    assert_eq!(into_own.delta_e_p99, Some(0.75));
    assert_eq!(bounces.steps[0].delta_e_p99, None);
    assert_eq!(bounces.steps[3].delta_e_p99, Some(0.0));
    assert!((bounces.steps[0].light_added - 0.125).abs() < EXACT);
    assert_eq!(bounces.enough, Some(10));
    assert_eq!(
        bounces.light,
        [(4, 0.5), (6, 0.625), (10, 0.8), (11, 0.8125), (16, 0.8125)]
    );
}

/// Schlick's cost is the Schlick point's against the exact law's render
/// (the scene's own), over the image and over its grazing pixels; a
/// scene whose own law is not exact has no such reading.
#[test]
fn schlicks_cost_is_read_against_the_exact_laws_render() {
    let mut schlick = point(
        "fresnel",
        ("whitted", 11, "schlick-rarer"),
        0.8,
        0.31,
        0.8,
        1.25,
    );
    schlick.grazing = Some(Grazing {
        pixels: 42,
        errors: schlick.errors,
        against_scene: Errors {
            rel_rmse: 0.125,
            delta_e_mean: 3.5,
            delta_e_p99: 7.25,
            flip_mean: 0.2,
            light: Some(0.9),
            light_noise: None,
        },
    });
    let points = vec![
        own(0.3, 0.8),
        point("fresnel", ("whitted", 11, "course"), 0.8, 0.5, 0.7, 9.0),
        schlick,
    ];
    let findings = Findings::of(&record(points.clone()));
    let cost = findings.schlick.unwrap();
    assert_eq!(cost.shortcut.delta_e_p99, 1.25);
    assert!((cost.shortcut.time_ratio - 0.8).abs() < EXACT);
    assert_eq!(cost.verdict, Verdict::Trade);
    assert_eq!(cost.rel_rmse, [0.3, 0.31]);
    let grazing = cost.grazing.unwrap();
    assert_eq!(
        (
            grazing.pixels,
            grazing.delta_e_mean,
            grazing.delta_e_p99,
            grazing.rel_rmse
        ),
        (42, 3.5, 7.25, 0.125)
    );
    let mut schlick_scene = points;
    schlick_scene[0].settings.fresnel = "schlick-rarer".to_owned();
    assert!(Findings::of(&record(schlick_scene)).schlick.is_none());
}

/// Local and Whitted are indistinguishable within ΔE p99 1 (the
/// just-noticeable difference, the verdicts' rule): 1.0 is, 1.01 is not.
#[test]
fn local_is_indistinguishable_from_whitted_within_the_just_noticeable_difference() {
    for (delta_e, indistinguishable) in [(0.0, true), (1.0, true), (1.01, false), (45.0, false)] {
        let findings = Findings::of(&record(vec![
            own(0.3, 0.8),
            point("integrator", ("local", 11, "exact"), 0.9, 0.3, 0.8, delta_e),
        ]));
        let got = findings.local_against_whitted.unwrap();
        assert_eq!(got.delta_e_p99, delta_e);
        assert_eq!(got.indistinguishable, indistinguishable, "ΔE {delta_e}");
    }
    let path_only = Findings::of(&record(vec![
        point("scene", ("path", 11, "exact"), 1.0, 0.1, 1.0, 0.0),
        point("integrator", ("local", 11, "exact"), 0.1, 0.9, 0.2, 40.0),
    ]));
    assert!(path_only.local_against_whitted.is_none());
}

/// Shortcuts sort by the verdicts' rule, fastest first: unseen and at
/// most 0.9× the time is worth it, faster and seen is a trade, unseen
/// and past 1/0.9× the time buys nothing; the accuracy to buy is what
/// lies on the relative RMSE front, at most 0.9× the scene's own, and is
/// seen against it, cheapest first (0.2701 against 0.3 is not a tenth
/// nearer; an unseen change is no upgrade).
#[test]
fn shortcuts_are_sorted_by_the_verdicts_rule_fastest_first() {
    let mut path = point("integrator", ("path", 11, "exact"), 20.0, 0.05, 0.99, 30.0);
    path.pareto = vec!["rel_rmse".to_owned()];
    let mut photon = point(
        "integrator",
        ("photon", 11, "exact"),
        200.0,
        0.01,
        1.0,
        31.0,
    );
    photon.pareto = vec!["rel_rmse".to_owned()];
    let mut fast_but_worse = point("max_depth", ("whitted", 0, "exact"), 0.1, 0.9, 0.1, 50.0);
    fast_but_worse.pareto = vec!["rel_rmse".to_owned()];
    let mut unseen_nearer = point("ray_offset", ("whitted", 11, "exact"), 1.0, 0.2, 0.8, 0.4);
    unseen_nearer.pareto = vec!["rel_rmse".to_owned()];
    let mut barely_nearer = point("fresnel", ("whitted", 11, "course"), 1.0, 0.2701, 0.8, 3.0);
    barely_nearer.pareto = vec!["rel_rmse".to_owned()];
    let findings = Findings::of(&record(vec![
        own(0.3, 0.8),
        unseen_nearer,
        barely_nearer,
        photon,
        point("max_depth", ("whitted", 8, "exact"), 0.85, 0.3, 0.8, 0.5),
        point("max_depth", ("whitted", 6, "exact"), 0.5, 0.3, 0.8, 0.9),
        point(
            "fresnel",
            ("whitted", 11, "schlick-rarer"),
            0.7,
            0.3,
            0.8,
            1.5,
        ),
        fast_but_worse,
        path,
        point("max_depth", ("whitted", 64, "exact"), 1.05, 0.3, 0.8, 0.0),
        point("max_depth", ("whitted", 32, "exact"), 3.0, 0.3, 0.8, 0.0),
    ]));
    let labels = |list: &[Shortcut]| list.iter().map(|s| s.label.clone()).collect::<Vec<_>>();
    assert_eq!(
        labels(&findings.worth_it),
        ["max_depth whitted 6 exact", "max_depth whitted 8 exact"]
    );
    assert_eq!(
        labels(&findings.seen),
        [
            "max_depth whitted 0 exact",
            "fresnel whitted 11 schlick-rarer"
        ]
    );
    assert_eq!(labels(&findings.no_gain), ["max_depth whitted 32 exact"]);
    let upgrades: Vec<&str> = findings.upgrades.iter().map(|u| u.label.as_str()).collect();
    assert_eq!(
        upgrades,
        ["integrator path 11 exact", "integrator photon 11 exact"]
    );
}

/// A metal's worst ΔE over the angles is the largest, with its angle.
#[test]
fn a_metals_worst_colour_error_is_its_largest_over_the_angles() {
    let measured = RgbOutcome::Measured {
        angles_deg: vec![0.0, 45.0, 85.0],
        delta_e: vec![5.25, 4.0, 7.5],
    };
    assert_eq!(measured.worst(), Some((7.5, 85.0)));
    assert_eq!(RgbOutcome::NoSpectrum.worst(), None);
}

/// Renders of the scene's own work (as many rays, the same image) time
/// only the machine: their least and most time ratios (0.6 and 1.3, to
/// 1e-12) bound the run's timing noise, a shortcut inside it is not worth
/// it (0.7) nor a dearer setting inside it no gain (1.2), and they are no
/// shortcuts themselves.
#[test]
fn renders_of_the_scenes_own_work_are_the_timing_noise() {
    let mut same_fast = point("max_depth", ("whitted", 64, "exact"), 0.6, 0.3, 0.8, 0.0);
    same_fast.rays = 1e4;
    let mut same_slow = point(
        "throughput_cutoff",
        ("whitted", 11, "exact"),
        1.3,
        0.3,
        0.8,
        0.0,
    );
    same_slow.rays = 1e4;
    let findings = Findings::of(&record(vec![
        own(0.3, 0.8),
        same_fast,
        same_slow,
        point(
            "fresnel",
            ("whitted", 11, "schlick-rarer"),
            0.5,
            0.3,
            0.8,
            0.5,
        ),
        point("max_depth", ("whitted", 8, "exact"), 0.7, 0.3, 0.8, 0.5),
        point("max_depth", ("whitted", 32, "exact"), 1.2, 0.3, 0.8, 0.0),
        point("max_depth", ("whitted", 63, "exact"), 1.4, 0.3, 0.8, 0.0),
    ]));
    let noise = findings.timing_noise.unwrap();
    assert_eq!(
        noise.labels,
        [
            "max_depth whitted 64 exact",
            "throughput_cutoff whitted 11 exact"
        ]
    );
    assert!((noise.ratios[0] - 0.6).abs() < EXACT && (noise.ratios[1] - 1.3).abs() < EXACT);
    let labels = |list: &[Shortcut]| list.iter().map(|s| s.label.clone()).collect::<Vec<_>>();
    assert_eq!(
        labels(&findings.worth_it),
        ["fresnel whitted 11 schlick-rarer"]
    );
    assert_eq!(labels(&findings.no_gain), ["max_depth whitted 63 exact"]);
}
