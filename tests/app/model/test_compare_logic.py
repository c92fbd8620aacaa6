"""Compare mode's logic (app/model/compare.py), held to independent oracles."""
from fractions import Fraction

import numpy as np
import pytest

from algorithms.exact import triangles as exact_triangles
from algorithms.core.errors import InputError
from algorithms.core.raster import Raster
from app.model import compare, geometry
from app.render import compose as render
from app.model.compare import EXACT, FRAME, PROGRESS, Pane
from app.model.scene import Scene
from tests.support import ROOT
from tests.support.bresenham import bresenham_pixels
from tests.support.compare_oracles import (FLOAT32_BITS, FLOAT64_BITS, dda_pixels, diff_counts,
                                           round_to_float)

DEMO = ((4, 5), (28, 15))
LONG = ((0, 0), (4095, 192))


def _final_diff(preset_key, a=0, b=1, primitives=None):
    item = compare.preset(preset_key)
    runs = compare.run_panes(item.panes, primitives or item.primitives())
    assert all(run.ok for run in runs), [run.error for run in runs]
    return compare.diff_runs(runs[a], runs[b], runs[a].last, runs[b].last), runs


# ------------------------------------------------------------ the oracle
def test_float_rounding_oracle_matches_the_hardware_on_simple_cases():
    # 1/3 and 0.1 rounded to float32 and float64: numpy agrees bit for bit.
    for value in (Fraction(1, 3), Fraction(1, 10), Fraction(192, 4095)):
        assert round_to_float(value, FLOAT64_BITS) == Fraction(float(value))
        assert round_to_float(value, FLOAT32_BITS) == Fraction(float(np.float32(float(value))))
    # A tie rounds to even: 1 + 2^-24 lies half-way between float32 neighbours.
    assert round_to_float(1 + Fraction(1, 2 ** 24), FLOAT32_BITS) == 1


# ------------------------------------------------------------ the diffs
def test_dda_vs_bresenham_on_the_demo_line_counts_agree_with_the_oracle():
    d, runs = _final_diff("dda-bresenham")
    assert runs[0].points == list(DEMO)
    expected = diff_counts(dda_pixels(*DEMO, FLOAT64_BITS), bresenham_pixels(*DEMO), 32, 24)
    assert d.counts == expected
    # Slope 5/12 has ties: the two really differ there.
    assert expected["only A"] > 0 and expected["only B"] > 0
    assert d.kind == "write count"


def test_dda_float32_vs_float64_on_a_long_line_counts_agree_with_the_oracle():
    d, runs = _final_diff("dda-precision")
    assert runs[0].points == list(LONG) and runs[0].grid == (4096, 200)
    single, double = dda_pixels(*LONG, FLOAT32_BITS), dda_pixels(*LONG, FLOAT64_BITS)
    expected = diff_counts(single, double, 4096, 200)
    assert d.counts == expected
    assert expected["only A"] == expected["only B"] == 16  # the shipped scene's claim
    # The cells that differ are exactly the columns where the two oracles part.
    parted = {x for (x, y), (_, y2) in zip(single, double) if y != y2}
    assert set(d.cells()[:, 0].tolist()) == parted


def test_fill_rules_on_a_mesh_counts_agree_with_the_exact_triangle_oracle():
    d, runs = _final_diff("fill-rule")
    points = runs[0].points
    window = (0, 0, 32, 24)
    top_left = exact_triangles.coverage(points, 8, "top-left", window)
    inclusive = exact_triangles.coverage(points, 8, "inclusive", window)
    both = set(top_left) & set(inclusive)
    assert d.counts == {"only A": len(set(top_left) - set(inclusive)),
                        "only B": len(set(inclusive) - set(top_left)),
                        "both": len(both),
                        "both, different value": sum(top_left[c] != inclusive[c] for c in both)}
    # The top-left rule covers each cell of the mesh once; the inclusive rule
    # covers shared-edge cells twice or more.
    assert set(top_left.values()) == {1} and d.counts["both, different value"] > 0


def test_painter_vs_zbuffer_counts_cells_of_a_different_colour():
    d, runs = _final_diff("painter-zbuffer")
    painter, zbuffer = (run.trace for run in runs)

    def last_colour(trace):
        colours = {}
        for pixel, value in zip(map(tuple, trace.written_pixels().tolist()),
                                trace.pixel_values()):
            colours[pixel] = int(value)
        return colours
    a, b = last_colour(painter), last_colour(zbuffer)
    both = set(a) & set(b)
    assert d.counts["both"] == len(both)
    assert d.counts["only A"] == len(set(a) - set(b)) and d.counts["only B"] == len(set(b) - set(a))
    assert d.counts["both, different value"] == sum(a[c] != b[c] for c in both) > 0
    assert d.kind == "colour"


