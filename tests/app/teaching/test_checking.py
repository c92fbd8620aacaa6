"""Checking a student's algorithm: the shipped sample files get the verdicts,
divergence steps and messages an independent oracle (exact rational
arithmetic, written here) says, within the limits."""
from __future__ import annotations

import textwrap
from fractions import Fraction

import pytest

from algorithms.core import registry
from app.teaching import checking
from app.teaching import student
from app.teaching.checking import Case, line_case
from tests.support import ROOT

SAMPLES = ROOT / "resources" / "students"
BRESENHAM = registry.get("line-bresenham")
LIMITS = student.Limits(seconds=1, memory=64 << 20)
# One segment of octant 1 with a tie, one steep, one vertical, one falling with a tie.
SEGMENTS = [((0, 0), (4, 2)), ((0, 0), (3, 7)), ((3, 1), (3, 8)), ((2, 1), (0, 0))]


def nearest_toward_p(p, q):
    """The textbook Bresenham pixels, P to Q: in each major column the pixel
    nearest the ideal line, a tie going to P's side; exact fractions."""
    (x0, y0), (x1, y1) = p, q
    steep = abs(y1 - y0) > abs(x1 - x0)
    a0, a1, b0, b1 = (y0, y1, x0, x1) if steep else (x0, x1, y0, y1)
    step = 1 if a1 >= a0 else -1
    pixels = []
    for a in range(a0, a1 + step, step):
        b = Fraction(b0) if a1 == a0 else b0 + Fraction((b1 - b0) * (a - a0), a1 - a0)
        low = b.numerator // b.denominator
        if b - low == Fraction(1, 2):
            chosen = low if b0 <= low else low + 1
        else:
            chosen = (b + Fraction(1, 2)).numerator // (b + Fraction(1, 2)).denominator
        pixels.append((chosen, a) if steep else (a, chosen))
    return pixels


def truncated(p, q):
    """What y = y0 + t*dy cut towards zero gives (the truncating sample's rule)."""
    (x0, y0), (x1, y1) = p, q
    dx, dy = x1 - x0, y1 - y0
    if abs(dx) >= abs(dy):
        step = 1 if dx >= 0 else -1
        return [(x, int(y0 + (Fraction(x - x0, dx) if dx else 0) * dy))
                for x in range(x0, x1 + step, step)]
    step = 1 if dy >= 0 else -1
    return [(int(x0 + Fraction(y - y0, dy) * dx), y) for y in range(y0, y1 + step, step)]


def check(name, segments=SEGMENTS, limits=LIMITS, against=BRESENHAM):
    path = name if not isinstance(name, str) else SAMPLES / name
    cases = [line_case(f"{p}->{q}", p, q) for p, q in segments]
    options = against.resolve({})
    return [checking.check_case(against, options, path, case, limits) for case in cases]


def write(tmp_path, body: str, name: str = "mine.py"):
    path = tmp_path / name
    path.write_text(textwrap.dedent(body))
    return path


def test_correct_bresenham_passes_with_its_decision_variable():
    results = check("bresenham_correct.py")
    assert [r.passed for r in results] == [True] * len(SEGMENTS)
    assert all(r.compared == ("d",) for r in results)
    assert [len(r.outcome.steps) for r in results] == [len(nearest_toward_p(p, q))
                                                        for p, q in SEGMENTS]


def test_off_by_one_misses_the_last_pixel():
    for (p, q), result in zip(SEGMENTS, check("off_by_one.py")):
        oracle = nearest_toward_p(p, q)
        assert not result.passed and result.outcome.ok
        assert result.reference.step == len(oracle) - 1
        assert result.reference.expected == f"pixel ({oracle[-1][0]}, {oracle[-1][1]})"
        assert result.reference.got == "the end"


def test_truncation_diverges_where_rounding_and_truncating_differ():
    for (p, q), result in zip(SEGMENTS, check("truncates.py")):
        oracle, cut = nearest_toward_p(p, q), truncated(p, q)
        first = next((n for n, (a, b) in enumerate(zip(oracle, cut)) if a != b), None)
        assert result.passed == (first is None)
        if first is not None:
            assert result.reference.step == first
            assert result.reference.got == f"pixel ({cut[first][0]}, {cut[first][1]})"


def test_an_exception_is_a_failure_with_the_students_traceback():
    vertical = check("raises.py", [((3, 1), (3, 8))])[0]
    assert vertical.outcome.kind == "exception" and not vertical.passed
    assert "ZeroDivisionError" in vertical.message()
    assert "raises.py" in vertical.outcome.error and "m = (y1 - y0) / (x1 - x0)" in vertical.outcome.error
    assert "student_child" not in vertical.outcome.error  # RasterLab's own frames are left out


@pytest.mark.parametrize("name, kind, words", [
    ("never_stops.py", "too-long", "does the loop end"),
    ("garbage.py", "shape", "step 0: yielded (0.0, 0.0)"),
    ("allocates.py", "memory", "memory limit"),
])
def test_bad_programs_fail_their_case_with_a_message(name, kind, words):
    result = check(name, [((0, 0), (4, 2))])[0]
    assert (result.outcome.kind, result.passed) == (kind, False)
    assert words in result.message()


def test_a_loop_that_never_yields_is_stopped_by_the_time_limit(tmp_path):
    path = write(tmp_path, """
        def draw(x0, y0, x1, y1):
            while True:
                pass
            yield x0, y0
    """)
    result = check(path, [((0, 0), (4, 2))], student.Limits(seconds=0.2, memory=64 << 20))[0]
    assert result.outcome.kind == "time" and not result.passed


