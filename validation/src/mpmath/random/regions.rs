//! Where the random cases fall: per law, the regions that stress it (tiny
//! cosines and angles, near the critical angle, total internal reflection,
//! an index near 1), counted per set. The regions overlap; a case may be in
//! several or none.
//!
//! The thresholds are stated once, here: a cosine, angle, index distance or
//! `κ` below [`SMALL`], an angle within [`SMALL`] rad of the critical angle.

use super::reference::{CaseSet, Law};

/// The threshold of "small" and "near".
pub const SMALL: f64 = 1e-3;

/// The critical angle of the index along the path, if it has one.
fn critical(eta_path: f64) -> Option<f64> {
    (eta_path < 1.0).then(|| eta_path.asin())
}

fn near_critical(theta: f64, eta_path: f64) -> bool {
    critical(eta_path).is_some_and(|c| (theta - c).abs() < SMALL)
}

/// A region: its name in English and in Hungarian, and whether case `i`
/// of a set lies in it.
type Region = ([&'static str; 2], fn(&CaseSet, usize) -> bool);

fn regions_of(law: Law) -> &'static [Region] {
    match law {
        Law::Dielectric => &[
            (["|cos θi| < 1e-3", "|cos θi| < 1e-3"], |s, i| {
                s.column("cos_i")[i].abs() < SMALL
            }),
            (
                [
                    "within 1e-3 rad of the critical angle",
                    "a határszög 1e-3 rad-os környezetében",
                ],
                |s, i| {
                    let (c, eta) = (s.column("cos_i")[i], s.column("eta")[i]);
                    let eta_path = if c >= 0.0 { eta } else { 1.0 / eta };
                    near_critical(c.abs().acos(), eta_path)
                },
            ),
            (
                ["total internal reflection", "teljes visszaverődés"],
                |s, i| s.tir.as_ref().is_some_and(|t| t[i]),
            ),
            (["|η − 1| < 1e-3", "|η − 1| < 1e-3"], |s, i| {
                (s.column("eta")[i] - 1.0).abs() < SMALL
            }),
        ],
        Law::Conductor => &[
            (["cos θi < 1e-3", "cos θi < 1e-3"], |s, i| {
                s.column("cos_i")[i] < SMALL
            }),
            (["κ < 1e-3", "κ < 1e-3"], |s, i| {
                s.column("kappa")[i] < SMALL
            }),
            (
                ["κ < 1e-3 and |n − 1| < 1e-3", "κ < 1e-3 és |n − 1| < 1e-3"],
                |s, i| s.column("kappa")[i] < SMALL && (s.column("n")[i] - 1.0).abs() < SMALL,
            ),
        ],
        Law::TransmittedAngle => &[
            (["θi < 1e-3", "θi < 1e-3"], |s, i| {
                s.column("theta_i")[i] < SMALL
            }),
            (
                [
                    "within 1e-3 rad of the critical angle",
                    "a határszög 1e-3 rad-os környezetében",
                ],
                |s, i| near_critical(s.column("theta_i")[i], s.column("eta_path")[i]),
            ),
            (
                ["total internal reflection", "teljes visszaverődés"],
                |s, i| s.column("theta_t")[i].is_nan(),
            ),
            (["|η − 1| < 1e-3", "|η − 1| < 1e-3"], |s, i| {
                (s.column("eta_path")[i] - 1.0).abs() < SMALL
            }),
        ],
        Law::CriticalAngle | Law::BrewsterAngle => &[
            (["η < 1", "η < 1"], |s, i| s.column("eta_path")[i] < 1.0),
            (["|η − 1| < 1e-3", "|η − 1| < 1e-3"], |s, i| {
                (s.column("eta_path")[i] - 1.0).abs() < SMALL
            }),
        ],
        Law::Schlick => &[
            (["cos θi < 1e-3", "cos θi < 1e-3"], |s, i| {
                s.column("cos_i")[i] < SMALL
            }),
            (["1 − cos θi < 1e-3", "1 − cos θi < 1e-3"], |s, i| {
                1.0 - s.column("cos_i")[i] < SMALL
            }),
            (["F0 < 1e-3", "F0 < 1e-3"], |s, i| s.column("f0")[i] < SMALL),
        ],
    }
}

/// The number of cases of `set` in each region of its law.
pub fn count(set: &CaseSet) -> Vec<(&'static str, usize)> {
    count_in_both(set)
        .into_iter()
        .map(|([en, _], n)| (en, n))
        .collect()
}

/// [`count`] with each region named in English and in Hungarian.
pub fn count_in_both(set: &CaseSet) -> Vec<([&'static str; 2], usize)> {
    regions_of(set.law)
        .iter()
        .map(|(names, inside)| (*names, (0..set.count).filter(|&i| inside(set, i)).count()))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mpmath::random::reference::{Sampling, Tier};

    #[test]
    fn a_case_just_past_glass_critical_angle_is_near_it_and_reflected() {
        let theta_c = (1.0f64 / 1.5).asin();
        let cos_i = -(theta_c + 1e-4).cos(); // inside glass, 1e-4 rad past it
        let set = CaseSet {
            law: Law::Dielectric,
            tier: Tier::F64,
            sampling: Sampling::Reals,
            count: 2,
            columns: [
                ("cos_i".to_owned(), vec![cos_i, 0.5]),
                ("eta".to_owned(), vec![1.5, 1.5]),
            ]
            .into(),
            tir: Some(vec![true, false]),
        };
        let counts = count(&set);
        assert_eq!(counts[1], ("within 1e-3 rad of the critical angle", 1));
        assert_eq!(counts[2], ("total internal reflection", 1));
        assert_eq!(counts[0].1 + counts[3].1, 0);
    }
}