def test_supersampling_against_the_exact_coverage_pane():
    d, runs = _final_diff("supersample", 1, 2)
    estimate, exact = runs[1].trace, runs[2].exact
    coverage = {}
    for pixel, value in zip(map(tuple, estimate.written_pixels().tolist()),
                            estimate.pixel_values()):
        coverage[pixel] = float(value)
    covered = {(int(x), int(y)) for y, x in np.argwhere(exact > 0)}
    both = set(coverage) & covered
    assert d.counts["only A"] == len(set(coverage) - covered)
    assert d.counts["only B"] == len(covered - set(coverage))
    assert d.counts["both, different value"] == sum(
        abs(coverage[(x, y)] - exact[y, x]) > compare.COVERAGE_TOLERANCE for x, y in both)
    assert d.kind == "coverage"
    # The exact pane's raster shows the coverage as grey over white.
    raster = runs[2].raster_at(0)
    x, y = next(iter(both))
    grey = round(255 * (1 - exact[y, x]))
    assert raster.colors[y, x] == (grey << 16) | (grey << 8) | grey


def test_diff_of_hand_made_rasters_and_the_main_window_overlay():
    a, b = Raster(4, 1, with_colors=True), Raster(4, 1, with_colors=True)
    for x, colour in ((0, 0xFF0000), (1, 0x00FF00), (2, 0x0000FF)):
        a.write(x, 0, colour)
    for x, colour in ((1, 0x00FF00), (2, 0x123456), (3, 0xFF0000)):
        b.write(x, 0, colour)
    d = compare.diff(a, b, a.colors, b.colors, "colour", "colour")
    assert d.counts == {"only A": 1, "only B": 1, "both": 2, "both, different value": 1}
    assert d.classes().tolist() == [[1, 3, 4, 2]]
    # The cells that differ are those the main window's comparison outlines.
    assert sorted(map(tuple, d.cells().tolist())) == \
        sorted(map(tuple, geometry.differences(a, b).tolist()))
    # Different kinds of value: only presence is compared.
    assert compare.diff(a, b, a.colors, b.colors, "colour", "").counts["both, different value"] == 0


def test_diff_image_colours_each_class():
    a, b = Raster(3, 1), Raster(3, 1)
    a.write(0, 0)
    a.write(1, 0)
    b.write(1, 0)
    b.write(2, 0)
    image = render.diff_image(compare.diff(a, b))
    for x, colour in enumerate((compare.DIFF_COLOURS[0], compare.DIFF_COLOURS[2],
                                compare.DIFF_COLOURS[1])):
        value = int(colour[1:], 16)
        assert tuple(image[0, x, :3]) == ((value >> 16) & 255, (value >> 8) & 255, value & 255)


# ------------------------------------------------------------ stepping
def test_linked_stepping_by_progress_and_by_frame():
    lasts = [10, 40, 0, 7]
    for position in range(41):
        by_progress = compare.linked_indices(position, lasts, PROGRESS)
        expected = []
        for last in lasts:
            exact = Fraction(position * last, 40)
            expected.append(int(exact) + (1 if exact - int(exact) >= Fraction(1, 2) else 0))
        assert by_progress == expected
        assert compare.linked_indices(position, lasts, FRAME) == [min(position, n) for n in lasts]
    # Half-way lands half-way in every run, and the ends on the ends.
    assert compare.linked_indices(20, lasts, PROGRESS) == [5, 20, 0, 4]
    assert compare.linked_indices(40, lasts, PROGRESS) == lasts
    assert compare.linked_indices(99, lasts, FRAME) == lasts  # clamped
    with pytest.raises(ValueError):
        compare.linked_indices(0, lasts, "time")


def test_the_diff_follows_the_step_on_show():
    item = compare.preset("dda-bresenham")
    runs = compare.run_panes(item.panes, item.primitives())
    for k in (0, 3, 12, 20):
        # The pixels each run has plotted by step k, by a scan of its steps.
        plotted = [[run.trace.step(i).pixel for i in range(k + 1) if run.trace.step(i).writes]
                   for run in runs]
        assert compare.diff_runs(runs[0], runs[1], k, k).counts == \
            diff_counts(plotted[0], plotted[1], 32, 24)


