"""Checking a student's flood fill, z-buffer and antialiased line: the shipped
samples get the verdicts and divergence steps that oracles written here
(scikit-image's flood fill, exact fractions) say; intensities count within
the documented tolerance."""
from __future__ import annotations

import textwrap
from fractions import Fraction

import numpy as np
import pytest
from skimage.segmentation import flood

from algorithms.core import registry
from app.teaching import check_families
from app.teaching import checking
from app.teaching import student
from tests.support import ROOT

SAMPLES = ROOT / "resources" / "students"
LIMITS = student.Limits(seconds=2, memory=128 << 20)


def case_named(spec, prefix):
    return next(c for c in checking.make_cases(spec, [("hard", None)]) if c.name.startswith(prefix))


# ----------------------------------------------------------------- fill
def outline_grid(contours, size=64):
    """The outline's pixels on a boolean grid: per edge, one pixel per step of
    the longer axis, the other coordinate the exact nearest (halves up)."""
    grid = np.zeros((size, size), bool)
    for contour in contours:
        for k, (x0, y0) in enumerate(contour):
            x1, y1 = contour[(k + 1) % len(contour)]
            n = max(abs(x1 - x0), abs(y1 - y0), 1)
            for i in range(n + 1):
                x = x0 + Fraction(i * (x1 - x0), n) + Fraction(1, 2)
                y = y0 + Fraction(i * (y1 - y0), n) + Fraction(1, 2)
                grid[y.__floor__(), x.__floor__()] = True
    return grid


def region_oracle(contours, seed) -> set:
    """scikit-image's 4-connected flood of the free pixels from the seed."""
    free = ~outline_grid(contours)
    mask = flood(free.astype(np.uint8), (seed[1], seed[0]), connectivity=1) & free
    return {(int(x), int(y)) for y, x in zip(*mask.nonzero())}


FLOOD = registry.get("flood-fill")


@pytest.mark.parametrize("prefix", ["hard 2:", "hard 4:"])
def test_a_correct_fill_fills_the_oracles_region_and_passes(prefix):
    case = case_named(FLOOD, prefix)
    contours, seed = case.args
    result = checking.check(SAMPLES / "fill_correct.py", "flood-fill", [case], limits=LIMITS)[0]
    got = {(x, y) for x, y, _ in result.outcome.steps}
    assert got == region_oracle(contours, seed)
    assert len(result.outcome.steps) == len(got)
    assert result.passed and result.has_exact


def test_a_fill_with_a_truncated_outline_fails_at_its_first_pixel_outside():
    case = case_named(FLOOD, "hard 2:")
    result = checking.check(SAMPLES / "fill_truncates.py", "flood-fill", [case], limits=LIMITS)[0]
    region = region_oracle(*case.args)
    pixels = [(x, y) for x, y, _ in result.outcome.steps]
    first_outside = next(n for n, p in enumerate(pixels) if p not in region)
    assert not result.passed
    assert result.reference.step == result.exact.step == first_outside
    assert result.reference.got == "pixel ({}, {})".format(*pixels[first_outside])


# ----------------------------------------------------------- visibility
def covers(tri, i, j) -> bool:
    """Pixel centre strictly inside, or on a left or bottom horizontal edge (y up)."""
    p = (Fraction(2 * i + 1, 2), Fraction(2 * j + 1, 2))
    area = cross(tri[0], tri[1], tri[2])
    if area == 0:
        return False
    if area < 0:
        tri = [tri[0], tri[2], tri[1]]
    for a, b in zip(tri, tri[1:] + tri[:1]):
        side = cross(a, b, p)
        if side < 0 or side == 0 and not (b[1] < a[1] or b[1] == a[1] and b[0] > a[0]):
            return False
    return True


def cross(a, b, p):
    return (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0])


def fragments(tri):
    """The pixels a triangle covers, row by row from the bottom, as the sample scans."""
    tri = [(Fraction(x), Fraction(y)) for x, y, _ in tri]
    return [(i, j) for j in range(32) for i in range(32) if covers(tri, i, j)]


def test_a_correct_z_buffer_passes_and_a_missing_depth_test_fails_where_the_far_one_overdraws():
    spec = registry.get("zbuffer")
    case = case_named(spec, "hard 1:")  # the near triangle first, a far one over it
    near, far = case.args[0]
    right, wrong = (checking.check(SAMPLES / name, "zbuffer", [case], limits=LIMITS)[0]
                    for name in ("zbuffer_correct.py", "zbuffer_no_test.py"))
    assert right.passed and right.has_exact
    first, second = fragments(near), fragments(far)
    assert [(x, y) for x, y, _ in right.outcome.steps] == first + [
        p for p in second if p not in set(first)]
    overdrawn = next(n for n, p in enumerate(second) if p in set(first))
    assert not wrong.passed
    assert wrong.reference.step == wrong.exact.step == len(first) + overdrawn


