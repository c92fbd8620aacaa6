"""Speed against error: operation counts, errors against the exact oracles, timings.

Pure (numpy and the standard library); ``app/analysis/report.py`` turns the rows into
the report. Every measurement is one row (``Row``): the family, the
experiment, the algorithm and its variant (the options that matter), the
swept parameter and its value, the metric, its value and its unit. The
sweeps are seeded, so two runs measure the same inputs and give the same
counts and errors; only the timings vary.

Operation counts. Each pseudo-code line carries the operations one
execution of it performs (``CodeLine.ops``; work that grows with a
quantity of the frame, such as the pixels of a Span run, in
``CodeLine.per``). A recorded trace names the line of every frame, so

    count[op] = sum over lines l of  executions(l) * ops[l][op]
              + sum over frames f with a scaled quantity q  of  q(f) * per[l][q][op],

executions(l) being ``np.bincount(trace.line)`` less the Note records
(commentary, no work). The counts are exact for what the annotations
describe and deterministic; the annotations say where they fold a loop
header into the body's line and where they give a lower bound.

Cost per pixel divides by the pixels the run wrote (duplicates included);
``ops`` is the sum of the arithmetic and comparison counts (int_add,
float_add, mul, div, sqrt, round, compare); pixels_tested and samples are
kept apart.

Timings are the median of repeats (``time.perf_counter``) of one call of
the fast kernel, where the algorithm has one, and of recording the
generator into a Trace (``AlgorithmSpec.record``).
"""
from __future__ import annotations

import math
import time
from dataclasses import dataclass, field
from fractions import Fraction
from math import lcm
from typing import Callable, Iterable

import numpy as np

from algorithms.exact import circles as exact_circles
from algorithms import registry
from algorithms.errors import InputError
from algorithms.steps import OP_NAMES, PER_PIXEL, PER_ROW, Note, Table

ARITHMETIC = ("int_add", "float_add", "mul", "div", "sqrt", "round", "compare")
COLUMNS = ("family", "experiment", "algorithm", "variant", "parameter", "parameter_value",
           "metric", "value", "unit")
SEED = 20240607


# ============================================================== rows
@dataclass
class Rows:
    """The measurements of a report, one dict per value (see COLUMNS)."""

    rows: list = field(default_factory=list)

    def add(self, family, experiment, algorithm, variant, parameter, parameter_value,
            metric, value, unit=""):
        value = float(value)
        if not math.isfinite(value):
            raise ValueError(f"{family}/{experiment}/{variant}/{metric}: {value} is not finite")
        self.rows.append({"family": family, "experiment": experiment, "algorithm": algorithm,
                          "variant": variant, "parameter": parameter,
                          "parameter_value": parameter_value, "metric": metric,
                          "value": value, "unit": unit})

    def select(self, **where) -> list[dict]:
        return [row for row in self.rows if all(row[k] == v for k, v in where.items())]

    def value(self, **where) -> float:
        found = self.select(**where)
        if len(found) != 1:
            raise KeyError(f"{len(found)} rows match {where}")
        return found[0]["value"]


# =================================================== operation counts
def op_counts(trace) -> dict[str, int]:
    """Operations the run performed, by name (OP_NAMES), from its code lines."""
    code = trace.code
    executions = np.bincount(trace.line, minlength=len(code)).astype(np.int64)
    notes = trace.steps_of(Note)
    if len(notes):
        executions -= np.bincount(trace.line[notes], minlength=len(code))
    counts = dict.fromkeys(OP_NAMES, 0)
    for k, line in enumerate(code):
        for name, count in line.ops.items():
            counts[name] += count * int(executions[k])
        for quantity, ops in line.per.items():
            amount = _quantity(trace, k, quantity, int(executions[k]))
            for name, count in ops.items():
                counts[name] += count * amount
    return counts


def _quantity(trace, line: int, quantity: str, executions: int) -> int:
    """How much of ``quantity`` the frames on ``line`` carry, summed."""
    if quantity == PER_PIXEL:
        spans = trace.spans()
        lengths = np.maximum(spans["x_end"] - spans["x_start"], 0)
        return int(lengths[spans["line"] == line].sum())
    if quantity == PER_ROW:
        return sum(len(table.rows) for _, table in trace.records_of(Table) if table.line == line)
    if quantity in trace.value_names:
        values = trace.series(quantity)[trace.line == line]
        return int(np.nansum(values))
    constants = trace.start.constants
    if quantity in constants:
        return int(constants[quantity]) * executions
    raise KeyError(f"code line {line} scales by {quantity!r}, which the run does not name")


def total_ops(counts: dict) -> int:
    return sum(counts[name] for name in ARITHMETIC)


def written_count(trace) -> int:
    """Pixels the run wrote (duplicates included, spans counted pixel by pixel)."""
    return int(len(trace.written_pixels()))


# ============================================================= timing
def median_seconds(call: Callable[[], object], repeats: int = 5, least: float = 0.002) -> float:
    """Median time of one call, over ``repeats`` samples.

    A sample repeats the call until it has run ``least`` seconds (for
    calls far shorter than the clock's resolution) and divides.
    """
    start = time.perf_counter()
    call()
    once = time.perf_counter() - start
    inner = max(1, min(1000, int(least / max(once, 1e-9))))
    samples = []
    for _ in range(max(1, repeats)):
        start = time.perf_counter()
        for _ in range(inner):
            call()
        samples.append((time.perf_counter() - start) / inner)
    return float(np.median(samples))


# =============================================================== lines
LINE_VARIANTS = (
    ("line-incremental", {"rounding": "floor"}, "incremental (floor)"),
    ("line-incremental", {"rounding": "round"}, "incremental (round)"),
    ("line-dda", {"dtype": "float64"}, "DDA float64"),
    ("line-dda", {"dtype": "float32"}, "DDA float32"),
    ("line-explicit", {}, "explicit"),
    ("line-implicit", {}, "implicit"),
    ("line-parametric", {"dt": "auto"}, "parametric dt=auto"),
    ("line-parametric", {"dt": 0.01}, "parametric dt=0.01"),
    ("line-parametric", {"dt": 0.001}, "parametric dt=0.001"),
    ("line-parametric", {"dt": 0.0001}, "parametric dt=0.0001"),
    ("line-bresenham", {}, "Bresenham"),
    ("line-bresenham", {"symmetric": True}, "Bresenham symmetric"),
)
IMPLICIT_MAX_BOX = 1_200_000  # pixels of the bounding box the implicit form may test