# ------------------------------------------------------------ panes
def test_every_preset_runs_every_pane():
    for item in compare.PRESETS:
        runs = compare.run_panes(item.panes, item.primitives())
        assert all(run.ok and len(run) >= 1 for run in runs), (item.key, [r.error for r in runs])
        a, b = item.diff
        assert compare.diff_runs(runs[a], runs[b], runs[a].last, runs[b].last) is not None


def test_panes_that_do_not_take_the_primitives_say_why():
    line = Scene(algorithm="line-bresenham", points=DEMO)
    circle = compare.Run(Pane("circle-midpoint"), line)
    assert not circle.ok and "takes 1 point" in circle.error and "2 points" in circle.error
    assert circle.raster_at(0) is None and len(circle) == 0
    quad = Scene(algorithm="polygon-scanline",
                 points=[((2.0, 2.0), (20.0, 3.0), (22.0, 15.0), (3.0, 14.0))])
    triangles = compare.Run(Pane("triangle-bbox"), quad)
    assert not triangles.ok and "3k points" in triangles.error
    unknown = compare.Run(Pane("no-such-thing"), line)
    assert not unknown.ok and "unknown algorithm" in unknown.error


def test_points_fit_between_triangles_and_contours():
    bbox, scan = compare.spec_of("triangle-bbox"), compare.spec_of("polygon-scanline")
    six = [(1.0, 1.0), (9.0, 1.0), (5.0, 8.0), (9.0, 1.0), (14.0, 6.0), (5.0, 8.0)]
    assert compare.fit_points(bbox, six, (), scan) == [six[:3], six[3:]]
    assert compare.fit_points(scan, six, (3,), bbox) == six
    with pytest.raises(InputError):
        compare.fit_points(scan, six, (), bbox)  # one contour of six is no triangle list


def test_scene_options_carry_over_and_the_pane_options_win():
    scene = Scene(algorithm="circle-midpoint", points=((16, 12),), options={"radius": 7})
    assert compare.pane_options(Pane("circle-sqrt8"), scene)["radius"] == 7
    assert compare.pane_options(Pane.of("circle-sqrt8", radius=5), scene)["radius"] == 5
    exact = compare.Run(Pane(EXACT), Scene(algorithm="aa-supersample",
                                            points=((3.3, 2.6), (28.7, 8.2), (11.4, 21.1))))
    assert exact.ok and len(exact) == 1 and exact.value_kind == "coverage"


def test_options_typed_as_text():
    assert compare.parse_options("line-dda", " dtype=float32 ") == (("dtype", "float32"),)
    typed = compare.parse_options("triangle-bbox", "fill_rule=inclusive; colors=#ff0000,#00ff00,"
                                                   "#0000ff")
    assert dict(typed) == {"fill_rule": "inclusive",
                           "colors": ("#ff0000", "#00ff00", "#0000ff")}
    assert compare.parse_options("triangle-bbox", compare.format_options(typed)) == typed
    assert compare.parse_options("line-dda", "") == ()
    for bad in ("dtype=float16", "dtype", "width=3", "=1"):
        with pytest.raises(InputError):
            compare.parse_options("line-dda", bad)


def test_window_panes_compare_with_the_previous_algorithm():
    class FakePlayer:
        spec = compare.spec_of("line-dda")
        options = {"dtype": "float32", "colors": ()}
        previous = (compare.spec_of("line-bresenham"), {"symmetric": True, "colors": ()})
    panes = compare.window_panes(FakePlayer())
    assert panes == (Pane.of("line-dda", dtype="float32"),
                     Pane.of("line-bresenham", symmetric=True))
    FakePlayer.previous = None
    assert compare.window_panes(FakePlayer())[1].algorithm != "line-dda"
    # A previous algorithm of another family (a triangle before a seed
    # fill) is not the default: a neighbour of the same family is.
    FakePlayer.spec = compare.spec_of("flood-fill")
    FakePlayer.options = {}
    FakePlayer.previous = (compare.spec_of("triangle-bbox"), {})
    other = compare.window_panes(FakePlayer())[1].algorithm
    assert compare.spec_of(other).family == "fill" and other != "flood-fill"


def test_the_logic_needs_no_qt():
    import subprocess
    import sys
    code = ("import sys; import app.model.compare as c; c.run_panes(c.PRESETS[0].panes, "
            "c.PRESETS[0].primitives()); print(any(m.startswith(('PySide6', 'pyqtgraph')) "
            "for m in sys.modules))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         cwd=str(ROOT))
    assert out.returncode == 0, out.stderr
    assert out.stdout.strip() == "False"
