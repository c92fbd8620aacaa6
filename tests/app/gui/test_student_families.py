"""File > Open algorithm… with a student's flood fill, z-buffer or
antialiased line: it joins the list, runs on the scene, and D finds its
first divergence with the family's comparison."""
from __future__ import annotations

import numpy as np
import pytest
from PySide6.QtCore import Qt
from PySide6.QtTest import QTest

from algorithms.core import registry
from tests.support import ROOT
from tests.support.gui import WAIT_MS

SAMPLES = ROOT / "resources" / "students"
OUTLINE = (((1, 1), (13, 3), (5, 10)),)
pytestmark = pytest.mark.usefixtures("forget_student_algorithms")


def run_file(window, qtbot, sample, against):
    name = window.student_actions.open(str(SAMPLES / sample), against)
    assert window.player.spec.name == name == window.picker.current_name()
    qtbot.waitUntil(lambda: window.player.trace is not None, timeout=WAIT_MS)
    return window.player.trace


def reference_writes(against, points, options, grid):
    return registry.get(against).record(points, options, grid=grid).written()


@pytest.mark.window("flood-fill", OUTLINE, grid=(16, 12), settled=True)
def test_a_fill_with_the_auto_seed_fills_the_reference_region(window, qtbot):
    trace = run_file(window, qtbot, "fill_correct.py", "flood-fill")
    reference = registry.get("flood-fill").record(OUTLINE, {}, grid=(16, 12))
    fill_colour = int(reference.start.constants["fill colour"][1:], 16)
    writes = reference.written()
    expected = {tuple(p) for p, v in zip(writes.pixels.tolist(), writes.values.tolist())
                if v == fill_colour}
    filled = [tuple(p) for p in trace.written_pixels().tolist()]
    assert len(filled) == len(set(filled)) == len(expected) > 10
    assert set(filled) == expected
    assert window.student_actions.first_divergence() is None
    run_file(window, qtbot, "fill_truncates.py", "flood-fill")
    QTest.keyClick(window, Qt.Key.Key_D)
    assert "First divergence" in window.statusBar().currentMessage()


@pytest.mark.window("line-wu", ((1, 1), (12, 5)), grid=(16, 12), settled=True)
def test_an_antialiased_line_shows_its_intensities_and_d_finds_the_swap(window, qtbot):
    trace = run_file(window, qtbot, "wu_correct.py", "line-wu")
    ref = reference_writes("line-wu", ((1, 1), (12, 5)), {}, (16, 12))
    assert np.allclose(trace.pixel_values(), ref.values)
    assert window.student_actions.first_divergence() is None
    assert "intensities" in window.statusBar().currentMessage()
    trace = run_file(window, qtbot, "wu_swapped.py", "line-wu")
    window.player.first()
    QTest.keyClick(window, Qt.Key.Key_D)
    assert window.player.index == trace.written().steps.tolist()[0]
    assert "intensity" in window.statusBar().currentMessage()