def random_segment(rng, length: float, spread: int = 1000):
    """A segment of about ``length`` px in a random direction from a random start."""
    angle = rng.uniform(0.0, 2.0 * math.pi)
    p = (int(rng.integers(0, spread)), int(rng.integers(0, spread)))
    q = (p[0] + int(round(length * math.cos(angle))), p[1] + int(round(length * math.sin(angle))))
    return p, q


def _keys(pixels: np.ndarray) -> np.ndarray:
    pixels = np.asarray(pixels, np.int64).reshape(-1, 2)
    return ((pixels[:, 0] + (1 << 30)) << 32) | (pixels[:, 1] + (1 << 30))


def line_errors(p, q, pixels) -> dict:
    """Error measures of a line's pixels (emission order) against the ideal segment PQ.

    * differing: pixels of the symmetric difference with the exact
      nearest-pixel line (one pixel per major-axis column, the nearest to
      the ideal line; where the line passes exactly midway, either of the
      two counts as nearest). Exact integer arithmetic. It is the sum of
      ``missed`` (columns without a nearest pixel) and ``extra`` (pixels
      beyond one nearest pixel per column): a pixel one row off counts in
      both, a second pixel in a column only in extra.
    * max_deviation: the largest perpendicular distance of a plotted pixel
      from the ideal line (px).
    * gaps: jumps between consecutive distinct plots that are not
      8-neighbours; duplicates: plots of a pixel plotted before.
    """
    pixels = np.asarray(pixels, np.int64).reshape(-1, 2)
    (x0, y0), (x1, y1) = p, q
    dx, dy = x1 - x0, y1 - y0
    if abs(dx) >= abs(dy):
        along, across, n, m = pixels[:, 0] - x0, pixels[:, 1] - y0, dx, dy
    else:
        along, across, n, m = pixels[:, 1] - y0, pixels[:, 0] - x0, dy, dx
    sign = 1 if n >= 0 else -1
    u, big_n = along * sign, abs(n)
    distinct = np.unique(_keys(pixels), return_index=True)[1]
    u_d, v_d = u[distinct], across[distinct]
    if big_n == 0:
        ok = (u_d == 0) & (v_d == 0)
    else:
        product = m * u_d
        low = product // big_n
        remainder = product - low * big_n
        nearest = low + (2 * remainder >= big_n)
        tie = 2 * remainder == big_n
        ok = (u_d >= 0) & (u_d <= big_n) & ((v_d == nearest) | (tie & (v_d == low)))
    hit = len(np.unique(u_d[ok]))
    differing = (len(distinct) - hit) + (big_n + 1 - hit)
    cross = dx * (pixels[:, 1] - y0) - dy * (pixels[:, 0] - x0)
    if dx == 0 and dy == 0:
        deviation = np.hypot(pixels[:, 0] - x0, pixels[:, 1] - y0)
    else:
        deviation = np.abs(cross) / math.sqrt(dx * dx + dy * dy)
    step = np.diff(pixels, axis=0)
    moved = step[np.any(step != 0, axis=1)]
    gaps = int(np.count_nonzero(np.abs(moved).max(axis=1) > 1)) if len(moved) else 0
    return {"differing": int(differing), "columns": big_n + 1, "missed": big_n + 1 - hit,
            "extra": len(distinct) - hit,
            "max_deviation": float(deviation.max()) if len(deviation) else 0.0,
            "gaps": gaps, "duplicates": int(len(pixels) - len(distinct)),
            "pixels": int(len(pixels))}


def asymmetry(forward, backward) -> int:
    """Pixels drawn by one direction of a segment and not by the other."""
    return int(len(np.setxor1d(_keys(forward), _keys(backward))))


def _implicit_fits(p, q) -> bool:
    return (abs(q[0] - p[0]) + 1) * (abs(q[1] - p[1]) + 1) <= IMPLICIT_MAX_BOX


def _line_pixels(spec, options, p, q):
    return spec.kernel((p, q), spec.resolve(options))


def measure_lines(settings, rows: Rows, rng, tick=lambda: None) -> None:
    """Error, cost and time of every line variant over random segments by length."""
    specs = {name: registry.get(name) for name, _, _ in LINE_VARIANTS}
    for length in settings.line_lengths:
        segments = [random_segment(rng, length) for _ in range(settings.segments)]
        for name, options, variant in LINE_VARIANTS:
            spec = specs[name]
            fits = [s for s in segments if name != "line-implicit" or _implicit_fits(*s)]
            if not fits:
                continue
            totals = {"differing": 0, "gaps": 0, "duplicates": 0, "asymmetric": 0,
                      "pixels": 0, "columns": 0, "missed": 0, "extra": 0}
            worst = 0.0
            kernel_seconds = 0.0
            for p, q in fits:
                pixels = _line_pixels(spec, options, p, q)
                errors = line_errors(p, q, pixels)
                for key in ("differing", "gaps", "duplicates", "pixels", "columns", "missed",
                            "extra"):
                    totals[key] += errors[key]
                worst = max(worst, errors["max_deviation"])
                totals["asymmetric"] += asymmetry(pixels, _line_pixels(spec, options, q, p))
                kernel_seconds += median_seconds(lambda: _line_pixels(spec, options, p, q),
                                                 settings.repeats)
            count = len(fits)
            add = lambda metric, value, unit="": rows.add(  # noqa: E731
                "lines", "length sweep", name, variant, "length", length, metric, value, unit)
            add("segments", count)
            add("differing pixels", totals["differing"] / count, "px per segment")
            add("differing fraction", totals["differing"] / totals["columns"])
            add("missed columns", totals["missed"] / totals["columns"], "fraction of columns")
            add("extra pixels", totals["extra"] / count, "px per segment")
            add("max deviation", worst, "px")
            add("gaps", totals["gaps"] / count, "per segment")
            add("duplicates", totals["duplicates"] / count, "per segment")
            add("asymmetric pixels", totals["asymmetric"] / count, "px per segment")
            add("kernel time", 1e9 * kernel_seconds / totals["pixels"], "ns/px")
            tick()
        if length <= settings.generator_max_length:
            _line_costs(settings, rows, specs, segments, length)
    _dda_threshold(settings, rows, rng)


