"""Editors made from option lists, the algorithm picker, points and grid."""
from PySide6.QtWidgets import QCheckBox, QComboBox, QLineEdit, QSpinBox

from algorithms.core import registry
from algorithms.core.registry import Option
from widgets.editors import AlgorithmPicker, ColorListEditor, GridEditor, OptionsEditor
from tests.support.gui import WAIT_MS

OPTIONS = (
    Option("symmetric", "bool", False, "ties the same both ways"),
    Option("steps", "int", 4, "how many", minimum=1, maximum=64),
    Option("dtype", "choice", "float64", "float type", choices=("float64", "float32")),
    Option("dt", "float", 0.001, "parameter step", minimum=1e-6, maximum=1.0, choices=("auto",)),
    Option("gamma", "float", 2.2, "a plain float", minimum=0.1, maximum=5),
    Option("colors", "colors", (), "vertex colours"),
)


def make_editor(qtbot):
    editor = OptionsEditor()
    qtbot.addWidget(editor)
    editor.set_options(OPTIONS, {o.name: o.default for o in OPTIONS}, 2, ("P", "Q"))
    edited = []
    editor.valueEdited.connect(lambda name, value: edited.append((name, value)))
    return editor, edited


def test_editors_follow_the_option_kinds(qtbot):
    editor, _ = make_editor(qtbot)
    assert isinstance(editor.editor("symmetric"), QCheckBox)
    spin = editor.editor("steps")
    assert isinstance(spin, QSpinBox) and (spin.minimum(), spin.maximum()) == (1, 64)
    assert isinstance(editor.editor("dtype"), QComboBox) and not editor.editor("dtype").isEditable()
    assert isinstance(editor.editor("dt"), QComboBox) and editor.editor("dt").isEditable()
    assert isinstance(editor.editor("gamma"), QLineEdit)
    assert isinstance(editor.editor("colors"), ColorListEditor)
    assert editor.editor("dt").currentText() == "0.001"


def test_edits_are_emitted_checked(qtbot):
    editor, edited = make_editor(qtbot)
    editor.editor("symmetric").setChecked(True)
    editor.editor("steps").setValue(9)
    editor.editor("dtype").setCurrentText("float32")
    assert edited == [("symmetric", True), ("steps", 9), ("dtype", "float32")]


def test_float_option_takes_numbers_and_names(qtbot):
    editor, edited = make_editor(qtbot)
    box = editor.editor("dt")
    box.setEditText("auto")
    box.lineEdit().editingFinished.emit()
    box.setEditText("0.25")
    box.lineEdit().editingFinished.emit()
    assert edited == [("dt", "auto"), ("dt", 0.25)]


def test_invalid_text_shows_the_message_and_keeps_the_last_good_value(qtbot):
    editor, edited = make_editor(qtbot)
    editor.show()
    box = editor.editor("dt")
    box.setEditText("fast")
    box.lineEdit().editingFinished.emit()
    assert edited == []
    assert "not a number" in editor.error_text("dt")
    assert box.currentText() == "0.001"  # back to the last good value
    box.setEditText("7")  # above the maximum
    box.lineEdit().editingFinished.emit()
    assert "above the maximum" in editor.error_text("dt")
    field = editor.editor("gamma")
    field.setText("nan")
    field.editingFinished.emit()
    assert "finite" in editor.error_text("gamma") and field.text() == "2.2"
    # A good value clears the message.
    box.setEditText("0.5")
    box.lineEdit().editingFinished.emit()
    assert editor.error_text("dt") == "" and edited == [("dt", 0.5)]


def test_colour_list_editor(qtbot):
    editor, edited = make_editor(qtbot)
    colors = editor.editor("colors")
    assert not colors.buttons[0].isEnabled()
    colors.check.setChecked(True)
    assert edited[-1][0] == "colors" and len(edited[-1][1]) == 2
    colors.set_color(1, "#00ff00")
    assert edited[-1] == ("colors", (edited[-1][1][0], "#00ff00"))
    colors.check.setChecked(False)
    assert edited[-1] == ("colors", ())


