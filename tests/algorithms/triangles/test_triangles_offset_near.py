"""Triangles far from the origin (option offset) and across w = 0 (option near)."""
import random
from fractions import Fraction

import pytest

from algorithms.exact import triangles as exact_triangles
from algorithms.core import registry
from algorithms.core.registry import InputError
from algorithms.core.steps import Note, Table
from algorithms.triangles import MAX_OFFSET

GRID = (20, 16)
TRAVERSALS = ("triangle-scan", "triangle-bbox", "triangle-incremental", "triangle-backtrack",
              "triangle-pineda", "triangle-linewise", "triangle-halfplane",
              "triangle-barycentric")


def random_triangles(seed, count=3):
    rnd = random.Random(seed)
    return [(rnd.randrange(0, GRID[0] * 16) / 16, rnd.randrange(0, GRID[1] * 16) / 16)
            for _ in range(3 * count)]


def counts(trace):
    result = {}
    for x, y in trace.written_pixels().tolist():
        result[(x, y)] = result.get((x, y), 0) + 1
    return result


def oracle(points, offset, rule="top-left"):
    """Exact coverage of the translated triangles in the translated window, moved back."""
    ox, oy = offset
    moved = [(Fraction(x) + ox, Fraction(y) + oy) for x, y in points]
    window = (ox, oy, ox + GRID[0], oy + GRID[1])
    found = exact_triangles.coverage(moved, 8, rule, window)
    return {(x - ox, y - oy): c for (x, y), c in found.items()}


@pytest.mark.parametrize("name", TRAVERSALS)
@pytest.mark.parametrize("offset", [(1_000_000, 1_000_000), (-MAX_OFFSET, 999_983)])
def test_exact_runs_far_away_match_the_oracle(name, offset):
    spec = registry.get(name)
    for seed in range(3):
        points = random_triangles(seed)
        trace = spec.record(points, {"offset": offset}, grid=GRID)
        assert counts(trace) == oracle(points, offset), (name, seed)
        # The kernel is moved the same way.
        if spec.kernel is not None:
            fast = spec.kernel(points, spec.resolve({"offset": offset}), GRID)
            assert sorted(map(tuple, fast.tolist())) == sorted(map(tuple, trace.written_pixels().tolist()))


def test_offset_run_shows_the_far_vertices_and_explains_exactly():
    spec = registry.get("triangle-bbox")
    points = [(1.5, 1.25), (15.75, 3.5), (6.0, 13.0)]
    trace = spec.record(points, {"offset": (1_000_000, 2_000_000)}, grid=GRID)
    last = trace.variables_at(len(trace) - 1)
    assert last["P0"] == (1_000_001.5, 2_000_001.25)
    assert last["offset"] == (1_000_000, 2_000_000)
    # The explanation's exact e0 at the first plotted pixel, against Fractions here.
    index = next(i for i in range(len(trace)) if trace.step(i).kind == "plot")
    x, y = trace.step(index).pixel
    rows = dict(spec.explain(trace, index))
    p1 = (Fraction(1_000_000) + Fraction(63, 4), Fraction(2_000_000) + Fraction(7, 2))
    p2 = (Fraction(1_000_006), Fraction(2_000_013))
    cx, cy = Fraction(2 * (x + 1_000_000) + 1, 2), Fraction(2 * (y + 2_000_000) + 1, 2)
    e0 = (p2[0] - p1[0]) * (cy - p1[1]) - (p2[1] - p1[1]) * (cx - p1[0])
    assert Fraction(rows["e0 exactly"].split()[0]) == e0
    assert rows["verdict"].startswith("in")


def test_float32_far_away_leaves_cracks_that_fixed_does_not():
    spec = registry.get("triangle-bbox")
    # Four triangles sharing edges, filling a square: an exact run has no crack.
    square = [(2, 2), (18, 2), (10, 8), (18, 2), (18, 14), (10, 8), (18, 14), (2, 14), (10, 8),
              (2, 14), (2, 2), (10, 8)]
    far = {"offset": (1_000_000, 1_000_000)}
    fixed = spec.record(square, far, grid=GRID).final_variables()
    single = spec.record(square, {**far, "precision": "float32"}, grid=GRID).final_variables()
    assert fixed["cracks"] == fixed["overlaps"] == 0 and fixed["filled"] == 16 * 12
    assert single["cracks"] + single["overlaps"] > 0


@pytest.mark.parametrize("offset", [(MAX_OFFSET + 1, 0), (0, -MAX_OFFSET - 1)])
def test_offsets_beyond_the_limit_are_refused_clearly(offset):
    with pytest.raises(InputError, match="offset"):
        registry.get("triangle-bbox").record([(1, 1), (5, 1), (1, 5)], {"offset": offset})


def test_cli_refuses_a_huge_offset_with_one_line(capsys):
    from app import cli
    status = cli.main(["run", "triangle-bbox", "--points", "1,1", "5,1", "1,5",
                       "--set", "offset=5000000,0"])
    err = capsys.readouterr().err
    assert status == 2 and "offset" in err and len(err.strip().splitlines()) == 1