def _line_costs(settings, rows, specs, segments, length) -> None:
    """Operation counts and generator time, from recorded traces."""
    for name, options, variant in LINE_VARIANTS:
        spec = specs[name]
        fits = [s for s in segments if name != "line-implicit" or
                (abs(s[1][0] - s[0][0]) + 1) * (abs(s[1][1] - s[0][1]) + 1) <= settings.max_frames]
        if not fits:
            continue
        counts = dict.fromkeys(OP_NAMES, 0)
        written = 0
        seconds = 0.0
        for p, q in fits[:settings.traced_segments]:
            trace = spec.record((p, q), options)
            for op, count in op_counts(trace).items():
                counts[op] += count
            written += written_count(trace)
            seconds += median_seconds(lambda: spec.record((p, q), options),
                                      settings.generator_repeats)
        _add_costs(rows, "lines", "length sweep", name, variant, "length", length, counts,
                   written, seconds)


def _add_costs(rows, family, experiment, name, variant, parameter, value, counts, written,
               seconds=None, per="px") -> None:
    written = max(written, 1)
    add = lambda metric, v, unit="": rows.add(family, experiment, name, variant,  # noqa: E731
                                               parameter, value, metric, v, unit)
    add("ops", total_ops(counts) / written, f"per {per}")
    for op in OP_NAMES:
        add(f"ops {op}", counts[op] / written, f"per {per}")
    if seconds is not None:
        add("generator time", 1e6 * seconds / written, f"us/{per}")


def _dda_threshold(settings, rows, rng) -> None:
    """Where DDA first misses the nearest pixel, float32 against float64."""
    spec = registry.get("line-dda")
    lengths = np.unique(np.round(np.logspace(1, math.log10(settings.dda_max_length),
                                             settings.dda_lengths)).astype(int))
    for dtype in ("float32", "float64"):
        options = spec.resolve({"dtype": dtype})
        first = None
        for length in lengths:
            wrong = 0
            differing = 0
            for _ in range(settings.dda_segments):
                p, q = random_segment(rng, int(length))
                errors = line_errors(p, q, spec.kernel((p, q), options))
                wrong += errors["differing"] > 0
                differing += errors["differing"]
            if wrong and first is None:
                first = int(length)
            add = lambda metric, v, unit="": rows.add(  # noqa: E731
                "lines", "DDA precision", "line-dda", f"DDA {dtype}", "length", int(length),
                metric, v, unit)
            add("segments wrong", wrong / settings.dda_segments, "fraction")
            add("differing pixels", differing / settings.dda_segments, "px per segment")
        rows.add("lines", "DDA precision", "line-dda", f"DDA {dtype}", "length", "all",
                 "first wrong length", first if first is not None else 0,
                 "px (0: never wrong up to the longest)")


# ============================================================== circles
CIRCLE_VARIANTS = (
    ("circle-sqrt4", "sqrt4 (4-way)"),
    ("circle-sqrt8", "sqrt8 (8-way)"),
    ("circle-midpoint", "midpoint"),
    ("ellipse-midpoint", "midpoint ellipse, rx = ry"),
)


def circle_options(name: str, r: int) -> dict:
    return {"rx": r, "ry": r} if name == "ellipse-midpoint" else {"radius": r}


def circle_offsets(name: str, r: int) -> np.ndarray:
    """The run's pixels (emission order) as offsets from a centre at the origin."""
    spec = registry.get(name)
    options = spec.resolve(circle_options(name, r))
    if spec.kernel is not None:
        return np.asarray(spec.kernel(((0, 0),), options), np.int64).reshape(-1, 2)
    return spec.record(((0, 0),), options).written_pixels()


def circle_errors(r: int, offsets: np.ndarray) -> dict:
    """Gaps around the ring, duplicates, radial deviation, difference from the midpoint oracle.

    A gap: two pixels next to each other in angular order around the
    centre that are not 8-neighbours; ``skipped`` adds up the pixels such
    jumps leave out (the longer coordinate difference minus one).
    """
    distinct = np.unique(offsets, axis=0)
    duplicates = len(offsets) - len(distinct)
    radius = np.hypot(distinct[:, 0], distinct[:, 1])
    deviation = np.abs(radius - r)
    gaps = skipped = 0
    if len(distinct) > 1:
        order = np.lexsort((radius, np.arctan2(distinct[:, 1], distinct[:, 0])))
        ring = distinct[order]
        jump = np.abs(ring - np.roll(ring, -1, axis=0)).max(axis=1)
        gaps = int(np.count_nonzero(jump > 1))
        skipped = int(np.clip(jump - 1, 0, None).sum())
    oracle = np.array(sorted(exact_circles.midpoint_circle(r)), np.int64).reshape(-1, 2)
    return {"pixels": len(offsets), "duplicates": duplicates, "gaps": gaps, "skipped": skipped,
            "max deviation": float(deviation.max()), "mean deviation": float(deviation.mean()),
            "differing": int(len(np.setxor1d(_keys(distinct), _keys(oracle))))}


def ring_holes(name: str, largest: int) -> np.ndarray:
    """Per r in 0..largest-1: pixels strictly between the circles of radius r and r + 1
    (r^2 < x^2 + y^2 < (r + 1)^2, exactly) that neither ring r nor ring r + 1 drew."""
    size = 2 * largest + 3
    axis = np.arange(-largest - 1, largest + 2, dtype=np.int64)
    d2 = axis[None, :] ** 2 + axis[:, None] ** 2
    band = np.floor(np.sqrt(d2.astype(np.float64))).astype(np.int64)
    band -= band * band > d2
    band += (band + 1) * (band + 1) <= d2
    between = (band * band != d2) & (band < largest)  # strictly inside band r .. r + 1
    inner = np.zeros((size, size), bool)  # drawn by ring r = band
    outer = np.zeros((size, size), bool)  # drawn by ring r + 1
    for r in range(largest + 1):
        offsets = circle_offsets(name, r)
        keep = (np.abs(offsets) <= largest + 1).all(axis=1)
        ys, xs = offsets[keep, 1] + largest + 1, offsets[keep, 0] + largest + 1
        inner[ys[band[ys, xs] == r], xs[band[ys, xs] == r]] = True
        outer[ys[band[ys, xs] == r - 1], xs[band[ys, xs] == r - 1]] = True
    holes = between & ~inner & ~outer
    return np.bincount(band[holes], minlength=largest)[:largest]


