"""The antialiasing family: estimating how much of each pixel a shape covers.

An aliased rasterizer asks one question per pixel: is the centre inside?
The answer is 0 or 1, and edges come out as stairs. The algorithms here
estimate the pixel's *coverage* instead, the fraction of its square the
shape covers (0..1; algorithms/exact/coverage.py computes it exactly):

* ``aa-supersample``: many samples per pixel, averaged by a filter;
* ``aa-adaptive``: a few samples, more only where they disagree;
* ``aa-filter``: the aliased image first, then blurred by a convolution;
* ``line-wu`` and ``line-area``: antialiased lines, by Xiaolin Wu's two
  pixels per column and by the exact area of the line's rectangle;
* ``aa-temporal``: a moving or spinning shape over several animation
  frames, sampled at one instant per frame (the wagon-wheel effect) or
  averaged over the frame's exposure (motion blur).

Every run names its coverage as the pixel value (``Start.pixel_value``), so
``run --json`` prints coverages in 0..1, and a packed colour as
``Start.color_value``: the ink blended over a white background by the
coverage (a grey for black ink), which the colour buffer shows.

Shapes (``shape``). ``triangles``: 3k points, k triangles, the union is
drawn. ``polygon``: all points form one contour, filled by ``fill_rule``
(evenodd or nonzero). ``thick-line``: 2k points, k segments, each the
rectangle of the segment widened by ``width`` / 2 on either side (``caps``
square also lengthens it by width / 2 at each end). Points are positions
in the plane (real numbers), as for triangles.

Samples and exactness. Vertices snap to multiples of 1/256 px (halves to
even), as the triangle family does. Sample positions lie on a lattice of
1/512 px, so every inside test is exact integer arithmetic (int64 in the
vectorised kernels, Python integers in the generators), and the generator
and the kernel of an algorithm give the same numbers to the last bit. A
sample exactly on an edge follows the same tie rule as pixel centres do
(left and bottom edges in; for polygons, the point nudged right and a
hair up decides). Per axis a sample sits at (2k + 1) / (2N) of the pixel
for a whole number k in 0..N-1:

* ``grid``: n x n samples, N = n, k = 0..n-1 (n = 1: the centre);
* ``rotated-grid``: an n x n grid turned by atan(1/n) so that no two of
  its n^2 samples share a row or a column of an n^2 x n^2 grid (n = 2 is
  the classic rotated-grid pattern); N = n^2, sample (i, j) at
  k_x = n i + j, k_y = n j + (n - 1 - i);
* ``jitter``: stratified: one uniformly random sample in each cell of the
  n x n grid, N = 256;
* ``random``: n^2 uniformly random samples, N = 256.

Positions are rounded to the 1/512 lattice (exact whenever N divides 256,
which holds for jitter, random and n a power of two). Jitter and random
take their numbers from a counter-based hash (SplitMix64's finaliser) of
(seed, x, y, sample): a pixel's samples depend on the seed and the pixel
only, so the generator, the kernel and any window of the grid agree.

Filters (``filter``) weigh the samples of one pixel; the filter's support
is the pixel itself. With h(k) = min(2k + 1, 2N - 2k - 1), which is 2N
times the sample's distance to the nearer pixel border along that axis:

* ``box``: every sample weighs 1 (the unweighted average);
* ``weighted``: w = h(k_x) + h(k_y). For the 4 x 4 grid this is the
  classic weighted kernel 1 2 2 1 / 2 3 3 2 / 2 3 3 2 / 1 2 2 1 (times 2),
  and for an n x n grid in general 1 + d_i + d_j (times 2), where d_i is
  how many samples lie between sample i and the pixel's border: weights
  grow by one per step inward along each axis. For other patterns it is
  the same function of the sample position;
* ``tent``: w = h(k_x) h(k_y), the product of two triangle functions that
  vanish at the pixel border;
* ``gaussian``: w = round(65536 exp(-r^2 / (2 sigma^2))), r the distance
  from the pixel centre in px, at least 1.

All weights are whole numbers W_s; coverage = sum(W_s hit_s) / sum(W_s) is
one correctly rounded division, and the weights normalised, W_s / sum W,
add up to exactly 1.
"""
from __future__ import annotations

import math
from fractions import Fraction

import numpy as np

from algorithms.exact import coverage as exact_coverage
from algorithms import triangles
from algorithms import registry as registry_module
from .interpolate import unpack
from .lines import Octant
from .registry import AlgorithmSpec, InputError, Inputs, Option, register
from .steps import CALC, NO_PIXEL, PLOT, VISIT, CodeLine, Note, Start, Table, Vars

NAN = math.nan
UNIT = 512          # sample lattice: 1/512 px
SNAP = 256          # vertices: 1/256 px
MAX_COORDINATE = 2.0 ** 20
BACKGROUND = (255, 255, 255)
WHITE = 0xFFFFFF
INK = "#000000"

PATTERNS = ("grid", "jitter", "random", "rotated-grid")
FILTERS = ("box", "weighted", "tent", "gaussian")
SHAPES = ("triangles", "polygon", "thick-line")
RULES = ("evenodd", "nonzero")
KERNELS = ("box3", "seed", "gaussian")

POINTS = Inputs(1, integer=False, multiple=True)
SEGMENT = Inputs(2, integer=True, names=("P", "Q"))

SHAPE = Option("shape", "choice", "triangles", "what the points draw: triangles (3k points), "
               "one polygon (all points) or thick lines (2k points, one segment each)",
               choices=SHAPES)
WIDTH = Option("width", "float", 1.0, "width of a thick line, in px", minimum=0.01, maximum=256)
CAPS = Option("caps", "choice", "butt", "ends of a thick line: butt (the rectangle ends at "
              "the endpoints) or square (it goes on for width/2)", choices=exact_coverage.CAPS)
POLYGON_RULE = Option("fill_rule", "choice", "evenodd", "which points a polygon covers: "
                      "evenodd or nonzero winding", choices=RULES)
COLORS = Option("colors", "colors", (), "a colour per shape (repeated when fewer); "
                "black ink when none")
PATTERN = Option("pattern", "choice", "grid", "where the samples lie in the pixel: a grid, "
                 "a jittered (stratified) grid, random, or a rotated grid", choices=PATTERNS)
N = Option("n", "int", 4, "samples per pixel: n x n", minimum=1, maximum=8)
FILTER = Option("filter", "choice", "box", "how the samples of a pixel are weighted: box "
                "(equally), weighted (more toward the centre; the 4 x 4 kernel 1 2 2 1 / "
                "2 3 3 2 / ... for n = 4), tent or gaussian", choices=FILTERS)
SIGMA = Option("sigma", "float", 0.5, "standard deviation of the gaussian filter, in px",
               minimum=0.05, maximum=4)
SEED = Option("seed", "int", 1, "seed of the random and jittered samples",
              minimum=0, maximum=2 ** 31 - 1)
SHAPE_OPTIONS = (SHAPE, WIDTH, CAPS, POLYGON_RULE, COLORS)


# ============================================================ shapes
def _snap(value: float) -> int:
    """A coordinate in 1/512 px units, snapped to the 1/256 px grid (halves to even)."""
    if not abs(value) <= MAX_COORDINATE:
        raise InputError(f"coordinate {value} is beyond +-{MAX_COORDINATE:g} px")
    return 2 * round(value * SNAP)


