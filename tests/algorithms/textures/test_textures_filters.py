"""Texture lookups against direct lookups, the pyramid against a box filter, filters against the
reference."""
from __future__ import annotations

import math

import numpy as np
import pytest
from PIL import Image

from algorithms.core import registry
from algorithms.triangles.interpolate import unpack
from algorithms.core.steps import PLOT
from algorithms.textures import texels
from algorithms.textures.sampling import Mapping, Sampler

SPEC = registry.get("triangle-texture")
CORNERS = [(1, 1), (14, 2), (3, 13)]


@pytest.fixture(scope="module")
def image_file(tmp_path_factory):
    """A random 8 x 4 RGB PNG: its first row is the texture's top row."""
    rng = np.random.default_rng(18)
    pixels = rng.integers(0, 256, size=(4, 8, 3), dtype=np.uint8)
    path = tmp_path_factory.mktemp("tex") / "random.png"
    Image.fromarray(pixels).save(path)
    return str(path), pixels.astype(float)


def _texel(pixels, i, j, wrap):
    height, width = pixels.shape[:2]
    if wrap == "repeat":
        i, j = i % width, j % height
    else:
        i, j = min(max(i, 0), width - 1), min(max(j, 0), height - 1)
    return pixels[height - 1 - j, i]  # v = 0 is the image's last row


def _direct(pixels, u, v, filter_name, wrap):
    height, width = pixels.shape[:2]
    if filter_name == "nearest":
        return _texel(pixels, math.floor(u * width), math.floor(v * height), wrap)
    s, t = u * width - 0.5, v * height - 0.5
    i, j = math.floor(s), math.floor(t)
    a, b = s - i, t - j
    return ((1 - a) * (1 - b) * _texel(pixels, i, j, wrap) + a * (1 - b) * _texel(pixels, i + 1, j, wrap)
            + (1 - a) * b * _texel(pixels, i, j + 1, wrap) + a * b * _texel(pixels, i + 1, j + 1, wrap))


@pytest.mark.parametrize("filter_name", ["nearest", "bilinear"])
@pytest.mark.parametrize("wrap", ["repeat", "clamp"])
def test_nearest_and_bilinear_equal_a_direct_lookup(image_file, filter_name, wrap):
    path, pixels = image_file
    options = {"texture": path, "filter": filter_name, "wrap": wrap,
               "uv": (-0.3, -0.2, 1.6, 0.1, 0.2, 1.3), "w": (1, 3, 2)}
    trace = SPEC.record(CORNERS, options, grid=(16, 16))
    checked = 0
    for i in range(len(trace)):
        step = trace.step(i)
        if step.pixel is None or trace.code[step.line].kind != PLOT:
            continue
        expected = _direct(pixels, step.values["u"], step.values["v"], filter_name, wrap)
        got = unpack(f"#{int(step.values['rgb']):06x}")
        assert np.all(np.abs(np.array(got) - expected) <= 0.5 + 1e-9)
        checked += 1
    assert checked > 50


def test_pyramid_levels_are_box_averages(image_file):
    path, pixels = image_file
    levels = texels.load(path).levels
    base = pixels[::-1]  # row 0 at v = 0
    assert len(levels) == 4  # 8x4, 4x2, 2x1, 1x1
    for k, level in enumerate(levels):
        bw, bh = min(2 ** k, 8), min(2 ** k, 4)
        for j in range(level.shape[0]):
            for i in range(level.shape[1]):
                block = base[j * bh:(j + 1) * bh, i * bw:(i + 1) * bw]
                assert np.allclose(level[j, i], block.reshape(-1, 3).mean(axis=0), atol=1e-9)


def test_checker_texels():
    texture = texels.load("checker:4")
    level = texture.levels[0]
    for j in range(0, 64, 5):
        for i in range(0, 64, 7):
            light = (i // 16 + j // 16) % 2 == 0
            assert level[j, i, 0] == (texels.LIGHT if light else texels.DARK)


# A floor receding to the horizon: w grows 12-fold from front to back.
FLOOR = ([(0.0, 0.0), (32.0, 0.0), (32.0, 20.0), (0.0, 0.0), (32.0, 20.0), (0.0, 20.0)],
         (0, 0, 8, 0, 8, 8, 0, 0, 8, 8, 0, 8), (1, 1, 12, 1, 12, 12))


def _errors(texture, filter_name, corners, uv, w, samples=8):
    """RMS and max of |filter - reference| (0..255 grey) over the pixels of the floor."""
    sampler = Sampler(texels.load(texture), filter_name, "repeat")
    reference = Sampler(texels.load(texture), "reference", "repeat", samples=samples)
    diffs = []
    for n in range(0, len(corners), 3):
        mapping = Mapping(corners[n:n + 3], [(uv[2 * k], uv[2 * k + 1]) for k in range(n, n + 3)],
                          w[n:n + 3])
        for y in range(0, 20, 2):
            for x in range(0, 32, 2):
                cx, cy = x + 0.5, y + 0.5
                if not _inside(corners[n:n + 3], cx, cy):
                    continue
                diffs.append(sampler.sample(mapping, x, y).color[0]
                             - reference.sample(mapping, x, y).color[0])
    diffs = np.array(diffs)
    return math.sqrt(np.mean(diffs ** 2)), np.max(np.abs(diffs))


def _inside(corners, x, y):
    (x0, y0), (x1, y1), (x2, y2) = corners
    d = [(x1 - x0) * (y - y0) - (y1 - y0) * (x - x0), (x2 - x1) * (y - y1) - (y2 - y1) * (x - x1),
         (x0 - x2) * (y - y2) - (y0 - y2) * (x - x2)]
    return all(v > 0 for v in d)


def test_mip_filters_stay_within_their_bounds_of_the_reference():
    corners, uv, w = FLOOR
    nearest = _errors("checker:8", "nearest", corners, uv, w)
    trilinear = _errors("checker:8", "trilinear", corners, uv, w)
    anisotropic = _errors("checker:8", "anisotropic", corners, uv, w)
    # The documented bounds (sampling.py): trilinear and anisotropic are within
    # 25% and 15% of the texture's range (200 levels here) in RMS, and each
    # beats point sampling, which aliases where a pixel covers many texels.
    assert trilinear[0] < 0.25 * 200 and anisotropic[0] < 0.15 * 200
    assert anisotropic[0] < trilinear[0] < nearest[0]


def test_reference_converges():
    corners, uv, w = FLOOR
    mapping = Mapping(corners[:3], [(uv[2 * k], uv[2 * k + 1]) for k in range(3)], w[:3])
    coarse = Sampler(texels.load("checker:8"), "reference", "repeat", samples=8)
    fine = Sampler(texels.load("checker:8"), "reference", "repeat", samples=32)
    gaps = [abs(coarse.sample(mapping, x, 1).color[0] - fine.sample(mapping, x, 1).color[0])
            for x in range(4, 30, 3)]
    # Documented: 8 x 8 points are within 1/8 of the range of the 32 x 32 estimate.
    assert max(gaps) <= 200 / 8
