"""Seed fill: the same region in every order, against a BFS written here."""
import json
import re
import sys
from collections import deque
from fractions import Fraction

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from algorithms.fill import flood as fill_module
from algorithms.fill.flood import outline_pixels, segment_pixels
from algorithms.core.registry import InputError, get
from algorithms.core.steps import PLOT, Span, Vars
from algorithms.core.trace import DEFAULT_STEP_CAP
from tests.support.trace_oracle import slow_replay
from tests.support import record

BOUNDARY, FILL = 0xC0392B, 0x2E86DE
ORDERS = ("stack", "queue", "span")
FOUR = ((1, 0), (-1, 0), (0, 1), (0, -1))
EIGHT = FOUR + ((1, 1), (-1, 1), (-1, -1), (1, -1))


def flood(contours, grid=(24, 20), **options):
    return record("flood-fill", contours, options, grid)


def final_sets(trace):
    """(boundary pixels, filled pixels) from the final raster's colours."""
    colors = trace.raster_at(len(trace) - 1).colors
    boundary = {(int(x), int(y)) for y, x in zip(*np.nonzero(colors == BOUNDARY))}
    filled = {(int(x), int(y)) for y, x in zip(*np.nonzero(colors == FILL))}
    return boundary, filled


def bfs(blocked, seed, grid, connectivity):
    """The seed's component among the grid's pixels that are not blocked."""
    width, height = grid
    steps = FOUR if connectivity == "4" else EIGHT
    seen, todo = {seed}, deque([seed])
    while todo:
        x, y = todo.popleft()
        for dx, dy in steps:
            q = (x + dx, y + dy)
            if 0 <= q[0] < width and 0 <= q[1] < height and q not in blocked and q not in seen:
                seen.add(q)
                todo.append(q)
    return seen


def fill_order(trace):
    """The pixels in the order the run fills them (spans left to right)."""
    order = []
    for i in range(len(trace)):
        step = trace.step(i)
        if isinstance(step.record, Span) and step.kind == PLOT:
            order += [(x, step.record.y) for x in range(step.record.x_start, step.record.x_end)]
        elif step.writes and step.line != 0:
            order.append(step.pixel)
    return order


# ------------------------------------------------------------ the outline
def round_half_up(value: Fraction) -> int:
    return (value + Fraction(1, 2)).__floor__()


@settings(max_examples=200)
@given(st.tuples(st.integers(-30, 30), st.integers(-30, 30)),
       st.tuples(st.integers(-30, 30), st.integers(-30, 30)))
def test_segments_round_to_the_nearest_pixel(p, q):
    pixels = segment_pixels(p, q)
    assert pixels[0] == p and pixels[-1] == q
    assert all(max(abs(a[0] - b[0]), abs(a[1] - b[1])) == 1 for a, b in zip(pixels, pixels[1:]))
    dx, dy = q[0] - p[0], q[1] - p[1]
    n = max(abs(dx), abs(dy))
    for i, (x, y) in enumerate(pixels):
        t = Fraction(i, n) if n else Fraction(0)
        assert (x, y) == (p[0] + round_half_up(t * dx), p[1] + round_half_up(t * dy))


def test_four_connected_outline_has_no_diagonal_steps():
    pixels = set(outline_pixels([[(2, 2), (12, 2), (2, 12)]], four=True))
    eight = set(outline_pixels([[(2, 2), (12, 2), (2, 12)]]))
    assert eight < pixels
    # Every diagonal pair of the outline has a shared edge neighbour in it.
    for x, y in pixels:
        for dx, dy in ((1, 1), (1, -1)):
            if (x + dx, y + dy) in pixels:
                assert (x + dx, y) in pixels or (x, y + dy) in pixels


# ---------------------------------------------------- same region, any order
SHAPES = [
    [[(2, 2), (20, 2), (20, 15), (2, 15)]],                     # a box
    [[(2, 2), (20, 2), (12, 8), (20, 15), (2, 15)]],            # a notch
    [[(1, 1), (22, 1), (22, 18), (1, 18)], [(8, 6), (14, 6), (14, 12), (8, 12)]],  # a hole
    [[(3, 1), (21, 9), (5, 18), (12, 9)]],                      # concave, diagonal
]


