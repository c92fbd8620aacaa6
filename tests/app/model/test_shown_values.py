"""Numbers people read: five significant figures and colours as #rrggbb,
in the tables, the steps table and the variables panel; --json keeps all."""
import json
import math
import subprocess
import sys

from algorithms.core import registry
from app.model import scene as scenes
from app.model import shipped
from app.model.exact import shown_rows
from app.model.notation import colour, colour_names
from app.model.steptable import StepTable, cell_to_json
from app.model.tables import TableIndex, cell_text
from tests.support import record

SCENE = "rendering/transparent-order"


def _blend_trace():
    scene = scenes.load(shipped.scene_path(SCENE))
    return registry.get(scene.algorithm), record(scene.algorithm, scene.points,
                                                  options=scene.options,
                                                  grid=(scene.width, scene.height))


def test_a_float_cell_reads_to_five_significant_figures():
    assert cell_text(0.1 + 0.1) == "0.2"
    assert cell_text(0.20000000000000004) == "0.2"
    assert cell_text(2 / 3) == "0.66667"
    assert cell_text(12.499999999) == "12.499999999"  # a near tie keeps its drift in sight


def test_colour_reads_packed_values_only():
    assert colour(40960) == "#00a000"
    assert colour(16744576.0) == "#ff8080"
    assert colour(float("nan")) is None and colour(0.5) is None and colour(2 ** 24) is None


def test_blend_declares_its_source_and_destination_as_colours():
    _spec, trace = _blend_trace()
    assert colour_names(trace.start) == {"src", "dst", "rgb"}


def test_blend_mean_depth_and_colours_read_short_in_the_panels():
    spec, trace = _blend_trace()
    (order,) = TableIndex(trace).at(2)
    assert [row[2] for row in order.rows] == ["0.2", "0.5", "0.8"]
    rows = dict(shown_rows(spec, trace, 3))
    assert (rows["src"], rows["dst"], rows["rgb"]) == ("#ff0000", "#ffffff", "#ff8080")


def test_blend_steps_text_is_short_and_json_keeps_every_digit():
    _spec, trace = _blend_trace()
    table = StepTable(trace)
    text = dict(zip(table.keys, table.text_row(3)))
    assert (text["mean z"], text["src"], text["dst"], text["rgb"]) == \
        ("0.2", "#ff0000", "#ffffff", "#ff8080")
    row = table.row(3)
    assert cell_to_json(row["mean z"]) == math.fsum([0.2] * 3) / 3 != 0.2  # every digit
    assert cell_to_json(row["src"]) == 0xFF0000


def test_run_json_keeps_full_precision():
    path = str(shipped.scene_path(SCENE))
    out = subprocess.run([sys.executable, "-m", "rasterlab", "run", "--scene", path, "--steps",
                          "--json"], capture_output=True, text=True, check=True).stdout
    assert "0.20000000000000004" in out
    assert json.loads(out)["algorithm"] == "blend-over"
