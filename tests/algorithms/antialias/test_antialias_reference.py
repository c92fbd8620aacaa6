"""The antialiasing family against references written here from the definitions
in algorithms/antialias/ (its package docstring and each module's), on the
hard-case catalogue's inputs (tests/algorithms/test_stability.py) and on
random ones.

The shapes a reference draws are made here: vertices snapped to 1/256 px
(halves to even) on the 1/512 px sample lattice; a triangle holds a sample
by the top-left rule (tests/support/raster_reference.py, whole numbers), a
polygon or a thick line's rectangle by its winding number
(algorithms/exact/polygons.py: the point nudged right and a hair up).

* aa-supersample: coverage = sum(w_s hit_s) / sum(w_s), exactly, over the
  documented sample positions ((2k + 1) / 2N of the pixel, rounded half up
  to the lattice) and the documented whole-number weights; the colour is
  the weighted sum of the last shape holding each sample (white where none)
  rounded half up. Jittered and random positions come from the documented
  hash (``sample_strata``: tests/algorithms/test_antialias_supersample.py
  holds them to one sample per stratum); everything after is checked.
* aa-adaptive: the recursive definition: a square's four corners and its
  centre; hits / 5 where they agree or at max_depth, else the mean of its
  four quarters; for the pixels the shapes' bounding boxes reach.
* aa-filter: the aliased image from exact coverage of the pixel centres,
  convolved with the documented kernel in whole numbers, zero beyond the
  grid, divided by the kernel's sum once.
* line-wu and line-subpixels: the exact oracles of
  tests/support/antialias_oracles.py (Wu's fractions per column; every
  subpixel the segment meets), here on the catalogue's segments.
* line-area: the area of the pixel square inside the segment's rectangle,
  by shapely (an independent polygon library), to 1e-9.
* aa-temporal: each frame's image as the mean over its instants of the
  fraction of the n x n grid samples inside the primitive moved to that
  instant (spokes as rectangles, a triangle moved or turned about its
  centroid).
"""
from __future__ import annotations

import functools
import math
from fractions import Fraction

import numpy as np
import pytest
import shapely
from hypothesis import example, given, settings
from hypothesis import strategies as st

from algorithms.antialias import sample_strata, time_samples
from algorithms.exact import polygons as exact_polygons
from algorithms.triangles.interpolate import unpack
from tests.support.catalogue import cases_of, recorded
from tests.support import record
from tests.support.antialias_oracles import subpixel_counts, wu_oracle
from tests.support.raster_reference import counter_clockwise, inside, triangle_pixels, twice_area

UNIT = 512
WHITE = (255, 255, 255)
SMALL = (14, 12)


def written(trace) -> dict:
    """{pixel: value} of the trace's writes, the last one where a pixel is written twice."""
    return dict(zip(map(tuple, trace.written_pixels().tolist()), trace.pixel_values().tolist()))


# ============================================================ shapes
def lattice(value) -> int:
    """A coordinate snapped to 1/256 px, in 1/512 px units."""
    return 2 * round(Fraction(value) * 256)


def rectangle(p, q, width, caps):
    """The segment's rectangle, widened by width / 2 on each side (and lengthened
    by width / 2 at each end with square caps); None when it has no area."""
    (px, py), (qx, qy) = (float(p[0]), float(p[1])), (float(q[0]), float(q[1]))
    dx, dy = qx - px, qy - py
    length, half = math.hypot(dx, dy), width / 2.0
    if length == 0 and caps == "butt":
        return None
    ux, uy = (dx / length, dy / length) if length else (1.0, 0.0)
    if caps == "square":
        px, py, qx, qy = px - ux * half, py - uy * half, qx + ux * half, qy + uy * half
    nx, ny = -uy * half, ux * half
    return [(px - nx, py - ny), (qx - nx, qy - ny), (qx + nx, qy + ny), (px + nx, py + ny)]


