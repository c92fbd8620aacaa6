"""Circles by symmetry and the midpoint circle, against the exact oracles.

The oracles (algorithms/exact/circles.py) are written from the definitions
with integer square roots; see that module for the derivation of the
midpoint circle's per-column rule.
"""
import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from algorithms.exact import circles as exact
from algorithms.circles.midpoint import midpoint_listing, mirrors8
from algorithms.core.registry import InputError, get
from tests.support.trace_oracle import slow_replay
from tests.support import record

CIRCLES = ("circle-sqrt4", "circle-sqrt8", "circle-midpoint")


def circle(name, r, centre=(0, 0), grid=(8, 8), **options):
    return record(name, (centre,), {"radius": r, **options}, grid)


def offsets(trace, centre=(0, 0)):
    """Written pixels as offsets from the centre, in emission order."""
    return [(x - centre[0], y - centre[1]) for x, y in trace.written_pixels().tolist()]


def neighbours(pixel, pixels):
    x, y = pixel
    return sum((x + dx, y + dy) in pixels for dx in (-1, 0, 1) for dy in (-1, 0, 1)
               if (dx, dy) != (0, 0))


def is_closed_curve(pixels) -> bool:
    """8-connected, and every pixel has two 8-neighbours or more (no loose ends)."""
    pixels = set(pixels)
    if any(neighbours(p, pixels) < 2 for p in pixels):
        return False
    todo, seen = [next(iter(pixels))], set()
    while todo:
        x, y = todo.pop()
        if (x, y) in seen:
            continue
        seen.add((x, y))
        todo += [(x + dx, y + dy) for dx in (-1, 0, 1) for dy in (-1, 0, 1)
                 if (x + dx, y + dy) in pixels]
    return seen == pixels


def same_raster(a, b):
    assert np.array_equal(a.counts, b.counts)
    assert (a.colors is None) == (b.colors is None)
    if a.colors is not None:
        assert np.array_equal(a.colors, b.colors)


# ------------------------------------------------------------ midpoint
@pytest.mark.parametrize("start", ["integer", "fraction"])
def test_midpoint_equals_the_oracle_without_duplicates(start):
    for r in range(0, 161):
        pixels = offsets(circle("circle-midpoint", r, start=start))
        assert len(pixels) == len(set(pixels)), r
        assert set(pixels) == exact.midpoint_circle(r), r


def test_both_starts_choose_identical_pixels():
    for r in range(0, 401):
        integer = circle("circle-midpoint", r, start="integer")
        fraction = circle("circle-midpoint", r, start="fraction")
        assert np.array_equal(integer.written_pixels(), fraction.written_pixels()), r
        # The fraction start's d is always the integer start's d plus 1/4.
        d_int, d_frac = integer.series("d"), fraction.series("d")
        known = ~np.isnan(d_int)
        assert np.array_equal(d_frac[known] - d_int[known], np.full(known.sum(), 0.25))


def test_small_radii_by_hand():
    assert offsets(circle("circle-midpoint", 0)) == [(0, 0)]
    assert offsets(circle("circle-midpoint", 1)) == [(0, 1), (1, 0), (0, -1), (-1, 0)]
    # r = 2: columns 0 and 1 have y = 2 (sqrt 3 = 1.73 rounds to 2); column 2
    # has y = 0 and lies past the diagonal.
    assert set(offsets(circle("circle-midpoint", 2))) == {
        (0, 2), (2, 0), (0, -2), (-2, 0),
        (1, 2), (2, 1), (2, -1), (1, -2), (-1, -2), (-2, -1), (-2, 1), (-1, 2)}


@pytest.mark.parametrize("r", [1000, 4096])
def test_large_radii(r):
    pixels = offsets(circle("circle-midpoint", r))
    assert len(pixels) == len(set(pixels))
    assert set(pixels) == exact.midpoint_circle(r)
    assert is_closed_curve(pixels)


@settings(max_examples=60)
@given(st.integers(0, 600), st.tuples(st.integers(-50, 50), st.integers(-50, 50)),
       st.sampled_from(["integer", "fraction"]))
def test_midpoint_is_eight_way_symmetric_anywhere(r, centre, start):
    pixels = offsets(circle("circle-midpoint", r, centre=centre, start=start), centre)
    assert len(pixels) == len(set(pixels))
    assert exact.eight_way(pixels) == set(pixels)
    if r >= 1:
        assert is_closed_curve(pixels)