def measure_circles(settings, rows: Rows, rng, tick=lambda: None) -> None:
    for name, variant in CIRCLE_VARIANTS:
        spec = registry.get(name)
        add = lambda r, metric, v, unit="": rows.add(  # noqa: E731
            "circles", "radius sweep", name, variant, "radius", r, metric, v, unit)
        for r in settings.radii:
            errors = circle_errors(r, circle_offsets(name, r))
            for metric in ("pixels", "duplicates", "gaps", "skipped", "max deviation",
                           "mean deviation", "differing"):
                unit = "px" if "deviation" in metric else ""
                add(r, "differing pixels" if metric == "differing" else metric,
                    errors[metric], unit)
        for r in settings.circle_cost_radii:
            options = spec.resolve(circle_options(name, r))
            trace = spec.record(((0, 0),), options)
            written = written_count(trace)
            seconds = median_seconds(lambda: spec.record(((0, 0),), options),
                                     settings.generator_repeats)
            _add_costs(rows, "circles", "radius sweep", name, variant, "radius", r,
                       op_counts(trace), written, seconds)
            if spec.kernel is not None:
                kernel = median_seconds(lambda: spec.kernel(((0, 0),), options), settings.repeats)
                add(r, "kernel time", 1e9 * kernel / written, "ns/px")
        holes = ring_holes(name, settings.hole_radius)
        rows.add("circles", "concentric rings", name, variant, "radii", f"0..{settings.hole_radius}",
                 "holes", int(holes.sum()), "px")
        rows.add("circles", "concentric rings", name, variant, "radii", f"0..{settings.hole_radius}",
                 "ring pairs with holes", int(np.count_nonzero(holes)))
        tick()


# ================================================== exact coverage (oracle)
def exact_cover(vertices, window, rule: str = "top-left") -> np.ndarray:
    """Which pixel centres of a window a triangle covers, decided exactly.

    ``vertices``: three points of ints, floats (taken at their exact
    values) or Fractions. ``window``: (i0, j0, i1, j1), the pixels
    i0 <= i < i1, j0 <= j < j1; the result is (j1 - j0, i1 - i0) bool.
    Written from the definition: the centre is inside when every edge
    function of the counter-clockwise triangle is positive, and on an
    edge (zero) when the rule keeps that edge (top-left: a left edge,
    a > 0, or a bottom one, a = 0 < b; inclusive: every edge; strict: none).
    """
    i0, j0, i1, j1 = window
    points = [(Fraction(x), Fraction(y)) for x, y in vertices]
    scale = 2 * lcm(*(c.denominator for point in points for c in point))
    v = [(int(x * scale), int(y * scale)) for x, y in points]
    area = (v[1][0] - v[0][0]) * (v[2][1] - v[0][1]) - (v[2][0] - v[0][0]) * (v[1][1] - v[0][1])
    out = np.zeros((max(0, j1 - j0), max(0, i1 - i0)), bool)
    if area == 0 or out.size == 0:
        return out
    if area < 0:
        v = [v[0], v[2], v[1]]
    half = scale // 2
    px = [(2 * i + 1) * half for i in range(i0, i1)]
    py = [(2 * j + 1) * half for j in range(j0, j1)]
    extent = max(abs(c) for c in px + py + [c for p in v for c in p])
    kind = np.int64 if 8 * extent * extent < 2 ** 62 else object
    px = np.array(px, dtype=kind)[None, :]
    py = np.array(py, dtype=kind)[:, None]
    out[:] = True
    for k in range(3):
        (xi, yi), (xj, yj) = v[k], v[(k + 1) % 3]
        a, b = -(yj - yi), xj - xi
        e = b * (py - yi) + a * (px - xi)
        if rule == "inclusive":
            keep = True
        elif rule == "strict":
            keep = False
        else:
            keep = a > 0 or (a == 0 and b > 0)
        out &= (e > 0) | ((e == 0) & keep) if keep else (e > 0)
    return out


def snapped(value, bits: int) -> Fraction:
    """The exact value of a coordinate snapped to multiples of 1/2^bits (halves to even)."""
    scale = 1 << bits
    return Fraction(round(Fraction(value) * scale), scale)


# ================================================================ meshes
def jittered_mesh(rng, cells: int, size: float, origin: float, jitter: float = 0.3):
    """A grid of cells x cells jittered quads (vertex lists) and their triangles.

    Coordinates are origin + a local position, rounded to float64 once:
    those floats are the input, and their exact values the truth.
    """
    local = np.stack(np.meshgrid(np.arange(cells + 1), np.arange(cells + 1), indexing="xy"),
                     axis=-1).astype(np.float64) * size
    local += rng.uniform(-jitter, jitter, local.shape) * size
    local += rng.uniform(0.0, 1.0, 2)  # a random sub-pixel offset of the whole mesh
    vertices = origin + local
    quads, triangles = [], []
    for j in range(cells):
        for i in range(cells):
            a, b = vertices[j, i], vertices[j, i + 1]
            c, d = vertices[j + 1, i + 1], vertices[j + 1, i]
            quad = [tuple(map(float, p)) for p in (a, b, c, d)]
            quads.append(quad)
            if (i + j) % 2:
                triangles += [(quad[0], quad[1], quad[2]), (quad[0], quad[2], quad[3])]
            else:
                triangles += [(quad[0], quad[1], quad[3]), (quad[1], quad[2], quad[3])]
    return quads, triangles


def _window_of(points, margin: int = 2):
    xs = [p[0] for p in points]
    ys = [p[1] for p in points]
    return (math.floor(min(xs)) - margin, math.floor(min(ys)) - margin,
            math.floor(max(xs)) + margin, math.floor(max(ys)) + margin)


def _mask_of(pixels, window) -> np.ndarray:
    i0, j0, i1, j1 = window
    mask = np.zeros((j1 - j0, i1 - i0), np.int32)
    pixels = np.asarray(pixels, np.int64).reshape(-1, 2)
    inside = ((pixels[:, 0] >= i0) & (pixels[:, 0] < i1) & (pixels[:, 1] >= j0)
              & (pixels[:, 1] < j1))
    np.add.at(mask, (pixels[inside, 1] - j0, pixels[inside, 0] - i0), 1)
    return mask


def _shifted(points, origin: int, bits: int | None):
    """Exact coordinates less a whole-pixel origin, snapped first where bits is given."""
    convert = (lambda c: Fraction(c)) if bits is None else (lambda c: snapped(c, bits))
    return [(convert(x) - origin, convert(y) - origin) for x, y in points]


