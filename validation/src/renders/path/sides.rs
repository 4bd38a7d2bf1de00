//! The two sides of a path comparison and what its tests found, shared by
//! the steps of [`super::compare_path`]; and the split of every
//! pixel-channel into a t-test or a deterministic comparison.

use crate::check::Check;
use crate::compare::welch::{guarded_variance, pixel_tests_guarded};
use crate::compare::Estimate;
use crate::renders::common::pixel_label;
use crate::renders::reference::PathImages;
use crate::statistics::Welch;

/// Both sides of a path comparison, per pixel-channel: the means, the
/// per-sample variances and the sample counts.
pub(super) struct Sides<'a> {
    pub(super) ours: (&'a [f64], &'a [f64]),
    pub(super) our_samples: u32,
    pub(super) mitsuba: &'a PathImages,
    pub(super) mitsuba_samples: u32,
    pub(super) width: u32,
    /// Each side's per-sample variance as the tests use it
    /// ([`guarded_variance`]): ours, Mitsuba's.
    pub(super) variance: (Vec<f64>, Vec<f64>),
}

impl<'a> Sides<'a> {
    /// Our means and per-sample variances against Mitsuba's images, each
    /// side's variance guarded by its neighbourhood's.
    pub(super) fn new(
        ours: (&'a [f64], &'a [f64]),
        our_samples: u32,
        mitsuba: &'a PathImages,
        mitsuba_samples: u32,
    ) -> Self {
        let width = mitsuba.scene.width;
        Sides {
            ours,
            our_samples,
            mitsuba,
            mitsuba_samples,
            width,
            variance: (
                guarded_variance(ours.1, width),
                guarded_variance(&mitsuba.variance, width),
            ),
        }
    }
}

/// What the t-tests found, for the check's metrics.
pub(super) struct Verdicts {
    pub(super) threshold: f64,
    pub(super) rejected: usize,
    pub(super) offset_findings: usize,
    pub(super) offset_example: Option<[String; 2]>,
    pub(super) rule_findings: usize,
    pub(super) rule_example: Option<[String; 2]>,
    /// Per pixel-channel: a rejection attributed to Mitsuba's offsets.
    pub(super) explained: Vec<bool>,
}

/// The render under Mitsuba's offset rule, made once when first asked for.
pub(super) type Moved = std::cell::OnceCell<Result<(Vec<f64>, Vec<f64>), String>>;

/// Every pixel-channel, as a t-test or, where neither side varies, a
/// deterministic comparison; with the sum of the differences of the means.
pub(super) struct Split {
    pub(super) tests: Vec<(usize, Welch)>,
    pub(super) deterministic: Vec<usize>,
    pub(super) sum: f64,
    pub(super) compared: usize,
}

pub(super) fn split(check: &mut Check, sides: &Sides) -> Split {
    let mut split = Split {
        tests: Vec::new(),
        deterministic: Vec::new(),
        sum: 0.0,
        compared: 0,
    };
    if sides.ours.0.len() != sides.mitsuba.mean.len() {
        return split; // failed by the caller: nothing to compare
    }
    let ours = Estimate {
        mean: sides.ours.0,
        variance: sides.ours.1,
        samples: sides.our_samples,
    };
    let mitsuba = Estimate {
        mean: &sides.mitsuba.mean,
        variance: &sides.mitsuba.variance,
        samples: sides.mitsuba_samples,
    };
    let guarded = (&sides.variance.0[..], &sides.variance.1[..]);
    let outcomes = pixel_tests_guarded(&ours, &mitsuba, guarded, None);
    for (i, outcome) in outcomes.into_iter().enumerate() {
        split.compared += 1;
        let difference = (ours.mean[i] - mitsuba.mean[i]).abs();
        split.sum += difference;
        check.measure_at_in_both(
            [
                "|mean ours − mean Mitsuba|, W/(sr m²)",
                "|miénk átlaga − Mitsuba átlaga|, W/(sr m²)",
            ],
            difference,
            || pixel_label(sides.width, i),
        );
        match outcome {
            Some(Some(w)) => split.tests.push((i, w)),
            _ => split.deterministic.push(i),
        }
    }
    split
}
