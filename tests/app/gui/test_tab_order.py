"""Tab order and Alt+letter mnemonics of the window's dialogs."""
import re

import pytest
from PySide6.QtCore import Qt
from PySide6.QtWidgets import QAbstractButton, QApplication, QLabel, QWidget

pytestmark = pytest.mark.window(files=True)


def tab_chain(top: QWidget) -> list[QWidget]:
    """The widgets of ``top`` that Tab visits, in order."""
    chain, widget = [], top.nextInFocusChain()
    while widget is not top and len(chain) < 1000:
        if widget.window() is top and widget.isVisible() and widget.isEnabled() \
                and widget.focusPolicy() & Qt.FocusPolicy.TabFocus:
            chain.append(widget)
        widget = widget.nextInFocusChain()
    return chain


def mnemonics(top: QWidget) -> list[str]:
    texts = [label.text() for label in top.findChildren(QLabel) if label.buddy() is not None]
    texts += [button.text() for button in top.findChildren(QAbstractButton) if button.isVisible()]
    return [m.group(1).lower() for t in texts if (m := re.search(r"&([^&])", t))]


def test_preferences_every_field_has_its_own_alt_letter(window, qtbot):
    dialog = window.preferences.open_dialog()
    qtbot.waitExposed(dialog)
    labelled = [label for label in dialog.findChildren(QLabel) if label.buddy() is not None]
    assert labelled and all("&" in label.text() for label in labelled)
    letters = mnemonics(dialog)
    assert len(letters) >= len(labelled) + 3  # the check boxes too
    assert len(set(letters)) == len(letters), letters
    dialog.close()


def test_export_dialog_tabs_down_its_side_panel_theme_and_text_size(window, qtbot):
    dialog = window.file_actions.export_animation().dialog
    qtbot.waitExposed(dialog)
    chain = tab_chain(dialog)
    order = [chain.index(w) for w in (dialog.panel, dialog.theme, dialog.text_size, dialog.path,
                                      dialog.export_button)]
    assert order == sorted(order)
    dialog.close()


def test_compare_tabs_pane_by_pane_then_the_diff_and_the_speed(window, qtbot):
    window.compare_entry.action.trigger()
    compare = window.compare_entry.window
    qtbot.waitExposed(compare)
    compare.add_pane()  # a pane added later takes its place among the others
    qtbot.waitUntil(lambda: all(pane.grid.isVisible() for pane in compare.view.panes))
    chain = tab_chain(compare)
    grids = [chain.index(pane.grid) for pane in compare.view.panes]
    lefts = [pane.mapTo(compare, pane.rect().topLeft()).x() for pane in compare.view.panes]
    assert grids == sorted(grids) and lefts == sorted(lefts)
    headers = [chain.index(pane.header.algorithm) for pane in compare.view.panes]
    assert all(h < g for h, g in zip(headers, grids))  # a pane's header before its grid
    assert chain.index(compare.fit_button) < headers[0]
    assert grids[-1] < chain.index(compare.view.diff.grid) < chain.index(
        compare.transport.speed_box)
    compare.close()


def test_a_dialog_rings_the_widget_tab_moves_to(window, qtbot):
    from PySide6.QtTest import QTest
    from widgets.focus_ring import FocusRing
    dialog = window.preferences.open_dialog()
    qtbot.waitExposed(dialog)
    dialog.activateWindow()
    qtbot.waitUntil(lambda: QApplication.focusWidget() is not None
                    and QApplication.focusWidget().window() is dialog)
    QTest.keyClick(QApplication.focusWidget(), Qt.Key.Key_Tab)
    ring = dialog.findChild(FocusRing)
    assert ring is not None and ring.isVisible()
    assert ring.target is QApplication.focusWidget()
    dialog.close()