TRIANGLE_PRECISIONS = (
    ("float32", {"precision": "float32", "subpixel_bits": 8}, 8),
    ("float64", {"precision": "float64", "subpixel_bits": 8}, 8),
    ("fixed 0 bits", {"precision": "fixed", "subpixel_bits": 0}, 0),
    ("fixed 4 bits", {"precision": "fixed", "subpixel_bits": 4}, 4),
    ("fixed 8 bits", {"precision": "fixed", "subpixel_bits": 8}, 8),
)
POLYGON_PRECISIONS = (
    ("float32", {"arithmetic": "float32"}, 8),
    ("float64", {"arithmetic": "float64"}, 8),
    ("fixed 0 bits", {"arithmetic": "exact"}, 0),
    ("fixed 4 bits", {"arithmetic": "exact"}, 4),
    ("fixed 8 bits", {"arithmetic": "exact"}, 8),
)


def _mesh_flaws(masks, window_interior) -> dict:
    counts = sum(masks)
    return {"overlaps": int(np.count_nonzero(counts > 1)),
            "cracks": int(np.count_nonzero(window_interior & (counts == 0)))}


def measure_precision(settings, rows: Rows, rng, tick=lambda: None) -> None:
    """Triangle and polygon meshes at growing coordinates, in every precision."""
    triangle_spec = registry.get("triangle-bbox")
    polygon_spec = registry.get("polygon-scanline")
    for magnitude in settings.magnitudes:
        quads, triangles = jittered_mesh(rng, settings.mesh_cells, settings.cell_size,
                                         float(magnitude))
        flat = [p for t in triangles for p in t]
        window = _window_of(flat)
        origin = math.floor(magnitude)
        local = (window[0] - origin, window[1] - origin, window[2] - origin, window[3] - origin)
        truth = [exact_cover(_shifted(t, origin, None), local) for t in triangles]
        truth_pixels = int(sum(m.sum() for m in truth))
        snapped_masks = {bits: [exact_cover(_shifted(t, origin, bits), local) for t in triangles]
                         for bits in (0, 4, 8)}
        # Quads are two of the triangles: the same exact rule fills both.
        quad_truth = [truth[2 * k] | truth[2 * k + 1] for k in range(len(quads))]
        quad_snapped = {bits: [m[2 * k] | m[2 * k + 1] for k in range(len(quads))]
                        for bits, m in snapped_masks.items()}
        for family, spec, variants, shapes, exact_truth, exact_snapped in (
                ("triangles", triangle_spec, TRIANGLE_PRECISIONS, triangles, truth, snapped_masks),
                ("polygons", polygon_spec, POLYGON_PRECISIONS, quads, quad_truth, quad_snapped)):
            for variant, options, bits in variants:
                add = lambda metric, v, unit="": rows.add(  # noqa: E731
                    family, "precision", spec.name, variant, "magnitude", magnitude,
                    metric, v, unit)
                try:
                    masks = [_mask_of(_run_shape(spec, family, shape, options, bits, window),
                                      window) for shape in shapes]
                except InputError:
                    add("rejected", 1)
                    continue
                versus_truth = sum(int(np.count_nonzero((m > 0) != t))
                                   for m, t in zip(masks, exact_truth))
                versus_snapped = sum(int(np.count_nonzero((m > 0) != t))
                                     for m, t in zip(masks, exact_snapped[bits]))
                interior = sum(exact_snapped[bits]) > 0
                flaws = _mesh_flaws(masks, interior)
                add("rejected", 0)
                add("misclassified vs true", versus_truth, "px")
                add("misclassified vs snapped", versus_snapped, "px")
                add("misclassified fraction", versus_truth / max(1, truth_pixels))
                add("overlaps", flaws["overlaps"], "px")
                add("cracks", flaws["cracks"], "px")
                add("covered pixels", truth_pixels, "px")
                seconds = median_seconds(
                    lambda: [_run_shape(spec, family, shape, options, bits, window)
                             for shape in shapes], settings.repeats)
                add("kernel time", 1e9 * seconds / max(1, truth_pixels), "ns/px")
                if magnitude == settings.magnitudes[0]:
                    _precision_costs(settings, rows, family, spec, variant, options, bits,
                                     shapes, window, magnitude)
        tick()


def _precision_costs(settings, rows, family, spec, variant, options, bits, shapes, window,
                     magnitude) -> None:
    """Operation counts and generator time of the mesh, one shape at a time."""
    counts = dict.fromkeys(OP_NAMES, 0)
    written = 0
    seconds = 0.0
    size = (window[2] + 1, window[3] + 1)
    for shape in shapes:
        if family == "triangles":
            points, resolved = list(shape), spec.resolve(options)
        else:
            points = ([(float(snapped(x, bits)), float(snapped(y, bits))) for x, y in shape],)
            resolved = spec.resolve(options)
        trace = spec.record(points, resolved, size)
        for op, count in op_counts(trace).items():
            counts[op] += count
        written += written_count(trace)
        seconds += median_seconds(lambda: spec.record(points, resolved, size),
                                  settings.generator_repeats)
    _add_costs(rows, family, "precision", spec.name, variant, "magnitude", magnitude, counts,
               written, seconds)


def _run_shape(spec, family, shape, options, bits, window):
    if family == "triangles":
        return spec.kernel(list(shape), spec.resolve(options), window)
    # The polygon fill snaps to 1/256 px; coarser grids are snapped here first
    # (exactly: a multiple of 1/16 or 1 is its own 1/256 snap).
    points = [(float(snapped(x, bits)), float(snapped(y, bits))) for x, y in shape]
    return spec.kernel((tuple(points),), spec.resolve(options))


# ============================================================ traversal
TRAVERSALS = ("triangle-scan", "triangle-bbox", "triangle-incremental", "triangle-backtrack",
              "triangle-pineda", "triangle-linewise", "triangle-halfplane",
              "triangle-barycentric")


def traversal_shapes(rng, grid: int, count: int) -> dict:
    """Named triangle classes on a grid x grid window: count random triangles each."""
    def point(lo, hi):
        return (float(rng.uniform(lo, hi)), float(rng.uniform(lo, hi)))

    shapes = {"large": [], "small": [], "sliver": [], "right": []}
    for _ in range(count):
        shapes["large"].append((point(1, grid - 1), point(1, grid - 1), point(1, grid - 1)))
        centre = point(6, grid - 6)
        shapes["small"].append(tuple((centre[0] + rng.uniform(-3, 3), centre[1] + rng.uniform(-3, 3))
                                     for _ in range(3)))
        a, b = point(1, grid / 4), point(3 * grid / 4, grid - 1)
        shapes["sliver"].append((a, b, (b[0] + rng.uniform(0.5, 1.5), b[1] - rng.uniform(1.5, 3))))
        c = point(2, grid / 3)
        w, h = rng.uniform(grid / 3, grid / 2), rng.uniform(grid / 3, grid / 2)
        shapes["right"].append((c, (c[0] + w, c[1]), (c[0], c[1] + h)))
    return shapes