@pytest.mark.parametrize("start", ["integer", "fraction"])
@pytest.mark.parametrize("r", [1, 2, 8, 23, 24])
def test_each_decision_is_f_at_the_midpoint(start, r):
    trace = circle("circle-midpoint", r, centre=(3, -2), start=start)
    decisions = 0
    for i in range(1, len(trace)):
        step = trace.step(i)
        if not step.branch:
            continue
        decisions += 1
        before = trace.step(i - 1)  # the loop test, on the current pixel
        x, y = before.pixel[0] - 3, before.pixel[1] + 2
        f4 = 4 * (x + 1) ** 2 + (2 * y - 1) ** 2 - 4 * r * r  # 4 F(x + 1, y - 1/2)
        d = step.values["d"]
        assert 4 * d == (f4 if start == "fraction" else f4 - 1)
        assert step.branch == ("E" if f4 < 0 else "SE")
        # E and SE, offsets from the current pixel, are highlighted.
        e, se = (before.pixel[0] + 1, before.pixel[1]), (before.pixel[0] + 1, before.pixel[1] - 1)
        assert trace.state_at(i).candidates == [e, se]
        assert step.pixel == (e if step.branch == "E" else se)
    # One decision per octant column after the first, and one more when the
    # loop ends by crossing the diagonal rather than on it.
    octant = exact.midpoint_octant(r)
    assert decisions == len(octant) - 1 + (octant[-1][0] != octant[-1][1])


def test_each_step_plots_its_distinct_mirrors_once():
    trace = circle("circle-midpoint", 30)
    mirror = midpoint_listing(((0, 0),), {"start": "integer"}).at["plot_mirrors"]
    groups, current = [], None
    for i in range(1, len(trace)):
        step = trace.step(i)
        if step.branch:
            current = (int(step.values["x"]), int(step.values["y"]))
            groups.append((current, []))
        elif step.writes and step.line == mirror:
            groups[-1][1].append(step.pixel)
    assert groups
    for (x, y), plotted in groups:
        if x > y:  # the step that crossed the diagonal plots nothing
            assert plotted == []
        else:
            assert tuple(plotted) == mirrors8(x, y)
            assert len(plotted) == (4 if x == y else 8)


def test_kernels_match_the_generators():
    for name in CIRCLES:
        spec = get(name)
        for r in list(range(0, 120)) + [511, 1000, 4096]:
            options = spec.resolve({"radius": r})
            kernel = spec.kernel(((5, -7),), options)
            written = spec.record(((5, -7),), options).written_pixels()
            assert kernel.dtype == np.int64
            assert np.array_equal(kernel, written), (name, r)


# --------------------------------------------------------- sqrt, 4 ways
@pytest.mark.parametrize("dtype", [np.float32, np.float64])
def test_a_float_square_root_floors_exactly_up_to_radius_4096(dtype):
    # What the C code's (int)sqrt((float)n) gives equals the exact root for
    # every n = r^2 - x^2 with r <= 4096: k is the root of all n in
    # [k^2, (k + 1)^2).
    k = np.arange(4097, dtype=np.int64)
    n = np.arange(4096 ** 2 + 1, dtype=np.int64)  # up to 2^24, exact in float32
    exact_root = np.repeat(k, 2 * k + 1)[:len(n)]
    assert np.array_equal(np.floor(np.sqrt(n.astype(dtype))).astype(np.int64), exact_root)


def test_sqrt4_pixels_and_duplicates():
    for r in range(0, 120):
        trace = circle("circle-sqrt4", r)
        pixels = offsets(trace)
        assert set(pixels) == exact.sqrt4_circle(r)
        # (r, 0) and (-r, 0) are each plotted twice, as (x, y) and (x, -y); at
        # r = 0 the two plots of the first line are one pixel.
        assert trace.final_variables()["duplicates"] == (1 if r == 0 else 2)
        assert len(pixels) - len(set(pixels)) == (1 if r == 0 else 2)


def test_sqrt4_gaps_where_the_arc_is_steep():
    for r in range(0, 300):
        final = circle("circle-sqrt4", r).final_variables()
        jumps = exact.sqrt4_gap_columns(r)
        assert final["gaps"] == 4 * len(jumps)
        assert final["missing"] == 4 * sum(skipped for _, skipped in jumps)
        assert list(final["gap_columns"]) == [x for x, _ in jumps]
        # Only past 45 degrees, where the arc falls faster than it runs.
        assert all(2 * x * x > r * r for x, _ in jumps)
        if r <= 2:
            assert final["gaps"] == 0
        else:
            # The last column always jumps: y(r - 1) = floor(sqrt(2r - 1)) >= 2.
            assert jumps[-1][0] == r


