"""View > Compare…: several algorithms side by side on the same primitives.

The window holds two to four panes (``app.compare.Pane``), runs them on the
primitives of the chosen comparison (the main window's, or the ones a
preset brings), and steps them together on one timeline, linked by frame
or by progress. A diff pane shows two of them cell by cell.
"""
from __future__ import annotations

import numpy as np
from PySide6.QtCore import QElapsedTimer, Qt, QTimer
from PySide6.QtGui import QAction, QKeySequence
from PySide6.QtWidgets import (QComboBox, QHBoxLayout, QLabel, QMainWindow, QPushButton,
                               QVBoxLayout, QWidget)

from algorithms.core.errors import InputError
from widgets.compare_view import CompareView
from widgets.transport import TransportBar

from app.model import compare
from app.render import frame as frame_view
from app.model.compare import (FRAME, LINKS, MAX_PANES, MIN_PANES, PRESETS, Pane,
                               window_primitives)
from app.model.scene import Scene
from app.render.compose import OUTLINE_STYLE, PALETTE, compose, diff_image
from app.render.patterns import pattern_scale

WINDOW_KEY = "window"  # the comparison of the main window's algorithm and the one before
MIN_TICK_MS = 16
ZOOM_CELLS = (4, 3)  # Next difference shows 8 x 6 cells around the difference