def measure_traversal(settings, rows: Rows, rng, tick=lambda: None) -> None:
    grid = (settings.traversal_grid, settings.traversal_grid)
    shapes = traversal_shapes(rng, settings.traversal_grid, settings.traversal_count)
    for name in TRAVERSALS:
        spec = registry.get(name)
        options = spec.resolve({})
        for shape, cases in shapes.items():
            tested = filled = 0
            counts = dict.fromkeys(OP_NAMES, 0)
            written = 0
            seconds = kernel_seconds = 0.0
            for triangle in cases:
                points = [p for p in triangle]
                trace = spec.record(points, options, grid)
                final = trace.final_variables()
                tested += int(final["tested"])
                filled += int(final["filled"])
                for op, count in op_counts(trace).items():
                    counts[op] += count
                written += written_count(trace)
                seconds += median_seconds(lambda: spec.record(points, options, grid),
                                          settings.generator_repeats)
                if spec.kernel is not None:
                    kernel_seconds += median_seconds(lambda: spec.kernel(points, options, grid),
                                                     settings.repeats)
            add = lambda metric, v, unit="": rows.add(  # noqa: E731
                "triangles", "traversal", name, name.removeprefix("triangle-"), "shape", shape,
                metric, v, unit)
            add("tested", tested / len(cases), "px per triangle")
            add("filled", filled / len(cases), "px per triangle")
            add("tested per filled", tested / max(filled, 1))
            _add_costs(rows, "triangles", "traversal", name, name.removeprefix("triangle-"),
                       "shape", shape, counts, written, seconds)
            if spec.kernel is not None:
                add("kernel time", 1e9 * kernel_seconds / max(written, 1), "ns/px")
        tick()
    _polygon_traversal(settings, rows, rng)


def star_polygon(rng, centre, radius, points=9):
    angles = np.sort(rng.uniform(0, 2 * math.pi, points))
    radii = np.where(np.arange(points) % 2, radius * 0.45, radius)
    return tuple((float(centre + r * math.cos(a)), float(centre + r * math.sin(a)))
                 for a, r in zip(angles, radii))


def convex_polygon(rng, centre, radius, points=8):
    angles = np.sort(rng.uniform(0, 2 * math.pi, points))
    return tuple((float(centre + radius * math.cos(a)), float(centre + radius * math.sin(a)))
                 for a in angles)


def _polygon_traversal(settings, rows, rng) -> None:
    size = settings.traversal_grid
    centre, radius = size / 2, size / 2 - 2
    shapes = {"convex": [convex_polygon(rng, centre, radius) for _ in range(settings.traversal_count)],
              "star": [star_polygon(rng, centre, radius) for _ in range(settings.traversal_count)]}
    for name in ("polygon-scanline", "polygon-convex", "polygon-tessellate"):
        spec = registry.get(name)
        options = spec.resolve({})
        for shape, cases in shapes.items():
            counts = dict.fromkeys(OP_NAMES, 0)
            written = 0
            seconds = kernel_seconds = 0.0
            done = 0
            for polygon in cases:
                points = (polygon,)
                try:
                    trace = spec.record(points, options, (size, size))
                except InputError:
                    continue  # a star is not convex: polygon-convex refuses it
                done += 1
                for op, count in op_counts(trace).items():
                    counts[op] += count
                written += written_count(trace)
                seconds += median_seconds(lambda: spec.record(points, options, (size, size)),
                                          settings.generator_repeats)
                if spec.kernel is not None:
                    kernel_seconds += median_seconds(lambda: spec.kernel(points, options),
                                                     settings.repeats)
            if not done:
                continue
            variant = name.removeprefix("polygon-")
            _add_costs(rows, "polygons", "traversal", name, variant, "shape", shape, counts,
                       written, seconds)
            if spec.kernel is not None:
                rows.add("polygons", "traversal", name, variant, "shape", shape, "kernel time",
                         1e9 * kernel_seconds / max(written, 1), "ns/px")


# ================================================================== fill
def measure_fill(settings, rows: Rows, rng, tick=lambda: None) -> None:
    """Seed fill of a disc's outline: cost and memory by order and connectivity."""
    spec = registry.get("flood-fill")
    r = settings.fill_radius
    size = 2 * r + 5
    outline = tuple((int(round(size / 2 + r * math.cos(a))), int(round(size / 2 + r * math.sin(a))))
                    for a in np.linspace(0, 2 * math.pi, 48, endpoint=False))
    references = {}
    for order in ("stack", "queue", "span"):
        for connectivity in ("4", "8"):
            options = spec.resolve({"order": order, "connectivity": connectivity,
                                    "outline": "4" if connectivity == "8" else "8"})
            trace = spec.record((outline,), options, (size, size))
            final = trace.final_variables()
            filled = int(final["filled"])
            seconds = median_seconds(lambda: spec.record((outline,), options, (size, size)),
                                     settings.generator_repeats)
            variant = f"{order}, {connectivity}-connected"
            add = lambda metric, v, unit="": rows.add(  # noqa: E731
                "fill", "disc", "flood-fill", variant, "radius", r, metric, v, unit)
            region = fill_pixels(trace)
            reference = references.setdefault(connectivity, region)
            add("filled", filled, "px")
            add("differs from stack order", int(len(np.setxor1d(region, reference))), "px")
            add("pops", int(final["pops"]))
            add("skipped pops", int(final["skipped"]))
            add("largest pending", int(final["largest"]), "entries")
            _add_costs(rows, "fill", "disc", "flood-fill", variant, "radius", r,
                       op_counts(trace), filled, seconds, per="filled px")
    tick()


def fill_pixels(trace) -> np.ndarray:
    """Keys of the pixels a seed fill filled (its outline, line 0, left out)."""
    writes = trace.written()
    return np.unique(_keys(writes.pixels[trace.line[writes.steps] != 0]))