class Shape:
    """One shape in lattice units: its inside test, colour and pixel box."""

    def __init__(self, contour, color, rule=None):
        self.contour, self.color, self.rule = contour, color, rule
        xs, ys = [p[0] for p in contour], [p[1] for p in contour]
        self.box = (min(xs) // UNIT, min(ys) // UNIT, max(xs) // UNIT, max(ys) // UNIT)

    def holds(self, sx, sy) -> bool:
        if self.rule is None:
            return inside(self.contour, sx, sy)
        winding = exact_polygons.winding_number([self.contour], sx, sy)
        return exact_polygons.is_covered(winding, self.rule)

    def reaches(self, x, y) -> bool:
        return self.box[0] <= x <= self.box[2] and self.box[1] <= y <= self.box[3]


def shapes_of(points, options) -> list[Shape]:
    kind = options.get("shape", "triangles")
    colors = [unpack(c) for c in options.get("colors") or ()] or [(0, 0, 0)]
    shapes = []
    if kind == "triangles":
        for k in range(len(points) // 3):
            tri = counter_clockwise([(lattice(x), lattice(y)) for x, y in points[3 * k:3 * k + 3]])
            if twice_area(tri):
                shapes.append(Shape(tri, colors[k % len(colors)]))
    elif kind == "polygon":
        contour = [(lattice(x), lattice(y)) for x, y in points]
        shapes.append(Shape(contour, colors[0], options.get("fill_rule", "evenodd")))
    else:
        for k in range(len(points) // 2):
            corners = rectangle(points[2 * k], points[2 * k + 1], options.get("width", 1.0),
                                options.get("caps", "butt"))
            if corners is not None:
                rect = [(lattice(x), lattice(y)) for x, y in corners]
                if shoelace(rect):
                    shapes.append(Shape(rect, colors[k % len(colors)], "nonzero"))
    return shapes


def shoelace(contour) -> int:
    """Twice the signed area."""
    return sum(a[0] * b[1] - b[0] * a[1] for a, b in zip(contour, contour[1:] + contour[:1]))


def reached(shapes, grid):
    """The grid's pixels some shape's box reaches, row by row."""
    return [(x, y) for y in range(grid[1]) for x in range(grid[0])
            if any(s.reaches(x, y) for s in shapes)]


def owner(shapes, x, y, sx, sy, inner=True):
    """The last shape holding the sample of pixel (x, y), or None. A sample inside
    the pixel (``inner``) can only lie in a shape whose box reaches the pixel."""
    for shape in reversed(shapes):
        if (not inner or shape.reaches(x, y)) and shape.holds(sx, sy):
            return shape
    return None


# ======================================================== supersampling
def strata(pattern, n, seed, x, y):
    """[(k_x, k_y)] of the pixel's samples and N, as documented."""
    if pattern == "grid":
        return [(i, j) for j in range(n) for i in range(n)], n
    if pattern == "rotated-grid":
        return [(n * i + j, n * j + (n - 1 - i)) for j in range(n) for i in range(n)], n * n
    return random_row(pattern, n, seed, y)[x]


@functools.lru_cache(maxsize=64)
def random_row(pattern, n, seed, y, width=64):
    """The jittered or random strata of the first ``width`` pixels of row y."""
    kx, ky, big = sample_strata(pattern, n, seed, y, np.arange(width))
    return [(list(zip(a, b)), big) for a, b in zip(kx.tolist(), ky.tolist())]


def offset(k, big) -> int:
    """(2k + 1) / 2N of the pixel, in lattice units, rounded half up:
    floor((2k + 1) UNIT / 2N + 1/2), in whole numbers."""
    return ((2 * k + 1) * UNIT + big) // (2 * big)


def weight(kx, ky, big, name, sigma) -> int:
    def h(k):
        return min(2 * k + 1, 2 * big - 2 * k - 1)
    if name == "box":
        return 1
    if name == "weighted":
        return h(kx) + h(ky)
    if name == "tent":
        return h(kx) * h(ky)
    du, dv = (2 * kx + 1 - big) / (2 * big), (2 * ky + 1 - big) / (2 * big)
    return max(1, round(65536 * math.exp(-(du * du + dv * dv) / (2 * sigma * sigma))))


def supersample_reference(points, options, grid):
    """{pixel: (coverage as a Fraction, packed colour)} for pixels with coverage > 0."""
    shapes = shapes_of(points, options)
    result = {}
    for x, y in reached(shapes, grid):
        samples, big = strata(options["pattern"], options["n"], options["seed"], x, y)
        cover = total = 0
        sums = [0, 0, 0]
        for kx, ky in samples:
            w = weight(kx, ky, big, options["filter"], options["sigma"])
            hit = owner(shapes, x, y, x * UNIT + offset(kx, big), y * UNIT + offset(ky, big))
            total += w
            cover += w if hit else 0
            sums = [s + w * c for s, c in zip(sums, hit.color if hit else WHITE)]
        if cover:
            r, g, b = ((2 * s + total) // (2 * total) for s in sums)
            result[(x, y)] = (Fraction(cover, total), (r << 16) | (g << 8) | b)
    return result


def check_supersample(points, options, grid, trace):
    options = {"pattern": "grid", "n": 4, "filter": "box", "sigma": 0.5, "seed": 1, **options}
    want = supersample_reference(points, options, grid)
    assert written(trace) == {p: float(c) for p, (c, _) in want.items()}
    colors = trace.raster_at(len(trace) - 1).colors
    assert {p: int(colors[p[1], p[0]]) for p in want} == {p: rgb for p, (_, rgb) in want.items()}


@pytest.mark.parametrize("case", cases_of("aa-supersample"), ids=str)
def test_supersample_on_the_catalogue(case):
    trace = recorded(case)
    if trace is not None:
        check_supersample(case.points, case.options, case.grid, trace)


COORD = st.integers(-16, 8 * 15).map(lambda v: v / 8)  # eighths: samples fall on edges
POINT = st.tuples(COORD, COORD)
COLORS = st.sampled_from([(), ("#ff0000", "#0000ff"), ("#123456",)])


@st.composite
def shape_inputs(draw):
    kind = draw(st.sampled_from(["triangles", "polygon", "thick-line"]))
    count = {"triangles": draw(st.sampled_from([3, 6])), "polygon": draw(st.integers(3, 6)),
             "thick-line": draw(st.sampled_from([2, 4]))}[kind]
    points = draw(st.lists(POINT, min_size=count, max_size=count))
    options = {"shape": kind, "colors": draw(COLORS)}
    if kind == "polygon":
        options["fill_rule"] = draw(st.sampled_from(["evenodd", "nonzero"]))
    if kind == "thick-line":
        options["width"] = draw(st.sampled_from([0.5, 1.0, 2.5]))
        options["caps"] = draw(st.sampled_from(["butt", "square"]))
    return points, options


# Edges along the rows and columns of a 4 x 4 grid's samples (at 1/8 + k/4):
# a top, a bottom, a left and a right edge, where the tie rule decides.
ON_SAMPLES = ([(1.125, 5.125), (9.125, 5.125), (5.0, 1.125), (3.125, 6.125), (9.125, 6.125),
               (9.125, 11.125), (10.125, 1.375), (10.125, 9.875), (12.5, 5.0)], {"colors": ()})


@settings(max_examples=40, deadline=None)
@given(shape_inputs(), st.sampled_from(["grid", "rotated-grid", "jitter", "random"]),
       st.integers(1, 4), st.sampled_from(["box", "weighted", "tent", "gaussian"]))
@example(ON_SAMPLES, "grid", 4, "box")
def test_supersample_random_shapes(shape, pattern, n, name):
    points, options = shape
    options = {**options, "pattern": pattern, "n": n, "filter": name, "seed": 3, "sigma": 0.4}
    trace = record("aa-supersample", points, options, SMALL)
    check_supersample(points, options, SMALL, trace)


# =============================================================== adaptive
def refine(shapes, x, y, ox, oy, size, level, depth) -> Fraction:
    half = size // 2
    corners = ((ox, oy), (ox + size, oy), (ox, oy + size), (ox + size, oy + size),
               (ox + half, oy + half))
    # Corners lie on the pixel's border, perhaps in a shape of the next pixel's.
    hits = sum(owner(shapes, x, y, x * UNIT + px, y * UNIT + py, inner=False) is not None
               for px, py in corners)
    if hits in (0, 5) or level >= depth:
        return Fraction(hits, 5)
    quarters = ((ox, oy), (ox + half, oy), (ox, oy + half), (ox + half, oy + half))
    return sum(refine(shapes, x, y, qx, qy, half, level + 1, depth) for qx, qy in quarters) / 4


def check_adaptive(points, options, grid, trace):
    shapes = shapes_of(points, options)
    want = {}
    for x, y in reached(shapes, grid):
        value = refine(shapes, x, y, 0, 0, UNIT, 0, options.get("max_depth", 3))
        if value:
            want[(x, y)] = float(value)
    assert written(trace) == want


@pytest.mark.parametrize("case", cases_of("aa-adaptive"), ids=str)
def test_adaptive_on_the_catalogue(case):
    trace = recorded(case)
    if trace is not None:
        check_adaptive(case.points, case.options, case.grid, trace)


@settings(max_examples=30, deadline=None)
@given(shape_inputs(), st.integers(0, 3))
@example(ON_SAMPLES, 2)
def test_adaptive_random_shapes(shape, depth):
    points, options = shape
    options = {**options, "max_depth": depth}
    check_adaptive(points, options, SMALL, record("aa-adaptive", points, options, SMALL))


# ========================================================== post-filtering
def kernel(name, sigma):
    if name == "box3":
        return [[1] * 3 for _ in range(3)]
    if name == "seed":
        return [[1, 4, 1], [4, 16, 4], [1, 4, 1]]
    r = max(1, math.ceil(3 * sigma))
    return [[round(65536 * math.exp(-(u * u + v * v) / (2 * sigma * sigma)))
             for u in range(-r, r + 1)] for v in range(-r, r + 1)]


def filter_reference(points, options, grid) -> dict:
    aliased = set()
    for k in range(len(points) // 3):
        aliased |= triangle_pixels(points[3 * k:3 * k + 3], grid, options.get("fill_rule",
                                                                              "top-left"))
    weights = kernel(options.get("kernel", "seed"), options.get("sigma", 0.8))
    r = len(weights) // 2
    total = sum(map(sum, weights))
    want = {}
    for y in range(grid[1]):
        for x in range(grid[0]):
            acc = sum(weights[v + r][u + r] for v in range(-r, r + 1) for u in range(-r, r + 1)
                      if (x + u, y + v) in aliased)
            if acc:
                want[(x, y)] = float(Fraction(acc, total))
    return want


def check_filter(points, options, grid, trace):
    assert written(trace) == filter_reference(points, options, grid)


@pytest.mark.parametrize("case", cases_of("aa-filter"), ids=str)
def test_filter_on_the_catalogue(case):
    trace = recorded(case)
    if trace is not None:
        check_filter(case.points, case.options, case.grid, trace)


@settings(max_examples=30, deadline=None)
@given(st.lists(POINT, min_size=3, max_size=6).filter(lambda p: len(p) % 3 == 0),
       st.sampled_from(["box3", "seed", "gaussian"]), st.sampled_from([0.4, 0.8, 1.3]),
       st.sampled_from(["top-left", "inclusive", "strict"]))
def test_filter_random_triangles(points, name, sigma, rule):
    options = {"kernel": name, "sigma": sigma, "fill_rule": rule}
    check_filter(points, options, SMALL, record("aa-filter", points, options, SMALL))


# ============================================================ Wu's line
@pytest.mark.parametrize("case", cases_of("line-wu"), ids=str)
def test_wu_on_the_catalogue(case):
    trace = recorded(case)
    if trace is not None:
        got = list(zip(map(tuple, trace.written_pixels().tolist()),
                       trace.pixel_values().tolist()))
        assert got == wu_oracle(*case.points, case.options.get("endpoints", "full"))


# ============================================================ area line
def area_reference(p, q, width, caps) -> dict:
    """{pixel: area of the pixel square inside the rectangle}, by shapely, with the
    coordinates taken relative to P (whole numbers: exact) so far lines keep
    their digits."""
    corners = rectangle((0.5, 0.5), (q[0] - p[0] + 0.5, q[1] - p[1] + 0.5), width, caps)
    if corners is None:
        return {}
    rect = shapely.Polygon(corners)
    x0, y0, x1, y1 = (math.floor(v) for v in rect.bounds)
    xs, ys = np.meshgrid(np.arange(x0, x1 + 1), np.arange(y0, y1 + 1))
    boxes = shapely.box(xs.ravel(), ys.ravel(), xs.ravel() + 1, ys.ravel() + 1)
    areas = shapely.area(shapely.intersection(boxes, rect))
    return {(int(x) + p[0], int(y) + p[1]): float(a)
            for x, y, a in zip(xs.ravel(), ys.ravel(), areas)}


def check_area(points, options, trace):
    p, q = points
    want = area_reference(p, q, options.get("width", 1.0), options.get("caps", "butt"))
    got = written(trace)
    # The line works at the pixels' own coordinates in float64: far from the
    # origin an area keeps the digits a coordinate leaves (1.4e-8 at 1e9 px).
    tolerance = 1e-9 + 16 * math.ulp(max(abs(c) for c in (*p, *q)))
    for pixel, a in got.items():
        assert a == pytest.approx(want.get(pixel, 0.0), abs=tolerance), pixel
    missing = {pixel for pixel, a in want.items() if a > tolerance} - set(got)
    assert not missing


@pytest.mark.parametrize("case", cases_of("line-area"), ids=str)
def test_area_on_the_catalogue(case):
    trace = recorded(case)
    if trace is not None:
        check_area(case.points, case.options, trace)


PIXEL = st.tuples(st.integers(-30, 30), st.integers(-30, 30))


@settings(max_examples=40, deadline=None)
@given(PIXEL, PIXEL, st.sampled_from([0.3, 1.0, 2.5]), st.sampled_from(["butt", "square"]))
def test_area_random_segments(p, q, width, caps):
    options = {"width": width, "caps": caps}
    check_area((p, q), options, record("line-area", (p, q), options))


# ============================================================ subpixels
@pytest.mark.parametrize("case", cases_of("line-subpixels"), ids=str)
def test_subpixels_on_the_catalogue(case):
    trace = recorded(case)
    if trace is not None:
        n = case.options.get("n", 3)
        counts = subpixel_counts(case.points, n, case.grid)
        assert written(trace) == {pixel: min(1.0, k / n) for pixel, k in counts.items()}
        assert dict(zip(map(tuple, trace.written_pixels().tolist()),
                        trace.series("subpixels")[trace.writes()].tolist())) == counts


# ============================================================= temporal
def moved(points, options, t):
    """The primitive at time t (frames), as shapes."""
    speed = options["speed"]
    if len(points) == 1:
        (cx, cy), = points
        spin = options["motion"] == "spin"
        base = math.radians(options["phase"] + (speed * t if spin else 0.0))
        shift = 0.0 if spin else speed * t
        ends = []
        for k in range(options["spokes"]):
            a = base + 2 * math.pi * k / options["spokes"]
            ends += [(cx + shift, cy), (cx + shift + options["radius"] * math.cos(a),
                                        cy + options["radius"] * math.sin(a))]
        return shapes_of(ends, {"shape": "thick-line", "width": options["spoke_width"]})
    if options["motion"] == "move":
        return shapes_of([(x + speed * t, y) for x, y in points], {})
    cx, cy = sum(p[0] for p in points) / 3, sum(p[1] for p in points) / 3
    c, s = math.cos(math.radians(speed * t)), math.sin(math.radians(speed * t))
    return shapes_of([(cx + c * (x - cx) - s * (y - cy), cy + s * (x - cx) + c * (y - cy))
                      for x, y in points], {})


TEMPORAL = {"motion": "spin", "mode": "instant", "frames": 12, "speed": 80.0, "time_samples": 8,
            "shutter": 1.0, "n": 2, "radius": 9.0, "spokes": 4, "spoke_width": 1.5,
            "phase": 0.0}


def temporal_reference(points, options, grid, frame) -> np.ndarray:
    options = {**TEMPORAL, **options}
    n = options["n"]
    if options["mode"] == "instant":
        instants = [frame]
    elif options.get("times") == "jittered":
        # One random instant per stratum: tests/algorithms/test_temporal_jitter.py checks them.
        instants = time_samples(options, frame)
    else:
        count = options["time_samples"]
        instants = [frame + options["shutter"] * (s + 0.5) / count for s in range(count)]
    offsets = [offset(k, n) for k in range(n)]
    hits = np.zeros((grid[1], grid[0]), np.int64)
    for t in instants:
        shapes = moved(points, options, t)
        for x, y in reached(shapes, grid):
            hits[y, x] += sum(owner(shapes, x, y, x * UNIT + a, y * UNIT + b) is not None
                              for a in offsets for b in offsets)
    return hits / (len(instants) * n * n)


def check_temporal(points, options, grid, trace):
    frames = trace.series("frame")
    images = [np.zeros((grid[1], grid[0])) for _ in range(options.get("frames", 12))]
    for i, value in zip(np.flatnonzero(~np.isnan(frames)), trace.series("coverage")[
            ~np.isnan(frames)]):
        x, y = trace.step(i).pixel
        images[int(frames[i])][y, x] = value
    for k, image in enumerate(images):
        assert np.array_equal(image, temporal_reference(points, options, grid, k)), k


@pytest.mark.parametrize("case", cases_of("aa-temporal"), ids=str)
def test_temporal_on_the_catalogue(case):
    trace = recorded(case)
    if trace is not None:
        check_temporal(case.points, case.options, case.grid, trace)


@settings(max_examples=12, deadline=None)
@given(st.sampled_from([[(6.0, 5.0)], [(2.0, 2.5), (9.25, 3.0), (4.0, 9.5)]]),
       st.sampled_from(["spin", "move"]), st.sampled_from(["instant", "motion-blur"]),
       st.sampled_from([-45.0, 2.5, 30.0, 90.0]), st.integers(1, 3))
def test_temporal_random_motions(points, motion, mode, speed, n):
    options = {"motion": motion, "mode": mode, "speed": speed, "n": n, "frames": 2,
               "time_samples": 3, "radius": 4.0, "shutter": 0.5}
    check_temporal(points, options, SMALL, record("aa-temporal", points, options, SMALL))

