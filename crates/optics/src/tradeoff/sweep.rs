//! What a scene's sweep renders: the settings that apply to it, each
//! varied alone from the scene's own, and the integrators of `003`'s
//! ladder; what does not apply is said, with why, not rendered.

use serde::Serialize;
use tracer::chains;
use tracer::job::RenderJob;
use tracer::needs::ReflectionDepth;
use tracer::scene::{
    FresnelModel, IntegratorKind, PixelFilter, Precision, RayOffset, RenderSpec, Settings,
};

/// Mitsuba 3's `RayEpsilon` in `float32`, 1500 · 2⁻²⁴: its relative offset.
const MITSUBA_EPSILON: f64 = 1500.0 / 16_777_216.0;

/// The course's fixed offset, m.
const COURSE_EPSILON: f64 = 1e-3;

/// A setting the sweep varies.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Axis {
    /// The scene's own settings, against which every other is read.
    Scene,
    /// The light transport: `003`'s ladder.
    Integrator,
    /// The bounce limit.
    MaxDepth,
    /// The Fresnel law of mirrors and glass.
    Fresnel,
    /// Samples per pixel of a Monte Carlo integrator.
    Spp,
    /// Where primary rays pass through their pixel.
    PixelFilter,
    /// How secondary rays leave a surface.
    RayOffset,
    /// The throughput below which a path is cut or rouletted.
    ThroughputCutoff,
    /// The precision tier the tracer computes in.
    Precision,
}

/// One setting of the sweep.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Point {
    /// What it varies.
    pub axis: Axis,
    /// How it reads in a table: `max_depth 4`, `fresnel schlick`.
    pub label: String,
    /// The settings it renders with, settled.
    pub settings: Settings,
}

/// An axis left out, and why.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Skipped {
    /// The setting.
    pub axis: &'static str,
    /// Why it is not swept here.
    pub why: &'static str,
    /// The same in Hungarian (text output only).
    #[serde(skip)]
    pub why_hu: &'static str,
}

/// The plan: the points to render, the scene's own first, and what was
/// left out.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Plan {
    /// Every point, the scene's own settings first; no two settle alike.
    pub points: Vec<Point>,
    /// The axes that do not apply, each with its reason.
    pub skipped: Vec<Skipped>,
}

