"""The depth buffer (or a run's other buffer: accumulation, stencil), the
stochastic samples and the coverage error of the step on show
(``MainWindow.depth_display``): what antialiasing and visibility runs show
besides the colour buffer."""
from __future__ import annotations

import numpy as np

from app.model.buffers import has_side_buffer, side_buffer
from app.model.geometry import exact_reference
from app.render import frame as frame_view
from app.render.compose import depth_image, depth_range, error_image, error_stats
from app.render.patterns import pattern_scale
from widgets.pattern_layer import PatternLayer


class DepthDisplay:
    """The depth dock, the samples on the grid and the coverage error of the
    run on show: its depth scale and its exact coverage, kept per run. The
    dock shows, for a run that keeps no depth buffer but another one
    (``Start.buffer_value``), that buffer instead, 0 dark and 1 light."""

    def __init__(self, window):
        self.window = window
        self._scale = None  # (clear, near, far) of a run that keeps a depth buffer
        self._side = False  # the run keeps another buffer (accumulation, stencil)
        self._hatch = PatternLayer(window.grid.view_box)  # the error map's sign, hatched
        self._hatched = None  # the AccuracyCache the hatch layer shows
        self.accuracy = None  # AccuracyCache of the antialiasing run on show
        window.depth_action.toggled.connect(self._toggled)
        window.depth_dock.visibilityChanged.connect(self._dock_shown)

    def prepare(self) -> None:
        """Per run: the depth view's scale, and the exact coverage of an
        antialiasing run (worked out when first needed, then kept)."""
        w = self.window
        player, trace = w.player, w.player.trace
        self._scale = None
        self.accuracy = None
        self._side = has_side_buffer(trace) and trace.start.depth_value is None
        self._name_dock(trace.start.buffer_name if self._side else "depth buffer")
        if trace is not None and trace.start.depth_value is not None:
            clear = float(trace.start.constants.get("clear_depth",
                                                    player.options.get("clear_depth", 1.0)))
            self._scale = (clear, *depth_range(trace.series(trace.start.depth_value), clear))
        if trace is not None and player.spec.family == "antialias" \
                and trace.start.pixel_value is not None:
            self.accuracy = AccuracyCache(player.spec, player.points, player.options,
                                          player.grid, trace)
            if not self.accuracy.available:
                self.accuracy = None
        w.error_action.setEnabled(self.accuracy is not None)
        w.depth_action.setEnabled(self._shows_buffer())
        self._place_dock()

    def error_map(self):
        """The signed coverage-error image while View > Coverage error is on
        for an antialiasing run, else None."""
        accuracy = self._shown_accuracy()
        if accuracy is None:
            return None
        return error_image(accuracy.estimate - accuracy.exact, accuracy.max, signed=True)

    def show(self, state) -> None:
        """The step's depth buffer, samples and coverage-error summary."""
        self._show_depth(state)
        self._show_samples(state)
        self._show_error_summary()

    def accuracy_rows(self, state, rows) -> list:
        """Exact coverage and error of the step's pixel, unless the
        algorithm's own explanation already gives them."""
        accuracy, pixel = self.accuracy, state.pixel
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

    def _shown_accuracy(self):
        return self.accuracy if self.window.error_action.isChecked() else None

    def _shows_buffer(self) -> bool:
        return self._scale is not None or self._side

    def _name_dock(self, name: str) -> None:
        title = name[:1].upper() + name[1:]
        self.window.depth_dock.setWindowTitle(title)
        self.window.depth_action.setText(title)

    def _place_dock(self) -> None:
        w = self.window
        want = self._shows_buffer() and w.depth_action.isChecked()
        if want != w.depth_dock.isVisibleTo(w):
            w.depth_dock.setVisible(want)

    def _toggled(self, on: bool) -> None:
        self._place_dock()
        self.window.show_frame()

    def _dock_shown(self, visible: bool) -> None:
        # Closing the dock by its own button turns the View toggle off.
        w = self.window
        if not visible and self._shows_buffer() and not w.depth_dock.isVisibleTo(w):
            w.depth_action.blockSignals(True)
            w.depth_action.setChecked(False)
            w.depth_action.blockSignals(False)

    def _show_depth(self, state) -> None:
        w = self.window
        if not self._shows_buffer() or not w.depth_dock.isVisibleTo(w):
            return
        if self._side:
            self._show_side_buffer(state)
            return
        clear, near, far = self._scale
        depth = state.raster.depth
        if depth is None:
            depth = np.full(state.raster.counts.shape, np.nan)
        w.depth_view.set_y_down(w.grid.y_down)
        w.depth_view.set_image(depth_image(depth, clear, near, far), near, far)

    def _show_side_buffer(self, state) -> None:
        w = self.window
        buffer = side_buffer(w.player.trace, state.index)
        w.depth_view.set_y_down(w.grid.y_down)
        w.depth_view.set_image(depth_image(buffer.values, 0.0, 0.0, 1.0), 0.0, 1.0,
                               legend=f"{buffer.name}: 0 = dark \u00b7 1 = light "
                                      "(never set since cleared: 0)")

    def _show_samples(self, state) -> None:
        w = self.window
        samples = frame_view.pixel_samples(w.player.trace, state.index)
        if samples is None:
            w.grid.set_samples()
        else:
            w.grid.set_samples(samples.xs, samples.ys, samples.hits, samples.current)

    def _show_hatch(self, accuracy) -> None:
        """The error map again, enlarged, with a hatch on the cells with too
        little coverage, so that the sign does not rest on colour alone."""
        if accuracy is None:
            self._hatch.clear()
            self._hatched = None
            return
        if accuracy is not self._hatched:
            height, width = accuracy.exact.shape
            scale = pattern_scale(width, height)
            if scale == 1:
                self._hatch.clear()
                return
            self._hatch.show_cells(error_image(accuracy.estimate - accuracy.exact, accuracy.max,
                                               signed=True, scale=scale), width, height)
            self._hatched = accuracy
        self._hatch.setVisible(True)

    def _show_error_summary(self) -> None:
        w = self.window
        accuracy = self._shown_accuracy()
        shown = accuracy is not None and not w.coverage.isChecked()
        w.error_scale.setVisible(shown)
        self._show_hatch(accuracy if shown else None)
        if accuracy is None:
            w.error_label.setText("")
            return
        w.error_scale.set_range(accuracy.max)
        w.error_label.setText(f"Coverage error: RMS {accuracy.rms:.4f} \u00b7 "
                              f"max {accuracy.max:.4f}")
        w.error_label.setToolTip("coverage - exact coverage per pixel (blue, hatched: too "
                                 "little; vermillion: too much); the RMS is taken over the pixels the "
                                 "run or the exact shape covers")


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
