"""Numerical stability: every registered algorithm over the hard-case catalogue.

The catalogue (tests/support/catalogue.py): the shipped scenes and families
of hard inputs chosen by what an algorithm takes: zero-length and
axis-aligned segments, exact ties, huge and tiny coordinates, radius 0 and
1, degenerate ellipses, collinear and repeated vertices, slivers and
near-degenerate triangles, vertices exactly on pixel centres and on scan
lines, shared edges, w near 0, every precision and fill rule.

Every run must either be refused with an InputError whose message is one
clear line, or finish and give:

* no infinite value in any frame, and no value that is NaN on one frame of
  a code line and a number on another frame of the same line (NaN marks a
  value a line does not set, so it must be NaN there always);
* final variables that are finite numbers;
* the same pixels from the fast kernel as from the generator, where the
  family promises it;
* the documented result where there is one, by the check the algorithm's
  oracle declares (AlgorithmSpec.oracle.check, a key of CHECKS): the exact
  oracles (algorithms/exact/, tests/support/, a breadth-first seed fill
  written here), or the documented bound (a nearest-pixel line lies within
  1/2 px of the ideal line; float precisions are exact below their
  documented coordinate sizes; a perspective-correct value lies between its
  vertex values).
"""
from __future__ import annotations

import functools
import math
from collections import Counter, deque

import numpy as np
import pytest

from algorithms.exact import (lines as exact, circles as exact_circles,
                              polygons as exact_polygons, triangles as exact_triangles)
from algorithms.core import registry
from algorithms.core.errors import InputError
from algorithms.fill.flood import NEIGHBOURS, outline_pixels
from tests.support import curve_oracles, triangle_variant_oracles
from tests.support.catalogue import CASES, GRID, TRIANGLES, Case



# ================================================================ checks
def check_refusal(case: Case, error: InputError) -> None:
    message = str(error)
    assert message.strip(), f"{case}: an empty message"
    assert "\n" not in message.strip(), f"{case}: a message of several lines: {message!r}"
    assert len(message) <= 300, f"{case}: a message of {len(message)} characters"
    assert "Traceback" not in message


def check_values(case: Case, trace) -> None:
    values = trace.values
    assert not np.isinf(values).any(), f"{case}: an infinite value in a frame"
    lean = np.ones(len(trace), bool)
    lean[trace.steps_of()] = False
    for line in np.unique(trace.line[lean]):
        rows = values[lean & (trace.line == line)]
        missing = np.isnan(rows)
        mixed = missing.any(axis=0) & ~missing.all(axis=0)
        names = [trace.value_names[k] for k in np.flatnonzero(mixed)]
        assert not names, (f"{case}: line {line} ({trace.code[line].text.strip()[:50]}) has "
                           f"NaN on some frames and numbers on others in {names}")
    for name, value in trace.final_variables().items():
        if isinstance(value, (int, float)) and not isinstance(value, bool):
            assert math.isfinite(value), f"{case}: final variable {name} = {value}"


PIXEL_FAMILIES = ("lines", "circles", "polygons", "triangles")


def check_kernel(case: Case, spec, trace) -> None:
    if spec.kernel is None:
        return
    options = spec.resolve(case.options)
    points = spec.inputs.check(case.points)
    try:
        pixels = (spec.kernel(points, options, case.grid) if spec.uses_grid
                  else spec.kernel(points, options))
    except InputError as error:
        # A kernel may refuse what the generator walks (the implicit form's box).
        check_refusal(case, error)
        return
    if spec.family not in PIXEL_FAMILIES:
        return
    kernel = Counter(map(tuple, np.asarray(pixels, np.int64).reshape(-1, 2).tolist()))
    generator = Counter(map(tuple, trace.written_pixels().tolist()))
    assert kernel == generator, f"{case}: kernel and generator differ"


# ----------------------------------------------------------- oracles
# Each algorithm declares the check it is held to here (AlgorithmSpec.oracle.check);
# CHECKS below maps those names to the functions.
def _written(trace) -> list[tuple[int, int]]:
    return [tuple(p) for p in trace.written_pixels().tolist()]