@pytest.mark.parametrize("contours", SHAPES)
@pytest.mark.parametrize("connectivity", ["4", "8"])
@pytest.mark.parametrize("outline", ["8", "4"])
def test_every_order_fills_the_bfs_region(contours, connectivity, outline):
    results = []
    for order in ORDERS:
        trace = flood(contours, order=order, connectivity=connectivity, outline=outline)
        boundary, filled = final_sets(trace)
        seed = trace.start.constants["seed"]
        assert boundary == {p for p in outline_pixels(contours, outline == "4")
                            if 0 <= p[0] < 24 and 0 <= p[1] < 20}
        assert filled == bfs(boundary, seed, (24, 20), connectivity)
        # Each pixel is written once: boundary and fill never overlap.
        assert trace.raster_at(len(trace) - 1).counts.max() == 1
        assert trace.final_variables()["filled"] == len(filled)
        results.append(filled)
    assert results[0] == results[1] == results[2]


@st.composite
def scenes(draw):
    contour = draw(st.lists(st.tuples(st.integers(0, 19), st.integers(0, 15)),
                            min_size=3, max_size=7))
    seed = draw(st.tuples(st.integers(0, 19), st.integers(0, 15)))
    return [contour], seed


@settings(max_examples=80)
@given(scenes(), st.sampled_from(["4", "8"]), st.sampled_from(["4", "8"]))
def test_random_outlines_and_seeds(scene, connectivity, outline):
    contours, seed = scene
    boundary = set(outline_pixels(contours, outline == "4"))
    if seed in boundary:
        with pytest.raises(InputError, match="boundary"):
            flood(contours, grid=(20, 16), seed=seed, outline=outline)
        return
    expected = bfs(boundary, seed, (20, 16), connectivity)
    for order in ORDERS:
        trace = flood(contours, grid=(20, 16), seed=seed, order=order,
                       connectivity=connectivity, outline=outline)
        assert final_sets(trace)[1] == expected
        assert sorted(fill_order(trace)) == sorted(expected)


# ------------------------------------------------------- orders in detail
def recursive_fill(blocked, seed, grid, steps):
    """The textbook recursive fill (small regions only)."""
    order, done = [], set(blocked)

    def fill(x, y):
        if not (0 <= x < grid[0] and 0 <= y < grid[1]) or (x, y) in done:
            return
        done.add((x, y))
        order.append((x, y))
        for dx, dy in steps:
            fill(x + dx, y + dy)

    fill(*seed)
    return order


def bfs_order(blocked, seed, grid, steps):
    order, seen, todo = [], {seed}, deque([seed])
    while todo:
        p = todo.popleft()
        order.append(p)
        for dx, dy in steps:
            q = (p[0] + dx, p[1] + dy)
            if 0 <= q[0] < grid[0] and 0 <= q[1] < grid[1] and q not in blocked and q not in seen:
                seen.add(q)
                todo.append(q)
    return order


@pytest.mark.parametrize("contours", SHAPES[:2] + SHAPES[3:])
@pytest.mark.parametrize("connectivity", ["4", "8"])
def test_stack_follows_the_recursion_and_queue_the_bfs(contours, connectivity):
    steps = FOUR if connectivity == "4" else EIGHT
    stack = flood(contours, order="stack", connectivity=connectivity, outline="4")
    queue = flood(contours, order="queue", connectivity=connectivity, outline="4")
    boundary, _ = final_sets(stack)
    seed = stack.start.constants["seed"]
    assert fill_order(stack) == recursive_fill(boundary, seed, (24, 20), steps)
    assert fill_order(queue) == bfs_order(boundary, seed, (24, 20), steps)


def test_span_fills_maximal_runs():
    trace = flood(SHAPES[2], order="span")
    boundary, filled = final_sets(trace)
    runs = [trace.step(i).record for i in range(len(trace))
            if isinstance(trace.step(i).record, Span) and trace.step(i).kind == PLOT]
    covered = [(x, run.y) for run in runs for x in range(run.x_start, run.x_end)]
    assert len(covered) == len(set(covered)) and set(covered) == filled
    for run in runs:
        # A run stops at the boundary or the grid's edge on both sides.
        for x in (run.x_start - 1, run.x_end):
            assert not 0 <= x < 24 or (x, run.y) in boundary
    assert trace.final_variables()["runs"] == len(runs)


