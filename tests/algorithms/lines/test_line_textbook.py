"""The lecture's line listings as printed, against exact oracles written here.

Each printed variant must reproduce what its listing does (the listing is
transcribed literally below, in integers or Fractions), and its distance
from the exact nearest-pixel line is counted, not waved away.
"""
from __future__ import annotations

import math
from fractions import Fraction

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from algorithms.core import registry
from algorithms.exact import lines as exact
from tests.support.linecases import NAMED_CASES, segments
from tests.support.bresenham import printed_draw_line

SEGMENTS = [((0, 0), (8, 3)), ((0, 0), (6, 3)), ((2, 1), (14, 7)), ((20, 3), (4, 18)),
            ((5, 20), (1, 2)), ((-7, -3), (9, -11)), ((3, 3), (3, 3)), ((0, 5), (9, 5)),
            ((1, 1), (9, 9)), ((12, 0), (0, 12))]


def run(name, points, **options):
    trace = registry.get(name).record(points, options, grid=(40, 32))
    return trace, [tuple(p) for p in trace.written_pixels().tolist()]


def _minor_major(p, q, pixel):
    return (pixel[1], pixel[0]) if exact.x_is_major(p, q) else (pixel[0], pixel[1])


# ----------------------------------------------------------------- ties to NE
@pytest.mark.parametrize("p, q", SEGMENTS)
def test_ties_ne_is_the_nearest_pixel_line_with_ties_away_from_p(p, q):
    _, pixels = run("line-bresenham-textbook", (p, q), variant="ties-ne")
    assert len(pixels) == max(abs(q[0] - p[0]), abs(q[1] - p[1])) + 1
    toward = p[1] if exact.x_is_major(p, q) else p[0]
    for pixel in pixels:
        minor, major = _minor_major(p, q, pixel)
        value = exact.line_value(p, q, major)
        if exact.is_half(value):
            below = exact.floor_exact(value)
            nearer_p = below if toward <= below else below + 1
            assert minor != nearer_p, f"tie at {pixel} went toward P"
        else:
            assert minor == exact.round_half_up_exact(value)


def test_ties_ne_differs_from_ties_e_exactly_at_the_tie_columns():
    p, q = (0, 0), (28, 14)
    _, ne = run("line-bresenham-textbook", (p, q), variant="ties-ne")
    _, e = run("line-bresenham", (p, q))
    differing = {a[0] for a, b in zip(ne, e) if a != b}
    assert differing == {x for x in range(29) if exact.is_half(exact.y_at(p, q, x))}
    assert len(differing) == 14


@pytest.mark.parametrize("p, q", SEGMENTS)
def test_sign_reversed_is_minus_d_with_the_same_pixels(p, q):
    t_ne, ne = run("line-bresenham-textbook", (p, q), variant="ties-ne")
    t_sr, sr = run("line-bresenham-textbook", (p, q), variant="sign-reversed")
    assert ne == sr
    for i in range(len(t_ne)):
        d = t_ne.step(i).values.get("d")
        if d is not None and not math.isnan(d):
            assert t_sr.step(i).values["D"] == -d


@pytest.mark.parametrize("p, q", [((0, 0), (8, 3)), ((4, 2), (20, 9)), ((0, 0), (5, 5))])
def test_s_and_n_are_the_derivations_distances(p, q):
    trace, pixels = run("line-bresenham-textbook", (p, q), variant="ties-ne")
    steps = [trace.step(i) for i in range(len(trace)) if trace.step(i).branch]
    assert len(steps) == q[0] - p[0]
    previous = pixels[0]
    for step in steps:
        x = step.pixel[0]
        s = exact.y_at(p, q, x) - previous[1]  # line above the lower candidate
        n = previous[1] + 1 - exact.y_at(p, q, x)
        assert step.values["s"] == pytest.approx(float(s), abs=1e-12)
        assert step.values["n"] == pytest.approx(float(n), abs=1e-12)
        assert step.values["d"] == (q[0] - p[0]) * (s - n)  # d = dx (s - n), exactly
        previous = step.pixel