def _small(p, q) -> bool:
    """Near the origin and of moderate length: where the nearest-pixel line is checked."""
    return max(abs(c) for c in (*p, *q)) < 4096 and max(abs(q[0] - p[0]), abs(q[1] - p[1])) < 5000


def nearest_line(case: Case, pixels, columns_once: bool = True) -> None:
    """The documented result: one pixel per major-axis column, the nearest to
    the ideal line (either one where it passes exactly midway)."""
    p, q = case.points
    major_x = exact.x_is_major(p, q)
    columns = Counter(px if major_x else py for px, py in pixels)
    assert all(n == 1 for n in columns.values()) or not columns_once, \
        f"{case}: a column with two pixels"
    for px, py in pixels:
        a, b = (px, py) if major_x else (py, px)
        value = exact.line_value(p, q, a)
        allowed = {exact.nearest_minor(value, "down", 0), exact.nearest_minor(value, "up", 0)}
        assert b in allowed, f"{case}: pixel {(px, py)} is not a nearest pixel"
    length = max(abs(q[0] - p[0]), abs(q[1] - p[1]))
    assert len(set(pixels)) == length + 1, f"{case}: not one pixel per column"


def end_pixels(case: Case, pixels) -> None:
    p, q = case.points
    assert pixels[0] == tuple(p) and pixels[-1] == tuple(q), f"{case}: an end pixel is missing"


def check_nearest_line(case: Case, spec, trace) -> None:
    pixels = _written(trace)
    if _small(*case.points):
        nearest_line(case, pixels)
    end_pixels(case, pixels)


def check_dda_line(case: Case, spec, trace) -> None:
    """float64 gives the nearest pixels; float32 drifts, the point of the option.
    Both drift on long or far segments, so even their ends are checked on small ones only."""
    if not _small(*case.points):
        return
    pixels = _written(trace)
    if spec.resolve(case.options)["dtype"] == "float64":
        nearest_line(case, pixels)
    end_pixels(case, pixels)


def check_incremental_line(case: Case, spec, trace) -> None:
    """Rounding gives the nearest pixels; floor biases the line down."""
    pixels = _written(trace)
    if spec.resolve(case.options)["rounding"] == "round" and _small(*case.points):
        nearest_line(case, pixels)
    end_pixels(case, pixels)


def check_parametric_line(case: Case, spec, trace) -> None:
    """dt auto gives the nearest pixels (a point plots P at t = 0 and t = 1);
    a fixed dt leaves gaps or repeats."""
    pixels = _written(trace)
    if spec.resolve(case.options)["dt"] == "auto" and _small(*case.points):
        nearest_line(case, pixels, columns_once=False)
    end_pixels(case, pixels)


def check_textbook_line(case: Case, spec, trace) -> None:
    """Ties to NE and the sign-reversed D give the nearest pixels; the listing
    as printed has faults, missing an end pixel among them."""
    if spec.resolve(case.options)["variant"] == "as-printed":
        return
    check_nearest_line(case, spec, trace)


def check_implicit_line(case: Case, spec, trace) -> None:
    p, q = case.points
    assert set(_written(trace)) == exact.implicit_pixels(p, q), \
        f"{case}: unlike the exact implicit line"


def exact_circle(expected):
    """The check that the offsets from the centre are ``expected(radius)``."""
    def check(case: Case, spec, trace) -> None:
        (xc, yc), = case.points
        offsets = {(x - xc, y - yc) for x, y in _written(trace)}
        assert offsets == expected(spec.resolve(case.options)["radius"]), \
            f"{case}: unlike the exact circle"
    return check


def check_midpoint_ellipse(case: Case, spec, trace) -> None:
    (xc, yc), = case.points
    offsets = {(x - xc, y - yc) for x, y in _written(trace)}
    options = spec.resolve(case.options)
    rx, ry = options["rx"], options["ry"]
    if rx == 0 or ry == 0:
        expected = exact_circles.ellipse_segment(rx, ry)
    elif rx == ry:
        expected = exact_circles.midpoint_circle(rx)
    else:
        expected = exact_circles.four_way(offsets)  # symmetric, at least
    assert offsets == expected, f"{case}: unlike the oracle"