# ------------------------------------------------------------ w = 0
STRADDLE = [(3, 12), (29, 12), (16, 21)]
W = (1.0, 1.0, -0.5)
S = (0.0, 10.0, 5.0)
NEAR = 0.05


def homogeneous_oracle(points, w, s, near, grid):
    """Per pixel centre: the point of the triangle in homogeneous space it shows, if any.

    The triangle's points are sum l_k (x_k w_k, y_k w_k, w_k) with l_k >= 0 summing to 1.
    A centre p sees the ray m (p, 1): solve M v = (p, 1) for v; the ray meets the
    triangle at m = 1 / sum(v) with l = m v, visible when all l >= 0 and m >= near.
    Returns {pixel: (s, margin)}: margin is how far the decision is from a tie.
    """
    rows = [[Fraction(p[0]) * Fraction(wk) for p, wk in zip(points, w)],
            [Fraction(p[1]) * Fraction(wk) for p, wk in zip(points, w)],
            [Fraction(wk) for wk in w]]
    result = {}
    for j in range(grid[1]):
        for i in range(grid[0]):
            v = solve(rows, (Fraction(2 * i + 1, 2), Fraction(2 * j + 1, 2), Fraction(1)))
            total = sum(v)
            if total <= 0:
                continue
            m = 1 / total
            weights = [m * vk for vk in v]
            margin = min(min(weights), (m - Fraction(near)) / m)
            if margin >= 0:
                result[(i, j)] = (float(sum(lk * sk for lk, sk in zip(weights, map(Fraction, s)))),
                                  margin)
            else:
                result[(i, j)] = (None, -margin)
    return result


def solve(m, b):
    """Cramer's rule for a 3 x 3 system in Fractions."""
    def det(a):
        return (a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1])
                - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0])
                + a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]))
    d = det(m)
    return [det([[b[r] if c == k else m[r][c] for c in range(3)] for r in range(3)]) / d
            for k in range(3)]


def test_near_clipping_draws_what_the_eye_sees():
    spec = registry.get("triangle-perspective")
    trace = spec.record(STRADDLE, {"w": W, "s": S, "near": NEAR}, grid=(32, 24))
    drawn = counts(trace)
    assert max(drawn.values()) == 1  # the fan's pieces share their edge without overlap
    truth = homogeneous_oracle(STRADDLE, W, S, NEAR, (32, 24))
    # Clipped corners are snapped to 1/256 px: only centres that close to a tie may differ.
    close = {p for p, (_, margin) in truth.items() if margin < Fraction(1, 200)}
    visible = {p for p, (value, _) in truth.items() if value is not None}
    assert (set(drawn) ^ visible) <= close
    assert len(visible) > 300 and len(close) < 40
    # The perspective-correct s at each drawn pixel is the one of the point seen (up to
    # the snapping of the cut corners, a few 1/1000 px at 100 px from the grid).
    persp = trace.series("s_persp")
    for index in trace.writes().nonzero()[0]:
        pixel = trace.step(int(index)).pixel
        if pixel not in close:
            assert persp[index] == pytest.approx(truth[pixel][0], abs=1e-3)
    # The naive projected triangle (pointing up) is not what is drawn.
    assert (16, 19) not in drawn and (16, 5) in drawn


def test_clipping_is_reported_as_frames():
    spec = registry.get("triangle-perspective")
    trace = spec.record(STRADDLE, {"w": W, "s": S, "near": NEAR}, grid=(32, 24))
    notes = [r.text for _, r in trace.records_of(Note)]
    assert any("crosses w = 0.05" in text and "4 corners" in text for text in notes)
    table = next(r for _, r in trace.records_of(Table) if r.name == "near clip")
    assert len(table.rows) == 4 and sum(1 for row in table.rows if row[3] == NEAR) == 2


def test_triangle_in_front_is_drawn_as_before_and_one_behind_not_at_all():
    spec = registry.get("triangle-perspective")
    front = {"w": (1.0, 2.0, 3.0), "s": S}
    plain = spec.record(STRADDLE, front, grid=(32, 24))
    clipped = spec.record(STRADDLE, {**front, "near": NEAR}, grid=(32, 24))
    assert counts(plain) == counts(clipped)
    behind = spec.record(STRADDLE, {"w": (-1.0, -2.0, 0.01), "s": S, "near": NEAR}, grid=(32, 24))
    assert len(behind.written_pixels()) == 0
    assert any("wholly behind" in r.text for _, r in behind.records_of(Note))


def test_w_below_zero_without_near_is_refused_and_points_to_near():
    spec = registry.get("triangle-perspective")
    with pytest.raises(InputError, match="near"):
        spec.record(STRADDLE, {"w": W, "s": S}, grid=(32, 24))


def test_a_near_plane_so_close_that_corners_fly_off_is_refused_clearly():
    spec = registry.get("triangle-perspective")
    with pytest.raises(InputError, match="larger near"):
        spec.record(STRADDLE, {"w": W, "s": S, "near": 1e-300}, grid=(32, 24))