class Shape:
    """One shape in lattice units: a counter-clockwise triangle, or contours with a rule."""

    def __init__(self, contours, rule: str, color, triangle: bool):
        self.contours = contours            # lists of (X, Y) integer vertices
        self.rule = rule
        self.color = color                  # (r, g, b)
        self.triangle = triangle
        xs = [p[0] for c in contours for p in c]
        ys = [p[1] for c in contours for p in c]
        self.box = (min(xs), min(ys), max(xs), max(ys))
        edges = [(c[k], c[(k + 1) % len(c)]) for c in contours for k in range(len(c))]
        self.edges = [(a[0], a[1], b[0], b[1]) for a, b in edges if a != b]
        if triangle:
            # The fill rule's tie: a sample on edge k counts on a left edge
            # (a > 0) or a bottom one (a == 0, b > 0), as for pixel centres.
            self.keep = []
            for k in range(3):
                (xi, yi), (xj, yj) = contours[0][(k + 1) % 3], contours[0][(k + 2) % 3]
                a, b = yi - yj, xj - xi
                self.keep.append(a > 0 or (a == 0 and b > 0))

    def outline_px(self):
        """The contours in px (exact binary fractions), for the exact reference."""
        return [[(x / UNIT, y / UNIT) for x, y in c] for c in self.contours]

    # ------------------------------------------------------------ tests
    def hit(self, sx: int, sy: int) -> bool:
        """Is the sample (in lattice units) inside? Python integers."""
        if self.triangle:
            tri = self.contours[0]
            for k in range(3):
                (xi, yi), (xj, yj) = tri[(k + 1) % 3], tri[(k + 2) % 3]
                e = (xj - xi) * (sy - yi) - (yj - yi) * (sx - xi)
                if e < 0 or (e == 0 and not self.keep[k]):
                    return False
            return True
        winding = 0
        for ax, ay, bx, by in self.edges:
            if ay <= sy < by and (bx - ax) * (sy - ay) - (by - ay) * (sx - ax) > 0:
                winding += 1
            elif by <= sy < ay and (ax - bx) * (sy - by) - (ay - by) * (sx - bx) > 0:
                winding -= 1
        return winding % 2 == 1 if self.rule == "evenodd" else winding != 0

    def hits(self, sx: np.ndarray, sy: np.ndarray) -> np.ndarray:
        """The same test on int64 arrays of samples."""
        if self.triangle:
            tri = self.contours[0]
            inside = np.ones(sx.shape, bool)
            for k in range(3):
                (xi, yi), (xj, yj) = tri[(k + 1) % 3], tri[(k + 2) % 3]
                e = (xj - xi) * (sy - yi) - (yj - yi) * (sx - xi)
                inside &= (e > 0) | ((e == 0) & self.keep[k])
            return inside
        winding = np.zeros(sx.shape, np.int64)
        for ax, ay, bx, by in self.edges:
            if ay < by:
                band = (sy >= ay) & (sy < by)
                winding += band & ((bx - ax) * (sy - ay) - (by - ay) * (sx - ax) > 0)
            elif by < ay:
                band = (sy >= by) & (sy < ay)
                winding -= band & ((ax - bx) * (sy - by) - (ay - by) * (sx - bx) > 0)
        return (winding % 2 == 1) if self.rule == "evenodd" else (winding != 0)


