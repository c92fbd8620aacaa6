"""The report's visibility rows and section: the painter's wrong pixels
against the splitting painter's, and the splitting's cost."""
import numpy as np

from algorithms.core import registry
from app.analysis import measure
from app.analysis.measure_visibility import measure_visibility, visibility_scenes
from app.analysis.report_findings import View
from app.analysis.report_visibility import section_visibility


def test_rows_and_section():
    rows = measure.Rows()
    measure_visibility(measure.settings(True), rows, np.random.default_rng([1, 7]))
    view = View(rows.rows)
    scenes = view.values("visibility", "painter")
    assert scenes[:3] == ["intersecting", "cyclic", "separate"]
    for scene in scenes:
        # Right but for centres within a rounding of where two triangles meet.
        split = view.get("visibility", "painter", "painter-split", scene, "disagree")
        assert split <= min(3, view.get("visibility", "painter", "painter", scene, "disagree"))
    for scene in ("intersecting", "cyclic"):
        assert view.get("visibility", "painter", "painter-split", scene, "disagree") == 0
        assert view.get("visibility", "painter", "painter", scene, "disagree") > 0
        assert view.get("visibility", "painter", "painter-split", scene, "splits") > 0
    text = section_visibility(view)
    assert text.count("\n| ") == len(scenes) + 1  # header and one row per scene


def test_the_z_buffer_is_the_reference():
    # disagree is measured against the z-buffer: recount it here from its picture.
    scene = visibility_scenes(np.random.default_rng(3), 1)["random 1 (6 triangles)"]
    trace = registry.get("painter-split").record(scene["points"], scene["options"], scene["grid"])
    zb = registry.get("zbuffer").record(scene["points"], {**scene["options"],
                                                          "clear_depth": 1e9}, scene["grid"])
    # The last colour written to each pixel is the one on show (dict keeps the last).
    mine = dict(zip(map(tuple, trace.written_pixels().tolist()), trace.pixel_values()))
    theirs = dict(zip(map(tuple, zb.written_pixels().tolist()), zb.pixel_values()))
    differ = sum(mine.get(p) != c for p, c in theirs.items()) + \
        sum(p not in theirs for p in mine)
    assert trace.final_variables()["disagree"] == differ
