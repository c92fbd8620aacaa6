"""Each template's answers against an oracle written here in exact
arithmetic (the textbook loops and tables worked out again), over 200
seeds each; and the refusals of scenes a template cannot ask about."""
import math
import re
from fractions import Fraction

import numpy as np
import pytest

from app.model.scene import Scene
from app.teaching.questions import circles, fill, lines, registry
from app.teaching.questions.model import NUMERICAL, SHORT

SEEDS = range(200)


def number_in(text, pattern):
    return int(re.search(pattern, text).group(1))


def accepted(answer, text):
    return text == answer.text or text in answer.also


# ------------------------------------------------------------------ oracles
def bresenham_octant1(p, q):
    """[(pixel, choice, d after)] of steps 1 .. dx, the textbook loop (ties to E)."""
    (x, y), (x1, y1) = p, q
    dx, dy = x1 - x, y1 - y
    assert 0 < dy < dx
    d, steps = 2 * dy - dx, []
    for _ in range(dx):
        tested = d
        if d <= 0:
            x, d = x + 1, d + 2 * dy
            steps.append(((x, y), "E", d, tested))
        else:
            x, y, d = x + 1, y + 1, d + 2 * (dy - dx)
            steps.append(((x, y), "NE", d, tested))
    return steps


def dda_pixels(p, q, real):
    (x0, y0), (x1, y1) = p, q
    steps = max(abs(x1 - x0), abs(y1 - y0))
    x_inc, y_inc = real(x1 - x0) / real(steps), real(y1 - y0) / real(steps)
    x, y = real(x0), real(y0)
    pixels = [(x0, y0)]
    for _ in range(steps):
        x, y = real(x + x_inc), real(y + y_inc)
        pixels.append((math.floor(float(x) + 0.5), math.floor(float(y) + 0.5)))
    return pixels


def midpoint_octant(r, start):
    """[(x, y)] offsets of the second octant and [d after step k], k = 1 .. ."""
    x, y = 0, r
    d = 1 - r if start == "integer" else Fraction(5, 4) - r
    offsets, after = [(0, r)], []
    while y > x:
        if d < 0:
            d, x = d + 2 * x + 3, x + 1
        else:
            d, x, y = d + 2 * (x - y) + 5, x + 1, y - 1
        after.append(d)
        if x > y:
            break
        offsets.append((x, y))
    return offsets, after


def xlow_edges(points):
    """{label: (ymin, ymax, x at ymin, 1/m)} of the non-horizontal edges."""
    edges = {}
    for k, a in enumerate(points):
        b = points[(k + 1) % len(points)]
        if a[1] == b[1]:
            continue
        low, high = (a, b) if a[1] < b[1] else (b, a)
        edges[f"P{k + 1}P{(k + 1) % len(points) + 1}"] = (
            low[1], high[1], Fraction(low[0]), Fraction(high[0] - low[0], high[1] - low[1]))
    return edges


def aet(points, y):
    """[(ymax, x, 1/m)] active at scan line y, sorted on x (then 1/m)."""
    active = [(ymax, x + (y - ymin) * inv, inv)
              for ymin, ymax, x, inv in xlow_edges(points).values() if ymin <= y < ymax]
    return sorted(active, key=lambda e: (e[1], e[2]))


def fraction_text(v):
    v = Fraction(v)
    return str(v.numerator) if v.denominator == 1 else f"{v.numerator}/{v.denominator}"


def entry_text(entry):
    return "(" + ", ".join(fraction_text(v) for v in entry) + ")"


# -------------------------------------------------------------------- lines
@pytest.mark.parametrize("seed", SEEDS)
@pytest.mark.usefixtures("no_pictures")
def test_bresenham_templates(seed):
    q = lines.decision_after_step(seed)
    steps = bresenham_octant1(*q.scene.points)
    assert all(tested != 0 for *_, tested in steps)  # no tie in a drawn variant
    k = number_in(q.text, r"d after step (\d+)")
    assert 1 <= k < len(steps)
    assert q.answer.kind == NUMERICAL and q.answer.value == steps[k - 1][2]
    assert len(q.worked.rows) == k

    q = lines.pixel_at_step(seed)
    steps = bresenham_octant1(*q.scene.points)
    k = number_in(q.text, r"plotted at step (\d+)\?")
    x, y = steps[k - 1][0]
    assert q.answer.kind == SHORT and q.answer.text == f"({x}, {y})"
    assert accepted(q.answer, f"({x},{y})")
    (x0, y0), (x1, y1) = q.scene.points
    assert max(x0, x1) < 16 and max(y0, y1) < 12

    q = lines.steps_choosing_ne(seed)
    steps = bresenham_octant1(*q.scene.points)
    chosen = [str(k + 1) for k, step in enumerate(steps) if step[1] == "NE"]
    assert q.answer.text == (" ".join(chosen) or "none")
    assert accepted(q.answer, ",".join(chosen) or "none")


@pytest.mark.parametrize("seed", SEEDS)
@pytest.mark.usefixtures("no_pictures")
def test_dda_precision(seed):
    q = lines.dda_precision(seed)
    p, r = q.scene.points
    single, double = dda_pixels(p, r, np.float32), dda_pixels(p, r, np.float64)
    first = next(k for k, (a, b) in enumerate(zip(single, double)) if a != b)
    assert q.answer.kind == NUMERICAL and q.answer.value == first
    assert f"float32 plots ({single[first][0]}, {single[first][1]})" in q.worked.summary


