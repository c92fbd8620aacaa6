"""A holder for a label whose text changes with every step.

A QLabel asks its layout for room again whenever its text changes, and the
ask climbs from layout to layout up to the main window, which lays out all
its docks again (animating them) and repaints them: a few milliseconds on
every step for a caption of the same size. ``SteadyBox`` stops the ask:
the label sits in it without a layout, and the box asks its own layout for
room only when the label's height at the box's width changes.
"""
from __future__ import annotations

from PySide6.QtCore import QEvent, QSize
from PySide6.QtWidgets import QLabel, QWidget


class SteadyBox(QWidget):
    """Holds ``label`` at the box's whole size."""

    def __init__(self, label: QLabel, parent=None):
        super().__init__(parent)
        self.label = label
        label.setParent(self)
        policy = label.sizePolicy()
        policy.setHeightForWidth(label.wordWrap())
        self.setSizePolicy(policy)
        self._asked = None  # the label's height and least width when the layout last asked
        self._look = None  # the label's font and least width when last looked at

    def hasHeightForWidth(self) -> bool:  # noqa: N802
        return self.label.wordWrap()

    def heightForWidth(self, width: int) -> int:  # noqa: N802
        if self.label.wordWrap():
            height = self.label.heightForWidth(width)
            if height >= 0:
                return height
        return self.label.sizeHint().height()

    def sizeHint(self) -> QSize:  # noqa: N802
        return QSize(max(self.label.sizeHint().width(), self.label.minimumWidth()),
                     self.heightForWidth(self.width()))

    def minimumSizeHint(self) -> QSize:  # noqa: N802
        # A wrapped label's narrowest is its longest word, which changes
        # with the text: the box takes the width it is given instead.
        hint = self.label.minimumSizeHint()
        width = 0 if self.label.wordWrap() else max(hint.width(), self.label.minimumWidth())
        return QSize(width, hint.height())

    def set_text(self, text: str) -> None:
        """Show ``text``; ask the layout for room only if the label's height
        changes. Measured here, before painting: measuring a rich-text
        label lays its text out again, which would ask for a second paint
        if it came after the first."""
        if text != self.label.text():
            self.label.setText(text)
            self._ask_if_needed()

    def _needs(self) -> tuple[int, int]:
        return self.heightForWidth(self.width()), self.label.minimumWidth()

    def _ask_if_needed(self) -> None:
        needs = self._needs()
        if needs != self._asked:
            self._asked = needs
            self.updateGeometry()

    def event(self, event) -> bool:
        if event.type() == QEvent.Type.LayoutRequest:
            # The label asks after each new text (set_text has answered
            # that); its font or least width changing needs an answer here.
            look = (self.label.font().key(), self.label.minimumWidth())
            if look != self._look:
                self._look = look
                self._ask_if_needed()
            return True
        return super().event(event)

    def changeEvent(self, event) -> None:  # noqa: N802
        super().changeEvent(event)
        if event.type() == QEvent.Type.StyleChange:
            # A new style sheet may pad the label otherwise: ask again.
            self._asked = None
            self._ask_if_needed()

    def resizeEvent(self, event) -> None:  # noqa: N802
        super().resizeEvent(event)
        self.label.setGeometry(self.rect())
        self._asked = self._needs()
