//! The rows a finding reads: the scene's own point against the points of
//! one axis, each reading what the record measured and nothing else.

use super::field::{
    BounceStep, Bounces, GrazingCost, LeftOut, LightLeftOut, LocalAgainstWhitted, Schlick, Shortcut,
};
use super::thresholds::NOISE_SIGMAS;
use crate::tradeoff::record::{Point, Record};
use crate::tradeoff::sweep::SCHLICK_SWEPT;
use crate::tradeoff::verdict::JUST_NOTICEABLE;

/// Whether `p` does `base`'s work: as many rays, and a render that is
/// theirs to the bit (no error against it at all).
pub(super) fn same_work(base: &Point, p: &Point) -> bool {
    p.rays == base.rays && p.against_scene.rel_rmse == 0.0 && p.against_scene.delta_e_p99 == 0.0
}

/// The scene's own settings and each point of the integrator axis, where
/// the record measured the light (and the truth's noise on it).
pub(super) fn light_left_out(
    record: &Record,
    base: &Point,
    rest: &[Point],
) -> Option<LightLeftOut> {
    let truth_noise = record.truth.light_noise_relative?;
    let integrators = std::iter::once(base)
        .chain(rest.iter().filter(|p| p.axis == "integrator"))
        .map(|p| {
            let left_out = 1.0 - p.errors.light?;
            let own = p.errors.light_noise.unwrap_or(0.0);
            let noise = truth_noise.hypot(own);
            Some(LeftOut {
                label: p.label.clone(),
                integrator: p.settings.integrator.clone(),
                left_out,
                noise,
                within_noise: left_out.abs() <= NOISE_SIGMAS * noise,
            })
        })
        .collect::<Option<Vec<_>>>()?;
    Some(LightLeftOut {
        max_depth: base.settings.max_depth,
        truth_noise,
        integrators,
    })
}

/// The depth axis with the scene's own point at its depth, in order of
/// depth, each step read from its two ends.
pub(super) fn bounces(base: &Point, rest: &[Point]) -> Option<Bounces> {
    let mut depths: Vec<&Point> = std::iter::once(base)
        .chain(rest.iter().filter(|p| p.axis == "max_depth"))
        .collect();
    if depths.len() < 2 {
        return None;
    }
    depths.sort_by_key(|p| p.settings.max_depth);
    let own = base.settings.max_depth;
    let between = |a: &Point, b: &Point| {
        if a.settings.max_depth == own {
            Some(b.against_scene.delta_e_p99)
        } else if b.settings.max_depth == own {
            Some(a.against_scene.delta_e_p99)
        } else {
            None
        }
    };
    let steps = depths
        .windows(2)
        .map(|pair| {
            let (a, b) = (pair[0], pair[1]);
            Some(BounceStep {
                from: a.settings.max_depth,
                to: b.settings.max_depth,
                light_added: b.errors.light? - a.errors.light?,
                rel_rmse_from: a.errors.rel_rmse,
                rel_rmse_to: b.errors.rel_rmse,
                delta_e_p99: between(a, b),
            })
        })
        .collect::<Option<Vec<_>>>()?;
    let light = depths
        .iter()
        .map(|p| Some((p.settings.max_depth, p.errors.light?)))
        .collect::<Option<Vec<_>>>()?;
    // The deepest run of depths all within sight of the scene's own.
    let enough = depths
        .iter()
        .rev()
        .take_while(|p| p.against_scene.delta_e_p99 <= JUST_NOTICEABLE)
        .last()
        .map(|p| p.settings.max_depth);
    Some(Bounces {
        own,
        light,
        steps,
        enough,
    })
}

/// The point of Schlick's form the sweep measures ([`SCHLICK_SWEPT`])
/// against a scene whose own law is exact.
pub(super) fn schlick(
    base: &Point,
    rest: &[Point],
    ratio: impl Fn(&Point) -> f64,
) -> Option<Schlick> {
    if base.settings.fresnel != "exact" {
        return None;
    }
    let p = rest
        .iter()
        .find(|p| p.axis == "fresnel" && p.settings.fresnel == SCHLICK_SWEPT.to_string())?;
    Some(Schlick {
        shortcut: Shortcut {
            label: p.label.clone(),
            time_ratio: ratio(p),
            delta_e_p99: p.against_scene.delta_e_p99,
        },
        verdict: p.verdict?,
        rel_rmse: [base.errors.rel_rmse, p.errors.rel_rmse],
        grazing: p.grazing.map(|g| GrazingCost {
            pixels: g.pixels,
            delta_e_mean: g.against_scene.delta_e_mean,
            delta_e_p99: g.against_scene.delta_e_p99,
            rel_rmse: g.against_scene.rel_rmse,
        }),
    })
}

/// Local against Whitted, where one is the scene's own and the other a
/// point of the integrator axis (its measure against the scene's own is
/// then the one between them).
pub(super) fn local_against_whitted(base: &Point, rest: &[Point]) -> Option<LocalAgainstWhitted> {
    let other = match base.settings.integrator.as_str() {
        "whitted" => "local",
        "local" => "whitted",
        _ => return None,
    };
    let p = rest
        .iter()
        .find(|p| p.axis == "integrator" && p.settings.integrator == other)?;
    let delta_e_p99 = p.against_scene.delta_e_p99;
    Some(LocalAgainstWhitted {
        delta_e_p99,
        indistinguishable: delta_e_p99 <= JUST_NOTICEABLE,
    })
}