/// The sweep around `job`'s settings; `spp` is what a Monte Carlo
/// integrator takes on the ladder when the scene's integrator is
/// deterministic.
pub fn plan(job: &RenderJob, spp: u32) -> Plan {
    let base = *job.settings();
    let needs = job.needs();
    let mut points = vec![Point {
        axis: Axis::Scene,
        label: format!("scene: {}", describe(&base)),
        settings: base,
    }];
    let mut skipped = Vec::new();
    let mut add = |axis: Axis, label: String, spec: RenderSpec| {
        let Ok(settings) = base.settle("tradeoff", &spec) else {
            return;
        };
        let renderable = RenderJob::with_settings(job.scene().clone(), settings).is_ok();
        if renderable && !points.iter().any(|p| p.settings == settings) {
            points.push(Point {
                axis,
                label,
                settings,
            });
        }
    };

    let caustics = !chains::find(job.scene(), needs).is_empty();
    for integrator in [
        IntegratorKind::Local,
        IntegratorKind::Whitted,
        IntegratorKind::Path,
        IntegratorKind::Photon,
        IntegratorKind::Course,
    ] {
        if integrator == IntegratorKind::Photon && !caustics {
            continue;
        }
        let spp = (integrator.samples() && !base.integrator.samples()).then_some(f64::from(spp));
        let label = match spp {
            Some(n) => format!("integrator {integrator}, {n} spp"),
            None => format!("integrator {integrator}"),
        };
        // A rung the scene's tier does not serve is taken in f32.
        let precision = (!base.precision.serves(integrator)).then_some(Precision::F32);
        let spec = RenderSpec {
            integrator: Some(integrator),
            spp,
            precision,
            ..RenderSpec::default()
        };
        add(Axis::Integrator, label, spec);
    }
    if !caustics {
        skipped.push(Skipped {
            axis: "integrator photon",
            why: "no delta light reaches a rough surface through mirrors or glass: photon renders what path does",
            why_hu: "egyetlen pont- vagy irányfény sem ér érdes felületet tükrön vagy üvegen át: a photon ugyanazt rajzolja, mint a path",
        });
    }

    let recursive = matches!(needs.reflection_depth, ReflectionDepth::UpToMaxDepth(_))
        || base.integrator.samples();
    if recursive {
        for depth in [0, 1, 2, 3, 4, 6, 8, 10, 11, 16, 32, 64] {
            let spec = RenderSpec {
                max_depth: Some(f64::from(depth)),
                ..RenderSpec::default()
            };
            add(Axis::MaxDepth, format!("max_depth {depth}"), spec);
        }
        for cutoff in [0.0, 1e-3, 1e-2, 1e-1] {
            let spec = RenderSpec {
                throughput_cutoff: Some(cutoff),
                ..RenderSpec::default()
            };
            add(
                Axis::ThroughputCutoff,
                format!("throughput_cutoff {cutoff}"),
                spec,
            );
        }
    } else {
        skipped.push(Skipped {
            axis: "max_depth, throughput_cutoff",
            why: "no mirror or glass sees another or itself, and the integrator does not bounce diffusely: depth never binds",
            why_hu: "egyik tükör vagy üveg sem látja a másikat vagy önmagát, és az integrátor nem pattan diffúzan: a mélység sosem korlátoz",
        });
    }

    if needs.conductors || needs.refraction {
        for model in [
            FresnelModel::Exact,
            FresnelModel::Schlick,
            FresnelModel::Course,
        ] {
            let spec = RenderSpec {
                fresnel: Some(model),
                ..RenderSpec::default()
            };
            add(Axis::Fresnel, format!("fresnel {model}"), spec);
        }
    } else {
        skipped.push(Skipped {
            axis: "fresnel",
            why: "no mirror or glass: no Fresnel law is evaluated",
            why_hu: "nincs tükör vagy üveg: egyetlen Fresnel-törvény sem értékelődik ki",
        });
    }

    if base.integrator.samples() && !needs.deterministic {
        for n in [1, 4, 16, 64, 256] {
            let spec = RenderSpec {
                spp: Some(f64::from(n)),
                ..RenderSpec::default()
            };
            add(Axis::Spp, format!("spp {n}"), spec);
        }
    } else {
        for n in [4, 16] {
            let spec = RenderSpec {
                pixel_filter: Some(PixelFilter::Box),
                spp: Some(f64::from(n)),
                ..RenderSpec::default()
            };
            add(
                Axis::PixelFilter,
                format!("pixel_filter box, {n} spp"),
                spec,
            );
        }
    }

    if needs.shadows || !matches!(needs.reflection_depth, ReflectionDepth::None) {
        for (label, offset) in [
            ("ray_offset robust".to_owned(), RayOffset::Robust),
            (
                format!("ray_offset fixed {COURSE_EPSILON} m (the course)"),
                RayOffset::Fixed(COURSE_EPSILON),
            ),
            (
                "ray_offset scaled 8.94e-5 (Mitsuba 3)".to_owned(),
                RayOffset::Scaled(MITSUBA_EPSILON),
            ),
        ] {
            let spec = RenderSpec {
                ray_offset: Some(offset),
                ..RenderSpec::default()
            };
            add(Axis::RayOffset, label, spec);
        }
    } else {
        skipped.push(Skipped {
            axis: "ray_offset",
            why: "no secondary ray leaves a surface: no shadow ray, no mirror or glass",
            why_hu: "egyetlen másodlagos sugár sem hagy el felületet: nincs árnyéksugár, tükör vagy üveg",
        });
    }

    if Precision::F64.serves(base.integrator) {
        for precision in [Precision::F32, Precision::F64] {
            let spec = RenderSpec {
                precision: Some(precision),
                ..RenderSpec::default()
            };
            add(Axis::Precision, format!("precision {precision}"), spec);
        }
    } else {
        skipped.push(Skipped {
            axis: "f32 against f64",
            why: "the scene's integrator computes in f32 only: the f64 tier is local's and whitted's (their rows on the ladder are f32)",
            why_hu: "a jelenet integrátora csak f32-ben számol: az f64-es szint a local és a whitted integrátoré (a létrán f32-ben szerepelnek)",
        });
    }
    skipped.push(Skipped {
        axis: "RGB against spectrum",
        why: "in the image: the tracer has no spectral mode; what three channels cost the colour of the scene's metals, by the harness's measure (metals.*), is stated apart",
            why_hu: "a képen: a követőnek nincs spektrális módja; hogy mennyibe kerül a három csatorna a jelenet fémeinek színében, azt a mérőcsomag mércéje (metals.*) külön mondja",
    });
    Plan { points, skipped }
}

