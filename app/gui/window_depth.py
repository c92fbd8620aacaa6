"""The depth buffer, the stochastic samples and the coverage error of the
step on show (a part of ``MainWindow``): what antialiasing and visibility
runs show besides the colour buffer."""
from __future__ import annotations

import numpy as np

from app.model.geometry import exact_reference
from app.render import frame as frame_view
from app.render.compose import depth_image, depth_range, error_stats


class DepthAndAccuracy:
    """Depth, samples and coverage error on the grid and in the panels."""

    def _prepare_depth_and_accuracy(self) -> None:
        """Per run: the depth view's scale, and the exact coverage of an
        antialiasing run (worked out when first needed, then kept)."""
        player, trace = self.player, self.player.trace
        self._depth = None
        self._accuracy = None
        if trace is not None and trace.start.depth_value is not None:
            clear = float(trace.start.constants.get("clear_depth",
                                                    player.options.get("clear_depth", 1.0)))
            self._depth = (clear, *depth_range(trace.series(trace.start.depth_value), clear))
        if trace is not None and player.spec.family == "antialias" \
                and trace.start.pixel_value is not None:
            self._accuracy = AccuracyCache(player.spec, player.points, player.options,
                                           player.grid, trace)
            if not self._accuracy.available:
                self._accuracy = None
        self.error_action.setEnabled(self._accuracy is not None)
        self.depth_action.setEnabled(self._depth is not None)
        self._place_depth_dock()

    def _place_depth_dock(self) -> None:
        want = self._depth is not None and self.depth_action.isChecked()
        if want != self.depth_dock.isVisibleTo(self):
            self.depth_dock.setVisible(want)

    def _depth_toggled(self, on: bool) -> None:
        self._place_depth_dock()
        self.show_frame()

    def _depth_dock_shown(self, visible: bool) -> None:
        # Closing the dock by its own button turns the View toggle off.
        if not visible and self._depth is not None and not self.depth_dock.isVisibleTo(self):
            self.depth_action.blockSignals(True)
            self.depth_action.setChecked(False)
            self.depth_action.blockSignals(False)

    def _show_depth(self, state) -> None:
        if self._depth is None or not self.depth_dock.isVisibleTo(self):
            return
        clear, near, far = self._depth
        depth = state.raster.depth
        if depth is None:
            depth = np.full(state.raster.counts.shape, np.nan)
        self.depth_view.set_y_down(self.grid.y_down)
        self.depth_view.set_image(depth_image(depth, clear, near, far), near, far)

    def _show_samples(self, state) -> None:
        samples = frame_view.pixel_samples(self.player.trace, state.index)
        if samples is None:
            self.grid.set_samples()
        else:
            self.grid.set_samples(samples.xs, samples.ys, samples.hits, samples.current)

    def _show_error_summary(self) -> None:
        accuracy = self._accuracy if self.error_action.isChecked() else None
        self.error_scale.setVisible(accuracy is not None and not self.coverage.isChecked())
        if accuracy is None:
            self.error_label.setText("")
            return
        self.error_scale.set_range(accuracy.max)
        self.error_label.setText(f"Coverage error: RMS {accuracy.rms:.4f} \u00b7 "
                                 f"max {accuracy.max:.4f}")
        self.error_label.setToolTip("coverage - exact coverage per pixel (blue: too little, "
                                    "red: too much); the RMS is taken over the pixels the "
                                    "run or the exact shape covers")

    def _accuracy_rows(self, state, rows) -> list:
        """Exact coverage and error of the step's pixel, unless the
        algorithm's own explanation already gives them."""
        accuracy, pixel = self._accuracy, state.pixel
        if accuracy is None or pixel is None or any(name == "exact coverage"
                                                    for name, _ in rows):
            return []
        x, y = pixel
        if not state.raster.inside(x, y):
            return []
        exact = float(accuracy.exact[y, x])
        final = float(accuracy.estimate[y, x])
        return [("exact coverage", f"{exact:.6f}"),
                ("error (final)", f"{final - exact:+.6f}")]



class AccuracyCache:
    """How far an antialiasing run's coverages are from the exact ones:
    worked out once per run, on first use."""

    def __init__(self, spec, points, options, grid, trace):
        self._args = (spec, points, options, grid)
        self.trace = trace
        self._done = False
        self.available = spec.name != "aa-temporal" and len(points) > 0

    def _compute(self) -> None:
        if self._done:
            return
        self._done = True
        exact = exact_reference(*self._args)
        estimate = frame_view.run_coverage(self.trace)
        if exact is None or estimate is None or exact.shape != estimate.shape:
            exact = np.zeros((self.trace.height, self.trace.width))
            estimate = exact
        self._exact, self._estimate = exact, estimate
        self._rms, self._max, self._error = error_stats(estimate, exact)

    def __getattr__(self, name):
        if name in ("exact", "estimate", "rms", "max", "error"):
            self._compute()
            return object.__getattribute__(self, "_" + name)
        raise AttributeError(name)
