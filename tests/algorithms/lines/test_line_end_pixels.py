"""Which line algorithms plot both end pixels, and how the printed Bresenham
listing sits against the corrected one.

Every line algorithm that is not a listing shown as printed plots P and Q;
each printed variant that can miss one is named with a segment where it
does. The as-printed Bresenham is ported line by line from the slide
(002's draw_line, with y = y1 for its y0) and held to a closed form in
Fractions: the corrected line for the ideal line lifted by 1 - 3m/2 rows.
"""
from __future__ import annotations

import math
import random
from fractions import Fraction

import pytest

from algorithms.core import registry
from tests.support.bresenham import printed_draw_line

GRID = (32, 24)
# The listings shown as printed, faults included: each may miss an end pixel.
PRINTED = {("line-explicit-printed", None), ("line-dda-printed", "truncate"),
           ("line-dda-printed", "x-only"), ("line-dda-printed", "add-first"),
           ("line-dda-printed", "x-truncate"), ("line-bresenham-textbook", "as-printed"),
           ("line-parametric-printed", None)}


def pixels(name, p, q, options=None):
    trace = registry.get(name).record((p, q), options or {}, grid=GRID)
    return {tuple(c) for c in trace.written_pixels().tolist()}


def runs():
    """(name, options) for every pixel-centre line algorithm and variant."""
    for spec in registry.all_specs():
        if spec.family != "lines" or not spec.inputs.integer:
            continue
        variant = next((o for o in spec.options if o.name == "variant"), None)
        for choice in (variant.choices if variant else (None,)):
            yield spec.name, choice, ({"variant": choice} if choice else {})


def random_segments(count, seed):
    rng = random.Random(seed)
    return [((rng.randint(0, 31), rng.randint(0, 23)), (rng.randint(0, 31), rng.randint(0, 23)))
            for _ in range(count)]


SEGMENTS = random_segments(120, 2) + [((5, 5), (5, 5)), ((3, 9), (3, 1)), ((20, 4), (2, 4)),
                                       ((0, 0), (23, 23)), ((30, 0), (0, 23))]


@pytest.mark.parametrize("name, variant, options",
                         [run for run in runs() if run[:2] not in PRINTED])
def test_every_line_algorithm_but_the_printed_listings_plots_both_end_pixels(name, variant,
                                                                              options):
    for p, q in SEGMENTS:
        drawn = pixels(name, p, q, options)
        assert p in drawn and q in drawn, f"{name} {options} {p}->{q}"


def test_the_printed_listings_are_all_still_registered():
    assert PRINTED <= {run[:2] for run in runs()}


# A segment where each printed listing misses an end pixel, and which.
MISSES = [
    ("line-explicit-printed", {}, (2, 4), (28, 15), "Q"),  # its loops stop before Q
    ("line-dda-printed", {"variant": "truncate"}, (13, 19), (24, 0), "Q"),  # x sums to 23.99...
    ("line-dda-printed", {"variant": "x-only"}, (0, 0), (0, 20), "Q"),  # one column, one pixel
    ("line-dda-printed", {"variant": "add-first"}, (0, 0), (10, 7), "PQ"),  # (0, 1) .. (10, 8)
    ("line-dda-printed", {"variant": "x-truncate"}, (8, 3), (15, 14), "Q"),  # steep: x steps
    ("line-bresenham-textbook", {"variant": "as-printed"}, (1, 2), (29, 8), "Q"),  # m <= 1/3
    ("line-parametric-printed", {"dt": 0.01}, (2, 3), (60, 20), "Q"),  # last t is 0.99
]


@pytest.mark.parametrize("name, options, p, q, missed", MISSES)
def test_each_printed_listing_misses_an_end_pixel_on_a_named_segment(name, options, p, q,
                                                                     missed):
    drawn = pixels(name, p, q, options)
    assert (p not in drawn) == ("P" in missed)
    assert (q not in drawn) == ("Q" in missed)