# ------------------------------------------------------- 4 and 8 neighbours
def test_eight_neighbours_leak_through_exactly_one_diagonal_gap():
    # A room (0,0)-(20,10) split by a wall that steps diagonally once:
    # x = 10 for y = 0..4 and x = 11 for y = 5..10. (10, 5) and (11, 4) are
    # free and touch only at a corner, between the wall pixels (10, 4) and
    # (11, 5).
    room = [(0, 0), (20, 0), (20, 10), (0, 10)]
    walls = [[(10, 0), (10, 4), (10, 4)], [(11, 5), (11, 10), (11, 10)]]
    contours = [room] + walls
    for order in ORDERS:
        four = final_sets(flood(contours, grid=(21, 11), seed=(3, 3), order=order))[1]
        eight = final_sets(flood(contours, grid=(21, 11), seed=(3, 3), order=order,
                                  connectivity="8"))[1]
        left = {(x, y) for x in range(1, 10) for y in range(1, 10)} | {(10, y) for y in range(5, 10)}
        right = {(x, y) for x in range(11, 20) for y in range(1, 5)} | \
                {(x, y) for x in range(12, 20) for y in range(5, 10)}
        assert four == left
        assert eight == left | right
        # The only corner-to-corner contacts between the rooms.
        contacts = {(a, b) for a in left for b in right
                    if max(abs(a[0] - b[0]), abs(a[1] - b[1])) == 1}
        assert contacts == {((10, 5), (11, 4))}


def test_eight_neighbours_leak_through_an_8_connected_outline():
    triangle = [[(2, 2), (12, 2), (2, 12)]]
    four = final_sets(flood(triangle, seed=(4, 4)))[1]
    eight = final_sets(flood(triangle, seed=(4, 4), connectivity="8"))[1]
    held = final_sets(flood(triangle, seed=(4, 4), connectivity="8", outline="4"))[1]
    inside = {(x, y) for x in range(3, 12) for y in range(3, 12) if x + y < 14}
    assert four == inside
    # From (6, 7) to (7, 8) between the hypotenuse's pixels (7, 7) and (6, 8).
    assert (6, 7) in four and (7, 8) in eight and (7, 8) not in four
    assert (23, 19) in eight and (0, 0) in eight
    assert held <= inside


# ------------------------------------------------------------- large
BIG_BOX = [[(0, 0), (1025, 0), (1025, 1025), (0, 1025)]]  # 1024 x 1024 inside


def fill_big(**options):
    limit = sys.getrecursionlimit()
    sys.setrecursionlimit(400)  # a recursive fill would need about a million
    try:
        trace = flood(BIG_BOX, grid=(1026, 1026), seed=(600, 3), **options)
    finally:
        sys.setrecursionlimit(limit)
    assert not trace.truncated and len(trace) < DEFAULT_STEP_CAP
    assert trace.final_variables()["filled"] == 1024 * 1024
    counts = trace.raster_at(len(trace) - 1).counts
    assert counts.sum() == 1026 * 1026 and counts.max() == 1
    return trace


def test_a_1024_square_fills_without_recursion():
    fill_big(order="stack")
    fill_big(order="span", connectivity="8")


def test_a_1024_square_with_eight_neighbours_stays_under_the_step_cap():
    # The most frames: every pixel is pushed by up to four filled neighbours.
    assert len(fill_big(order="queue", connectivity="8")) > 4_000_000


# ------------------------------------------------------------- seeds
def test_bad_seeds_are_input_errors():
    box = SHAPES[0]
    with pytest.raises(InputError, match="boundary"):
        flood(box, seed=(2, 5))
    with pytest.raises(InputError, match="outside the 24x20 grid"):
        flood(box, seed=(24, 5))
    with pytest.raises(InputError, match="outside"):
        flood(box, seed=(-1, 5))
    with pytest.raises(InputError, match="no free pixel"):
        flood([[(2, 2), (9, 9), (5, 5)]])  # collinear: nothing inside
    with pytest.raises(InputError):
        flood([[(2, 2), (9, 9)]])  # an outline needs three points


def test_auto_seed_is_inside_the_first_outline():
    trace = flood(SHAPES[2])
    x, y = trace.start.constants["seed"]
    assert 1 < x < 22 and 1 < y < 18 and not (8 <= x <= 14 and 6 <= y <= 12)
    # A seed outside the outline fills the outside instead.
    outside = final_sets(flood(SHAPES[0], seed=(0, 0)))[1]
    assert (23, 19) in outside and (5, 5) not in outside