# ========================================================= interpolation
def measure_interpolation(settings, rows: Rows, rng, tick=lambda: None) -> None:
    """Affine against perspective-correct interpolation, against the exact value."""
    from algorithms.exact import triangles as exact_triangles

    size = settings.interpolation_grid
    triangle = ((2.25, 3.5), (size - 2.75, size * 0.25 + 0.125), (size * 0.375, size - 2.5))
    s = (0.0, 1.0, 0.5)
    perspective = registry.get("triangle-perspective")
    affine = registry.get("triangle-barycentric")
    for ratio in settings.w_ratios:
        w = (1.0, float(ratio), (1.0 + float(ratio)) / 2)
        options = perspective.resolve({"s": s, "w": w})
        trace = perspective.record(list(triangle), options, (size, size))
        written = trace.writes()
        pixels = np.stack([trace.x[written], trace.y[written]], axis=1)
        s_affine = trace.series("s_affine")[written]
        s_persp = trace.series("s_persp")[written]
        exact_tri = [(Fraction(x), Fraction(y)) for x, y in triangle]
        snapped_tri = [(snapped(x, 8), snapped(y, 8)) for x, y in exact_tri]
        truth = np.array([float(exact_triangles.perspective_correct(
            exact_triangles.barycentric(snapped_tri, (Fraction(2 * int(i) + 1, 2),
                                                      Fraction(2 * int(j) + 1, 2))),
            [Fraction(v) for v in s], [Fraction(v) for v in w])) for i, j in pixels])
        for variant, values in (("affine", s_affine), ("perspective-correct", s_persp)):
            error = np.abs(values - truth)
            add = lambda metric, v, unit="": rows.add(  # noqa: E731
                "interpolation", "w ratio", perspective.name if variant != "affine"
                else "triangle-perspective", variant, "w ratio", ratio, metric, v, unit)
            add("max error", float(error.max()), "of the attribute's range")
            add("rms error", float(np.sqrt(np.mean(error ** 2))), "of the attribute's range")
        tick()
    # Cost per covered pixel: the affine blend (barycentric with s) and the
    # perspective-correct one.
    for spec, variant, options in ((affine, "affine", {"s": s}),
                                   (perspective, "perspective-correct", {"s": s, "w": (1.0, 4.0, 2.5)})):
        resolved = spec.resolve(options)
        trace = spec.record(list(triangle), resolved, (size, size))
        seconds = median_seconds(lambda: spec.record(list(triangle), resolved, (size, size)),
                                 settings.generator_repeats)
        _add_costs(rows, "interpolation", "cost", spec.name, variant, "triangle", "one",
                   op_counts(trace), written_count(trace), seconds)
    _depth_precision(settings, rows)


DEPTH_BUFFERS = ("fixed 24-bit", "float32", "float64", "float32 reversed")
DEPTH_GAP = 1e-3  # the second surface lies this fraction of its depth behind the first


def depth_values(z: np.ndarray, near: float, far: float, kind: str) -> np.ndarray:
    """Stored depth of eye-space depths z in [near, far] in a buffer of ``kind``.

    Standard (fixed 24-bit, float32, float64): d = f (z - n) / (z (f - n))
    in [0, 1], 0 at near, computed as A - B / z with A = f / (f - n),
    B = f n / (f - n) in the buffer's type (float64 for the fixed buffer,
    then rounded to a multiple of 1 / (2^24 - 1)). Reversed float32:
    d = n (f - z) / (z (f - n)) = B' / z - A', 1 at near and 0 at far, so
    the far depths, which crowd together, sit where floats are densest.
    """
    if kind == "fixed 24-bit":
        d = far / (far - near) - far * near / (far - near) / z
        return np.round(d * (2 ** 24 - 1))
    t = {"float32": np.float32, "float64": np.float64, "float32 reversed": np.float32}[kind]
    zt = z.astype(t)
    if kind == "float32 reversed":
        a, b = t(near / (far - near)), t(far * near / (far - near))
        return b / zt - a
    a, b = t(far / (far - near)), t(far * near / (far - near))
    return a - b / zt


def _depth_precision(settings, rows) -> None:
    """Where two surfaces 0.1 % of their depth apart fight, by far/near ratio.

    Eye depths z run log-uniformly from near to far / 1.001 (every decade
    of distance weighs the same); the second surface lies at z * 1.001. A
    depth fights when the stored values do not put the nearer surface
    strictly in front (so the drawing order decides).
    """
    for ratio in settings.near_far:
        near, far = 1.0, float(ratio)
        z = np.geomspace(near, far / (1 + DEPTH_GAP), settings.depth_rows)
        for kind in DEPTH_BUFFERS:
            front = depth_values(z, near, far, kind)
            back = depth_values(z * (1 + DEPTH_GAP), near, far, kind)
            fighting = (front <= back) if kind == "float32 reversed" else (front >= back)
            first = float(z[np.argmax(fighting)]) if fighting.any() else 0.0
            add = lambda metric, v, unit="": rows.add(  # noqa: E731
                "interpolation", "depth precision", "z-buffer", kind, "far/near", ratio,
                metric, v, unit)
            add("z-fighting fraction", float(np.mean(fighting)), "of log depth range")
            add("first fighting depth", first, "x near (0: none)")


# ========================================================== antialiasing
def antialias_available() -> str:
    """'' when the antialiasing module can be measured, else why not."""
    try:
        from algorithms import antialias
        needed = ("supersample_image", "reference_coverage", "PATTERNS", "FILTERS")
        missing = [name for name in needed if not hasattr(antialias, name)]
        if missing:
            return f"algorithms.antialias lacks {', '.join(missing)}"
        grid = (8, 8)
        points = [(1.2, 1.1), (6.7, 2.3), (3.1, 6.6)]
        antialias.supersample_image(points, {"n": 2}, grid, colors=False)
        antialias.reference_coverage(points, {}, grid)
    except Exception as error:  # noqa: BLE001 - any failure means: leave it out
        return f"{type(error).__name__}: {error}"
    return ""


