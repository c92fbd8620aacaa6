"""The report's texture measurements and section."""
from __future__ import annotations

import math

import numpy as np
import pytest

from app.analysis import measure
from app.analysis.counting import Rows
from app.analysis.measure_textures import FILTERS, SCENES, W_RATIOS, measure_textures
from app.analysis.report_findings import View
from app.analysis.report_textures import section_textures


@pytest.fixture(scope="module")
def view():
    rows = Rows()
    ticks = []
    measure_textures(measure.settings(True), rows, np.random.default_rng(0),
                     lambda: ticks.append(1))
    assert len(ticks) == len(SCENES) * len(FILTERS) + len(W_RATIOS)
    return View(rows.rows)


def test_mip_mapping_beats_point_sampling_on_both_scenes(view):
    for scene in SCENES:
        rms = {f: view.get("textures", "filters", f, scene, "rms error") for f in FILTERS}
        assert rms["trilinear"] < rms["bilinear"] < rms["nearest"]
        assert rms["anisotropic"] < rms["nearest"]
        fetches = {f: view.get("textures", "filters", f, scene, "fetches") for f in FILTERS}
        assert fetches["nearest"] == 1 and fetches["bilinear"] == 4
        assert 4 < fetches["trilinear"] <= 8 and fetches["anisotropic"] >= fetches["trilinear"]


def test_affine_error_starts_at_zero_and_grows_with_w(view):
    errors = [view.get("textures", "affine", "affine", r, "rms error") for r in W_RATIOS]
    assert errors[0] == 0 and all(a < b for a, b in zip(errors, errors[1:]))
    assert all(math.isfinite(e) for e in errors)


def test_the_section_has_both_tables(view):
    text = section_textures(view)
    assert text.startswith("## Textures") and "| zone plate | anisotropic |" in text
    assert "| 100 |" in text


def test_the_figure_has_two_panels(view):
    from app.analysis.report_textures import texture_figure
    image = texture_figure(view)
    assert image is not None and image.width > 2 * image.height