# ---------------------------------------------------------------- the kernel
# The kernel and the generator share one decision loop, so agreeing with the
# generator proves little: the kernel is held to the oracles themselves.
def kernel_pixels(p, q, variant):
    pixels = registry.get("line-bresenham-textbook").kernel((p, q), {"variant": variant})
    return [tuple(pixel) for pixel in pixels.tolist()]


@pytest.mark.parametrize("p, q", SEGMENTS)
def test_the_kernel_is_the_nearest_pixel_line_with_ties_away_from_p(p, q):
    minor = 1 if exact.x_is_major(p, q) else 0
    away = "up" if q[minor] >= p[minor] else "down"  # the tie's side nearer Q
    expected = exact.nearest_pixel_line(p, q, away)
    assert kernel_pixels(p, q, "ties-ne") == kernel_pixels(p, q, "sign-reversed") == expected


# ------------------------------------------------------- the printed listing


FIRST_OCTANT = [((0, 0), (8, 3)), ((0, 0), (10, 1)), ((3, 2), (17, 9)), ((0, 0), (7, 7)),
                ((1, 4), (30, 4))]


@pytest.mark.parametrize("p, q", FIRST_OCTANT)
def test_as_printed_reproduces_the_listing_and_counts_its_error(p, q):
    trace, pixels = run("line-bresenham-textbook", (p, q), variant="as-printed")
    assert pixels == printed_draw_line(*p, *q) == kernel_pixels(p, q, "as-printed")
    nearest = exact.nearest_pixel_line(p, q, "up")
    wrong = [a for a, b in zip(pixels, nearest) if a != b]
    if q[0] > p[0]:
        assert pixels[1][1] == p[1] + 1, "the printed start always steps up first"
    if q[1] - p[1] in (0, q[0] - p[0]):
        assert q[1] - p[1] > 0 or wrong, "a flat line climbs under the printed start"
    first = trace.start.constants["first_difference"]
    _, corrected = run("line-bresenham-textbook", (p, q), variant="sign-reversed")
    parted = next(((a, b) for a, b in zip(pixels, corrected) if a != b), None)
    assert first == ("none" if parted is None else f"{parted[0]} instead of {parted[1]}")
    assert (parted is None) == (not wrong)


def test_as_printed_error_on_a_shallow_line_is_counted():
    p, q = (0, 0), (10, 1)
    _, pixels = run("line-bresenham-textbook", (p, q), variant="as-printed")
    nearest = exact.nearest_pixel_line(p, q, "up")
    # By hand: D starts at -9, so x = 1 steps up; D then falls 9, 7, ..., -1
    # and x = 7 steps up again: x = 1..4 and 7..10 sit a row too high.
    wrong = [a[0] for a, b in zip(pixels, nearest) if a != b]
    assert wrong == [1, 2, 3, 4, 7, 8, 9, 10]
    assert pixels[-1] == (10, 2), "the printed line does not even end at Q"


# ------------------------------------------------------------ midpoint line
@pytest.mark.parametrize("p, q", SEGMENTS)
def test_midpoint_gives_bresenhams_pixels(p, q):
    _, mid = run("line-midpoint", (p, q))
    _, bres = run("line-bresenham", (p, q))
    assert mid == bres


@pytest.mark.parametrize("p, q", [((0, 0), (8, 3)), ((2, 5), (19, 12))])
def test_midpoint_d_is_twice_the_implicit_form_at_m(p, q):
    trace, _ = run("line-midpoint", (p, q))
    (x0, y0), (x1, y1) = p, q
    for i in range(len(trace)):
        step = trace.step(i)
        if not step.branch:
            continue
        mx, my = Fraction(step.values["Mx"]), Fraction(step.values["My"])
        f = (y1 - y0) * (mx - x0) - (x1 - x0) * (my - y0)
        assert step.values["d"] == 2 * f
        assert (step.branch == "NE") == (f > 0)


