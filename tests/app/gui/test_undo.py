"""Undo and redo of every scene edit, driven through the editors a person uses."""
import json
import random

import pytest
from PySide6.QtCore import QSettings, Qt
from PySide6.QtTest import QTest
from PySide6.QtWidgets import QApplication

from algorithms.core import registry
from app.model.history import MERGE_SECONDS
from app.gui.window import MainWindow
from tests.support.gui import WAIT_MS, drag, settle

LEFT = Qt.MouseButton.LeftButton
NONE = Qt.KeyboardModifier.NoModifier
CTRL = Qt.KeyboardModifier.ControlModifier


class Clock:
    """A clock the test moves by hand, so merging does not depend on speed."""

    def __init__(self):
        self.now = 0.0

    def __call__(self):
        return self.now


@pytest.fixture
def make(qtbot, tmp_path):
    def build(algorithm="line-bresenham"):
        w = MainWindow(algorithm)
        qtbot.addWidget(w)
        w.add_file_actions(QSettings(str(tmp_path / "s.ini"), QSettings.Format.IniFormat))
        w.clock = Clock()
        w.history.clock = w.clock
        w.show()
        qtbot.waitExposed(w)
        settle(qtbot, w)
        return w
    return build


def scene_json(w) -> str:
    """The saved scene file, less the view (the step may move by fraction)."""
    data = w.file_actions.current_scene().to_json()
    data.pop("view", None)
    return json.dumps(data, sort_keys=True)


def final_pixels(w):
    trace = w.player.trace
    return None if trace is None else sorted(map(tuple, trace.written_pixels().tolist()))


def fresh_pixels(w):
    """The same scene recorded afresh, away from the window."""
    player = w.player
    if player.trace is None:
        return None
    trace = player.spec.record(player.input_points(), dict(player.options), player.grid)
    return sorted(map(tuple, trace.written_pixels().tolist()))


# --------------------------------------------------------------- the edits
def edit_typed_point(w, rng):
    table = w.points
    rows = len(w.player.points)
    if not rows:
        return
    width, height = w.player.grid
    axis = rng.choice(("x", "y"))
    limit = (width if axis == "x" else height) - 1
    if w.player.spec.inputs.integer:
        text = str(rng.randint(0, limit))
    else:
        text = str(rng.randint(0, limit * 256) / 256)
    table.type_value(rng.randrange(rows), axis, text)


def edit_attribute(w, rng):
    table = w.points
    columns = [c for c in table.column_names() if c not in ("x", "y")]
    if not columns or not w.player.points:
        return
    column = rng.choice(columns)
    row = rng.randrange(len(w.player.points))
    if column == "colors":
        text = "#%06x" % rng.randrange(1 << 24)
    elif column == "w":
        text = str(rng.choice((0.5, 1, 2, 3.25)))
    else:
        text = str(rng.choice((-0.5, 0, 0.25, 0.75, 1)))
    table.type_value(row, column, text)


def edit_algorithm(w, rng):
    name = rng.choice(("line-bresenham", "line-dda", "circle-midpoint", "polygon-scanline",
                       "triangle-bbox", "zbuffer"))
    w.picker.setCurrentItem(w.picker.item_for(name))


def edit_option(w, rng):
    spec = w.player.spec
    for option in rng.sample(list(spec.options), len(spec.options)):
        editor = w.options.editor(option.name)
        if option.kind == "bool":
            editor.setChecked(not editor.isChecked())
            return
        if option.kind == "choice":
            editor.setCurrentIndex((editor.currentIndex() + 1) % editor.count())
            return
        if option.kind == "int" and not option.choices:
            low, high = editor.minimum(), min(editor.maximum(), editor.minimum() + 12)
            editor.setValue(rng.randint(low, high))
            return


def edit_grid(w, rng):
    box = rng.choice((w.grid_editor.width_box, w.grid_editor.height_box))
    box.setValue(rng.randint(16, 40))


def edit_origin(w, _rng):
    w.grid_editor.origin.setCurrentIndex(1 - w.grid_editor.origin.currentIndex())


def edit_rows(w, rng):
    table = w.points
    if not table.add_button.isVisible():
        return
    if w.player.points and rng.random() < 0.5:
        table.view.setCurrentIndex(table.model.index(rng.randrange(len(w.player.points)), 0))
        table.remove_row()
    else:
        table.add_row()


def edit_clear(w, _rng):
    w.clear_points()