def test_errors_from_elsewhere_are_shown_inline(qtbot):
    editor, _ = make_editor(qtbot)
    editor.show()
    editor.editor("steps").blockSignals(True)
    editor.editor("steps").setValue(30)
    editor.editor("steps").blockSignals(False)
    editor.show_error("steps", "the run refused 30 steps")
    assert editor.error_text("steps") == "the run refused 30 steps"
    assert editor.editor("steps").value() == 4


def test_picker_groups_by_family_and_emits_names(qtbot):
    picker = AlgorithmPicker()
    qtbot.addWidget(picker)
    specs = registry.all_specs()
    picker.set_specs(specs)
    assert picker.names() == [s.name for s in specs]
    families = [picker.topLevelItem(i).text(0) for i in range(picker.topLevelItemCount())
                if not picker.topLevelItem(i).isHidden()]
    assert families == list(dict.fromkeys(s.family.capitalize() for s in specs))
    with qtbot.waitSignal(picker.algorithmChosen, timeout=WAIT_MS) as blocker:
        picker.setCurrentItem(picker.item_for(specs[-1].name))
    assert blocker.args == [specs[-1].name]
    # Setting the current algorithm from outside is silent.
    with qtbot.assertNotEmitted(picker.algorithmChosen):
        picker.set_current(specs[0].name)
    assert picker.current_name() == specs[0].name


def test_grid_editor(qtbot):
    grid = GridEditor(4096)
    qtbot.addWidget(grid)
    grid.set_grid(32, 24)
    assert grid.width_box.maximum() == 4096
    with qtbot.waitSignal(grid.gridChanged, timeout=WAIT_MS) as blocker:
        grid.width_box.setValue(64)
    assert blocker.args == [64, 24]
    with qtbot.waitSignal(grid.originChanged, timeout=WAIT_MS) as blocker:
        grid.origin.setCurrentIndex(1)
    assert blocker.args == [True]


def test_the_algorithm_search_keeps_only_matching_entries(qtbot):
    from algorithms.core import registry
    from widgets.editors import AlgorithmPicker
    picker = AlgorithmPicker()
    qtbot.addWidget(picker)
    specs = registry.all_specs()
    picker.set_specs(specs)
    shown = picker.set_filter("circle")
    # The oracle: the specs whose own words mention "circle".
    expected = [s.name for s in specs if "circle" in
                f"{s.title} {s.name} {s.summary} {s.family.replace('-', ' ')}".lower()]
    assert shown == expected and len(shown) >= 3
    for name in picker.names():
        assert picker.item_for(name).isHidden() == (name not in expected)
    assert picker.set_filter("") == [s.name for s in specs]
    chosen = []
    picker.algorithmChosen.connect(chosen.append)
    picker.set_filter("midpoint ellipse")
    picker.choose_first_shown()
    assert chosen == ["ellipse-midpoint"]


def test_the_search_reads_scan_line_as_scanline_and_says_when_nothing_matches(qtbot):
    from algorithms.core import registry
    from widgets.editors import AlgorithmPicker
    picker = AlgorithmPicker()
    qtbot.addWidget(picker)
    specs = registry.all_specs()
    picker.set_specs(specs)
    # The oracle: the specs that say "scanline" or "scan line" or "scan-line" anywhere.
    expected = [s.name for s in specs if any(
        form in f"{s.title} {s.name} {s.summary}".lower()
        for form in ("scanline", "scan line", "scan-line"))]
    assert expected
    assert picker.set_filter("scan-line") == expected
    assert picker.set_filter("Scanline") == expected
    assert picker.nothing.isHidden()
    assert picker.set_filter("zzqx") == []
    assert not picker.nothing.isHidden() and "zzqx" in picker.nothing.text(0)
    assert picker.set_filter("") and picker.nothing.isHidden()


def test_a_stale_filter_never_hides_the_algorithm_on_show(qtbot):
    from algorithms.core import registry
    from widgets.editors import AlgorithmPicker
    picker = AlgorithmPicker()
    qtbot.addWidget(picker)
    picker.set_specs(registry.all_specs())
    picker.set_filter("circle")
    picker.set_current("line-bresenham")  # a line scene opened meanwhile
    item = picker.item_for("line-bresenham")
    assert not item.isHidden() and not item.parent().isHidden()
    assert picker.current_name() == "line-bresenham"
    assert picker.item_for("line-dda").isHidden()  # the filter still holds for the rest