class Shapes:
    """The shapes a run draws, from its points and shape options."""

    def __init__(self, points, options):
        kind = options.get("shape", "triangles")
        colors = [unpack(c) for c in (options.get("colors") or ())] or [unpack(INK)]
        self.kind = kind
        self.items: list[Shape] = []
        self.degenerate = 0
        points = [(float(x), float(y)) for x, y in points]
        if kind == "triangles":
            if len(points) % 3:
                raise InputError(f"shape triangles: expected a multiple of 3 points, got "
                                 f"{len(points)}")
            for k in range(len(points) // 3):
                tri = [(_snap(x), _snap(y)) for x, y in points[3 * k:3 * k + 3]]
                area = exact_coverage.twice_signed_area(tri)
                if area == 0:
                    self.degenerate += 1
                    continue
                if area < 0:
                    tri = [tri[0], tri[2], tri[1]]
                self.items.append(Shape([tri], "nonzero", colors[k % len(colors)], True))
        elif kind == "polygon":
            if len(points) < 3:
                raise InputError(f"shape polygon: expected at least 3 points, got {len(points)}")
            contour = [(_snap(x), _snap(y)) for x, y in points]
            self.items.append(Shape([contour], options.get("fill_rule", "evenodd"),
                                    colors[0], False))
        elif kind == "thick-line":
            if len(points) % 2:
                raise InputError(f"shape thick-line: expected 2 points per segment, got "
                                 f"{len(points)}")
            for k in range(len(points) // 2):
                corners = exact_coverage.segment_rectangle(
                    points[2 * k], points[2 * k + 1], options.get("width", 1.0),
                    options.get("caps", "butt"))
                rect = [(_snap(x), _snap(y)) for x, y in corners]
                if exact_coverage.twice_signed_area(rect) == 0:
                    self.degenerate += 1
                    continue
                self.items.append(Shape([rect], "nonzero", colors[k % len(colors)], False))
        else:
            raise InputError(f"option shape: unknown shape {kind!r}")

    def window(self, grid) -> tuple[int, int, int, int]:
        """Pixels (x0, y0, x1, y1; x1, y1 excluded) the shapes' boxes reach, within the grid."""
        width, height = int(grid[0]), int(grid[1])
        if not self.items:
            return (0, 0, 0, 0)
        x0 = min(s.box[0] for s in self.items) // UNIT
        y0 = min(s.box[1] for s in self.items) // UNIT
        x1 = max(s.box[2] for s in self.items) // UNIT + 1
        y1 = max(s.box[3] for s in self.items) // UNIT + 1
        x0, y0 = max(x0, 0), max(y0, 0)
        x1, y1 = min(x1, width), min(y1, height)
        return (x0, y0, max(x0, x1), max(y0, y1))

    def mask(self, window) -> np.ndarray:
        """Pixels of the window that some shape's box reaches."""
        x0, y0, x1, y1 = window
        mask = np.zeros((y1 - y0, x1 - x0), bool)
        for s in self.items:
            a, b = max(s.box[0] // UNIT, x0), min(s.box[2] // UNIT + 1, x1)
            c, d = max(s.box[1] // UNIT, y0), min(s.box[3] // UNIT + 1, y1)
            if a < b and c < d:
                mask[c - y0:d - y0, a - x0:b - x0] = True
        return mask

    def owner(self, sx: int, sy: int) -> int:
        """The last shape containing the sample, or -1."""
        for index in range(len(self.items) - 1, -1, -1):
            if self.items[index].hit(sx, sy):
                return index
        return -1

    def owners(self, sx: np.ndarray, sy: np.ndarray) -> np.ndarray:
        result = np.full(sx.shape, -1, np.int64)
        for index, shape in enumerate(self.items):
            result[shape.hits(sx, sy)] = index
        return result

    def outlines_px(self):
        return [shape.outline_px() for shape in self.items]


def reference_coverage(points, options, grid, exact: bool = False) -> np.ndarray:
    """Exact coverage of the snapped shapes a run draws: what the estimates aim at."""
    options = {**{o.name: o.default for o in SHAPE_OPTIONS}, **options}
    shapes = Shapes(points, options)
    if not shapes.items:
        window = exact_coverage.window_of(grid)
        return np.zeros((window[3] - window[1], window[2] - window[0]))
    contours = [c for outline in shapes.outlines_px() for c in outline]
    if shapes.kind == "polygon":
        return exact_coverage.polygon_coverage(contours, grid, shapes.items[0].rule, exact)
    if len(contours) == 1:
        return exact_coverage.polygon_coverage(contours, grid, "signed", exact)
    return exact_coverage.polygon_coverage(contours, grid, "nonzero", exact)


# =========================================================== samples
_GAMMA = np.uint64(0x9E3779B97F4A7C15)


def _mix(z: np.ndarray) -> np.ndarray:
    """SplitMix64's finaliser: a bijection of 64-bit words that scatters every bit."""
    z = z ^ (z >> np.uint64(30))
    z = z * np.uint64(0xBF58476D1CE4E5B9)
    z = z ^ (z >> np.uint64(27))
    z = z * np.uint64(0x94D049BB133111EB)
    return z ^ (z >> np.uint64(31))


def random_bits(seed: int, x, y, stream) -> np.ndarray:
    """32 pseudo-random bits (int64) for each (seed, x, y, stream), from a counter-based hash.

    Each pixel's numbers depend on the seed and the pixel alone, not on the
    order or the window they are asked for in.
    """
    with np.errstate(over="ignore"):
        z = _mix(np.uint64(seed) + _GAMMA)
        for part in (x, y, stream):
            z = _mix(z ^ (np.asarray(part).astype(np.uint64) + _GAMMA))
    return (z >> np.uint64(32)).astype(np.int64)


def sample_strata(pattern: str, n: int, seed: int, y: int, xs: np.ndarray):
    """Per pixel of row y at columns xs: (k_x, k_y) int64 arrays (len(xs), m), and N.

    A sample sits at ((2 k_x + 1) / 2N, (2 k_y + 1) / 2N) of its pixel.
    """
    xs = np.asarray(xs, np.int64)
    if xs.size and (xs.min() < 0 or y < 0):
        raise InputError("samples exist for pixels of the grid only (x, y >= 0)")
    m = n * n
    s = np.arange(m)
    i, j = s % n, s // n
    if pattern == "grid":
        kx, ky, big = i, j, n
    elif pattern == "rotated-grid":
        kx, ky, big = n * i + j, n * j + (n - 1 - i), n * n
    elif pattern in ("jitter", "random"):
        big = SNAP
        sample = np.arange(m, dtype=np.uint64)[None, :]
        r = [random_bits(seed, xs[:, None], y, 2 * sample + axis) for axis in (0, 1)]
        if pattern == "jitter":
            # stratum i of n, then a uniform place in it: floor((i + u) * 256 / n), u = r / 2^32
            kx = (((i[None, :] << 32) + r[0]) * SNAP) // (n << 32)
            ky = (((j[None, :] << 32) + r[1]) * SNAP) // (n << 32)
        else:
            kx, ky = r[0] >> 24, r[1] >> 24  # 0 .. 255
        return kx, ky, big
    else:
        raise InputError(f"option pattern: unknown pattern {pattern!r}")
    kx = np.broadcast_to(np.asarray(kx, np.int64), (len(xs), m))
    ky = np.broadcast_to(np.asarray(ky, np.int64), (len(xs), m))
    return kx, ky, big


def lattice(k: np.ndarray, big: int) -> np.ndarray:
    """Offsets in the pixel, in 1/512 px: (2k + 1) / 2N of 512, rounded (halves up)."""
    return ((2 * k + 1) * UNIT + big) // (2 * big)


def sample_weights(kx, ky, big: int, name: str, sigma: float = 0.5) -> np.ndarray:
    """Whole-number filter weights of samples at strata (kx, ky) of N = big."""
    kx, ky = np.asarray(kx, np.int64), np.asarray(ky, np.int64)
    if name == "box":
        return np.ones(np.broadcast(kx, ky).shape, np.int64)
    hx = np.minimum(2 * kx + 1, 2 * big - 2 * kx - 1)
    hy = np.minimum(2 * ky + 1, 2 * big - 2 * ky - 1)
    if name == "weighted":
        return hx + hy
    if name == "tent":
        return hx * hy
    if name == "gaussian":
        du = (2 * kx + 1 - big) / (2.0 * big)
        dv = (2 * ky + 1 - big) / (2.0 * big)
        w = np.rint(65536.0 * np.exp(-(du * du + dv * dv) / (2.0 * sigma * sigma)))
        return np.maximum(w, 1).astype(np.int64)
    raise InputError(f"option filter: unknown filter {name!r}")


def normalised_weights(pattern, n, name, sigma=0.5, seed=1, x=0, y=0) -> list[Fraction]:
    """The weights of pixel (x, y)'s samples as exact fractions (they add up to 1)."""
    kx, ky, big = sample_strata(pattern, n, seed, y, np.array([x]))
    w = sample_weights(kx[0], ky[0], big, name, sigma)
    total = int(w.sum())
    return [Fraction(int(v), total) for v in w]


def _blend(weighted_channels, total: int) -> int:
    """Packed colour from per-channel sums of weight * channel, rounded half up."""
    r, g, b = ((2 * c + total) // (2 * total) for c in weighted_channels)
    return (int(r) << 16) | (int(g) << 8) | int(b)


def _ink_blend(ink, coverage: float) -> int:
    """Ink over the white background by the coverage."""
    channels = [min(255, max(0, math.floor(255 + (c - 255) * coverage + 0.5))) for c in ink]
    return (channels[0] << 16) | (channels[1] << 8) | channels[2]


# ------------------------------------------------- operation counts
# CodeLine.ops of the antialiasing family. Inside tests are exact integer
# arithmetic on the 1/512 px lattice, so their additions are int_add.
# Conventions:
# * One shape's inside test, in full as the vectorised kernel (Shape.hits)
#   does it: a triangle evaluates three edges e = (xj - xi)(sy - yi) -
#   (yj - yi)(sx - xi) (2 mul, 3 int_add each; the vertex differences are
#   setup) with the sign and the tie test (2 compares each); a polygon or a
#   thick line's rectangle takes, per edge, the band test (2 compares), the
#   cross product and its sign (2 mul, 5 int_add, 1 compare) and the
#   winding step (1 int_add), then the fill rule's test (1 compare).
# * A sample that misses tests every shape. The generators look for the
#   last shape containing a sample, from the last one back, and stop
#   there: a hit counts that one shape's test only (exact with one shape, a
#   lower bound with more).
# * A sample's position x * 512 + offset, per axis: 1 mul, 1 int_add.
# * Setup lines (snapping, weights tables) and loops that yield no frame
#   of their own are not counted; a pixel loop's step and test (1 int_add,
#   1 compare) and its bounding-box mask test (1 compare) go with the
#   pixel's frame. The display colour (the ink blended over white for the
#   colour buffer) is not counted where the pseudo-code writes a coverage.
LOOP = {"int_add": 1, "compare": 1}
POSITION = {"mul": 2, "int_add": 2}


def _ops_sum(*parts, times: int = 1) -> dict:
    total = {}
    for part in parts:
        for name, count in part.items():
            total[name] = total.get(name, 0) + count * times
    return {name: count for name, count in total.items() if count}


def _shape_test_ops(shape: Shape) -> dict:
    if shape.triangle:
        return {"mul": 6, "int_add": 9, "compare": 6}
    edges = len(shape.edges)
    return {"mul": 2 * edges, "int_add": 6 * edges, "compare": 3 * edges + 1}


def _test_ops(shapes: Shapes | None) -> tuple[dict, dict]:
    """(one hit's test, one miss's test): the last shape's, and every shape's."""
    if shapes is None or not shapes.items:
        return {}, {}
    every = _ops_sum(*(_shape_test_ops(s) for s in shapes.items))
    return _shape_test_ops(shapes.items[-1]), every


def _code_shapes(points, options) -> Shapes | None:
    try:
        return Shapes(points, options)
    except (InputError, ValueError, TypeError):
        return None


def _sample_ops(hit: bool, test: dict, extra: dict | None = None) -> dict:
    """One sample frame: the position, the test, the hit/miss compare, the loop."""
    return _ops_sum({"samples": 1, "compare": 1}, POSITION, test, LOOP, extra or {})


# ==================================================== supersampling
def supersample_image(points, options, grid, colors: bool = True):
    """Vectorised supersampling: (coverage (H, W) float64, colour (H, W) int64 or None).

    Pixels outside every shape's box have coverage 0 and the background
    colour. Rows go in blocks of about a million samples; each shape is
    tested only on the samples of its own bounding box.
    """
    options = {**{o.name: o.default for o in SUPERSAMPLE_OPTIONS}, **options}
    shapes = Shapes(points, options)
    width, height = int(grid[0]), int(grid[1])
    coverage = np.zeros((height, width))
    rgb = np.full((height, width), WHITE, np.int64) if colors else None
    x0, y0, x1, y1 = shapes.window(grid)
    if x1 <= x0 or y1 <= y0:
        return coverage, rgb
    n, pattern, name = options["n"], options["pattern"], options["filter"]
    xs = np.arange(x0, x1, dtype=np.int64)
    palette = np.array([s.color for s in shapes.items] + [BACKGROUND], np.int64)
    boxes = [(s.box[0] // UNIT, s.box[1] // UNIT, s.box[2] // UNIT + 1, s.box[3] // UNIT + 1)
             for s in shapes.items]
    rows_per_block = max(1, (1 << 20) // (len(xs) * n * n))
    for top in range(y0, y1, rows_per_block):
        bottom = min(top + rows_per_block, y1)
        strata = [sample_strata(pattern, n, options["seed"], y, xs) for y in range(top, bottom)]
        big = strata[0][2]
        kx = np.stack([k[0] for k in strata])
        ky = np.stack([k[1] for k in strata])
        w = sample_weights(kx, ky, big, name, options["sigma"])
        sx = xs[None, :, None] * UNIT + lattice(kx, big)
        sy = np.arange(top, bottom, dtype=np.int64)[:, None, None] * UNIT + lattice(ky, big)
        owner = np.full(sx.shape, -1, np.int64)
        for index, (shape, box) in enumerate(zip(shapes.items, boxes)):
            c0, c1 = max(box[0], x0) - x0, min(box[2], x1) - x0
            r0, r1 = max(box[1], top) - top, min(box[3], bottom) - top
            if c0 >= c1 or r0 >= r1:
                continue
            part = owner[r0:r1, c0:c1]
            part[shape.hits(sx[r0:r1, c0:c1], sy[r0:r1, c0:c1])] = index
        total = w.sum(axis=2)
        coverage[top:bottom, x0:x1] = (w * (owner >= 0)).sum(axis=2) / total
        if colors:
            sums = (w[..., None] * palette[owner]).sum(axis=2)  # owner -1: the background
            channels = (2 * sums + total[..., None]) // (2 * total[..., None])
            rgb[top:bottom, x0:x1] = ((channels[..., 0] << 16) | (channels[..., 1] << 8)
                                      | channels[..., 2])
    return coverage, rgb


def supersample_code(points, options):
    hit_test, miss_test = _test_ops(_code_shapes(points, options))
    m = options.get("n", 4) ** 2
    # Each sample adds w_s times the colour it takes (3 mul, 3 int_add); a
    # hit also adds w_s to cover. The pixel's frame carries W = sum of w_s
    # (m - 1 int_add), cover / W (1 div), colour / W rounded half up per
    # channel ((2 c + W) // 2W: 2 mul, 1 int_add, 1 div), the cover > 0
    # test, the pixel loop and its mask test; its samples' results are
    # looked at: one pixel tested.
    accumulate = {"mul": 3, "int_add": 3}
    pixel = _ops_sum({"int_add": m - 1 + 3, "div": 4, "mul": 6, "compare": 1,
                      "pixels_tested": 1}, LOOP, {"compare": 1})
    return (
        CodeLine("setup: snap the vertices to 1/256 px;  samples s of the pattern with filter "
                 "weights w_s (whole numbers);  W = sum of w_s"),
        CodeLine("for each pixel (x, y) the shapes' bounding boxes reach, row by row:"),
        CodeLine("    cover = 0;  colour = 0;  for each sample s at (x + u_s, y + v_s):"),
        CodeLine("        if s is inside a shape:  cover += w_s;  colour += w_s * colour of "
                 "the last shape containing s", VISIT, "hit",
                 ops=_sample_ops(True, hit_test, _ops_sum(accumulate, {"int_add": 1}))),
        CodeLine("        else:  colour += w_s * background", VISIT, "miss",
                 ops=_sample_ops(False, miss_test, accumulate)),
        CodeLine("    coverage = cover / W;  if coverage > 0: write (x, y) with coverage and "
                 "colour / W", PLOT, ops=pixel),
        CodeLine("    else: nothing covers the pixel's samples", VISIT, ops=pixel),
        CodeLine("done"),
    )


def _shape_vars(shapes: Shapes, line: int):
    values = {}
    prefix = {"triangles": "T", "polygon": "polygon", "thick-line": "line"}[shapes.kind]
    for number, outline in enumerate(shapes.outlines_px()):
        name = prefix if shapes.kind == "polygon" else f"{prefix}{number + 1}"
        values[name] = tuple(outline[0])
    yield Vars(line, values)
    if shapes.degenerate:
        yield Note(line, f"{shapes.degenerate} shape(s) have no area once snapped and "
                         "cover nothing.")


def _sample_table(options, line: int):
    pattern, n, name = options["pattern"], options["n"], options["filter"]
    if pattern in ("jitter", "random"):
        return Note(line, f"{pattern}: every pixel has samples of its own (seed "
                          f"{options['seed']}); the values sx, sy show each one.")
    kx, ky, big = sample_strata(pattern, n, options["seed"], 0, np.array([0]))
    w = sample_weights(kx[0], ky[0], big, name, options["sigma"])
    total = int(w.sum())
    rows = tuple((s + 1, f"{2 * int(a) + 1}/{2 * big}", f"{2 * int(b) + 1}/{2 * big}", int(v),
                  f"{Fraction(int(v), total)}")
                 for s, (a, b, v) in enumerate(zip(kx[0], ky[0], w)))
    return Table(line, "samples", ("s", "u", "v", "w", "w / W"), rows)


def supersample(points, options, grid):
    shapes = Shapes(points, options)
    n, pattern, name = options["n"], options["pattern"], options["filter"]
    constants = {"pattern": pattern, "n": n, "samples per pixel": n * n, "filter": name,
                 "shape": shapes.kind}
    if pattern in ("jitter", "random"):
        constants["seed"] = options["seed"]
    if name == "gaussian":
        constants["sigma"] = options["sigma"]
    if shapes.kind == "polygon":
        constants["fill_rule"] = options["fill_rule"]
    yield Start(0, ("sx", "sy", "hit", "weight", "coverage", "rgb"), constants,
                pixel_value="coverage", color_value="rgb")
    yield from _shape_vars(shapes, 0)
    yield _sample_table(options, 0)
    window = shapes.window(grid)
    x0, y0, x1, y1 = window
    mask = shapes.mask(window)
    xs = np.arange(x0, x1, dtype=np.int64)
    tested = written = 0
    area = 0.0
    nothing = (NAN,) * 4
    for y in range(y0, y1):
        kx, ky, big = sample_strata(pattern, n, options["seed"], y, xs)
        weights = sample_weights(kx, ky, big, name, options["sigma"])
        offsets_x, offsets_y = lattice(kx, big), lattice(ky, big)
        for column, x in enumerate(range(x0, x1)):
            if not mask[y - y0, column]:
                continue
            w = [int(v) for v in weights[column]]
            total = sum(w)
            cover = 0
            sums = [0, 0, 0]
            for s in range(len(w)):
                sx = x * UNIT + int(offsets_x[column, s])
                sy = y * UNIT + int(offsets_y[column, s])
                owner = shapes.owner(sx, sy)
                tested += 1
                color = shapes.items[owner].color if owner >= 0 else BACKGROUND
                for c in range(3):
                    sums[c] += w[s] * color[c]
                if owner >= 0:
                    cover += w[s]
                yield (3 if owner >= 0 else 4, x, y, sx / UNIT, sy / UNIT,
                       1.0 if owner >= 0 else 0.0, w[s] / total, cover / total, NAN)
            coverage = cover / total
            rgb = float(_blend(sums, total))
            if cover:
                written += 1
                area += coverage
                yield (5, x, y, *nothing, coverage, rgb)
            else:
                yield (6, x, y, *nothing, 0.0, rgb)
    yield Vars(7, {"pixels": written, "samples": tested, "area": area})


# ======================================================== explanations
def _outline_vars(variables) -> list:
    outlines = []
    for name, value in variables.items():
        if (name.startswith("T") or name.startswith("line") or name == "polygon") \
                and isinstance(value, tuple) and value and isinstance(value[0], tuple):
            outlines.append(list(value))
    return outlines


def _exact_pixel(variables, x: int, y: int):
    """Exact coverage of pixel (x, y) by the shapes named in the run's variables."""
    outlines = _outline_vars(variables)
    if not outlines:
        return None
    window = (x, y, x + 1, y + 1)
    shape = variables.get("shape")
    if shape == "polygon":
        rule = variables.get("fill_rule", "evenodd")
        return float(exact_coverage.polygon_coverage(outlines, window, rule)[0, 0])
    rule = "signed" if len(outlines) == 1 else "nonzero"
    return float(exact_coverage.polygon_coverage(outlines, window, rule)[0, 0])


def explain_samples(trace, i):
    """Where the sample lies in its pixel; for a pixel, the exact coverage and the error."""
    step = trace.step(i)
    if step.pixel is None:
        return []
    x, y = step.pixel
    rows = []
    if "sx" in step.values:
        u, v = step.values["sx"] - x, step.values["sy"] - y
        rows.append(("in the pixel", f"u = {Fraction(u).limit_denominator(UNIT)}, "
                                     f"v = {Fraction(v).limit_denominator(UNIT)}"))
        if "weight" in step.values:
            rows.append(("w_s / W", f"{step.values['weight']:.6g}"))
        return rows
    if "coverage" in step.values and step.kind in (PLOT, VISIT):
        exact = _exact_pixel(trace.variables_at(i), x, y)
        if exact is not None:
            estimate = step.values["coverage"]
            rows.append(("exact coverage", f"{exact:.6f}"))
            rows.append(("error", f"{estimate - exact:+.6f}"))
    if "rgb" in step.values:
        rows.append(("colour", f"#{int(step.values['rgb']):06x}"))
    return rows


# ============================================================ adaptive
def adaptive_code(points, options):
    depth = options.get("max_depth", 3)
    hit_test, miss_test = _test_ops(_code_shapes(points, options))
    # A new point: the cache lookup (1 compare), the test, the hit/miss
    # compare, the position and the counter (1 int_add); a point already
    # tested in the pixel yields no frame, its lookup is counted with the
    # square's decision. Every square ends on line 5 or 6, which carries
    # half the size (1 div), the four corner and centre coordinates (4
    # int_add), the five lookups (5 compare), hits += hit (5 int_add) and
    # the agree and level tests (3 compare). Line 5 adds hits / 5 (1 div);
    # line 6 the quarters' origins (2 int_add), their levels (4 int_add)
    # and the mean of four (4 float_add, 1 div).
    square = {"div": 1, "int_add": 9, "compare": 8}
    new = {"compare": 1, "int_add": 1}
    # The pixel: float(value) (1 div), value > 0, the bookkeeping of
    # samples spent (total, most, split: 2 int_add, 2 compare), the loop
    # and the mask test; the pixel's samples are looked at: one pixel tested.
    pixel = _ops_sum({"div": 1, "compare": 3, "int_add": 2, "pixels_tested": 1}, LOOP,
                     {"compare": 1})
    return (
        CodeLine("setup: snap the vertices to 1/256 px"),
        CodeLine("for each pixel (x, y) the shapes' bounding boxes reach:  refine(the pixel "
                 "square, level 0)"),
        CodeLine("refine(square, level): test its four corners and its centre (a point "
                 "already tested in this pixel is not tested again):"),
        CodeLine("    sample inside a shape", VISIT, "hit",
                 ops=_ops_sum({"samples": 1, "compare": 1}, POSITION, hit_test, new)),
        CodeLine("    sample outside", VISIT, "miss",
                 ops=_ops_sum({"samples": 1, "compare": 1}, POSITION, miss_test, new)),
        CodeLine(f"    if the five agree, or level == {depth}: value = (hits among the five) / 5",
                 ops=_ops_sum(square, {"div": 1})),
        CodeLine("    else: split the square into four;  value = mean of refine(quarter, "
                 "level + 1)", CALC, "split",
                 ops=_ops_sum(square, {"int_add": 6, "float_add": 4, "div": 1})),
        CodeLine("coverage = value;  if coverage > 0: write (x, y)", PLOT, ops=pixel),
        CodeLine("else: nothing to write", VISIT, ops=pixel),
        CodeLine("done"),
    )


class _Adaptive:
    def __init__(self, shapes, max_depth):
        self.shapes = shapes
        self.max_depth = max_depth

    def refine(self, x, y, ox, oy, size, level, cache, counter):
        """Frames of one square; returns its value as a Fraction."""
        half = size // 2
        corners = ((ox, oy), (ox + size, oy), (ox, oy + size), (ox + size, oy + size),
                   (ox + half, oy + half))
        hits = 0
        for px, py in corners:
            hit = cache.get((px, py))
            if hit is None:
                sx, sy = x * UNIT + px, y * UNIT + py
                hit = self.shapes.owner(sx, sy) >= 0
                cache[(px, py)] = hit
                counter[0] += 1
                yield (3 if hit else 4, x, y, sx / UNIT, sy / UNIT, 1.0 if hit else 0.0,
                       float(level), NAN, NAN, NAN, NAN)
            hits += hit
        if hits in (0, 5) or level >= self.max_depth:
            value = Fraction(hits, 5)
            yield (5, x, y, NAN, NAN, NAN, float(level), float(value), NAN, NAN, NAN)
            return value
        yield (6, x, y, NAN, NAN, NAN, float(level), NAN, NAN, NAN, NAN)
        total = Fraction(0)
        for qx, qy in ((ox, oy), (ox + half, oy), (ox, oy + half), (ox + half, oy + half)):
            total += yield from self.refine(x, y, qx, qy, half, level + 1, cache, counter)
        return total / 4


def adaptive(points, options, grid):
    shapes = Shapes(points, options)
    depth = options["max_depth"]
    # The corners of the finest squares and their centres: the most a pixel can take.
    constants = {"max_depth": depth, "shape": shapes.kind,
                 "at most per pixel": (2 ** depth + 1) ** 2 + 4 ** depth}
    if shapes.kind == "polygon":
        constants["fill_rule"] = options["fill_rule"]
    yield Start(0, ("sx", "sy", "hit", "level", "value", "samples", "coverage", "rgb"),
                constants, pixel_value="coverage", color_value="rgb")
    yield from _shape_vars(shapes, 0)
    window = shapes.window(grid)
    x0, y0, x1, y1 = window
    mask = shapes.mask(window)
    ink = shapes.items[0].color if shapes.items else unpack(INK)
    engine = _Adaptive(shapes, depth)
    total = written = split = most = 0
    for y in range(y0, y1):
        for x in range(x0, x1):
            if not mask[y - y0, x - x0]:
                continue
            counter = [0]
            value = yield from engine.refine(x, y, 0, 0, UNIT, 0, {}, counter)
            spent = counter[0]
            total += spent
            most = max(most, spent)
            split += spent > 5
            coverage = float(value)
            line = 7 if value > 0 else 8
            written += value > 0
            yield (line, x, y, NAN, NAN, NAN, NAN, NAN, float(spent), coverage,
                   float(_ink_blend(ink, coverage)))
    yield Vars(9, {"pixels": written, "samples": total, "subdivided": split,
                   "most in a pixel": most})


def adaptive_image(points, options, grid) -> tuple[np.ndarray, np.ndarray]:
    """(coverage, samples spent) per pixel, (H, W), from the adaptive generator."""
    options = {**{o.name: o.default for o in ADAPTIVE_OPTIONS}, **options}
    coverage = np.zeros((int(grid[1]), int(grid[0])))
    spent = np.zeros((int(grid[1]), int(grid[0])), np.int64)
    for frame in adaptive(points, options, grid):
        if type(frame) is tuple and frame[0] in (7, 8):
            coverage[frame[2], frame[1]] = frame[9]
            spent[frame[2], frame[1]] = int(frame[8])
    return coverage, spent


# ========================================================= post-filter
def filter_kernel(name: str, sigma: float = 0.8) -> np.ndarray:
    """Whole-number convolution weights, (2r + 1) x (2r + 1), row 0 at the bottom."""
    if name == "box3":
        return np.ones((3, 3), np.int64)
    if name == "seed":
        return np.array([[1, 4, 1], [4, 16, 4], [1, 4, 1]], np.int64)
    if name == "gaussian":
        r = max(1, math.ceil(3 * sigma))
        d = np.arange(-r, r + 1)
        g = np.exp(-(d[:, None] ** 2 + d[None, :] ** 2) / (2.0 * sigma * sigma))
        return np.rint(65536.0 * g).astype(np.int64)
    raise InputError(f"option kernel: unknown kernel {name!r}")


def aliased_image(points, options, grid) -> np.ndarray:
    """1 where the triangles cover the pixel centre (the fill rule of the triangle family)."""
    counts = triangles.fill(points, (int(grid[0]), int(grid[1])),
                            options.get("fill_rule", "top-left"))
    return (counts > 0).astype(np.int64)


def filter_sums(image: np.ndarray, kernel: np.ndarray) -> np.ndarray:
    """sum over (u, v) of K[v, u] I[y + v, x + u] for every pixel; zeros beyond the grid."""
    r = kernel.shape[0] // 2
    height, width = image.shape
    padded = np.zeros((height + 2 * r, width + 2 * r), np.int64)
    padded[r:r + height, r:r + width] = image
    sums = np.zeros((height, width), np.int64)
    for v in range(-r, r + 1):
        for u in range(-r, r + 1):
            weight = int(kernel[v + r, u + r])
            if weight:
                sums += weight * padded[r + v:r + v + height, r + u:r + u + width]
    return sums


def filter_image(points, options, grid) -> np.ndarray:
    """Vectorised aa-filter: the filtered aliased image, values 0..1."""
    options = {**{o.name: o.default for o in FILTER_OPTIONS}, **options}
    kernel = filter_kernel(options["kernel"], options["sigma"])
    return filter_sums(aliased_image(points, options, grid), kernel) / int(kernel.sum())


def filter_code(points, options):
    kernel = options.get("kernel", "seed")
    text = {"box3": "K = 1/9 [1 1 1; 1 1 1; 1 1 1]",
            "seed": "K = 1/36 [1 4 1; 4 16 4; 1 4 1]",
            "gaussian": f"K = exp(-(u^2 + v^2) / 2 sigma^2), sigma = {options.get('sigma', 0.8):g},"
                        " as whole numbers, divided by their sum"}[kernel]
    # Line 1: each covered centre is one frame of the aliased triangle
    # rasterizer: e_k at the centre (6 mul, 6 int_add), three sign tests, one
    # pixel tested. Counted per unit of the frame's coverage, which is 1 on
    # every such frame, so the summary record on line 1 counts nothing;
    # centres the triangles miss yield no frame and are not counted.
    # Line 3: every tap of the kernel, (2r + 1)^2 of them, reads I: its
    # position (2 int_add), the bounds tests in full (4 compares), the test
    # of I (1 compare, one pixel tested) and the tap loop (1 int_add, 1
    # compare); a covered tap adds its weight and counts itself (2 int_add,
    # per value taps); then out = acc / sum (1 div). The kernel's weights
    # and the reach mask are setup, not counted.
    radius = 1
    try:
        radius = filter_kernel(kernel, options.get("sigma", 0.8)).shape[0] // 2
    except InputError:
        pass
    taps = (2 * radius + 1) ** 2
    tap = {"int_add": 3, "compare": 6, "pixels_tested": 1}
    return (
        CodeLine(f"setup: {text}"),
        CodeLine("aliased image: I[x, y] = 1 where the triangles cover the pixel centre", PLOT,
                 per={"coverage": {"mul": 6, "int_add": 6, "compare": 3,
                                   "pixels_tested": 1}}),
        CodeLine("for each pixel (x, y) that the kernel reaches from a covered pixel, row by "
                 "row:"),
        CodeLine("    out[x, y] = sum over (u, v) of K[u, v] * I[x + u, y + v];  write (x, y) "
                 "with out[x, y]", PLOT, ops=_ops_sum(tap, times=taps) | {"div": 1},
                 per={"taps": {"int_add": 2}}),
        CodeLine("done"),
    )


def post_filter(points, options, grid):
    kernel = filter_kernel(options["kernel"], options["sigma"])
    total = int(kernel.sum())
    r = kernel.shape[0] // 2
    constants = {"kernel": options["kernel"], "size": f"{2 * r + 1} x {2 * r + 1}",
                 "kernel sum": total}
    if options["kernel"] == "gaussian":
        constants["sigma"] = options["sigma"]
    yield Start(0, ("coverage", "taps", "rgb"), constants, pixel_value="coverage",
                color_value="rgb")
    rows = tuple((v, *(int(kernel[v + r, u + r]) for u in range(-r, r + 1)))
                 for v in range(r, -r - 1, -1))
    yield Table(0, "kernel", ("v \\ u", *(str(u) for u in range(-r, r + 1))), rows)
    yield from _shape_vars(Shapes(points, {"shape": "triangles"}), 0)
    image = aliased_image(points, options, grid)
    height, width = image.shape
    ink = unpack(INK)
    for y, x in np.argwhere(image):
        yield (1, int(x), int(y), 1.0, NAN, float(_ink_blend(ink, 1.0)))
    yield Vars(1, {"aliased pixels": int(image.sum())})
    reach = filter_sums(image, (kernel > 0).astype(np.int64)) > 0
    written = 0
    for y, x in np.argwhere(reach):
        y, x = int(y), int(x)
        acc = taps = 0
        for v in range(-r, r + 1):
            for u in range(-r, r + 1):
                if 0 <= y + v < height and 0 <= x + u < width and image[y + v, x + u]:
                    acc += int(kernel[v + r, u + r])
                    taps += 1
        value = acc / total
        written += 1
        yield (3, x, y, value, float(taps), float(_ink_blend(ink, value)))
    yield Vars(4, {"pixels": written})


# ============================================================== lines
def _ink_grey(intensity: float) -> float:
    return float(_ink_blend((0, 0, 0), intensity))


def wu_code(points, options):
    gap = options.get("endpoints", "full") == "gap"
    scale = "  (x 1/2 in the two end columns)" if gap else ""
    # Line 0 maps into octant 1 as the line family does (2 int_add for the
    # differences, 3 compares). It runs once, so the resets e -= dx; y += 1
    # of line 5, which happen about dy times along the line, are counted
    # there by its constant dy (2 int_add each). Each column's intensities
    # are worked out once, with the near pixel's frame: f = e/dx and 1 -
    # e/dx as (dx - e)/dx (1 int_add, 2 div), and in gap mode the end-column
    # test (2 compares) and the scaling (2 mul). Every pixel frame maps
    # (u, v) back to the grid (4 mul, 4 int_add) and tests intensity > 0.
    # Line 5 carries e += dy, the test e >= dx and the column loop.
    column = _ops_sum({"int_add": 1, "div": 2}, {"compare": 2, "mul": 2} if gap else {})
    pixel = {"mul": 4, "int_add": 4, "compare": 1}
    return (
        CodeLine("map P, Q into octant 1:  dx = major extent, dy = minor extent;  e = 0;  "
                 "y = y0   (the ideal line is at y + e/dx)", ops={"int_add": 2, "compare": 3},
                 per={"dy": {"int_add": 2}}),
        CodeLine("for x = x0 .. x1:"),
        CodeLine(f"    plot(x, y, 1 - e/dx){scale}", PLOT, "near", ops=_ops_sum(pixel, column)),
        CodeLine(f"    plot(x, y + 1, e/dx){scale}", PLOT, "far", ops=pixel),
        CodeLine("    (intensity 0: the line passes exactly through this centre; nothing "
                 "written)", VISIT, ops=pixel),
        CodeLine("    e += dy;  if e >= dx:  e -= dx;  y += 1", ops=_ops_sum({"int_add": 1,
                                                                                "compare": 1},
                                                                               LOOP)),
        CodeLine("done"),
    )


def wu(points, options):
    p, q = points
    octant = Octant(p, q)
    dx, dy = octant.dx, octant.dy
    gap = options["endpoints"] == "gap"
    yield Start(0, ("e", "f", "intensity", "rgb"), {"dx": dx, "dy": dy, "octant": octant.number,
                                                     "endpoints": options["endpoints"]},
                pixel_value="intensity", color_value="rgb")
    if dx == 0:
        yield (2, p[0], p[1], 0.0, 0.0, 1.0, _ink_grey(1.0))
        yield Vars(6, {"pixels": 1})
        return
    e = v = 0
    written = 0
    for u in range(dx + 1):
        scale = 0.5 if gap and u in (0, dx) else 1.0
        f = e / dx
        near = (dx - e) / dx * scale
        far = e / dx * scale
        for line, offset, intensity in ((2, 0, near), (3, 1, far)):
            x, y = octant.to_grid(p, u, v + offset)
            if intensity > 0:
                written += 1
                yield (line, x, y, float(e), f, intensity, _ink_grey(intensity))
            else:
                yield (4, x, y, float(e), f, 0.0, NAN)
        e += dy
        if e >= dx:
            e -= dx
            v += 1
        yield (5, NO_PIXEL, NO_PIXEL, float(e), NAN, NAN, NAN)
    yield Vars(6, {"pixels": written})


def wu_image(points, options) -> dict:
    """{(x, y): intensity} of Wu's line (the sum where a pixel is written twice)."""
    options = {**{o.name: o.default for o in WU_OPTIONS}, **options}
    result = {}
    for frame in wu(points, options):
        if type(frame) is tuple and frame[0] in (2, 3):
            result[(frame[1], frame[2])] = result.get((frame[1], frame[2]), 0.0) + frame[5]
    return result


def area_code(points, options):
    caps = options.get("caps", "butt")
    # The areas come from the exact coverage reference, vectorised over the
    # rectangle's window: per pixel a running sum down its column (1
    # float_add) and, where an edge of R crosses the pixel, the mean of a
    # clamped linear function over the crossing (2 mul, 1 div, 6 float_add,
    # 6 compares). One crossing per pixel is counted: R's two long edges
    # cross the pixels along its border and none cross the inner ones, so
    # this is an estimate. The near pixel's frame also tests a > 0 (1
    # compare) and a written one adds a to the column total (1 float_add);
    # line 4 closes a column (the loop step and test). The rectangle's
    # corners (line 0: 4 mul, 1 sqrt, 1 div, 8 float_add for the unit
    # direction and the offsets) are computed once, with the Start record.
    area = {"float_add": 7, "mul": 2, "div": 1, "compare": 7, "pixels_tested": 1}
    return (
        CodeLine(f"R = the rectangle of the segment between the centres of P and Q, widened by "
                 f"w/2 on each side{'' if caps == 'butt' else ' and at each end'}",
                 ops={"mul": 4, "sqrt": 1, "div": 1, "float_add": 8}),
        CodeLine("for each column along the major axis, from P's side to Q's:"),
        CodeLine("    for each pixel of the column that R reaches:  a = area(R and the pixel "
                 "square);  plot(x, y, a)", PLOT, ops=_ops_sum(area, {"float_add": 1}, LOOP)),
        CodeLine("        (a = 0: R only touches the pixel; nothing written)", VISIT,
                 ops=_ops_sum(area, LOOP)),
        CodeLine("    column total = sum of a   (= w * length / dx where R crosses the "
                 "whole column)", ops=LOOP),
        CodeLine("done"),
    )


def segment_window(p, q, width, caps):
    corners = exact_coverage.segment_rectangle((p[0] + 0.5, p[1] + 0.5),
                                               (q[0] + 0.5, q[1] + 0.5), width, caps)
    xs = [c[0] for c in corners]
    ys = [c[1] for c in corners]
    return (math.floor(min(xs)), math.floor(min(ys)), math.ceil(max(xs)) + 1,
            math.ceil(max(ys)) + 1)


def area_image(points, options, exact: bool = False):
    """(window, coverage) of the line's rectangle: pixel (x, y) is coverage[y - y0, x - x0]."""
    options = {**{o.name: o.default for o in AREA_OPTIONS}, **options}
    p, q = points
    window = segment_window(p, q, options["width"], options["caps"])
    coverage = exact_coverage.segment_coverage((p[0] + 0.5, p[1] + 0.5), (q[0] + 0.5, q[1] + 0.5),
                                               options["width"], window, options["caps"], exact)
    return window, coverage


def line_area(points, options):
    p, q = points
    octant = Octant(p, q)
    window, coverage = area_image(points, options)
    x0, y0, _, _ = window
    yield Start(0, ("intensity", "column", "rgb"),
                {"width": options["width"], "caps": options["caps"], "octant": octant.number},
                pixel_value="intensity", color_value="rgb")
    steep = octant.steep
    major_sign = octant.major[1] if steep else octant.major[0]
    minor_sign = octant.minor_sign
    origin_major, origin_minor = (y0, x0) if steep else (x0, y0)
    # The coverage laid out as [major][minor], whatever the slope.
    table = coverage if steep else coverage.T
    columns = [c for c in range(table.shape[0]) if table[c].any()]
    columns.sort(key=lambda c: major_sign * c)
    written = 0
    total_area = 0.0
    for c in columns:
        line_values = table[c]
        nonzero = np.flatnonzero(line_values)
        rows = range(int(nonzero.min()), int(nonzero.max()) + 1)
        rows = sorted(rows, key=lambda r: minor_sign * r)
        column_total = 0.0
        for r in rows:
            a = float(line_values[r])
            major, minor = origin_major + c, origin_minor + r
            x, y = (minor, major) if steep else (major, minor)
            if a > 0:
                column_total += a
                written += 1
                yield (2, x, y, a, column_total, _ink_grey(a))
            else:
                yield (3, x, y, 0.0, column_total, NAN)
        total_area += column_total
        yield (4, NO_PIXEL, NO_PIXEL, NAN, column_total, NAN)
    yield Vars(5, {"pixels": written, "area": total_area,
                   "rectangle area": options["width"] * math.hypot(q[0] - p[0], q[1] - p[1])
                   + (options["width"] ** 2 if options["caps"] == "square" else 0.0)})


# ============================================================ temporal
def _temporal_shapes(points, options, t: float) -> Shapes:
    """The primitive at time t (in frames), as shapes."""
    kind = _primitive(points, options)
    speed = options["speed"]
    if kind == "wheel":
        (cx, cy), = points
        angle = math.radians(options["phase"] + speed * t) if options["motion"] == "spin" \
            else math.radians(options["phase"])
        shift = speed * t if options["motion"] == "move" else 0.0
        spokes = []
        for k in range(options["spokes"]):
            a = angle + 2 * math.pi * k / options["spokes"]
            radius = options["radius"]
            spokes += [(cx + shift, cy), (cx + shift + radius * math.cos(a), cy + radius * math.sin(a))]
        return Shapes(spokes, {"shape": "thick-line", "width": options["spoke_width"],
                               "caps": "butt"})
    if options["motion"] == "spin":
        cx = sum(p[0] for p in points) / 3
        cy = sum(p[1] for p in points) / 3
        a = math.radians(speed * t)
        c, s = math.cos(a), math.sin(a)
        moved = [(cx + c * (x - cx) - s * (y - cy), cy + s * (x - cx) + c * (y - cy))
                 for x, y in points]
    else:
        moved = [(x + speed * t, y) for x, y in points]
    return Shapes(moved, {"shape": "triangles"})


def _primitive(points, options) -> str:
    kind = options.get("primitive", "auto")
    if kind == "auto":
        if len(points) not in (1, 3):
            raise InputError(f"aa-temporal: expected 1 point (a wheel's centre) or 3 (a "
                             f"triangle), got {len(points)}")
        kind = "wheel" if len(points) == 1 else "triangle"
    expected = 1 if kind == "wheel" else 3
    if len(points) != expected:
        raise InputError(f"primitive {kind}: expected {expected} point"
                         f"{'' if expected == 1 else 's'}"
                         f"{' (the centre)' if kind == 'wheel' else ''}, got {len(points)}")
    return kind


def time_samples(options, frame: int) -> list[float]:
    """The instants (in frames) a frame's image averages."""
    if options["mode"] == "instant":
        return [float(frame)]
    count, shutter = options["time_samples"], options["shutter"]
    return [frame + shutter * (s + 0.5) / count for s in range(count)]


def temporal_frames(points, options, grid) -> list[np.ndarray]:
    """Image k of the animation, coverage (H, W) float64, for k = 0 .. frames - 1."""
    options = {**{o.name: o.default for o in TEMPORAL_OPTIONS}, **options}
    points = [tuple(map(float, p)) for p in points]
    width, height = int(grid[0]), int(grid[1])
    n = options["n"]
    images = []
    xs = np.arange(width, dtype=np.int64)
    kx, ky, big = sample_strata("grid", n, 0, 0, xs)
    ox, oy = lattice(kx[0], big), lattice(ky[0], big)
    for frame in range(options["frames"]):
        instants = time_samples(options, frame)
        hits = np.zeros((height, width), np.int64)
        for t in instants:
            shapes = _temporal_shapes(points, options, t)
            x0, y0, x1, y1 = shapes.window((width, height))
            if x1 <= x0 or y1 <= y0:
                continue
            cols = np.arange(x0, x1, dtype=np.int64)
            rows = np.arange(y0, y1, dtype=np.int64)
            sx = cols[None, :, None] * UNIT + ox[None, None, :]
            sy = rows[:, None, None] * UNIT + oy[None, None, :]
            sx, sy = np.broadcast_arrays(sx, sy)
            inside = shapes.owners(sx, sy) >= 0
            hits[y0:y1, x0:x1] += inside.sum(axis=2)
        images.append(hits / (len(instants) * n * n))
    return images


def apparent_speed(points, options) -> float:
    """The motion the frames seem to show, per frame: the speed folded into one period."""
    if options["motion"] == "move":
        return float(options["speed"])
    period = 360.0 / options["spokes"] if _primitive(points, options) == "wheel" else 360.0
    return float((options["speed"] + period / 2) % period - period / 2)


def temporal_code(points, options):
    blur = options.get("mode", "instant") == "motion-blur"
    sample = (f"average over {options.get('time_samples', 8)} instants t = k + shutter (s + 1/2) "
              f"/ {options.get('time_samples', 8)}" if blur else "one instant t = k")
    # Every pixel frame of line 2 stands for the pixel's n^2 samples at each
    # of the frame's instants, each tested against every shape (the images
    # come from the vectorised kernel, which tests them all), at its
    # position (POSITION) and summed (1 int_add); then one division. Pixels
    # the primitive's window reaches but that show nothing in this frame or
    # the last yield no frame and are not counted, nor is moving the
    # primitive to each instant (line 1: per instant, not per pixel).
    instants = options.get("time_samples", 8) if blur else 1
    per_pixel = instants * options.get("n", 2) ** 2
    shape_test = {}
    try:
        shape_test = _test_ops(_temporal_shapes(
            [tuple(map(float, p)) for p in points],
            {**{o.name: o.default for o in TEMPORAL_OPTIONS}, **options}, 0.0))[1]
    except (InputError, ValueError, TypeError, KeyError):
        pass
    one = _ops_sum({"samples": 1, "int_add": 1}, POSITION, shape_test)
    pixel = _ops_sum(one, times=per_pixel) | {"div": 1}
    pixel = _ops_sum(pixel, {"compare": 2, "pixels_tested": 1})
    return (
        CodeLine("setup: the primitive, its motion per frame, the n x n samples of a pixel"),
        CodeLine(f"for each animation frame k:  {sample}"),
        CodeLine("    for each pixel (x, y) the primitive reaches in any frame:  coverage = "
                 "(samples inside, over all instants) / (instants * n^2);  write it", PLOT,
                 ops=pixel),
        CodeLine("done"),
    )


def temporal(points, options, grid):
    kind = _primitive(points, options)
    images = temporal_frames(points, options, grid)
    apparent = apparent_speed(points, options)
    constants = {"primitive": kind, "motion": options["motion"], "mode": options["mode"],
                 "frames": options["frames"], "speed": options["speed"], "apparent speed":
                 apparent}
    yield Start(0, ("frame", "coverage", "rgb"), constants, pixel_value="coverage",
                color_value="rgb", replaces=True)
    reach = np.zeros(images[0].shape, bool) if images else np.zeros((0, 0), bool)
    for image in images:
        reach |= image > 0
    cells = np.argwhere(reach)
    previous = np.zeros(reach.shape)
    ink = unpack(INK)
    for k, image in enumerate(images):
        instants = time_samples(options, k)
        values = {"frame": k, "t": f"{instants[0]:g} .. {instants[-1]:g}" if len(instants) > 1
                  else instants[0]}
        if options["motion"] == "spin":
            values["angle"] = options["speed"] * instants[0] % 360
        yield Vars(1, values)
        for y, x in cells:
            value = float(image[y, x])
            if value > 0 or previous[y, x] > 0:
                yield (2, int(x), int(y), float(k), value, float(_ink_blend(ink, value)))
        previous = image
    yield Vars(3, {"frames": len(images), "apparent speed": apparent})


def animation_frame_steps(spec, trace) -> list[int]:
    """The step at which each animation frame of an ``aa-temporal`` run is
    complete (its image fully written), in order; [] for other runs.

    Frame k starts with a Vars record naming ``frame`` k; the step before
    the next frame's record (or before the closing record) shows image k
    with frame k's variables.
    """
    if spec.name != "aa-temporal" or trace.start is None:
        return []
    starts = [index for index, record in trace.records_of(Vars) if "frame" in record.values]
    ends = [start - 1 for start in starts[1:]] + [len(trace) - 2]
    return [max(end, start) for start, end in zip(starts, ends)]


# ========================================================= registering
registry_module.all_specs()

SUPERSAMPLE_OPTIONS = (PATTERN, N, FILTER, SIGMA, SEED) + SHAPE_OPTIONS
ADAPTIVE_OPTIONS = (Option("max_depth", "int", 3, "how often a square may be split in four",
                           minimum=0, maximum=7),) + SHAPE_OPTIONS
FILTER_OPTIONS = (Option("kernel", "choice", "seed", "the convolution kernel: box3 (3 x 3 "
                         "average), seed (1/36 [1 4 1; 4 16 4; 1 4 1]) or gaussian",
                         choices=KERNELS),
                  Option("sigma", "float", 0.8, "standard deviation of the gaussian kernel, "
                         "in px (its radius is ceil(3 sigma))", minimum=0.2, maximum=4),
                  triangles.FILL_RULE)
WU_OPTIONS = (Option("endpoints", "choice", "full", "full: every column's two intensities add "
                     "up to 1, end columns too; gap: the end columns get half, as the segment "
                     "covers half of them (Wu's endpoint rule for whole-pixel endpoints)",
                     choices=("full", "gap")),)
AREA_OPTIONS = (Option("width", "float", 1.0, "line width in px", minimum=0.01, maximum=64),
                CAPS)
TEMPORAL_OPTIONS = (
    Option("primitive", "choice", "auto", "wheel (1 point: the centre) or triangle (3 points); "
           "auto picks by the number of points", choices=("auto", "wheel", "triangle")),
    Option("motion", "choice", "spin", "spin about the centre, or move along +x",
           choices=("spin", "move")),
    Option("mode", "choice", "instant", "instant: one sample time per frame; motion-blur: "
           "average over the frame's exposure", choices=("instant", "motion-blur")),
    Option("frames", "int", 12, "animation frames", minimum=1, maximum=240),
    Option("speed", "float", 80.0, "degrees per frame (spin) or px per frame (move)",
           minimum=-3600, maximum=3600),
    Option("time_samples", "int", 8, "instants averaged per frame with motion-blur",
           minimum=1, maximum=64),
    Option("shutter", "float", 1.0, "fraction of the frame interval the exposure lasts",
           minimum=0.01, maximum=1),
    Option("n", "int", 2, "spatial samples per pixel: n x n grid", minimum=1, maximum=8),
    Option("radius", "float", 9.0, "wheel radius in px", minimum=1, maximum=2048),
    Option("spokes", "int", 4, "number of spokes", minimum=1, maximum=32),
    Option("spoke_width", "float", 1.5, "spoke width in px", minimum=0.1, maximum=64),
    Option("phase", "float", 0.0, "angle of the first spoke at t = 0, degrees",
           minimum=-360, maximum=360),
)

AA_NOTES = (
    "Coverage is the fraction of the pixel square a shape covers (0..1); values are "
    "coverages, and the grid shows the ink blended over white by them.",
    "Vertices snap to 1/256 px and samples lie on a 1/512 px lattice: every inside test is "
    "exact.",
)


def _register(name, title, summary, inputs, options, code, generator, notes=(), explain=None,
              uses_grid=True):
    register(AlgorithmSpec(name=name, title=title, family="antialias", summary=summary,
                           inputs=inputs, options=options, code=code, generator=generator,
                           notes=AA_NOTES + tuple(notes), explain=explain, uses_grid=uses_grid))


_register("aa-supersample", "Supersampling", "n x n samples per pixel (grid, jittered, random "
          "or rotated grid), weighted by a filter", POINTS, SUPERSAMPLE_OPTIONS,
          supersample_code, supersample, explain=explain_samples,
          notes=("weighted: w = h(u) + h(v), h = distance to the nearer pixel border; for the "
                 "4 x 4 grid exactly the kernel 1 2 2 1 / 2 3 3 2 / 2 3 3 2 / 1 2 2 1.",
                 "With n = 1, pattern grid and filter box the one sample is the centre: the "
                 "aliased picture."))
_register("aa-adaptive", "Adaptive supersampling", "corners and centre first; split a square "
          "in four where its samples disagree", POINTS, ADAPTIVE_OPTIONS, adaptive_code,
          adaptive, explain=explain_samples,
          notes=("Cheap where a pixel is wholly in or out, but a detail that falls between "
                 "the five samples of a square is missed.",
                 "Corners are shared by the squares of one pixel, not between pixels; "
                 "samples counts each tested point once per pixel."))
_register("aa-filter", "Post-filtering (convolution)", "render aliased, then blur: each pixel "
          "becomes a weighted average of its neighbourhood", Inputs(3, integer=False,
                                                                    names=("P0", "P1", "P2"),
                                                                    multiple=True),
          FILTER_OPTIONS, filter_code, post_filter, explain=explain_samples,
          notes=("The filter reads the aliased image and writes a new one; it blurs the "
                 "stairs but cannot recover detail the centres missed.",))
_register("line-wu", "Xiaolin Wu's line", "two pixels per column along the minor axis, "
          "intensities 1 - f and f", SEGMENT, WU_OPTIONS, wu_code, wu, uses_grid=False,
          notes=("Whole-pixel endpoints as in the line family: the segment joins the two "
                 "end pixels' centres; e counts the fraction in units of 1/dx, exactly.",))
_register("line-area", "Area-sampled line", "intensity = the area of the pixel square that "
          "the line's rectangle covers", SEGMENT, AREA_OPTIONS, area_code, line_area,
          uses_grid=False,
          notes=("Areas come from the exact coverage reference (float64, vectorised).",))
_register("aa-temporal", "Temporal aliasing and motion blur", "a spinning wheel or moving "
          "triangle over several frames: one instant per frame, or averaged over the exposure",
          POINTS, TEMPORAL_OPTIONS, temporal_code, temporal,
          notes=("The wagon-wheel effect: a wheel with s spokes looks the same every 360/s "
                 "degrees, so a turn of speed per frame looks like the apparent speed.",
                 "temporal_frames(points, options, grid) gives the images as arrays."))