# ------------------------------------------------------------ DDA as printed
@pytest.mark.parametrize("p, q", [((0, 0), (16, 3)), ((0, 0), (8, 5)), ((-8, -4), (0, -1)),
                                  ((0, 0), (3, 24))])
def test_dda_truncate_is_the_exact_truncation(p, q):
    # Slopes with power-of-two denominators add up exactly in floats, so
    # the listing's (int) cast can be compared with exact truncation.
    _, pixels = run("line-dda-printed", (p, q), variant="truncate")
    steps = max(abs(q[0] - p[0]), abs(q[1] - p[1]))
    expected = [(math.trunc(p[0] + Fraction(k * (q[0] - p[0]), steps)),
                 math.trunc(p[1] + Fraction(k * (q[1] - p[1]), steps))) for k in range(steps + 1)]
    assert pixels == expected


def test_dda_truncate_error_against_rounding_is_counted():
    p, q = (0, 0), (16, 3)
    _, pixels = run("line-dda-printed", (p, q), variant="truncate")
    rounded = exact.nearest_pixel_line(p, q, "up")
    expected = sum(exact.y_at(p, q, x) % 1 >= Fraction(1, 2) for x in range(17))
    assert sum(a != b for a, b in zip(pixels, rounded)) == expected > 0


@pytest.mark.parametrize("p, q", [((0, 0), (3, 7)), ((10, 2), (4, 20)), ((2, 2), (9, 4)),
                                  ((5, 1), (5, 9))])
def test_dda_x_only_has_one_pixel_per_column_and_misses_rows(p, q):
    trace, pixels = run("line-dda-printed", (p, q), variant="x-only")
    columns = range(min(p[0], q[0]), max(p[0], q[0]) + 1)
    assert sorted(x for x, _ in pixels) == list(columns)
    for x, y in pixels:
        if q[0] != p[0]:  # no ties in these slopes, so floats round as exact values do
            assert y == exact.round_half_up_exact(exact.y_at(p, q, x))
    rows = set(range(min(p[1], q[1]), max(p[1], q[1]) + 1))
    missed = len(rows - {y for _, y in pixels})
    assert missed == trace.start.constants["rows_missed"] == max(0, len(rows) - len(columns))



def c_round(value: Fraction) -> int:
    """C's round(): halves away from zero."""
    whole = math.floor(abs(value) + Fraction(1, 2))
    return whole if value >= 0 else -whole


def add_first_listing(x1, y1, x2, y2):
    """The slide's DDA loop as printed, in Fractions: y += m, then write."""
    m = Fraction(y2 - y1, x2 - x1) if x2 != x1 else Fraction(0)
    y, out = Fraction(y1), []
    for i in range(x1, x2 + 1):
        y += m
        out.append((i, c_round(y)))
    return out


def line_dda_listing(x1, y1, x2, y2):
    """LineDDA as printed, in Fractions: DisplayPixel takes the float y as an
    int, which truncates toward zero."""
    dx, dy = x2 - x1, y2 - y1
    m = Fraction(dy, dx) if dx else Fraction(0)
    x, y = x1, Fraction(y1)
    out = [(x1, y1)]
    for _ in range(1, dx + 1):
        x += 1
        y += m
        out.append((x, math.trunc(y)))
    return out


DDA_LISTINGS = {"add-first": add_first_listing, "x-truncate": line_dda_listing}


def dyadic_segments():
    """Segments whose x extent is a power of two: m and its sums are exact in floats."""
    p = st.tuples(st.integers(-30, 30), st.integers(-30, 30))
    return st.builds(lambda p, k, dy, back: (p, (p[0] + (-1 if back else 1) * 2 ** k, p[1] + dy)),
                     p, st.integers(0, 5), st.integers(-60, 60), st.booleans())


def test_dda_add_first_gives_the_listings_pixels_on_the_slides_line():
    _, pixels = run("line-dda-printed", ((0, 0), (10, 7)), variant="add-first")
    assert pixels[0] == (0, 1) and pixels[-1] == (10, 8)
    assert len(pixels) == 11