def test_sqrt4_gaps_counted_on_the_drawn_pixels():
    # Independently of the oracle: walk the first quadrant's arc column by
    # column over the drawn pixels and count steps between non-neighbours.
    for r in (3, 10, 57, 200):
        pixels = set(offsets(circle("circle-sqrt4", r)))
        arc = sorted(((x, y) for x, y in pixels if x >= 0 and y >= 0))
        jumps = sum(1 for a, b in zip(arc, arc[1:]) if max(abs(a[0] - b[0]), abs(a[1] - b[1])) > 1)
        assert circle("circle-sqrt4", r).final_variables()["gaps"] == 4 * jumps > 0
        assert not is_closed_curve(pixels)


def test_sqrt4_gap_counts_for_some_radii():
    # By hand for r = 6: y = 6, 5, 5, 5, 4, 3, 0 for x = 0..6; only the last
    # column drops by more than one (3 -> 0, two pixels skipped per arc).
    final = circle("circle-sqrt4", 6).final_variables()
    assert (final["gaps"], final["missing"], tuple(final["gap_columns"])) == (4, 8, (6,))


# --------------------------------------------------------- sqrt, 8 ways
def test_sqrt8_has_no_gaps():
    for r in range(0, 250):
        trace = circle("circle-sqrt8", r)
        pixels = offsets(trace)
        assert set(pixels) == exact.sqrt8_circle(r)
        final = trace.final_variables()
        assert final["gaps"] == 0
        if r >= 1:
            assert len(pixels) == len(set(pixels))
            assert is_closed_curve(pixels), r
        else:
            assert set(pixels) == {(0, 0)} and final["duplicates"] == 3


# ------------------------------------------------------------ shared
@pytest.mark.parametrize("name", CIRCLES)
def test_radius_is_checked(name):
    with pytest.raises(InputError):
        circle(name, -1)
    with pytest.raises(InputError):
        circle(name, 4097)
    with pytest.raises(InputError):
        circle(name, 2.5)


@pytest.mark.parametrize("name", CIRCLES)
def test_pixels_past_the_grid_are_clipped_but_kept(name):
    trace = circle(name, 12, centre=(2, 2), grid=(10, 10))
    written = trace.written_pixels()
    inside = (written >= 0).all(axis=1) & (written < 10).all(axis=1)
    assert not inside.all()
    assert trace.raster_at(len(trace) - 1).counts.sum() == inside.sum()


@pytest.mark.parametrize("name, options", [
    ("circle-midpoint", {"radius": 9}), ("circle-midpoint", {"radius": 9, "start": "fraction"}),
    ("circle-sqrt4", {"radius": 9}), ("circle-sqrt8", {"radius": 9})])
def test_state_at_equals_slow_replay(name, options, small_keyframes):
    small_keyframes(5)
    trace = get(name).record(((10, 10),), options, grid=(21, 21))
    for i in range(len(trace)):
        state = trace.state_at(i)
        same_raster(state.raster, slow_replay(trace, i))
        assert state.step == trace.step(i)
    assert len(trace._keyframes) > 3


@pytest.mark.parametrize("name", CIRCLES)
def test_panel_rows_for_every_step(name):
    spec = get(name)
    trace = spec.record(((8, 8),), {"radius": 7}, grid=(17, 17))
    for i in range(len(trace)):
        rows = spec.panel_rows(trace, i)
        assert all(isinstance(a, str) and isinstance(b, str) for a, b in rows)


def test_command_line(capsys):
    from app.cli import main  # here, so the algorithm tests do not need the app
    assert main(["run", "circle-midpoint", "--points", "16,12", "--set", "radius=8"]) == 0
    out = capsys.readouterr().out
    assert "44 pixels" in out
    assert main(["run", "circle-midpoint", "--points", "16,12", "--set", "radius=8",
                 "--set", "start=fraction", "--json"]) == 0
    import json
    result = json.loads(capsys.readouterr().out)
    assert {(x - 16, y - 12) for x, y in result["pixels"]} == exact.midpoint_circle(8)
    assert result["options"] == {"radius": 8, "start": "fraction"}
    assert main(["run", "circle-sqrt4", "--points", "16,12", "--set", "radius=-3"]) == 2
    assert capsys.readouterr().err.count("\n") == 1