def test_a_crash_is_a_failure_with_its_status(tmp_path):
    crash = write(tmp_path, """
        import os
        def draw(x0, y0, x1, y1):
            print("debugging output")
            yield x0, y0
            os._exit(3)
    """)
    result = check(crash, [((0, 0), (4, 2))])[0]
    assert result.outcome.kind == "crash" and "status 3" in result.message()


def test_a_variable_with_the_references_name_is_compared(tmp_path):
    # d after its update instead of the d that decided the pixel.
    path = write(tmp_path, """
        def draw(x0, y0, x1, y1):
            dx, dy = x1 - x0, y1 - y0
            d = 2 * dy - dx
            x, y = x0, y0
            yield x, y, {"d": d}
            while x < x1:
                if d <= 0:
                    d += 2 * dy
                else:
                    d += 2 * (dy - dx)
                    y += 1
                x += 1
                yield x, y, {"d": d, "mine": 1}
    """)
    result = check(path, [((0, 0), (7, 3))])[0]
    # The textbook's d sequence for (7, 3): -1, then -1 (it chose pixel 1), 5, ...
    assert result.compared == ("d",)
    assert (result.reference.step, result.reference.expected, result.reference.got) == \
        (1, "d = -1", "d = 5")


def test_prints_do_not_disturb_the_result(tmp_path):
    path = write(tmp_path, """
        def draw(x0, y0, x1, y1):
            print("[1, 2]")
            yield x0, y0
    """)
    result = check(path, [((4, 4), (4, 4))])[0]
    assert result.passed and "[1, 2]" in result.outcome.output


def midpoint_student(tmp_path, skip_octant=False):
    return write(tmp_path, name=f"circle_{skip_octant}.py", body=f"""
        def draw(xc, yc, r):
            seen = set()
            x, y, d = 0, r, 1 - r
            while x <= y:
                for px, py in ((x, y), (y, x), (y, -x), (x, -y), (-x, -y), (-y, -x), (-y, x), (-x, y)):
                    if {skip_octant} and (px, py) == (-x, y) and x > 0:
                        continue
                    if (px, py) not in seen:
                        seen.add((px, py))
                        yield xc + px, yc + py
                if d < 0:
                    d += 2 * x + 3
                else:
                    d += 2 * (x - y) + 5
                    y -= 1
                x += 1
    """)


def test_a_circle_compares_its_pixels_in_any_order(tmp_path):
    spec = registry.get("circle-midpoint")
    cases = [Case(f"r={r}", ((16, 16),), {"radius": r}, (16, 16, r)) for r in (1, 5, 8)]
    good = midpoint_student(tmp_path)
    for case in cases:
        result = checking.check_case(spec, spec.resolve({}), good, case, LIMITS)
        assert result.passed and result.has_exact, result.message()
    skips = midpoint_student(tmp_path, skip_octant=True)
    result = checking.check_case(spec, spec.resolve({}), skips, cases[1], LIMITS)
    assert not result.passed and result.reference.got == "the end"


def test_the_students_file_never_runs_in_this_process(tmp_path):
    import os
    import sys
    path = write(tmp_path, """
        import os
        os.environ["RASTERLAB_STUDENT_WAS_HERE"] = "1"
        def draw(x0, y0, x1, y1):
            yield x0, y0
    """, name="side_effects.py")
    result = check(path, [((4, 4), (4, 4))])[0]
    assert result.passed
    assert "RASTERLAB_STUDENT_WAS_HERE" not in os.environ
    assert not any(getattr(m, "__file__", None) == str(path) for m in list(sys.modules.values()))


STUDENTS = ROOT / "tests" / "support" / "students"


def test_triangles_and_polygons_compare_as_collections_with_the_exact_fill():
    from algorithms.core.cases import POLYGON_CASES, TRIANGLE_CASES
    for against, student_file, made in (
            ("triangle-bbox", "triangle_exact.py",
             [checking.triangle_case(str(t), t) for t in TRIANGLE_CASES[2:5]]),
            ("polygon-scanline", "polygon_evenodd.py",
             [checking.polygon_case(str(c), c) for c in POLYGON_CASES[2:4]])):
        spec = registry.get(against)
        for case in made:
            result = checking.check_case(spec, spec.resolve({}), STUDENTS / student_file, case,
                                         LIMITS)
            assert result.passed and result.has_exact, result.message()


def test_an_inclusive_triangle_fills_its_top_edge_and_fails(tmp_path):
    from algorithms.core.cases import TRIANGLE_CASES
    source = (STUDENTS / "triangle_exact.py").read_text()
    inclusive = write(tmp_path, source.replace("if e < 0 or (e == 0 and not (dy < 0 or (dy == 0 and dx > 0))):",
                                               "if e < 0:"), name="inclusive.py")
    spec = registry.get("triangle-bbox")
    top_edge = TRIANGLE_CASES[3]  # its top edge runs through the centres of row 7
    result = checking.check_case(spec, spec.resolve({}), inclusive,
                                 checking.triangle_case("top", top_edge), LIMITS)
    # Centres exactly on the top edge, and the bottom vertex's (on two right
    # edges), are filled only by the inclusive rule.
    on_edges = {f"pixel ({x}, 7)" for x in range(1, 10)} | {"pixel (5, 1)"}
    assert not result.passed and result.reference.got in on_edges