class CompareWindow(QMainWindow):
    """Compare mode, opened from the main window (non-modal)."""

    def __init__(self, main=None, parent=None):
        super().__init__(parent if parent is not None else main, Qt.WindowType.Window)
        self.main = main
        # The main window's colours (a preference may have changed them).
        self.colours = getattr(main, "palette_", PALETTE)
        self.setWindowTitle("Compare \u2014 RasterLab")
        self.panes: list[Pane] = []
        self.runs: list[compare.Run] = []
        self._wired_headers: list = []  # pane headers whose signals are connected
        self.primitives: Scene | None = None
        self.preset_key = WINDOW_KEY
        self.link = FRAME
        self.position = 0
        self.pair = (0, 1)
        self.current_diff = None
        self._last_shown = None  # the key of the difference "Next difference" went to
        self._errors: dict[int, str] = {}
        self._build()
        self._timer = QTimer(self)
        self._timer.setTimerType(Qt.TimerType.PreciseTimer)
        self._timer.timeout.connect(self._tick)
        self._clock = QElapsedTimer()
        self._owed = 0.0
        if main is not None:
            main.player.traceChanged.connect(self.main_changed)
        self._fit_to_screen(1400, 720)
        self.apply_preset(WINDOW_KEY if main is not None else PRESETS[0].key)

    def _fit_to_screen(self, width: int, height: int) -> None:
        """As large as asked, but never larger than the screen it opens on."""
        screen = (self.main.screen() if self.main is not None else None) or self.screen()
        if screen is not None:
            room = screen.availableGeometry()
            width, height = min(width, room.width() - 40), min(height, room.height() - 60)
        self.resize(max(width, 640), max(height, 400))

    # ------------------------------------------------------------ building
    def _build(self) -> None:
        centre = QWidget(self)
        layout = QVBoxLayout(centre)
        layout.setContentsMargins(8, 6, 8, 0)
        layout.setSpacing(6)
        layout.addLayout(self._build_bar())
        self.description = QLabel(centre)
        self.description.setWordWrap(True)
        self.description.setStyleSheet("color: #55606d;")
        layout.addWidget(self.description)
        self.view = CompareView(self.colours, OUTLINE_STYLE, compare.DIFF_CLASSES,
                                compare.DIFF_COLOURS, MAX_PANES, centre)
        layout.addWidget(self.view, 1)
        self.transport = TransportBar(centre)
        layout.addWidget(self.transport)
        self.setCentralWidget(centre)
        t = self.transport
        t.firstRequested.connect(lambda: self.seek(0, pause=True))
        t.backRequested.connect(lambda: self.step(-1))
        t.playRequested.connect(self.toggle)
        t.forwardRequested.connect(lambda: self.step(1))
        t.lastRequested.connect(lambda: self.seek(self.last, pause=True))
        t.seekRequested.connect(lambda k: self.seek(k, pause=True))
        self._shortcuts()

    def _build_bar(self) -> QVBoxLayout:
        bar = QHBoxLayout()
        bar.setSpacing(6)
        self.preset_box = QComboBox(self)
        self.preset_box.setToolTip("What to compare: the main window's algorithm against the "
                                   "one before it, or one of the prepared comparisons")
        self.preset_box.addItem("Main window: this algorithm and the one before", WINDOW_KEY)
        for item in PRESETS:
            self.preset_box.addItem(item.title, item.key)
        self.preset_box.activated.connect(
            lambda _i: self.apply_preset(self.preset_box.currentData()))
        self.link_box = QComboBox(self)
        self.link_box.addItems(list(LINKS))
        self.link_box.setToolTip("frame: every pane shows the same step number (held at the "
                                 "end of shorter runs); progress: every pane shows the same "
                                 "fraction of its own run")
        self.link_box.currentTextChanged.connect(self.set_link)
        self.a_box, self.b_box = QComboBox(self), QComboBox(self)
        self.a_box.setToolTip("Pane A of the diff")
        self.b_box.setToolTip("Pane B of the diff")
        self.a_box.activated.connect(lambda k: self.set_pair(k, self.pair[1]))
        self.b_box.activated.connect(lambda k: self.set_pair(self.pair[0], k))
        self.add_button = QPushButton("Add pane", self)
        self.add_button.setToolTip(f"Add a pane (at most {MAX_PANES})")
        self.add_button.clicked.connect(self.add_pane)
        self.next_button = QPushButton("Next difference", self)
        self.next_button.setToolTip("Zoom to the next cell where the two diffed panes differ "
                                    "(N)")
        self.next_button.clicked.connect(self.next_difference)
        fit = self.fit_button = QPushButton("Fit", self)
        fit.setToolTip("Fit the grid to the views (F)")
        fit.clicked.connect(lambda: self.view.fit())
        for widget in (QLabel("Compare", self), self.preset_box):
            bar.addWidget(widget)
        bar.addStretch(1)
        # The controls in a second row: one row would not fit a 1280 px screen.
        controls = QHBoxLayout()
        controls.setSpacing(6)
        for widget in (QLabel("Link by", self), self.link_box, QLabel("Diff", self), self.a_box,
                       QLabel("vs", self), self.b_box):
            controls.addWidget(widget)
        controls.addStretch(1)
        for widget in (self.add_button, self.next_button, fit):
            controls.addWidget(widget)
        rows = QVBoxLayout()
        rows.setSpacing(4)
        rows.addLayout(bar)
        rows.addLayout(controls)
        return rows

    def _shortcuts(self) -> None:
        for keys, slot in (("Space", self.toggle), ("Right", lambda: self.step(1)),
                           ("Left", lambda: self.step(-1)),
                           ("Shift+Right", lambda: self.step(10)),
                           ("Shift+Left", lambda: self.step(-10)),
                           ("Home", lambda: self.seek(0, pause=True)),
                           ("End", lambda: self.seek(self.last, pause=True)),
                           ("F", self.view.fit), ("N", self.next_difference),
                           ("Esc", self.close), ("Ctrl+W", self.close)):
            action = QAction(self)
            action.setShortcut(QKeySequence(keys))
            action.triggered.connect(slot)
            self.addAction(action)

    # ------------------------------------------------------------- choices
    def apply_preset(self, key: str) -> None:
        """Show a comparison: its panes on its primitives."""
        if key == WINDOW_KEY and self.main is None:
            key = PRESETS[0].key  # no main window to follow
        if key == WINDOW_KEY:
            self.panes = list(compare.window_panes(self.main.player))
            self.primitives = window_primitives(self.main.player)
            self.description.setText("The main window's algorithm against the one shown "
                                     "before it; the panes follow the main window's points.")
            self.pair = (0, 1)
        else:
            item = compare.preset(key)
            self.panes = list(item.panes)
            self.primitives = item.primitives(self._window_primitives())
            self.description.setText(f"{item.description}  Primitives: {self.primitives.title}.")
            self.pair = item.diff
            key = item.key
        self.preset_key = key
        self._main_spec = None if self.main is None else self.main.player.spec.name
        self.preset_box.setCurrentIndex(max(0, self.preset_box.findData(key)))
        self._errors.clear()
        self.view.set_pane_count(len(self.panes))
        self._connect_headers()
        self.rerun(to_end=True)
        if self.main is not None:
            self.view.set_y_down(self.main.grid.y_down)
        self.view.set_grid(*self.primitives.grid)
        self.view.fit()

    def _window_primitives(self) -> Scene | None:
        if self.main is None or not self.main.player.points:
            return None
        return window_primitives(self.main.player)

    def _follows_main(self) -> bool:
        if self.main is None:
            return False
        if self.preset_key == WINDOW_KEY:
            return True
        primitives = self._window_primitives()
        return primitives is not None and compare.preset(self.preset_key).uses_window(primitives)

    def main_changed(self) -> None:
        # The panes follow the main window's points while they use them.
        if not self.isVisible() or not self._follows_main():
            return
        if self.main.player.trace is None:
            return  # points still being placed
        if self.preset_key == WINDOW_KEY and self.main.player.spec.name != self._main_spec:
            self.apply_preset(WINDOW_KEY)  # another algorithm: compare it with the one before
            return
        self.primitives = window_primitives(self.main.player)
        self.view.set_y_down(self.main.grid.y_down)
        if tuple(self.primitives.grid) != self.view.grids()[0].grid_size:
            self.view.set_grid(*self.primitives.grid)
        self.rerun()

    def set_pane(self, k: int, algorithm: str | None = None, options_text: str | None = None):
        """Change pane k's algorithm (its options start afresh) or its
        options (typed as key=value pairs). Bad options are refused with a
        message in the pane; the pane keeps its last good options."""
        pane = self.panes[k]
        if algorithm is not None and algorithm != pane.algorithm:
            pane = Pane(algorithm)
            self._errors.pop(k, None)
        if options_text is not None:
            try:
                pane = Pane(pane.algorithm, compare.parse_options(pane.algorithm, options_text))
                self._errors.pop(k, None)
            except InputError as error:
                self._errors[k] = str(error)
        self.panes[k] = pane
        self.rerun()

    def add_pane(self) -> None:
        if len(self.panes) >= MAX_PANES:
            return
        self.panes.append(self.panes[-1])
        self.view.set_pane_count(len(self.panes))
        self._connect_headers()
        self.rerun()

    def remove_pane(self, k: int) -> None:
        if len(self.panes) <= MIN_PANES:
            return
        del self.panes[k]
        self._errors = {(i if i < k else i - 1): text for i, text in self._errors.items()
                        if i != k}
        a, b = (i if i < k else max(0, i - 1) for i in self.pair)
        if a == b:
            b = (a + 1) % len(self.panes)
        self.pair = (a, b)
        self.view.set_pane_count(len(self.panes))
        self._connect_headers()
        self.rerun()

    def set_pair(self, a: int, b: int) -> None:
        """Which two panes the diff shows."""
        self.pair = compare.diff_pair(self.pair, a, b, len(self.panes))
        self._update_pair_boxes()
        self.show_frame()

    def set_link(self, link: str) -> None:
        """Link the panes' steps by "frame" or by "progress"."""
        if link not in LINKS:
            return
        self.link = link
        if self.link_box.currentText() != link:
            self.link_box.setCurrentText(link)
        self.show_frame()

    def _connect_headers(self) -> None:
        items = [(name, compare.algorithm_title(name)) for name in compare.algorithm_names()]
        for k, pane in enumerate(self.view.panes):
            header = pane.header
            if header in self._wired_headers:
                continue
            self._wired_headers.append(header)
            header.set_algorithms(items)
            header.algorithmChosen.connect(lambda name, p=pane: self._header_algorithm(p, name))
            header.optionsTyped.connect(lambda text, p=pane: self._header_options(p, text))
            header.removeRequested.connect(lambda p=pane: self._header_remove(p))
        self._order_tabs()

    def _order_tabs(self) -> None:
        """Tab as the window reads: the bar, each pane left to right (its
        algorithm, options, grid), the diff, the speed. Panes added later
        would otherwise come last, after the diff and the speed."""
        chain = [self.preset_box, self.link_box, self.a_box, self.b_box, self.add_button,
                 self.next_button, self.fit_button]
        for pane in self.view.panes:
            chain += [pane.header.algorithm, pane.header.options, pane.grid]
        chain += [self.view.diff.grid, self.transport.speed_box]
        for before, after in zip(chain, chain[1:]):
            QWidget.setTabOrder(before, after)

    def _pane_index(self, widget) -> int:
        return self.view.panes.index(widget)

    def _header_algorithm(self, widget, name: str) -> None:
        self.set_pane(self._pane_index(widget), algorithm=name)

    def _header_options(self, widget, text: str) -> None:
        k = self._pane_index(widget)
        if text.strip() == compare.format_options(self.panes[k].options) and k not in self._errors:
            return
        self.set_pane(k, options_text=text)

    def _header_remove(self, widget) -> None:
        self.remove_pane(self._pane_index(widget))

    # ------------------------------------------------------------ running
    def rerun(self, to_end: bool = False) -> None:
        """Record every pane afresh; the timeline keeps its relative place."""
        old_last = self.last
        fraction = 1.0 if to_end or old_last == 0 else self.position / old_last
        self.runs = compare.run_panes(self.panes, self.primitives)
        self.transport.set_range(self.last)
        self.position = round(fraction * self.last)
        self._update_pair_boxes()
        self.show_frame()

    @property
    def last(self) -> int:
        return compare.timeline_last(self.runs)

    def indices(self) -> list[int]:
        return compare.linked_indices(self.position, [run.last for run in self.runs], self.link)

    def _update_headers(self) -> None:
        for k, (pane, run) in enumerate(zip(self.panes, self.runs)):
            widget = self.view.panes[k]
            widget.header.set_current(pane.algorithm, compare.format_options(pane.options),
                                      _options_help(pane.algorithm))
            widget.header.show_options_error(self._errors.get(k, ""))
            role = "A: " if k == self.pair[0] else "B: " if k == self.pair[1] else ""
            applied = ", ".join(f"{n}={compare.value_text(v)}" for n, v in run.options.items())
            widget.set_title(role + run.title, f"{run.title}\n{applied}")
        self.add_button.setEnabled(len(self.panes) < MAX_PANES)

    def _update_pair_boxes(self) -> None:
        labels = [f"{k + 1}: {run.title}" for k, run in enumerate(self.runs)]
        for box, k in ((self.a_box, self.pair[0]), (self.b_box, self.pair[1])):
            box.blockSignals(True)
            box.clear()
            box.addItems(labels)
            box.setCurrentIndex(k)
            box.blockSignals(False)
        self._update_headers()

    def next_difference(self) -> tuple | None:
        """Zoom all views to the next differing cell (left to right, then
        bottom to top), around it a region the size of a small grid."""
        if self.current_diff is None:
            return None
        cells = self.current_diff.cells()
        if not len(cells):
            return None
        cells = cells[np.lexsort((cells[:, 1], cells[:, 0]))]
        keys = cells[:, 0] * (self.primitives.grid[1] + 1) + cells[:, 1]
        last = self._last_shown
        k = 0 if last is None else int(np.searchsorted(keys, last, side="right")) % len(keys)
        x, y = (int(v) for v in cells[k])
        self._last_shown = int(keys[k])
        # Close enough that the cell and its neighbours fill the panes.
        half_w, half_h = ZOOM_CELLS
        self.view.show_region(x + 0.5 - half_w, y + 0.5 - half_h, x + 0.5 + half_w,
                              y + 0.5 + half_h)
        return (x, y)

    # ------------------------------------------------------------ stepping
    def seek(self, position: int, pause: bool = False) -> None:
        if pause:
            self.pause()
        self.position = min(max(int(position), 0), self.last)
        self.show_frame()

    def step(self, delta: int) -> None:
        self.seek(self.position + delta, pause=True)

    @property
    def playing(self) -> bool:
        return self._timer.isActive()

    def toggle(self) -> None:
        if self.playing:
            self.pause()
        else:
            self.play()

    def play(self) -> None:
        if self.playing or self.last < 1:
            return
        if self.position >= self.last:
            self.seek(0)
        self._owed = 0.0
        self._clock.start()
        self._timer.start(max(MIN_TICK_MS, int(1000.0 / self.transport.speed)))
        self.transport.set_playing(True)

    def pause(self) -> None:
        if self.playing:
            self._timer.stop()
            self.transport.set_playing(False)

    def _tick(self) -> None:
        # As the main window plays: as many steps as the time and the speed
        # call for, at least one a tick.
        self._owed += self._clock.restart() / 1000.0 * self.transport.speed
        steps = max(1, int(self._owed))
        self._owed = max(0.0, self._owed - steps)
        self.seek(self.position + steps)
        if self.position >= self.last:
            self.pause()

    # ------------------------------------------------------------- display
    def show_frame(self) -> None:
        """Bring every pane and the diff to the current position."""
        indices = self.indices()
        a, b = self.pair
        self.current_diff = None
        if self.runs[a].ok and self.runs[b].ok:
            self.current_diff = compare.diff_runs(self.runs[a], self.runs[b],
                                                  indices[a], indices[b])
        cells = None if self.current_diff is None else self.current_diff.cells()
        for k, (run, index) in enumerate(zip(self.runs, indices)):
            self._show_pane(k, run, index, cells if k in self.pair else None)
        self._show_diff()
        self.transport.set_position(self.position)

    def _show_pane(self, k: int, run, index: int, differences) -> None:
        pane = self.view.panes[k]
        if not run.ok:
            width, height = self.primitives.grid
            pane.show_frame(compose(_empty(width, height), None, self.colours))
            pane.grid.show_paths([])
            pane.set_message(run.error, error=True)
            return
        state = run.state_at(index)
        raster = state.raster if state is not None else run.raster_at(index)
        current, spans = frame_view.step_cells(state) if state is not None else ((), ())
        candidates = state.candidates if state is not None else ()
        pane.show_frame(compose(raster, None, self.colours), current, candidates, spans,
                        differences)
        pane.grid.show_paths(run.paths())
        if self._errors.get(k):
            pane.set_message(self._errors[k], error=True)
        elif run.trace is not None and run.trace.truncated:
            pane.set_message(run.trace.message, error=True)
        elif state is not None:
            pane.set_message(frame_view.step_caption(state, run.last))
        else:
            pane.set_message("one frame: the exact area of each pixel the shapes cover")

    def _show_diff(self) -> None:
        a, b = self.pair
        run_a, run_b = self.runs[a], self.runs[b]
        view = self.view
        view.legend.set_names({"only A": f"only in A ({a + 1})", "only B": f"only in B ({b + 1})"})
        width, height = self.primitives.grid
        d = self.current_diff
        if d is None:
            view.diff.show_frame(compose(_empty(width, height), None, self.colours))
            view.diff.set_title(f"Diff of {a + 1} and {b + 1}")
            view.diff.set_message("No diff: " + (run_a.error or run_b.error or
                                                 "the two panes have different grids"), True)
            view.legend.set_counts(None)
            return
        scale = pattern_scale(width, height)
        view.diff.show_frame(diff_image(d, self.colours), patterned=(
            diff_image(d, self.colours, scale) if scale > 1 else None))
        view.diff.grid.show_paths(run_a.paths())
        view.diff.set_title(f"Diff: A = {a + 1}, B = {b + 1}",
                            f"A: {run_a.title}\nB: {run_b.title}")
        counts = d.counts
        view.legend.set_counts(d.by_class)
        compared = (f"values compared: {d.kind}" if d.kind else
                    "the two runs write different kinds of value: only presence compared")
        view.diff.set_message(f"{counts['only A']:,} only in A \u00b7 {counts['only B']:,} only "
                              f"in B \u00b7 {counts['both']:,} in both "
                              f"({counts['both, different value']:,} with a different value); "
                              f"{compared}")

    def closeEvent(self, event):  # noqa: N802
        self.pause()
        super().closeEvent(event)


def _options_help(algorithm: str) -> str:
    """One line per option: its meaning, default and choices."""
    try:
        spec = compare.spec_of(algorithm)
    except InputError as error:
        return str(error)
    lines = [f"{o.name}: {o.help} (default {compare.value_text(o.default)}"
             + (f"; {', '.join(o.choices)}" if o.choices else "") + ")" for o in spec.options]
    return "\n".join(lines) or "This algorithm has no options."


def _empty(width: int, height: int):
    from algorithms.core.raster import Raster
    return Raster(width, height)
