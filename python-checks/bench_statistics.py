"""The statistics of ``bench_vs_mitsuba.py``: the variance of a render from
two of them, and whether two sets of renders estimate the same image.

Images are float64 arrays of shape (height, width, 3), linear radiance.
"""
import math

import mpmath
import numpy as np

# The harness's float32 tolerance of a render's pixel (validation/src/renders/mod.rs):
# a difference within it is not a disagreement, however many samples resolve it.
TOLERANCE_ABSOLUTE, TOLERANCE_RELATIVE = 1e-5, 1e-3


def pair_variance(first, second):
    """The variance of one render's pixel-channel from two independent
    renders: ``mean((I1 - I2)^2) / 2`` over every pixel and channel."""
    return float(np.mean((first - second) ** 2) / 2.0)


def guarded_variance(variance):
    """Per pixel-channel the larger of its variance and its 3 x 3
    neighbourhood's mean, clipped at the border (the harness's
    ``compare::welch::guarded_variance``: a pixel whose few renders all
    missed a rare large value shows too small a variance as well as too
    small a mean; its neighbours integrate nearly the same light)."""
    h, w, _ = variance.shape
    padded = np.pad(variance, ((1, 1), (1, 1), (0, 0)))
    ones = np.pad(np.ones((h, w, 1)), ((1, 1), (1, 1), (0, 0)))
    total = sum(padded[j:j + h, i:i + w] for j in range(3) for i in range(3))
    count = sum(ones[j:j + h, i:i + w] for j in range(3) for i in range(3))
    return np.maximum(variance, total / count)


def two_sided_critical_t(threshold, dof):
    """``t`` with ``P(|T| > t) = threshold`` under Student's t of ``dof``
    degrees of freedom, by bisection (the tail falls monotonically in t)."""
    dof = mpmath.mpf(dof)

    def tail(t):  # P(|T| > t) = I_{dof / (dof + t^2)}(dof / 2, 1 / 2)
        return mpmath.betainc(dof / 2, mpmath.mpf(1) / 2, 0, dof / (dof + t * t), regularized=True)

    low, high = mpmath.mpf(0), mpmath.mpf(1)
    while tail(high) > threshold:
        low, high = high, 2 * high
    for _ in range(60):  # the bracket to 2^-60 of its width, past float's 2^-52
        middle = (low + high) / 2
        low, high = (middle, high) if tail(middle) > threshold else (low, middle)
    return float((low + high) / 2)


def tolerance(reference):
    return TOLERANCE_ABSOLUTE + TOLERANCE_RELATIVE * np.abs(reference)


def pixel_tests(a, b, alpha):
    """Welch's t per pixel-channel of the renders ``a`` against ``b``
    (stacked, (n, h, w, 3)), each side's variance over its renders guarded,
    ``min(n_a, n_b) - 1`` degrees of freedom (Welch's never fall below
    it), Bonferroni over the pixel-channels where some side's guarded
    variance is not zero; elsewhere the tolerance alone decides."""
    na, nb = len(a), len(b)
    mean_a, mean_b = a.mean(axis=0), b.mean(axis=0)
    var_a = guarded_variance(a.var(axis=0, ddof=1))
    var_b = guarded_variance(b.var(axis=0, ddof=1))
    se = np.sqrt(var_a / na + var_b / nb)
    difference = np.abs(mean_a - mean_b)
    beyond = difference > tolerance(mean_b)
    # Deterministic only where a whole neighbourhood is: a few renders of
    # a pixel an edge barely crosses can all come out the same by chance.
    varies = (var_a > 0) | (var_b > 0)
    tests = int(varies.sum())
    threshold = alpha / max(tests, 1)
    t = np.where(varies, difference / np.where(se > 0, se, 1.0), 0.0)
    critical = two_sided_critical_t(threshold, min(na, nb) - 1)
    return {
        "tests": tests,
        "threshold": threshold,
        "critical_t": critical,
        "max_t": float(t.max()),
        "failed": int(np.sum(varies & beyond & (t > critical))),
        "deterministic_failed": int(np.sum(~varies & beyond)),
    }


def image_mean_tests(a, b, alpha):
    """Per channel, Welch's t of the renders' image means (one value a
    render): the test that sees a uniform shift no pixel's test resolves.
    Taken over renders rather than from the pixels' variances, it stays
    right where a sampler correlates a render's pixels. Bonferroni over
    the three channels, ``min(n_a, n_b) - 1`` degrees of freedom."""
    na, nb = len(a), len(b)
    means_a, means_b = a.mean(axis=(1, 2)), b.mean(axis=(1, 2))
    critical = two_sided_critical_t(alpha / 3, min(na, nb) - 1)
    channels = []
    for c in range(3):
        ma, mb = float(means_a[:, c].mean()), float(means_b[:, c].mean())
        se = math.sqrt(means_a[:, c].var(ddof=1) / na + means_b[:, c].var(ddof=1) / nb)
        t = abs(ma - mb) / se if se > 0 else (math.inf if ma != mb else 0.0)
        fails = t > critical and abs(ma - mb) > float(tolerance(mb))
        channels.append({"tracer": ma, "mitsuba": mb, "t": t, "critical_t": critical, "fails": bool(fails)})
    return channels


def agreement(ours, theirs, alpha):
    """Whether the renders ``ours`` and ``theirs`` (lists of images, at
    least two each) estimate the same image: half of ``alpha`` to the
    per-pixel tests, half to the image mean's."""
    a, b = np.stack(ours), np.stack(theirs)
    pixels = pixel_tests(a, b, alpha / 2)
    channels = image_mean_tests(a, b, alpha / 2)
    agrees = pixels["failed"] == 0 and pixels["deterministic_failed"] == 0 and not any(c["fails"] for c in channels)
    return {"agrees": agrees, "alpha": alpha, "pixels": pixels, "image_mean": channels}


def spread(values):
    """The median and the min-max of ``values``."""
    values = sorted(values)
    return {"median": float(np.median(values)), "min": values[0], "max": values[-1]}


def geometric_mean(values):
    values = list(values)
    return math.exp(sum(math.log(v) for v in values) / len(values)) if values else None
