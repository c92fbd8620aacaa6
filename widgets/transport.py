"""The transport bar: first, back, play/pause, forward, last, speed,
timeline and the step counter."""
from __future__ import annotations

import math

from PySide6.QtCore import QEvent, QSize, Qt, Signal
from PySide6.QtGui import QFont, QFontMetrics
from PySide6.QtWidgets import (QHBoxLayout, QLabel, QSizePolicy, QSlider, QSpinBox, QStyle,
                               QStyleOptionSlider, QToolButton, QVBoxLayout, QWidget)

from .dirty import fill_own_background
from .media_icons import media_icon

SPEED_MIN = 1
SPEED_MAX = 2000
_SPEED_TICKS = 1000  # resolution of the logarithmic speed slider


class Timeline(QSlider):
    """The scrub slider: a click on the groove goes to the step under the
    pointer (and a drag goes on from there), not one page towards it."""

    def mousePressEvent(self, event):  # noqa: N802
        if event.button() == Qt.MouseButton.LeftButton and not self._on_handle(event):
            self.setValue(self.value_at(event.position().toPoint().x()))
        super().mousePressEvent(event)  # on the handle now: the drag goes on

    def _on_handle(self, event) -> bool:
        option = QStyleOptionSlider()
        self.initStyleOption(option)
        handle = self.style().subControlRect(QStyle.ComplexControl.CC_Slider, option,
                                             QStyle.SubControl.SC_SliderHandle, self)
        return handle.contains(event.position().toPoint())

    def value_at(self, x: int) -> int:
        """The value under ``x`` (the slider's own coordinates), the handle's
        half-width taken off each end as the style draws it."""
        option = QStyleOptionSlider()
        self.initStyleOption(option)
        style = self.style()
        groove = style.subControlRect(QStyle.ComplexControl.CC_Slider, option,
                                      QStyle.SubControl.SC_SliderGroove, self)
        handle = style.subControlRect(QStyle.ComplexControl.CC_Slider, option,
                                      QStyle.SubControl.SC_SliderHandle, self)
        span = groove.width() - handle.width()
        return QStyle.sliderValueFromPosition(self.minimum(), self.maximum(),
                                              x - groove.x() - handle.width() // 2, max(1, span))


class TransportBar(QWidget):
    """Buttons, speed and timeline. Emits requests; shows what it is told."""

    firstRequested = Signal()
    backRequested = Signal()
    playRequested = Signal()   # toggle play / pause
    forwardRequested = Signal()
    lastRequested = Signal()
    seekRequested = Signal(int)
    speedChanged = Signal(float)

    def __init__(self, parent=None):
        super().__init__(parent)
        self.setObjectName("transport")
        self._playing = False
        self._last = 0
        self._position = 0
        self._make_buttons()
        self._make_timeline()
        speed_label = self._make_speed()
        self._lay_out(speed_label)
        self.set_speed(8)
        self.set_range(0)

    def _make_buttons(self) -> None:
        """First, back, play, forward and last (their icons: ``_paint_icons``)."""

        def button(icon, name, key, signal):
            b = QToolButton(self)
            b.setObjectName(icon)
            b.setIconSize(QSize(20, 20))
            b.setAccessibleName(name)  # an icon alone says nothing to a screen reader
            b.setToolTip(f"{name} ({key})")
            b.setAutoRaise(True)
            # Buttons never take the keyboard focus, so Space and the arrows
            # stay with the window's shortcuts.
            b.setFocusPolicy(Qt.FocusPolicy.NoFocus)
            b.clicked.connect(signal.emit)
            return b

        self.first_button = button("first", "First step", "Home", self.firstRequested)
        self.back_button = button("back", "Step back", "Left", self.backRequested)
        self.play_button = button("play", "Play", "Space", self.playRequested)
        self.play_button.setIconSize(QSize(26, 26))
        self.forward_button = button("forward", "Step forward", "Right", self.forwardRequested)
        self.last_button = button("last", "Last step", "End", self.lastRequested)
        self._paint_icons()

    def _paint_icons(self) -> None:
        """Icons in the palette's text colour: redrawn when the theme changes."""
        palette = self.palette()
        for b in (self.first_button, self.back_button, self.forward_button, self.last_button):
            b.setIcon(media_icon(b.objectName(), palette))
        self.play_button.setIcon(media_icon("pause" if self._playing else "play", palette))

    def changeEvent(self, event):  # noqa: N802
        super().changeEvent(event)
        if event.type() == QEvent.Type.PaletteChange:
            self._paint_icons()
        elif event.type() == QEvent.Type.FontChange:
            self._fit_counter()
            self._fit_speed()

    def _make_timeline(self) -> None:
        """The scrub slider and the step counter."""
        self.timeline = Timeline(Qt.Orientation.Horizontal, self)
        self.timeline.setToolTip("Drag to scrub through the run")
        self.timeline.setAccessibleName("Step")
        self.timeline.setFocusPolicy(Qt.FocusPolicy.NoFocus)
        self.timeline.setRange(0, 0)
        self.timeline.setSizePolicy(QSizePolicy.Policy.Expanding, QSizePolicy.Policy.Fixed)
        self.timeline.valueChanged.connect(self._timeline_moved)

        self.counter = QLabel(self)
        self.counter.setObjectName("stepCounter")
        self.counter.setAlignment(Qt.AlignmentFlag.AlignLeft | Qt.AlignmentFlag.AlignVCenter)
        self.counter.setToolTip("The step on show and the last step of the run")
        fill_own_background(self.timeline, self.counter)  # both change every step

    def _make_speed(self) -> QLabel:
        """The speed slider and the steps-per-second box beside it."""
        self.speed_label = speed_label = QLabel("Speed", self)
        self.speed_slider = QSlider(Qt.Orientation.Horizontal, self)
        self.speed_slider.setRange(0, _SPEED_TICKS)
        self.speed_slider.setFixedWidth(110)
        self.speed_slider.setFocusPolicy(Qt.FocusPolicy.NoFocus)
        self.speed_slider.setToolTip("Steps per second while playing (logarithmic)")
        self.speed_slider.setAccessibleName("Speed")
        self.speed_box = QSpinBox(self)
        self.speed_box.setRange(SPEED_MIN, SPEED_MAX)
        self.speed_box.setSuffix(" steps/s")
        self.speed_box.setAccessibleName("Steps per second")
        self.speed_box.setKeyboardTracking(False)
        self.speed_box.setToolTip("Steps per second while playing; at high speeds "
                                  "frames are skipped to keep up")
        self.speed_slider.valueChanged.connect(self._speed_slid)
        self.speed_box.valueChanged.connect(self._speed_typed)
        return speed_label

    def _lay_out(self, speed_label) -> None:
        # The timeline takes the whole width above the buttons: scrubbing
        # wants every pixel it can get.
        top = QHBoxLayout()
        top.setContentsMargins(0, 0, 0, 0)
        top.addWidget(self.timeline, 1)
        self._row = row = QHBoxLayout()
        row.setContentsMargins(0, 0, 0, 0)
        row.setSpacing(2)
        for b in (self.first_button, self.back_button, self.play_button, self.forward_button,
                  self.last_button):
            row.addWidget(b)
        row.addSpacing(12)
        row.addWidget(self.counter)
        row.addStretch(1)
        row.addWidget(speed_label)
        row.addSpacing(6)
        row.addWidget(self.speed_slider)
        row.addSpacing(4)
        row.addWidget(self.speed_box)
        layout = QVBoxLayout(self)
        layout.setContentsMargins(10, 6, 10, 4)
        layout.setSpacing(2)
        layout.addLayout(top)
        layout.addLayout(row)

    # ----------------------------------------------------------- narrow
    def minimumSizeHint(self):  # noqa: N802
        """Narrow enough without the speed slider and its label: a large
        zoom on a small screen puts them aside (``resizeEvent``) rather than
        run the step counter into them or push the window past the screen."""
        hint = super().minimumSizeHint()
        if self.speed_slider.isVisibleTo(self):
            hint.setWidth(hint.width() - self._slider_width())
        return hint

    def _slider_width(self) -> int:
        """The width the speed slider and its label take in the row."""
        return (self.speed_label.sizeHint().width() + self.speed_slider.width()
                + 2 * self._row.spacing())

    def resizeEvent(self, event):  # noqa: N802
        super().resizeEvent(event)
        self._fit_speed()

    def _fit_speed(self) -> None:
        room = self.width() >= self.minimumSizeHint().width() + self._slider_width()
        if room != self.speed_slider.isVisibleTo(self):
            self.speed_label.setVisible(room)
            self.speed_slider.setVisible(room)

    # ------------------------------------------------------------ shown state
    def set_range(self, last: int) -> None:
        """The run has steps 0 .. last (last = -1 when there is no run)."""
        self._last = last
        self.timeline.blockSignals(True)
        self.timeline.setRange(0, max(0, last))
        self.timeline.setPageStep(max(1, (last + 1) // 20))
        self.timeline.blockSignals(False)
        enabled = last > 0
        for widget in (self.first_button, self.back_button, self.play_button, self.forward_button,
                       self.last_button, self.timeline):
            widget.setEnabled(enabled)
        self._fit_counter()
        self._update_counter()

    def _fit_counter(self) -> None:
        """The counter as large as the run's longest text, fixed: a new
        text then asks no layout for room (a label's new text otherwise
        lays out the main window again: 1 to 2 ms a step, measured, with the
        caption's). Measured in the bar's font, which the counter has, in
        bold as its style sheet draws it."""
        digits = len(f"{max(self._last, 0):,}")
        bold = QFont(self.font())
        bold.setBold(True)
        metrics = QFontMetrics(bold)
        self.counter.setFixedSize(
            metrics.horizontalAdvance("step " + "8" * (2 * digits + 1) + " / ") + 12,
            metrics.height())

    def set_position(self, index: int) -> None:
        self._position = index
        if self.timeline.value() != index:
            self.timeline.blockSignals(True)
            self.timeline.setValue(index)
            self.timeline.blockSignals(False)
        self._update_counter()

    def set_playing(self, playing: bool) -> None:
        self._playing = playing
        self._paint_icons()
        name = "Pause" if playing else "Play"
        self.play_button.setAccessibleName(name)
        self.play_button.setToolTip(f"{name} (Space)")

    @property
    def speed(self) -> float:
        return float(self.speed_box.value())

    def set_speed(self, speed: float) -> None:
        speed = int(min(max(round(speed), SPEED_MIN), SPEED_MAX))
        self.speed_box.setValue(speed)

    def _update_counter(self) -> None:
        if self._last < 0:
            self.counter.setText("no run")
        else:
            self.counter.setText(f"step {self._position:,} / {self._last:,}")

    # ---------------------------------------------------------------- input
    def _timeline_moved(self, value: int) -> None:
        self.seekRequested.emit(value)

    def _speed_slid(self, tick: int) -> None:
        speed = round(math.exp(math.log(SPEED_MIN) + (math.log(SPEED_MAX) - math.log(SPEED_MIN))
                               * tick / _SPEED_TICKS))
        if speed != self.speed_box.value():
            self.speed_box.setValue(speed)

    def _speed_typed(self, speed: int) -> None:
        tick = round((math.log(speed) - math.log(SPEED_MIN))
                     / (math.log(SPEED_MAX) - math.log(SPEED_MIN)) * _SPEED_TICKS)
        self.speed_slider.blockSignals(True)
        self.speed_slider.setValue(tick)
        self.speed_slider.blockSignals(False)
        self.speedChanged.emit(float(speed))
