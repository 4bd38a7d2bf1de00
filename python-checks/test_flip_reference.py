"""Checks of the FLIP reference generator (python3 -m pytest -q python-checks)."""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import flip_reference as fr  # noqa: E402


def test_identical_images_do_not_differ_and_black_against_white_nearly_saturates():
    gradient = fr._gradient()
    error_map, mean = fr.evaluate(gradient, gradient.copy())
    assert mean == 0.0 and not error_map.any()
    _, mean = fr.evaluate(fr._constant((0, 0, 0)), fr._constant((255, 255, 255)))
    assert 0.9 < mean <= 1.0


def test_more_noise_looks_more_different():
    rng = np.random.default_rng(1)
    gradient = fr._gradient()
    means = [fr.evaluate(gradient, fr._noisy(gradient, a, rng))[1] for a in (2, 8, 32)]
    assert means[0] < means[1] < means[2], means


def test_the_pairs_are_the_stated_size_and_distinct_where_named_so():
    pairs = fr.pairs()
    assert len({name for name, _, _ in pairs}) == len(pairs)
    for name, a, b in pairs:
        assert a.shape == b.shape == (fr.HEIGHT, fr.WIDTH, 3) and a.dtype == np.uint8, name
        assert (name == "identical gradient") == np.array_equal(a, b), name