@pytest.mark.parametrize("variant", sorted(DDA_LISTINGS))
@settings(max_examples=200, deadline=None)
@given(segment=dyadic_segments())
def test_dda_listings_as_printed_on_exact_slopes(variant, segment):
    p, q = segment
    _, pixels = run("line-dda-printed", (p, q), variant=variant)
    assert pixels == DDA_LISTINGS[variant](*p, *q)


@pytest.mark.parametrize("variant", sorted(DDA_LISTINGS))
@settings(max_examples=200, deadline=None)
@given(segment=segments())
def test_dda_listings_as_printed_on_random_segments(variant, segment):
    assert_as_listed(variant, *segment)


def assert_as_listed(variant, p, q):
    """The pixels of the listing, but that float sums of m can land a hair off
    a whole number (or a half), where the cast (or the rounding) may go either
    way: there a pixel may differ by one."""
    _, pixels = run("line-dda-printed", (p, q), variant=variant)
    listed = DDA_LISTINGS[variant](*p, *q)
    assert [x for x, _ in pixels] == [x for x, _ in listed]
    for (x, y), (_, expected) in zip(pixels, listed):
        exact_y = y_of_listing(variant, p, q, x)
        edge = exact_y.denominator == (1 if variant == "x-truncate" else 2)
        assert y == expected or (edge and abs(y - expected) == 1), (x, y, expected)


def y_of_listing(variant, p, q, x):
    """The exact y the listing holds when it writes column x."""
    m = Fraction(q[1] - p[1], q[0] - p[0]) if q[0] != p[0] else Fraction(0)
    steps = x - p[0] + (1 if variant == "add-first" else 0)
    return p[1] + steps * m


@pytest.mark.parametrize("p, q", NAMED_CASES)
@pytest.mark.parametrize("variant", sorted(DDA_LISTINGS))
def test_dda_listings_as_printed_on_the_hard_cases(variant, p, q):
    assert_as_listed(variant, p, q)


def test_line_dda_float_sums_fall_short_of_a_whole_number():
    # Seven float additions of 3/7 give 2.9999999999999996, which the cast makes 2.
    _, pixels = run("line-dda-printed", ((0, 0), (7, 3)), variant="x-truncate")
    assert line_dda_listing(0, 0, 7, 3)[-1] == (7, 3)
    assert pixels[-1] == (7, 2)


def test_line_dda_as_printed_leaves_gaps_and_sits_low_when_steep():
    p, q = (0, 0), (3, 7)
    _, pixels = run("line-dda-printed", (p, q), variant="x-truncate")
    assert pixels == [(0, 0), (1, 2), (2, 4), (3, 7)]
    nearest = exact.nearest_pixel_line(p, q, "up")
    assert len(nearest) == 8 > len(pixels)
    # Truncation sits at or below the rounded exact x-stepping line, never above.
    for x, y in pixels:
        assert y <= exact.round_half_up_exact(exact.y_at(p, q, x))


@pytest.mark.parametrize("variant", sorted(DDA_LISTINGS))
def test_dda_listings_count_up_only(variant):
    _, pixels = run("line-dda-printed", ((9, 2), (1, 5)), variant=variant)
    assert pixels == ([] if variant == "add-first" else [(9, 2)])


# ------------------------------------------------ the unbounded implicit form
def near_infinite_line(p, q, x, y):
    """Squared distance from (x, y) to its foot on the line PQ, below 1/4."""
    dx, dy = q[0] - p[0], q[1] - p[1]
    if dx == dy == 0:
        return (x - p[0]) ** 2 + (y - p[1]) ** 2 < Fraction(1, 4)
    t = Fraction((x - p[0]) * dx + (y - p[1]) * dy, dx * dx + dy * dy)
    fx, fy = p[0] + t * dx, p[1] + t * dy
    return (x - fx) ** 2 + (y - fy) ** 2 < Fraction(1, 4)


@pytest.mark.parametrize("p, q", [((3, 2), (6, 4)), ((5, 5), (5, 5)), ((9, 1), (2, 6)),
                                  ((2, 3), (8, 3))])