# ------------------------------------------------------------- frames
def test_panel_shows_size_and_next_entries():
    trace = flood(SHAPES[0], order="queue")
    pop = fill_module.fill_listing(SHAPES[0], get("flood-fill").resolve({"order": "queue"})).at["pop"]
    pops = [(i, trace.step(i)) for i in range(len(trace)) if isinstance(trace.step(i).record, Vars)
            and "next" in trace.step(i).record.values and trace.step(i).line == pop]
    assert pops
    for (i, a), (j, b) in zip(pops, pops[1:]):
        listed = a.record.values["next"]
        if listed != "(empty)":
            # A queue's front does not change when pixels join at its back.
            assert listed.startswith(f"({b.pixel[0]}, {b.pixel[1]})")
        # The size after a pop is one less than after the frame before it.
        assert b.record.values["size"] == trace.variables_at(j - 1)["size"] - 1
        assert trace.variables_at(j)["next"] == b.record.values["next"]


def test_entries_stop_after_the_detail_limit(monkeypatch):
    monkeypatch.setattr(fill_module, "DETAIL_POPS", 10)
    trace = flood(SHAPES[0])
    records = [trace.step(i).record for i in range(len(trace))]
    pops = [r for r in records if isinstance(r, Vars) and "next" in r.values]
    # 10 pops, the pushes of their fills, the listing's end, and the final record.
    assert 10 + 2 < len(pops) <= 2 * 10 + 2
    assert sum(type(r).__name__ == "Note" for r in records) == 1
    assert trace.final_variables()["filled"] == len(final_sets(trace)[1])


def simulated_stack(blocked, seed, grid, connectivity, order):
    """The stack (or queue) of the fill re-run here: after each pop, each
    fill or skip, and each fill's pushes, as (event, pixel, entries) with the
    entry to come out next first. Neighbours are pushed E, W, N, S (then
    NE, NW, SW, SE); a stack pushes them in reverse so that E comes out first."""
    width, height = grid
    steps = FOUR if connectivity == "4" else EIGHT
    free = {(x, y) for x in range(width) for y in range(height) if (x, y) not in blocked}
    pending, events = [seed], []
    stack = order == "stack"

    def coming():
        return list(reversed(pending)) if stack else list(pending)
    while pending:
        p = pending.pop() if stack else pending.pop(0)
        events.append(("pop", p, coming()))
        if p not in free:
            events.append(("skip", p, coming()))
            continue
        free.discard(p)
        pushed = [(p[0] + dx, p[1] + dy) for dx, dy in steps if (p[0] + dx, p[1] + dy) in free]
        events.append(("fill", p, coming()))  # the fill shows the stack as the pop left it
        pending.extend(reversed(pushed) if stack else pushed)
        if pushed:
            events.append(("push", p, coming()))
    return events


def listed(entries):
    """The panel's "next": the first five, then how many more."""
    text = " ".join(f"({x}, {y})" for x, y in entries[:5]) or "(empty)"
    return text + (f" +{len(entries) - 5} more" if len(entries) > 5 else "")


@pytest.mark.parametrize("order", ["stack", "queue"])
@pytest.mark.parametrize("connectivity", ["4", "8"])
def test_the_stack_shown_at_every_step_is_the_stack(order, connectivity, monkeypatch):
    monkeypatch.setattr(fill_module, "DETAIL_POPS", 60)  # listed for 60 pops, size only after
    contours = [[(1, 1), (22, 1), (22, 22), (1, 22)]]
    trace = flood(contours, grid=(24, 24), order=order, connectivity=connectivity)
    seed = trace.start.constants["seed"]
    at = fill_module.fill_listing(contours, get("flood-fill").resolve(
        {"order": order, "connectivity": connectivity})).at
    events = simulated_stack(set(outline_pixels(contours)), tuple(seed), (24, 24),
                             connectivity, order)
    k, checked, past = 0, 0, 0
    names = {at["pop"]: "pop", at["skip"]: "skip", at["plot_fill"]: "fill"}
    for i in range(len(trace)):
        step = trace.step(i)
        kind = names.get(step.line)
        if kind is None or type(step.record).__name__ == "Note":
            continue
        if kind == "fill" and isinstance(step.record, Vars):
            kind = "push"
        variables = trace.variables_at(i)
        listing = not variables["next"].startswith("(not listed")
        if events[k][0] == "pop" and kind != "pop":  # past the listing a pop has no step
            k += 1
        event, pixel, entries = events[k]
        k += 1
        if kind == "fill" and not listing and k < len(events) and events[k][0] == "push":
            entries = events[k][2]  # past the listing the fill's step shows its pushes done
            k += 1
        assert (kind, step.pixel) == (event, pixel), i
        assert variables["size"] == len(entries), i
        if listing:
            assert variables["next"] == listed(entries), i
            checked += 1
        else:
            past += 1
    assert k == len(events)
    assert checked > 100 and past > 100
    assert trace.variables_at(len(trace) - 1)["size"] == 0