def test_every_printed_listing_has_a_named_miss():
    named = {(name, options.get("variant")) for name, options, *_ in MISSES}
    assert named == PRINTED


# ------------------------------------------- the printed Bresenham, lifted
def nearest_row(m, u, lift=Fraction(0)):
    """The row nearest the line v = m u + lift, halves up (the corrected listing's rule)."""
    return math.floor(m * u + lift + Fraction(1, 2))


def first_octant(dx, dy):
    return [(u, 0 if u == 0 else nearest_row(Fraction(dy, dx), u, 1 - Fraction(3 * dy, 2 * dx)))
            for u in range(dx + 1)]


@pytest.mark.parametrize("dx", range(1, 41))
def test_the_printed_listing_is_the_corrected_rule_on_a_line_lifted_by_1_minus_3m_over_2(dx):
    for dy in range(dx + 1):
        assert printed_draw_line(0, 0, dx, dy) == first_octant(dx, dy), (dx, dy)


def test_the_program_draws_the_listing_as_printed():
    rng = random.Random(7)
    for _ in range(150):
        x1, y1 = rng.randint(0, 10), rng.randint(0, 10)
        dx = rng.randint(0, 21)
        dy = rng.randint(0, dx)
        drawn = pixels("line-bresenham-textbook", (x1, y1), (x1 + dx, y1 + dy),
                       {"variant": "as-printed"})
        assert drawn == set(printed_draw_line(x1, y1, x1 + dx, y1 + dy))


def compare_with_corrected(dx, dy):
    printed = printed_draw_line(0, 0, dx, dy)
    corrected = [(u, nearest_row(Fraction(dy, dx), u)) for u in range(dx + 1)]
    higher = sum(a[1] > b[1] for a, b in zip(printed, corrected))
    lower = sum(a[1] < b[1] for a, b in zip(printed, corrected))
    return higher, lower


def test_a_row_high_below_slope_2_3_equal_at_it_low_above():
    for dx in range(3, 40):
        for dy in range(dx + 1):
            higher, lower = compare_with_corrected(dx, dy)
            if 3 * dy < 2 * dx:
                assert lower == 0, (dx, dy)
            elif 3 * dy == 2 * dx:
                assert higher == lower == 0, (dx, dy)
            else:
                assert higher == 0, (dx, dy)
    # Never below the corrected line under 2/3, never above it over 2/3; how many
    # pixels differ depends on the slope: flat, every pixel after P is a row high.
    assert printed_draw_line(0, 0, 9, 0)[1:] == [(u, 1) for u in range(1, 10)]
    assert compare_with_corrected(28, 6) == (18, 0)
    assert compare_with_corrected(4, 2) == (0, 0)  # lifted by 1/4: no row changes
    assert compare_with_corrected(10, 9) == (0, 4)
    assert compare_with_corrected(10, 10) == (0, 0)  # half a row low: again no row changes


def test_the_printed_listing_plots_q_only_above_slope_1_3():
    for dx in range(1, 40):
        for dy in range(dx + 1):
            plotted = printed_draw_line(0, 0, dx, dy)[-1] == (dx, dy)
            assert plotted == (3 * dy > dx), (dx, dy)


def test_the_scene_of_the_printed_listing_says_what_it_shows():
    from app.model import shipped
    from app.model.scene import load
    scene = load(shipped.scene_path("line-bresenham-as-printed"))
    p, q = scene.points
    dx, dy = q[0] - p[0], q[1] - p[1]
    lift = 1 - Fraction(3 * dy, 2 * dx)
    assert f"{lift.numerator}/{lift.denominator} of a row" in scene.description
    assert 3 * dy <= dx and "Q is not drawn" in scene.description
    higher, lower = compare_with_corrected(dx, dy)
    assert f"{higher} of its {dx + 1} pixels" in scene.description and lower == 0
