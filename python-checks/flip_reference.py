"""The LDR FLIP reference: NVIDIA's own evaluator (flip-evaluator on PyPI) on
image pairs of known character, for the harness to hold the suite's FLIP
(the nv-flip crate's binding of an older copy of the same C++) against.

Each pair is 8-bit sRGB, generated here from a fixed seed and written whole
into the JSON (base64, row-major RGB), so the Rust side compares the same bytes
rather than regenerating them. FLIP is evaluated as LDR at 67 pixels per
degree (both sides state it rather than trust a default), and the mean of
the error map is written with the error map's 50th, 90th and 99th
percentiles and its maximum.

Writes ``validation/reference/flip.json`` (schema ``flip/1``), or the path given.
"""
import base64
import os
import sys

import flip_evaluator
import numpy as np
from atomic_write import write_json

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DEFAULT_PATH = os.path.join(ROOT, "validation", "reference", "flip.json")
REGENERATE = ".venv/bin/python python-checks/flip_reference.py"
WIDTH, HEIGHT = 32, 24
PIXELS_PER_DEGREE = 67.0
SEED = 20261204


def _gradient():
    x = np.linspace(0.0, 1.0, WIDTH)[None, :, None]
    y = np.linspace(0.0, 1.0, HEIGHT)[:, None, None]
    rgb = np.concatenate([x + 0 * y, y + 0 * x, 0.5 * (x + y)], axis=2)
    return np.round(255 * rgb).astype(np.uint8)


def _checker(shift):
    yy, xx = np.mgrid[0:HEIGHT, 0:WIDTH]
    on = (((xx + shift) // 4) + (yy // 4)) % 2 == 1
    return np.repeat(np.where(on, 230, 25).astype(np.uint8)[:, :, None], 3, axis=2)


def _constant(rgb):
    return np.tile(np.array(rgb, dtype=np.uint8), (HEIGHT, WIDTH, 1))


def _noisy(image, amplitude, rng):
    noise = rng.integers(-amplitude, amplitude + 1, size=image.shape)
    return np.clip(image.astype(np.int64) + noise, 0, 255).astype(np.uint8)


def _blurred(image):
    padded = np.pad(image.astype(np.float64), ((1, 1), (1, 1), (0, 0)), mode="edge")
    box = sum(padded[dy:dy + HEIGHT, dx:dx + WIDTH] for dy in range(3) for dx in range(3)) / 9.0
    return np.round(box).astype(np.uint8)


def pairs():
    """The named pairs (reference, test), in a fixed order."""
    rng = np.random.default_rng(SEED)
    gradient = _gradient()
    return [
        ("identical gradient", gradient, gradient.copy()),
        ("gradient, noise of 4 levels", gradient, _noisy(gradient, 4, rng)),
        ("gradient, noise of 40 levels", gradient, _noisy(gradient, 40, rng)),
        ("checker moved one pixel", _checker(0), _checker(1)),
        ("checker blurred", _checker(0), _blurred(_checker(0))),
        ("red against orange", _constant((200, 30, 30)), _constant((210, 110, 30))),
        ("black against white", _constant((0, 0, 0)), _constant((255, 255, 255))),
        ("grey, one level brighter", _constant((128, 128, 128)), _constant((129, 129, 129))),
    ]


def evaluate(reference, test):
    """FLIP's error map and mean for two 8-bit sRGB images."""
    error_map, mean, _ = flip_evaluator.evaluate(
        reference.astype(np.float32) / 255.0,
        test.astype(np.float32) / 255.0,
        "LDR",
        inputsRGB=True,
        applyMagma=False,
        computeMeanError=True,
        parameters={"ppd": PIXELS_PER_DEGREE},
    )
    return np.asarray(error_map, dtype=np.float64).reshape(HEIGHT, WIDTH), float(mean)


def _round(x):
    return float(f"{x:.7g}")


def build_reference():
    out = []
    for name, reference, test in pairs():
        error_map, mean = evaluate(reference, test)
        values = error_map.ravel()
        out.append({
            "name": name,
            "reference_rgb8_base64": base64.b64encode(reference.tobytes()).decode("ascii"),
            "test_rgb8_base64": base64.b64encode(test.tobytes()).decode("ascii"),
            "mean": _round(mean),
            "p50": _round(np.percentile(values, 50)),
            "p90": _round(np.percentile(values, 90)),
            "p99": _round(np.percentile(values, 99)),
            "max": _round(values.max()),
        })
    return {
        "schema": "flip/1",
        "description": "NVIDIA's LDR FLIP error maps of 8-bit sRGB image pairs of known character, summarised.",
        "generator": "python-checks/flip_reference.py",
        "regenerate": REGENERATE,
        "flip_evaluator_version": flip_evaluator_version(),
        "dynamic_range": "LDR",
        "pixels_per_degree": PIXELS_PER_DEGREE,
        "width": WIDTH,
        "height": HEIGHT,
        "pairs": out,
    }


def flip_evaluator_version():
    from importlib.metadata import version
    return version("flip-evaluator")


def main(path=DEFAULT_PATH):
    write_json(path, build_reference())


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else DEFAULT_PATH)