EDITS = (edit_typed_point, edit_attribute, edit_algorithm, edit_option, edit_grid,
         edit_origin, edit_rows, edit_clear)


@pytest.mark.parametrize("seed", [1, 2])
def test_random_edits_undo_and_redo_restore_scenes_exactly(make, qtbot, seed):
    w = make("line-bresenham")
    rng = random.Random(seed)
    first, first_json, first_pixels = w.player.scene, scene_json(w), final_pixels(w)
    # A drag on the grid (a real gesture) among the random edits.
    drag(qtbot, w, (28.5, 15.5), (24.5, 18.5))
    kinds = set()
    for _ in range(26):
        edit = rng.choice(EDITS)
        before = w.player.scene
        edit(w, rng)
        if w.player.scene != before:
            kinds.add(edit.__name__)
        w.clock.now += 2 * MERGE_SECONDS  # every edit its own entry
    assert len(kinds) >= 6, kinds
    last, last_json, last_pixels = w.player.scene, scene_json(w), final_pixels(w)
    assert last != first

    undos = 0
    while w.history.can_undo:
        w.undo()
        undos += 1
    assert undos >= len(kinds)
    assert w.player.scene == first
    assert scene_json(w) == first_json
    assert final_pixels(w) == first_pixels == fresh_pixels(w)
    assert w.picker.current_name() == first.algorithm
    assert not w.actions_["undo"].isEnabled() and w.actions_["undo"].text() == "&Undo"

    while w.history.can_redo:
        w.redo()
    assert w.player.scene == last
    assert scene_json(w) == last_json
    assert final_pixels(w) == last_pixels == fresh_pixels(w)
    assert not w.actions_["redo"].isEnabled()


def test_algorithm_switch_is_undone_with_its_points_and_options(make):
    w = make("line-bresenham")
    w.points.type_value(1, "x", "20")
    line = w.player.scene
    w.picker.setCurrentItem(w.picker.item_for("polygon-scanline"))
    assert w.player.spec.name == "polygon-scanline"
    assert w.actions_["undo"].text() == "&Undo algorithm switch"
    w.undo()
    assert w.player.scene == line
    assert w.player.points == [(4, 5), (20, 15)]
    assert w.picker.current_name() == "line-bresenham"
    assert "Bresenham" in w.windowTitle()
    w.undo()
    assert w.player.points == [(4, 5), (28, 15)]


def test_menu_names_the_edit(make):
    w = make("circle-midpoint")
    undo, redo = w.actions_["undo"], w.actions_["redo"]
    assert not undo.isEnabled() and not redo.isEnabled()
    w.options.editor("radius").setValue(5)
    assert undo.text() == "&Undo change radius" and undo.isEnabled()
    w.clock.now += 10
    w.grid_editor.width_box.setValue(40)
    assert undo.text() == "&Undo grid size"
    w.clock.now += 10
    w.grid_editor.origin.setCurrentIndex(1)
    assert undo.text() == "&Undo origin" and w.grid.y_down
    w.undo()
    assert redo.text() == "&Redo origin" and undo.text() == "&Undo grid size"
    assert not w.grid.y_down and w.grid_editor.origin.currentIndex() == 0
    w.undo()
    assert w.player.grid == (32, 24) and w.grid_editor.width_box.value() == 32
    assert redo.text() == "&Redo grid size"


def test_stepping_one_field_merges_until_a_pause(make):
    w = make("circle-midpoint")
    box = w.options.editor("radius")
    start = w.player.options["radius"]
    box.setFocus()
    for _ in range(4):
        QTest.keyClick(box, Qt.Key.Key_Up)
        w.clock.now += 0.2
    assert w.player.options["radius"] == start + 4
    w.clock.now += MERGE_SECONDS + 1  # a pause: a new entry
    QTest.keyClick(box, Qt.Key.Key_Up)
    w.undo()
    assert w.player.options["radius"] == start + 4
    w.undo()
    assert w.player.options["radius"] == start
    assert not w.history.can_undo


def test_dragging_a_handle_is_one_entry(make, qtbot):
    w = make("line-bresenham")
    drag(qtbot, w, (28.5, 15.5), (20.5, 10.5), steps=6)
    assert w.player.points == [(4, 5), (20, 10)]
    assert len(w.history) == 1 and w.actions_["undo"].text() == "&Undo move point"
    w.undo()
    assert w.player.points == [(4, 5), (28, 15)]