def measure_antialias(settings, rows: Rows, rng, tick=lambda: None) -> None:
    """RMS and max error against exact coverage, by pattern, filter and samples; time."""
    from algorithms import antialias

    size = settings.aa_grid
    points = []
    for _ in range(settings.aa_triangles):
        points += [(float(rng.uniform(1, size - 1)), float(rng.uniform(1, size - 1)))
                   for _ in range(3)]
    grid = (size, size)
    reference = antialias.reference_coverage(points, {}, grid)
    edge = (reference > 0) & (reference < 1)
    for pattern in antialias.PATTERNS:
        for filter_name in antialias.FILTERS:
            for n in settings.aa_samples:
                options = {"pattern": pattern, "filter": filter_name, "n": n}
                coverage, _ = antialias.supersample_image(points, options, grid, colors=False)
                seconds = median_seconds(
                    lambda: antialias.supersample_image(points, options, grid, colors=False),
                    settings.repeats)
                error = coverage - reference
                add = lambda metric, v, unit="": rows.add(  # noqa: E731
                    "antialiasing", "supersampling", "aa-supersample",
                    f"{pattern} {filter_name}", "samples per pixel", n * n, metric, v, unit)
                add("rms error", float(np.sqrt(np.mean(error ** 2))), "coverage")
                add("max error", float(np.abs(error).max()), "coverage")
                add("edge rms error", float(np.sqrt(np.mean(error[edge] ** 2))) if edge.any()
                    else 0.0, "coverage")
                add("kernel time", 1e9 * seconds / (size * size), "ns/px")
                add("samples", n * n, "per pixel")
        tick()
    if hasattr(antialias, "adaptive_image"):
        for depth in settings.aa_depths:
            options = {"max_depth": depth}
            try:
                coverage, spent = antialias.adaptive_image(points, options, grid)
            except InputError:
                continue
            seconds = median_seconds(lambda: antialias.adaptive_image(points, options, grid),
                                     settings.generator_repeats)
            error = coverage - reference
            add = lambda metric, v, unit="": rows.add(  # noqa: E731
                "antialiasing", "adaptive", "aa-adaptive", "adaptive", "max depth", depth,
                metric, v, unit)
            add("rms error", float(np.sqrt(np.mean(error ** 2))), "coverage")
            add("max error", float(np.abs(error).max()), "coverage")
            add("samples", float(spent.mean()), "per pixel")
            add("generator time", 1e6 * seconds / (size * size), "us/px")


def pareto_front(points: Iterable[tuple[float, float, object]]) -> list:
    """The (cost, error, label) points no other point beats on both cost and error."""
    ordered = sorted(points, key=lambda p: (p[0], p[1]))
    front, best = [], math.inf
    for point in ordered:
        if point[1] < best:
            front.append(point)
            best = point[1]
    return front


# ============================================================== settings
@dataclass(frozen=True)
class Settings:
    quick: bool
    repeats: int
    generator_repeats: int
    line_lengths: tuple
    segments: int
    traced_segments: int
    generator_max_length: int
    max_frames: int
    dda_max_length: int
    dda_lengths: int
    dda_segments: int
    radii: tuple
    circle_cost_radii: tuple
    hole_radius: int
    magnitudes: tuple
    mesh_cells: int
    cell_size: float
    traversal_grid: int
    traversal_count: int
    fill_radius: int
    interpolation_grid: int
    w_ratios: tuple
    near_far: tuple
    depth_rows: int
    aa_grid: int
    aa_triangles: int
    aa_samples: tuple
    aa_depths: tuple


def settings(quick: bool) -> Settings:
    if quick:
        return Settings(
            quick=True, repeats=3, generator_repeats=1,
            line_lengths=(100, 1000, 10_000, 100_000), segments=3, traced_segments=2,
            generator_max_length=1000, max_frames=20_000,
            dda_max_length=100_000, dda_lengths=17, dda_segments=6,
            radii=tuple(range(0, 33)) + (64, 256, 1024), circle_cost_radii=(100,),
            hole_radius=48,
            magnitudes=(10, 1e3, 1e5, 1e6, 1e7), mesh_cells=3, cell_size=6.0,
            traversal_grid=32, traversal_count=1, fill_radius=14,
            interpolation_grid=24, w_ratios=(1, 2, 10, 100, 10_000),
            near_far=(10, 1e3, 1e5, 1e7), depth_rows=4096,
            aa_grid=24, aa_triangles=3, aa_samples=(1, 2, 4, 8), aa_depths=(1, 3))
    return Settings(
        quick=False, repeats=7, generator_repeats=5,
        line_lengths=(100, 300, 1000, 3000, 10_000, 30_000, 100_000), segments=24,
        traced_segments=6, generator_max_length=10_000, max_frames=200_000,
        dda_max_length=100_000, dda_lengths=61, dda_segments=48,
        radii=tuple(range(0, 129)) + (256, 512, 1024, 2048, 4096),
        circle_cost_radii=(10, 100, 1000), hole_radius=256,
        magnitudes=(10, 100, 1e3, 1e4, 1e5, 1e6, 1e7), mesh_cells=6, cell_size=7.0,
        traversal_grid=64, traversal_count=6, fill_radius=60,
        interpolation_grid=64, w_ratios=(1, 1.5, 2, 4, 10, 100, 1000, 10_000, 1e6),
        near_far=(10, 100, 1e3, 1e4, 1e5, 1e6, 1e7), depth_rows=65_536,
        aa_grid=48, aa_triangles=6, aa_samples=tuple(range(1, 9)), aa_depths=(1, 2, 3, 4))


# ================================================================= run
FAMILIES = ("lines", "circles", "polygons", "fill", "triangles", "interpolation",
            "antialiasing")


def tasks(config: Settings) -> list[tuple[str, str, Callable]]:
    """(family, label, measure) in order; each measure(config, rows, rng, tick)."""
    found = [("lines", "lines", measure_lines),
             ("circles", "circles", measure_circles),
             ("polygons", "meshes (polygons and triangles)", measure_precision),
             ("triangles", "traversals", measure_traversal),
             ("fill", "seed fill", measure_fill),
             ("interpolation", "interpolation and depth", measure_interpolation)]
    if not antialias_available():
        found.append(("antialiasing", "antialiasing", measure_antialias))
    return found


def ticks(config: Settings) -> int:
    """How many times the measures call tick(): the progress bar's length."""
    total = len(config.line_lengths) * len(LINE_VARIANTS)
    total += len(CIRCLE_VARIANTS) + len(config.magnitudes) + len(TRAVERSALS) + 1
    total += len(config.w_ratios)
    if not antialias_available():
        from algorithms import antialias
        total += len(antialias.PATTERNS)
    return total


def run(config: Settings, progress: Callable[[int, int, str], None] | None = None,
        seed: int = SEED) -> tuple[Rows, dict]:
    """Every measurement, and how long each family took (seconds)."""
    rows = Rows()
    total = ticks(config)
    done = [0]
    seconds = {}
    for family, label, measure in tasks(config):
        def tick(label=label):
            done[0] += 1
            if progress:
                progress(min(done[0], total), total, label)
        if progress:
            progress(done[0], total, label)
        start = time.perf_counter()
        measure(config, rows, np.random.default_rng([seed, FAMILIES.index(family)]), tick)
        seconds[label] = time.perf_counter() - start
    if progress:
        progress(total, total, "done")
    return rows, seconds