def covered_polygon(lift: float = 0.0):
    """The check against the exact polygon. Sampled at (i + 1/2, j + 1/2 - lift)
    instead of the centre, pixels follow the centre rule on the polygon lifted by ``lift``."""
    def check(case: Case, spec, trace) -> None:
        options = spec.resolve(case.options)
        pixels = _written(trace)
        if options.get("arithmetic", "exact") != "exact" or options.get("ties", "left-bottom") != \
                "left-bottom":
            return
        points = case.points
        if lift:
            points = [[(x, y + lift) for x, y in contour] for contour in points]
        expected = exact_polygons.covered_pixels(points, options.get("fill_rule", "evenodd"))
        assert len(pixels) == len(set(pixels)), f"{case}: a pixel filled twice"
        assert set(pixels) == expected, f"{case}: unlike the exact polygon"
    return check


def oracle_fill(case: Case, spec, trace) -> None:
    options = spec.resolve(case.options)
    width, height = case.grid
    if spec.inputs.contours:
        boundary = set(outline_pixels(case.points, four=options["outline"] == "4"))
    else:
        (cx, cy), = case.points
        boundary = {(cx + x, cy + y) for x, y in exact_circles.midpoint_circle(options["radius"])}
    boundary = {b for b in boundary if 0 <= b[0] < width and 0 <= b[1] < height}
    seed = trace.start.constants["seed"]
    # The seed's component among the pixels of its own kind: free, or outline.
    same = (lambda n: n in boundary) if tuple(seed) in boundary else (
        lambda n: n not in boundary)
    region, queue = ({tuple(seed)}, deque([tuple(seed)])) if seed != "none" else (set(), [])
    while queue:
        x, y = queue.popleft()
        for dx, dy in NEIGHBOURS[options["connectivity"]]:
            n = (x + dx, y + dy)
            if 0 <= n[0] < width and 0 <= n[1] < height and same(n) and n not in region:
                region.add(n)
                queue.append(n)
    filled = [p for p in _written(trace)]
    inside = [p for p in filled if 0 <= p[0] < width and 0 <= p[1] < height]
    drawn = Counter(inside)
    assert set(drawn) == region | boundary
    once_more = boundary & region  # outline pixels a region fill recolours
    assert all(drawn[p] == 1 + (p in once_more) for p in region | boundary), \
        f"{case}: a pixel filled twice"


@functools.lru_cache(maxsize=None)
def exact_coverage(points, bits, rule, grid, cull) -> dict:
    """The exact oracle's counts, shared by every traversal of the same case."""
    return exact_triangles.coverage(points, bits, rule, (0, 0, grid[0], grid[1]), cull)


def oracle_triangles(case: Case, spec, trace) -> None:
    options = spec.resolve(case.options)
    bits = options["subpixel_bits"]
    # Clipped at the near plane, the run draws other triangles than the input's
    # (tests/algorithms/triangles/test_triangles_offset_near.py checks them).
    clipped = options.get("near", 0) > 0
    # The offset moves the arithmetic (not the pixels) that far from the origin.
    largest = (max(abs(c) for point in case.points for c in point)
               + max(abs(v) for v in options.get("offset", (0, 0))))
    exact_run = (options["precision"] == "fixed"
                 or (options["precision"] == "float64" and largest < 2 ** 16)
                 or (options["precision"] == "float32" and largest < 8))
    if exact_run and largest < 1e7 and not clipped:
        expected = exact_coverage(tuple(case.points), bits, options["fill_rule"], case.grid,
                                  options["cull"])
        got = Counter(p for p in _written(trace))
        assert got == Counter(expected), f"{case}: unlike the exact coverage"
    final = trace.final_variables()
    if options["fill_rule"] == "top-left" and options["precision"] == "fixed":
        assert final["overlaps"] == 0 and final["cracks"] == 0, f"{case}: overlaps or cracks"
    if "alpha" in trace.value_names:
        plotted = trace.writes()
        total = (trace.series("alpha") + trace.series("beta") + trace.series("gamma"))[plotted]
        assert np.allclose(total, 1.0, atol=1e-6), f"{case}: weights do not sum to 1"


