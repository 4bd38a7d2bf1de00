//! What a scene's sweep renders: the settings that apply to it, each
//! varied alone from the scene's own, and the integrators of `003`'s
//! ladder; what does not apply is said, with why, not rendered.

use serde::Serialize;
use tracer::chains;
use tracer::job::RenderJob;
use tracer::needs::{Needs, ReflectionDepth};
use tracer::scene::{
    FresnelModel, IntegratorKind, PixelFilter, Precision, RayOffset, RenderSpec, Settings,
};

/// The form of Schlick's approximation the sweep and the budget measure:
/// the rarer medium's, the form the tracer rendered as `schlick` before the
/// forms were named (the records of version 1 call it so).
pub const SCHLICK_SWEPT: FresnelModel = FresnelModel::SchlickRarer;

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
    /// How it reads in a table: `max_depth 4`, `fresnel schlick-rarer`.
    pub label: String,
    /// The settings it renders with, settled.
    pub settings: Settings,
}

/// An axis left out, and why.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Skipped {
    /// The setting.
    pub axis: &'static str,
    /// The same in Hungarian (text output only): a setting's name stays.
    #[serde(skip)]
    pub axis_hu: &'static str,
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
    let needs = job.needs();
    let mut planner = Planner::new(job);
    planner.integrators(!chains::find(job.scene(), needs).is_empty(), spp);
    planner.depths(needs);
    planner.fresnel(needs);
    planner.samples(needs);
    planner.ray_offsets(needs);
    planner.precisions();
    planner.skip(
        ["RGB against spectrum", "RGB a spektrum helyett"],
        "in the image: the tracer has no spectral mode; what three channels cost the colour of the scene's metals, by the harness's measure (metals.*), is stated apart",
        "a képen: a követőnek nincs spektrális módja; hogy mennyibe kerül a három csatorna a jelenet fémeinek színében, azt a mérőcsomag mércéje (metals.*) külön mondja",
    );
    Plan {
        points: planner.points,
        skipped: planner.skipped,
    }
}

/// The plan as it grows, axis by axis, around one job's settings.
struct Planner<'a> {
    /// The job swept.
    job: &'a RenderJob,
    /// Its own settings, from which each point varies one.
    base: Settings,
    /// The points so far, the scene's own first.
    points: Vec<Point>,
    /// The axes left out so far.
    skipped: Vec<Skipped>,
}

impl<'a> Planner<'a> {
    /// The plan of `job` with its own settings alone.
    fn new(job: &'a RenderJob) -> Self {
        let base = *job.settings();
        Planner {
            job,
            base,
            points: vec![Point {
                axis: Axis::Scene,
                label: format!("scene: {}", describe(&base)),
                settings: base,
            }],
            skipped: Vec::new(),
        }
    }

    /// Adds the point of `axis` that `spec` makes of the scene's own
    /// settings, where they settle, the scene renders with them, and no
    /// point already settles alike.
    fn add(&mut self, axis: Axis, label: String, spec: RenderSpec) {
        let Ok(settings) = self.base.settle("tradeoff", &spec) else {
            return;
        };
        let renderable = RenderJob::with_settings(self.job.scene().clone(), settings).is_ok();
        if renderable && !self.points.iter().any(|p| p.settings == settings) {
            self.points.push(Point {
                axis,
                label,
                settings,
            });
        }
    }

    /// Leaves `axis` out, for the reason `why` (`why_hu` in Hungarian).
    fn skip(
        &mut self,
        [axis, axis_hu]: [&'static str; 2],
        why: &'static str,
        why_hu: &'static str,
    ) {
        self.skipped.push(Skipped {
            axis,
            axis_hu,
            why,
            why_hu,
        });
    }

    /// `003`'s ladder of integrators, photon only where the scene has
    /// `caustics`; a sampling rung at `spp` where the scene's own
    /// integrator is deterministic.
    fn integrators(&mut self, caustics: bool, spp: u32) {
        let base = self.base;
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
            let spp =
                (integrator.samples() && !base.integrator.samples()).then_some(f64::from(spp));
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
            self.add(Axis::Integrator, label, spec);
        }
        if !caustics {
            self.skip(
                ["integrator photon"; 2],
                "no delta light reaches a rough surface through mirrors or glass: photon renders what path does",
                "egyetlen pont- vagy irányfény sem ér érdes felületet tükrön vagy üvegen át: a photon ugyanazt rajzolja, mint a path",
            );
        }
    }