/// The settings in a few words: `whitted, max_depth 11, fresnel exact`;
/// a path's throughput cutoff (where its Russian roulette starts) where it
/// is not the default.
pub fn describe(s: &Settings) -> String {
    let mut words = format!("{}", s.integrator);
    if s.integrator.samples() || s.pixel_filter == PixelFilter::Box {
        words += &format!(", {} spp", s.spp);
    }
    words += &format!(", max_depth {}, fresnel {}", s.max_depth, s.fresnel);
    if s.integrator.samples() && s.throughput_cutoff != Settings::default().throughput_cutoff {
        words += &format!(", throughput_cutoff {}", s.throughput_cutoff);
    }
    words
}

/// The ground truth's settings: all the light (the caustic photon map
/// where a delta light reaches a rough surface through mirrors or glass),
/// a box filter, `spp` samples, depth at least 64, the exact laws, the
/// robust offset.
pub fn truth_settings(job: &RenderJob, spp: u32) -> Settings {
    let base = *job.settings();
    let caustics = !chains::find(job.scene(), job.needs()).is_empty();
    let spec = RenderSpec {
        integrator: Some(if caustics {
            IntegratorKind::Photon
        } else {
            IntegratorKind::Path
        }),
        spp: Some(f64::from(spp)),
        precision: Some(Precision::F32),
        max_depth: Some(f64::from(base.max_depth.max(64))),
        fresnel: Some(FresnelModel::Exact),
        ray_offset: Some(RayOffset::Robust),
        pixel_filter: Some(PixelFilter::Box),
        ..RenderSpec::default()
    };
    base.settle("tradeoff.truth", &spec)
        .expect("the truth's settings are each within their domain")
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;
    use tracer::job::Overrides;

    /// A course scene at 8 × 6, for the tests of what a sweep or a budget
    /// plans for it.
    pub(crate) fn job(name: &str) -> RenderJob {
        let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("../tracer/scenes")
            .join(format!("{name}.json"));
        let overrides = Overrides {
            width: Some(8),
            height: Some(6),
            ..Overrides::default()
        };
        RenderJob::load(&path, &overrides).unwrap()
    }

    fn axes(plan: &Plan) -> Vec<Axis> {
        let mut axes: Vec<Axis> = plan.points.iter().map(|p| p.axis).collect();
        axes.dedup();
        axes
    }

    #[test]
    fn a_scene_without_mirrors_or_glass_sweeps_no_fresnel_law_and_no_depth() {
        let plan = plan(&job("shadow"), 16);
        assert!(!axes(&plan).contains(&Axis::Fresnel));
        assert!(!axes(&plan).contains(&Axis::MaxDepth));
        assert!(plan.skipped.iter().any(|s| s.axis == "fresnel"));
        assert!(
            axes(&plan).contains(&Axis::RayOffset),
            "shadow rays leave surfaces"
        );
    }

    #[test]
    fn the_kaleidoscope_sweeps_depth_fresnel_and_its_ladder() {
        let plan = plan(&job("kaleidoscope_lit"), 16);
        let axes = axes(&plan);
        for axis in [
            Axis::Scene,
            Axis::Integrator,
            Axis::MaxDepth,
            Axis::Fresnel,
            Axis::PixelFilter,
        ] {
            assert!(axes.contains(&axis), "{axis:?} missing from {axes:?}");
        }
        // Deterministic scene integrator: no spp axis, path on the ladder at 16.
        assert!(!axes.contains(&Axis::Spp));
        assert!(plan
            .points
            .iter()
            .any(|p| p.label == "integrator path, 16 spp"));
        assert_eq!(plan.points[0].axis, Axis::Scene);
    }

    #[test]
    fn no_two_points_render_the_same_settings() {
        for scene in [
            "kaleidoscope_lit",
            "glass_spheres",
            "gold_spheres",
            "shadow",
        ] {
            let plan = plan(&job(scene), 16);
            for (i, p) in plan.points.iter().enumerate() {
                assert!(
                    plan.points[..i].iter().all(|q| q.settings != p.settings),
                    "{scene}: {} repeats an earlier point",
                    p.label
                );
            }
        }
    }

    /// A whitted scene sweeps its tier: one row at f64 beside its own f32,
    /// and no reason left for not sweeping it; a path scene keeps the
    /// reason, and a scene at f64 keeps every rung of the ladder.
    #[test]
    fn the_tier_is_swept_where_the_integrator_computes_in_f64() {
        let whitted = plan(&job("gold_spheres"), 16);
        let tiers: Vec<&Point> = whitted
            .points
            .iter()
            .filter(|p| p.axis == Axis::Precision)
            .collect();
        assert_eq!(tiers.len(), 1, "{:?}", whitted.points);
        assert_eq!(tiers[0].settings.precision, Precision::F64);
        assert_eq!(tiers[0].label, "precision f64");
        assert!(whitted.skipped.iter().all(|s| s.axis != "f32 against f64"));

        let scene = job("inside_water").scene().clone();
        let settings = scene.settings.settle(
            "test",
            &RenderSpec {
                integrator: Some(IntegratorKind::Path),
                ..RenderSpec::default()
            },
        );
        let path = plan(
            &RenderJob::with_settings(scene, settings.unwrap()).unwrap(),
            16,
        );
        assert!(path.points.iter().all(|p| p.axis != Axis::Precision));
        assert!(path.skipped.iter().any(|s| s.axis == "f32 against f64"));

        let at_f64 = RenderJob::with_settings(
            job("gold_spheres").scene().clone(),
            Settings {
                precision: Precision::F64,
                ..*job("gold_spheres").settings()
            },
        )
        .unwrap();
        let ladder = plan(&at_f64, 16);
        for integrator in [IntegratorKind::Path, IntegratorKind::Course] {
            assert!(
                ladder
                    .points
                    .iter()
                    .any(|p| p.settings.integrator == integrator
                        && p.settings.precision == Precision::F32),
                "{integrator} missing from the ladder at f64"
            );
        }
        assert_eq!(
            truth_settings(&at_f64, 64).precision,
            Precision::F32,
            "the truth is the path tracer's, in f32"
        );
    }

    #[test]
    fn glass_has_no_course_integrator_and_its_truth_carries_the_caustics() {
        let job = job("glass_spheres");
        let plan = plan(&job, 16);
        assert!(plan
            .points
            .iter()
            .all(|p| p.settings.integrator != IntegratorKind::Course));
        let truth = truth_settings(&job, 64);
        assert_eq!(truth.integrator, IntegratorKind::Photon);
        assert_eq!(truth.pixel_filter, PixelFilter::Box);
        assert!(truth.max_depth >= 64);
    }
}