def oracle_perspective(case: Case, spec, trace) -> None:
    """The exact coverage, and each perspective-correct value between its vertex values."""
    oracle_triangles(case, spec, trace)
    s = spec.resolve(case.options)["s"]
    values = trace.series("s_persp")[trace.writes()]
    assert np.all(values >= min(s) - 1e-9) and np.all(values <= max(s) + 1e-9), \
        f"{case}: a perspective-correct value outside its vertex values"


def _pixels_check(check):
    """A check of tests/support, which takes the resolved options and the written pixels."""
    return lambda case, spec, trace: check(case, spec.resolve(case.options), trace,
                                           _written(trace))


# The checks by the name an algorithm's oracle declares (AlgorithmSpec.oracle.check).
CHECKS = {"nearest-line": check_nearest_line, "dda-line": check_dda_line,
          "incremental-line": check_incremental_line, "parametric-line": check_parametric_line,
          "textbook-line": check_textbook_line, "implicit-line": check_implicit_line,
          "sqrt4-circle": exact_circle(exact_circles.sqrt4_circle),
          "sqrt8-circle": exact_circle(exact_circles.sqrt8_circle),
          "midpoint-circle": exact_circle(exact_circles.midpoint_circle),
          "midpoint-ellipse": check_midpoint_ellipse,
          "covered-polygon": covered_polygon(), "covered-polygon-lifted": covered_polygon(0.5),
          "seed-fill": oracle_fill, "triangle-coverage": oracle_triangles,
          "perspective-coverage": oracle_perspective,
          **{name: _pixels_check(check) for name, check in {
              **curve_oracles.CHECKS, **triangle_variant_oracles.CHECKS}.items()}}


# ================================================================ the test
@pytest.mark.parametrize("case", CASES, ids=str)
def test_hard_case(case: Case):
    spec = registry.get(case.algorithm)
    try:
        trace = spec.record(case.points, case.options, case.grid)
    except InputError as error:
        check_refusal(case, error)
        assert case.valid is not True, f"{case}: refused a valid input: {error}"
        return
    assert case.valid is not False, f"{case}: ran an input it should refuse"
    assert not trace.truncated or len(trace) == trace.step_cap
    check_values(case, trace)
    check_kernel(case, spec, trace)
    if spec.oracle.check:
        CHECKS[spec.oracle.check](case, spec, trace)


def test_catalogue_covers_every_algorithm():
    named = {case.algorithm for case in CASES}
    assert named == {spec.name for spec in registry.all_specs()}
    assert any(case.name.startswith("scene ") for case in CASES)


# ============================================== fixes the catalogue led to
def test_whole_number_points_beyond_32_bit_frames_are_refused():
    spec = registry.get("line-bresenham")
    for points, words in ((((2 ** 40, 0), (2 ** 40 + 3, 1)), "beyond"),
                          (((10 ** 400, 0), (1, 1)), "not a finite number")):
        with pytest.raises(InputError, match=words) as refused:
            spec.record(points)
        check_refusal(Case("huge", spec.name, points), refused.value)
    # The largest accepted coordinate still records, pixels and all.
    edge = registry.MAX_INTEGER_COORDINATE
    trace = spec.record(((edge - 3, -edge), (edge, -edge + 2)))
    assert trace.written_pixels()[-1].tolist() == [edge, -edge + 2]


def test_a_parameter_plane_that_overflows_is_refused():
    spec = registry.get("triangle-plane")
    points = TRIANGLES["huge coordinates"]
    with pytest.raises(InputError, match="overflows"):
        spec.record(points, {"colors": (), "z": (0.0, 1e300, -1e300)}, GRID)
    # The same values on a triangle of ordinary size have a plane.
    trace = spec.record(TRIANGLES["plain"], {"colors": (), "z": (0.0, 1e300, -1e300)}, GRID)
    assert np.isfinite(trace.series("z")[trace.writes()]).all()