def test_a_yielded_depth_that_is_wrong_fails(tmp_path):
    spec = registry.get("zbuffer")
    case = case_named(spec, "hard 4:")  # two triangles at depth 1/2
    source = (SAMPLES / "zbuffer_correct.py").read_text()
    path = tmp_path / "shifted.py"
    path.write_text(source.replace('{"z": float(z)}', '{"z": float(z) + 0.001}'))
    result = checking.check(path, "zbuffer", [case], limits=LIMITS)[0]
    assert not result.passed
    assert result.reference.step == 0 and result.reference.expected.startswith("z = 0.5 ")


# ----------------------------------------------------------- antialias
def wu_oracle(p, q) -> dict:
    """Per pixel, the share of the ideal line's column: 1 - f below it, f above."""
    (x0, y0), (x1, y1) = p, q
    image = {}
    for x in range(x0, x1 + 1):
        y = y0 + Fraction((y1 - y0) * (x - x0), x1 - x0)
        low = y.__floor__()
        for pixel, share in (((x, low), 1 - (y - low)), ((x, low + 1), y - low)):
            if share:
                image[pixel] = share
    return image


def student_file(tmp_path, error) -> object:
    """A student who draws the oracle's intensities, each off by ``error``."""
    path = tmp_path / f"off_{error}.py"
    path.write_text(textwrap.dedent(f"""\
        def draw(x0, y0, x1, y1):
            for x in range(x0, x1 + 1):
                y = y0 + (y1 - y0) * (x - x0) / (x1 - x0)
                low = int(y // 1)
                for yy, share in ((low, 1 - (y - low)), (low + 1, y - low)):
                    if share:
                        yield x, yy, share + {error!r}
        """))
    return path


@pytest.mark.parametrize("error, passes", [(0.0, True), (check_families.TOLERANCE / 2, True),
                                           (check_families.TOLERANCE * 2, False)])
def test_intensities_count_within_the_tolerance(tmp_path, error, passes):
    p, q = (0, 0), (7, 3)
    case = checking.line_case("shallow", p, q)
    result = checking.check(student_file(tmp_path, error), "line-wu", [case], limits=LIMITS)[0]
    got = {(x, y): v["intensity"] for x, y, v in result.outcome.steps}
    assert got.keys() == wu_oracle(p, q).keys()
    assert result.passed is passes
    assert (result.exact is None) is passes


def test_swapped_intensities_fail_at_the_first_pixel_and_the_correct_sample_passes():
    case = checking.line_case("shallow", (0, 0), (7, 3))
    right, wrong = (checking.check(SAMPLES / name, "line-wu", [case], limits=LIMITS)[0]
                    for name in ("wu_correct.py", "wu_swapped.py"))
    assert right.passed
    oracle = wu_oracle((0, 0), (7, 3))
    assert {(x, y): Fraction(v["intensity"]).limit_denominator(7)
            for x, y, v in right.outcome.steps} == oracle
    x, y, values = wrong.outcome.steps[0]
    assert not wrong.passed and wrong.reference.step == 0
    assert values["intensity"] != float(oracle.get((x, y), 0))


def test_the_line_area_reference_and_its_exact_coverage_judge_alike():
    case = checking.line_case("steep", (1, 1), (3, 8))
    result = checking.check(SAMPLES / "wu_correct.py", "line-area", [case], limits=LIMITS)[0]
    assert not result.passed and result.has_exact
    assert result.reference.step == result.exact.step


# ---------------------------------------------------------------- shape
def test_a_third_item_that_is_not_a_number_is_a_shape_failure(tmp_path):
    path = tmp_path / "words.py"
    path.write_text("def draw(x0, y0, x1, y1):\n    yield x0, y0, 'dark'\n")
    case = checking.line_case("one", (0, 0), (3, 1))
    result = checking.check(path, "line-wu", [case], limits=LIMITS)[0]
    assert result.outcome.kind == "shape" and "'dark'" in result.message()


@pytest.mark.parametrize("name", ["aa-supersample", "painter-split", "flood-fill-circle"])
def test_other_algorithms_of_these_families_are_refused(name):
    with pytest.raises(checking.InputError, match="check compares"):
        checking.kind_of(registry.get(name))


def test_a_fill_that_leaks_through_the_diagonal_outline_is_cut_off(tmp_path):
    """Eight neighbours slip between the outline's diagonal steps: the fill
    never ends, and the case fails once it yields far more than the reference."""
    source = (SAMPLES / "fill_correct.py").read_text()
    path = tmp_path / "leaks.py"
    path.write_text(source.replace(
        "stack += [(x + 1, y), (x - 1, y), (x, y + 1), (x, y - 1)]",
        "stack += [(x + a, y + b) for a in (-1, 0, 1) for b in (-1, 0, 1) if a or b]"))
    case = case_named(FLOOD, "hard 2:")
    result = checking.check(path, "flood-fill", [case], limits=LIMITS)[0]
    region = region_oracle(*case.args)
    assert result.outcome.kind == "too-long" and not result.passed
    assert len(result.outcome.steps) == 4 * len(region) + 1000
    assert "does the loop end" in result.message()
