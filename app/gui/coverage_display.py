"""View > Coverage counts in the window (``MainWindow.coverage_display``):
the status bar's count of overlaps, the cracks a mesh run reports, and the
overlaps' patterns laid over the grid.

The grid's own image has one pixel per cell, too small for a pattern, so
the counts are shown again, enlarged and patterned by the same composer
as exported frames (app/render/compose.py ``coverage_image``), in a layer
over the cells: a cell written twice reads as such without its colour.
"""
from __future__ import annotations

import numpy as np

from algorithms.core.steps import Table
from app.render.compose import coverage_counts, coverage_image
from app.render.patterns import pattern_scale
from widgets.pattern_layer import PatternLayer


class CoverageDisplay:
    """What View > Coverage counts shows besides the grid's colours."""

    def __init__(self, window):
        self.window = window
        self.patterns = PatternLayer(window.grid.view_box)
        # The counts and palette on show: a step that writes nothing keeps
        # the layer (it takes some 50 ms to make for a 256 x 256 grid).
        self._shown = None

    def show(self, state) -> None:
        """The coverage of ``state`` (a FrameState of the player's run), or
        nothing of it while coverage counts are off."""
        w = self.window
        on = w.coverage.isChecked() and state is not None
        self._show_patterns(state if on else None)
        if state is None:
            w.coverage_label.setText("")
            return
        if not on:
            w.coverage_label.setText("")
            w.grid.set_differences(w.player.differences)
            return
        cracks = crack_cells(w.player.trace, state.index)
        w.grid.set_differences(cracks)  # outlined instead of the compared run's differences
        w.coverage_label.setText(summary(coverage_counts(state.raster), len(cracks)))

    def _show_patterns(self, state) -> None:
        counts = None if state is None else state.raster.counts
        scale = 1 if counts is None else pattern_scale(counts.shape[1], counts.shape[0])
        if scale == 1 or not (counts >= 2).any():
            self.patterns.clear()
            self._shown = None
            return
        palette = self.window.palette_
        if self._shown is not None and self._shown[1] is palette \
                and np.array_equal(self._shown[0], counts):
            self.patterns.setVisible(True)
            return
        height, width = counts.shape
        self.patterns.show_cells(coverage_image(counts, palette, scale), width, height)
        self._shown = (counts.copy(), palette)


def summary(levels, cracks: int) -> str:
    """The status bar's words for coverage counts ``levels`` (0, 1, 2, 3+)."""
    _none, _once, twice, more = levels
    overlaps = twice + more
    return (("No pixel covered twice" if not overlaps else
             f"{overlaps:,} pixel{'s' if overlaps != 1 else ''} covered twice or more"
             + (f" ({more:,} three times or more)" if more else ""))
            + (f" · {cracks:,} crack{'s' if cracks != 1 else ''} outlined" if cracks else ""))


def crack_cells(trace, index: int) -> list:
    """The pixels of the run's "cracks" table recorded at or before ``index``."""
    for _, table in trace.records_of(Table, hi=index + 1):
        if table.name == "cracks":
            return [tuple(row) for row in table.rows]
    return []