def test_undo_keeps_the_step_by_fraction(make):
    w = make("line-bresenham")
    w.player.seek(w.player.last // 2)
    fraction = w.player.index / w.player.last
    w.points.type_value(1, "x", "31")
    w.undo()
    assert abs(w.player.index / w.player.last - fraction) <= 1 / w.player.last


def test_ctrl_z_in_a_text_field_is_the_fields_own_undo(make, qtbot):
    w = make("triangle-bbox")
    w.points.type_value(0, "x", "5.5")
    assert w.history.can_undo
    points = list(w.player.points)
    field = w.options.editor("z")
    field.setFocus()
    qtbot.waitUntil(lambda: QApplication.focusWidget() is field, timeout=WAIT_MS)
    QTest.keyClicks(field, "1,2,3")
    QTest.keyClick(field, Qt.Key.Key_Z, CTRL)
    assert w.player.points == points  # the scene did not go back
    assert field.text() == ""  # the field took back its typing
    w.grid.setFocus()
    qtbot.waitUntil(lambda: QApplication.focusWidget() is w.grid, timeout=WAIT_MS)
    QTest.keyClick(w.grid, Qt.Key.Key_Z, CTRL)
    assert w.player.points != points
    QTest.keyClick(w.grid, Qt.Key.Key_Z, CTRL | Qt.KeyboardModifier.ShiftModifier)
    assert w.player.points == points


def test_opening_a_scene_starts_a_new_history(make):
    w = make("line-bresenham")
    w.points.type_value(0, "x", "9")
    assert w.actions_["undo"].isEnabled()
    w.set_scene("line-dda", [(1, 1), (9, 4)])
    assert not w.actions_["undo"].isEnabled() and w.actions_["undo"].text() == "&Undo"


def test_every_registered_algorithm_switch_undoes(make):
    """Each switch (with its fallback shapes) comes back exactly."""
    w = make("line-bresenham")
    names = [spec.name for spec in registry.all_specs()][::5]
    states = [w.player.scene]
    for name in names:
        w.picker.setCurrentItem(w.picker.item_for(name))
        states.append(w.player.scene)
    for state in reversed(states[:-1]):
        w.undo()
        assert w.player.scene == state


def test_ctrl_z_in_a_spin_box_stays_in_the_box(make, qtbot):
    w = make("circle-midpoint")
    w.points.type_value(0, "x", "9")
    points = list(w.player.points)
    box = w.options.editor("radius")
    box.setFocus()
    qtbot.waitUntil(lambda: QApplication.focusWidget() is box, timeout=WAIT_MS)
    box.lineEdit().selectAll()
    QTest.keyClicks(box, "7")
    QTest.keyClick(box, Qt.Key.Key_Z, CTRL)
    assert w.player.points == points


def test_history_merges_by_key_within_its_time():
    from app.model.history import EditHistory
    from app.model.scene import Scene

    def scene(x):
        return Scene(algorithm="line-dda", points=[(x, 0), (5, 5)])
    clock = Clock()
    history = EditHistory(clock)
    history.push(scene(0), scene(1), ("option", "a"), 1.5)
    clock.now = 1.0
    history.push(scene(1), scene(2), ("option", "a"), 1.5)  # merges
    clock.now = 2.0
    history.push(scene(2), scene(3), ("option", "a"), 1.5)  # merges: 1 s after the last
    clock.now = 10.0
    history.push(scene(3), scene(4), ("option", "a"), 1.5)  # too late: a new entry
    history.push(scene(4), scene(4), None)  # no change: no entry
    assert len(history) == 2 and history.undo_text == "move point"
    assert history.undo(scene(4)) == scene(3)
    assert history.undo(scene(3)) == scene(0)
    assert history.undo(scene(0)) is None
    assert history.redo(scene(0)) == scene(3) and history.redo_text == "move point"
    # After an undo or redo the next edit never merges into an older entry.
    history.push(scene(3), scene(7), ("option", "a"), 1.5)
    assert len(history) == 2 and not history.can_redo


def test_the_first_click_of_a_new_segment_is_named_for_what_it_does(make):
    w = make("line-bresenham")
    from app.model.drawing import Place, Remove
    w.grid.gestured.emit(Place((9, 3)))
    assert w.player.points == [(9, 3)]  # the segment starts anew at the click
    assert w.actions_["undo"].text() == "&Undo start a new shape"
    w.undo()
    assert w.player.points == [(4, 5), (28, 15)]
    w.grid.gestured.emit(Remove(1))
    assert w.actions_["undo"].text() == "&Undo remove point"