# ------------------------------------------------------------------ circles
@pytest.mark.parametrize("seed", SEEDS)
@pytest.mark.usefixtures("no_pictures")
def test_circle_templates(seed):
    q = circles.second_octant(seed)
    (xc, yc), = q.scene.points
    offsets, _ = midpoint_octant(q.scene.options["radius"], q.scene.options["start"])
    expected = " ".join(f"({xc + x}, {yc + y})" for x, y in offsets)
    assert q.answer.text == expected
    assert all(0 <= yc + y < 12 and 0 <= xc + x < 16 for x, y in offsets)

    q = circles.decision_after_steps(seed)
    start = q.scene.options["start"]
    assert ("5/4 - R" if start == "fraction" else "1 - R") in q.text
    _, after = midpoint_octant(q.scene.options["radius"], start)
    k = number_in(q.text, r"d after (\d+) step")
    assert 1 <= k < len(after)
    assert q.answer.value == after[k - 1] and isinstance(q.answer.value, (int, Fraction))
    assert q.answer.text == fraction_text(after[k - 1])


@pytest.mark.usefixtures("no_pictures")
def test_both_circle_starts_are_drawn():
    starts = {circles.decision_after_steps(seed).scene.options["start"]
              for seed in range(40)}
    assert starts == {"integer", "fraction"}


# --------------------------------------------------------------------- fill
@pytest.mark.parametrize("seed", SEEDS)
@pytest.mark.usefixtures("no_pictures")
def test_fill_templates(seed):
    q = fill.aet_at(seed)
    points = q.scene.points[0]
    y = number_in(q.text, r"at scan line (\d+), sorted")
    entries = aet(points, y)
    assert q.answer.text == " ".join(entry_text(e) for e in entries)
    assert all((x - Fraction(1, 2)).denominator != 1 for _, x, _ in entries)  # no tie

    q = fill.span_at(seed)
    points = q.scene.points[0]
    y = number_in(q.text, r"filled on scan line (\d+)\?")
    entries = aet(points, y)
    runs = []
    for (_, left, _), (_, right, _) in zip(entries[::2], entries[1::2]):
        first, end = math.ceil(left - Fraction(1, 2)), math.ceil(right - Fraction(1, 2))
        if end > first:
            runs.append(f"{first}..{end - 1}")
    assert runs and q.answer.text == " ".join(runs)

    q = fill.edge_entry(seed)
    label = re.search(r"entry of edge (P\dP\d)\?", q.text).group(1)
    _, ymax, x, inv = xlow_edges(q.scene.points[0])[label]
    assert q.answer.text == entry_text((ymax, x, inv))
    assert accepted(q.answer, entry_text((ymax, x, inv)).replace(" ", ""))


# --------------------------------------------------------- given scenes
def test_a_given_scene_is_asked_about():
    scene = Scene(algorithm="line-bresenham", points=((1, 1), (9, 4)), width=16, height=12)
    q = lines.decision_after_step(3, scene)
    assert q.scene == scene and "P = (1, 1), Q = (9, 4)" in q.text
    k = number_in(q.text, r"d after step (\d+)")
    assert q.answer.value == bresenham_octant1((1, 1), (9, 4))[k - 1][2]


@pytest.mark.parametrize("name, scene, message", [
    ("line-bresenham-d", Scene(algorithm="line-dda", points=((1, 1), (9, 4))), "asks about"),
    ("line-bresenham-d", Scene(algorithm="line-bresenham", points=((1, 1), (2, 2))), "needs 2"),
    ("line-dda-precision", Scene(algorithm="line-dda", points=((1, 1), (9, 4))), "same pixels"),
    ("circle-midpoint-d", Scene(algorithm="circle-midpoint", points=((5, 5),),
                                options={"radius": 1}), "needs 2"),
    ("fill-aet", Scene(algorithm="polygon-scanline", points=(((1, 1), (9, 1), (5, 8)),),
                       options={"fill_rule": "nonzero"}), "even-odd"),
])
def test_a_scene_that_does_not_suit_is_refused(name, scene, message):
    with pytest.raises(ValueError, match=message) as error:
        registry.get(name).make(0, scene)
    assert "\n" not in str(error.value)


def test_the_registry():
    assert list(registry.TEMPLATES)[:3] == ["line-bresenham-d", "line-bresenham-pixel",
                                            "line-bresenham-ne"]
    assert {t.family for t in registry.TEMPLATES.values()} >= {"lines", "circles", "fill"}
    assert [t.name for t in registry.for_algorithm("circle-midpoint")] == [
        "circle-octant-pixels", "circle-midpoint-d"]
    with pytest.raises(ValueError, match="rasterlab questions --list"):
        registry.get("no-such-template")


def test_every_template_draws_a_picture_and_repeats_its_seed():
    for template in registry.TEMPLATES.values():
        q = template.make(11)
        assert q.picture.startswith(b"\x89PNG") and q.template == template.name
        assert template.make(11) == q