def test_implicit_infinite_is_every_grid_pixel_near_the_line(p, q):
    grid = (12, 9)
    trace = registry.get("line-implicit-infinite").record((p, q), {}, grid=grid)
    pixels = {tuple(c) for c in trace.written_pixels().tolist()}
    expected = {(x, y) for x in range(grid[0]) for y in range(grid[1])
                if near_infinite_line(p, q, x, y)}
    assert pixels == expected
    segment = exact.implicit_pixels(p, q)
    assert segment <= pixels
    if p != q:  # the line runs on past both ends of the segment
        assert len(pixels - segment) > 0


# ---------------------------------------------- the parametric loop as printed
def printed_ts(dt):
    """The listing's t values: repeated float addition, while t <= 1.0."""
    ts, t = [], 0.0
    while t <= 1.0:
        ts.append(t)
        t += dt
    return ts


@pytest.mark.parametrize("p, q, dt", [((0, 0), (1000, 3), 0.001), ((2, 2), (30, 17), 0.1),
                                      ((5, 9), (1, 1), 0.3)])
def test_parametric_printed_reproduces_the_loop_and_counts_what_it_misses(p, q, dt):
    trace, pixels = run("line-parametric-printed", (p, q), dt=dt)
    ts = printed_ts(dt)
    # The listing's own float arithmetic, r = P + D*t, then round halves up.
    expected = [tuple(math.floor(a + (b - a) * t + 0.5) for a, b in zip(p, q)) for t in ts]
    assert pixels == expected
    # Exact steps k*dt (as Fractions of the decimal dt), up to and including t = 1.
    step = Fraction(str(dt))
    exact_ts = [k * step for k in range(int(1 / step) + 1)]
    ideal = {tuple(exact.round_half_up_exact(a + t * (b - a)) for a, b in zip(p, q))
             for t in exact_ts}
    missed = ideal - set(pixels)
    assert (tuple(q) in pixels) == (trace.final_variables()["Q_plotted"] == "yes")
    if (p, q, dt) == ((0, 0), (1000, 3), 0.001):
        assert ts[-1] < 1.0 and missed == {(1000, 3)}, "the printed loop never reaches t = 1"


# --------------------------------------------- the slips flagged in the panels
def panel(name, points, **options):
    spec = registry.get(name)
    return " ".join(line.text for line in spec.code(points, spec.resolve(options)))


def line_bresenham_000(x1, y1, x2, y2):
    """The lecture's LineBresenham, with x = x + 1 put back inside the E branch."""
    dx, dy = x2 - x1, y2 - y1
    d, incr_e, incr_ne = 2 * dy - dx, 2 * dy, 2 * (dy - dx)
    x, y = x1, y1
    out = [(x, y)]
    while x < x2:
        if d <= 0:
            d = d + incr_e
            x = x + 1
        else:
            d = d + incr_ne
            x = x + 1
            y = y + 1
        out.append((x, y))
    return out


def test_the_bresenham_panels_flag_the_printed_slips():
    ties_ne = panel("line-bresenham-textbook", ((0, 0), (8, 3)), variant="ties-ne")
    assert "d <= 0" in ties_ne and "x = x + 1" in ties_ne and "else" in ties_ne
    printed = panel("line-bresenham-textbook", ((0, 0), (8, 3)), variant="as-printed")
    assert "y = y0" in printed and "draw_line" in printed


@pytest.mark.parametrize("p, q", [((0, 0), (28, 14)), ((0, 0), (8, 3)), ((2, 1), (14, 7)),
                                  ((0, 0), (6, 6)), ((0, 0), (4, 2))])
def test_the_printed_d_le_0_sends_ties_to_e_as_line_bresenham_does(p, q):
    # What the panel says of the printed test d <= 0: line-bresenham's pixels,
    # which differ from ties-ne's exactly where the line passes half-way.
    _, bresenham = run("line-bresenham", (p, q))
    assert line_bresenham_000(*p, *q) == bresenham
