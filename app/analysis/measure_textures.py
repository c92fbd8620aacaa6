"""The report's texture measurements: each filter's error against the reference and its cost,
and affine against perspective-correct texture coordinates as the w ratio grows.

Scenes: the receding checkerboard floor and the zone plate on the same
floor (resources/scenes/rendering). Error: per pixel the mean over the
three channels of |filter - reference|, in levels of 0..255; RMS and
maximum over the covered pixels. The reference is triangle-texture's own
(the texture averaged over the pixel's pre-image by n x n sub-pixel
points; n = 16 in the full report, 8 in the quick one). Cost: texel
fetches per pixel from the executed pseudo-code (the generator's
``fetches`` on the lines it ran), and the numpy kernel's time per pixel.
"""
from __future__ import annotations

import numpy as np

from algorithms.core import registry
from algorithms.core.steps import PLOT
from algorithms.textures.kernel import texture_image

from .counting import Rows, median_seconds

FAMILY = "textures"
FILTERS = ("nearest", "bilinear", "mip-nearest", "trilinear", "anisotropic")
FLOOR = [(0, 0), (48, 0), (26.4, 30), (0, 0), (26.4, 30), (21.6, 30)]
GRID = (48, 32)
SCENES = {"floor": {"texture": "checker:4", "uv": (0, 0, 2, 0, 2, 9, 0, 0, 2, 9, 0, 9)},
          "zone plate": {"texture": "zoneplate",
                         "uv": (0, 0, 1, 0, 1, 4.5, 0, 0, 1, 4.5, 0, 4.5)}}
W_RATIOS = (1, 2, 4, 10, 100)


def measure_textures(settings, rows: Rows, rng, tick=lambda: None) -> None:
    spec = registry.get("triangle-texture")
    samples = 8 if settings.quick else 16
    for scene, extra in SCENES.items():
        base = {**extra, "w": (1, 1, 10, 1, 10, 10)}
        reference_options = spec.resolve({**base, "filter": "reference", "samples": samples})
        _, reference = texture_image(FLOOR, reference_options, GRID)
        for name in FILTERS:
            options = spec.resolve({**base, "filter": name})
            _, colours = texture_image(FLOOR, options, GRID)
            error = np.abs(colours - reference).mean(axis=1)
            add = lambda metric, value, unit="": rows.add(  # noqa: E731
                FAMILY, "filters", spec.name, name, "scene", scene, metric, value, unit)
            add("rms error", float(np.sqrt(np.mean(error ** 2))), "levels of 255")
            add("max error", float(error.max()), "levels of 255")
            add("fetches", _fetches_per_pixel(spec, options), "texels per pixel")
            seconds = median_seconds(lambda: texture_image(FLOOR, options, GRID),
                                     settings.repeats)
            add("kernel time", 1e6 * seconds / len(colours), "us/px")
            tick()
    _measure_affine(spec, rows, tick)


def _fetches_per_pixel(spec, options) -> float:
    """Texels fetched per written pixel, from the frames on the lookup line."""
    trace = spec.record(FLOOR, options, GRID)
    plot = np.array([line.kind == PLOT for line in trace.code])[trace.line]
    fetches = trace.series("fetches")[plot]
    return float(np.nansum(fetches) / max(1, len(fetches)))


def _measure_affine(spec, rows: Rows, tick) -> None:
    """|uv affine - uv perspective-correct| in texels over the floor, far w = r at the back."""
    size = 64  # checker:4 is 64 x 64 texels
    for ratio in W_RATIOS:
        w = (1, 1, ratio, 1, ratio, ratio)
        uv = {}
        for perspective in (True, False):
            options = spec.resolve({**SCENES["floor"], "w": w, "perspective": perspective,
                                    "filter": "nearest"})
            trace = spec.record(FLOOR, options, GRID)
            plot = np.array([line.kind == PLOT for line in trace.code])[trace.line]
            uv[perspective] = np.stack([trace.series("u")[plot], trace.series("v")[plot]], 1)
        error = np.hypot(*(size * (uv[False] - uv[True])).T)
        add = lambda metric, value: rows.add(  # noqa: E731
            FAMILY, "affine", spec.name, "affine", "w ratio", ratio, metric, value, "texels")
        add("rms error", float(np.sqrt(np.mean(error ** 2))))
        add("max error", float(error.max()))
        tick()


def texture_ticks() -> int:
    return len(SCENES) * len(FILTERS) + len(W_RATIOS)
