"""The lecture's line listings as printed, against exact oracles written here.

Each printed variant must reproduce what its listing does (the listing is
transcribed literally below, in integers or Fractions), and its distance
from the exact nearest-pixel line is counted, not waved away.
"""
from __future__ import annotations

import math
from fractions import Fraction

import pytest

from algorithms.core import registry
from algorithms.exact import lines as exact

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
def printed_draw_line(x1, y1, x2, y2):
    """The slide's listing, transcribed (its y = y0 read as y = y1)."""
    pixels, y = [], y1
    dx, dy = 2 * (x2 - x1), 2 * (y2 - y1)
    dydx, d = dy - dx, (dy - dx) // 2
    for x in range(x1, x2 + 1):
        pixels.append((x, y))
        if d > 0:
            d -= dy
        else:
            y += 1
            d -= dydx
    return pixels


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