def test_the_span_fill_stack_changes_with_its_pushes():
    contours = [[(1, 1), (22, 1), (22, 22), (1, 22)], [(8, 8), (14, 8), (14, 14), (8, 14)]]
    trace = flood(contours, grid=(24, 24), order="span")
    at = fill_module.fill_listing(contours, get("flood-fill").resolve({"order": "span"})).at
    size, pushes = 1, 0
    for i in range(1, len(trace)):
        step, variables = trace.step(i), trace.variables_at(i)
        if isinstance(step.record, Span) and step.line == at["push_runs"]:
            # The runs of free (unwritten) pixels the scanned row holds now: one push each.
            free = trace.raster_at(i).counts[step.record.y] == 0
            xs = range(step.record.x_start, step.record.x_end)
            runs = sum(free[x] and (x == xs[0] or not free[x - 1]) for x in xs)
            if runs:
                after = trace.variables_at(i + 1)
                assert after["size"] == variables["size"] + runs, i  # shown at the next step
                pushes += 1
        if "size" in variables:
            shown = variables["next"]
            assert len(re.findall(r"\(\d+, \d+\)", shown)) == min(5, variables["size"]), i
            if variables["size"] > 5:
                assert f"+{variables['size'] - 5} more" in shown, i
    assert pushes > 10


@pytest.mark.parametrize("order", ORDERS)
@pytest.mark.parametrize("connectivity", ["4", "8"])
def test_state_at_equals_slow_replay(order, connectivity, small_keyframes):
    small_keyframes(7)
    trace = flood([[(1, 1), (9, 1), (5, 4), (9, 8), (1, 8)]], grid=(11, 10), order=order,
                   connectivity=connectivity)
    for i in range(len(trace)):
        state = trace.state_at(i)
        replay = slow_replay(trace, i)
        assert np.array_equal(state.raster.counts, replay.counts)
        assert np.array_equal(state.raster.colors, replay.colors)
    assert len(trace._keyframes) > 3


@pytest.mark.parametrize("order", ORDERS)
def test_values_line_up_with_pixels(order):
    trace = flood(SHAPES[1], order=order)
    pixels, values = trace.written_pixels(), trace.pixel_values()
    assert len(pixels) == len(values)
    boundary = len(outline_pixels(SHAPES[1]))
    assert set(values[:boundary]) == {BOUNDARY} and set(values[boundary:]) == {FILL}


@pytest.mark.parametrize("order", ORDERS)
def test_panel_rows_for_every_step(order):
    spec = get("flood-fill")
    trace = spec.record(SHAPES[1], {"order": order}, grid=(24, 20))
    for i in range(len(trace)):
        assert all(isinstance(b, str) for _, b in spec.panel_rows(trace, i))


def test_command_line(capsys):
    from app.cli import main  # here, so the algorithm tests do not need the app
    argv = ["run", "flood-fill", "--points", "2,2", "20,2", "20,15", "2,15", "--set", "seed=5,5"]
    assert main(argv + ["--json"]) == 0
    result = json.loads(capsys.readouterr().out)
    pixels = [tuple(p) for p in result["pixels"]]
    assert len(pixels) == len(set(pixels)) == 19 * 14
    assert result["values"].count("#c0392b") == 2 * (19 + 14) - 4
    assert result["values"].count("#2e86de") == 17 * 12
    assert result["final"]["filled"] == 17 * 12
    assert main(argv[:-1] + ["seed=2,5"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "boundary" in err
    assert main(argv[:-1] + ["seed=40,5"]) == 2
    assert "outside" in capsys.readouterr().err