    /// The bounce limit and the throughput cutoff, where depth binds.
    fn depths(&mut self, needs: &Needs) {
        let recursive = matches!(needs.reflection_depth, ReflectionDepth::UpToMaxDepth(_))
            || self.base.integrator.samples();
        if !recursive {
            self.skip(
                ["max_depth, throughput_cutoff"; 2],
                "no mirror or glass sees another or itself, and the integrator does not bounce diffusely: depth never binds",
                "egyik tükör vagy üveg sem látja a másikat vagy önmagát, és az integrátor nem pattan diffúzan: a mélység sosem korlátoz",
            );
            return;
        }
        for depth in [0, 1, 2, 3, 4, 6, 8, 10, 11, 16, 32, 64] {
            let spec = RenderSpec {
                max_depth: Some(f64::from(depth)),
                ..RenderSpec::default()
            };
            self.add(Axis::MaxDepth, format!("max_depth {depth}"), spec);
        }
        for cutoff in [0.0, 1e-3, 1e-2, 1e-1] {
            let spec = RenderSpec {
                throughput_cutoff: Some(cutoff),
                ..RenderSpec::default()
            };
            self.add(
                Axis::ThroughputCutoff,
                format!("throughput_cutoff {cutoff}"),
                spec,
            );
        }
    }

    /// The Fresnel laws, where the scene has a mirror or glass.
    fn fresnel(&mut self, needs: &Needs) {
        if !(needs.conductors || needs.refraction) {
            self.skip(
                ["fresnel"; 2],
                "no mirror or glass: no Fresnel law is evaluated",
                "nincs tükör vagy üveg: egyetlen Fresnel-törvény sem értékelődik ki",
            );
            return;
        }
        for model in [FresnelModel::Exact, SCHLICK_SWEPT, FresnelModel::Course] {
            let spec = RenderSpec {
                fresnel: Some(model.into()),
                ..RenderSpec::default()
            };
            self.add(Axis::Fresnel, format!("fresnel {model}"), spec);
        }
    }

    /// Samples per pixel for a Monte Carlo integrator that is not
    /// deterministic here; the box filter's samples otherwise.
    fn samples(&mut self, needs: &Needs) {
        if self.base.integrator.samples() && !needs.deterministic {
            for n in [1, 4, 16, 64, 256] {
                let spec = RenderSpec {
                    spp: Some(f64::from(n)),
                    ..RenderSpec::default()
                };
                self.add(Axis::Spp, format!("spp {n}"), spec);
            }
            return;
        }
        for n in [4, 16] {
            let spec = RenderSpec {
                pixel_filter: Some(PixelFilter::Box),
                spp: Some(f64::from(n)),
                ..RenderSpec::default()
            };
            self.add(
                Axis::PixelFilter,
                format!("pixel_filter box, {n} spp"),
                spec,
            );
        }
    }

    /// The ray offsets (robust, the course's, Mitsuba 3's), where a
    /// secondary ray leaves a surface.
    fn ray_offsets(&mut self, needs: &Needs) {
        let secondary = needs.shadows || !matches!(needs.reflection_depth, ReflectionDepth::None);
        if !secondary {
            self.skip(
                ["ray_offset"; 2],
                "no secondary ray leaves a surface: no shadow ray, no mirror or glass",
                "egyetlen másodlagos sugár sem hagy el felületet: nincs árnyéksugár, tükör vagy üveg",
            );
            return;
        }
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
            self.add(Axis::RayOffset, label, spec);
        }
    }

    /// f32 against f64, where the scene's integrator has an f64 tier.
    fn precisions(&mut self) {
        if !Precision::F64.serves(self.base.integrator) {
            self.skip(
                ["f32 against f64", "f32 az f64 helyett"],
                "the scene's integrator computes in f32 only: the f64 tier is local's and whitted's (their rows on the ladder are f32)",
                "a jelenet integrátora csak f32-ben számol: az f64-es szint a local és a whitted integrátoré (a létrán f32-ben szerepelnek)",
            );
            return;
        }
        for precision in [Precision::F32, Precision::F64] {
            let spec = RenderSpec {
                precision: Some(precision),
                ..RenderSpec::default()
            };
            self.add(Axis::Precision, format!("precision {precision}"), spec);
        }
    }
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
        fresnel: Some(FresnelModel::Exact.into()),
        ray_offset: Some(RayOffset::Robust),
        pixel_filter: Some(PixelFilter::Box),
        ..RenderSpec::default()
    };
    base.settle("tradeoff.truth", &spec)
        .expect("the truth's settings are each within their domain")
}

#[cfg(test)]
pub(crate) mod tests;
