"""Lines and circles: pixels against the ideal curve, cost per pixel, DDA's drift."""
from __future__ import annotations

import math

import numpy as np

from algorithms.exact import circles as exact_circles
from algorithms.core import registry
from algorithms.core.steps import OP_NAMES

from .counting import (Rows, add_costs, median_seconds, op_counts, pixel_keys, timed,
                       written_count)


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
    distinct, hit, columns = _nearest_hits(p, q, pixels)
    xs, ys = pixels[:, 0] - x0, pixels[:, 1] - y0
    if not len(pixels):
        worst = 0.0
    elif dx == 0 and dy == 0:
        worst = float(np.hypot(xs, ys).max())
    else:
        # Dividing by the (positive) length keeps the order, so the largest
        # |cross product| gives the largest distance, divided once.
        worst = float(np.abs(dx * ys - dy * xs).max()) / math.sqrt(dx * dx + dy * dy)
    # A repeated plot is a step of (0, 0), which is no gap either.
    gaps = int(np.count_nonzero((np.abs(np.diff(pixels[:, 0])) > 1)
                                | (np.abs(np.diff(pixels[:, 1])) > 1)))
    return {"differing": (distinct - hit) + (columns - hit), "columns": columns,
            "missed": columns - hit, "extra": distinct - hit, "max_deviation": worst,
            "gaps": gaps, "duplicates": int(len(pixels) - distinct),
            "pixels": int(len(pixels))}


def differing_pixels(p, q, pixels) -> int:
    """``line_errors(p, q, pixels)["differing"]`` alone."""
    distinct, hit, columns = _nearest_hits(p, q, np.asarray(pixels, np.int64).reshape(-1, 2))
    return (distinct - hit) + (columns - hit)


def _nearest_hits(p, q, pixels) -> tuple[int, int, int]:
    """(distinct pixels, columns holding a nearest pixel, columns) of a
    line's (n, 2) int64 pixels against the exact nearest-pixel line of PQ."""
    (x0, y0), (x1, y1) = p, q
    dx, dy = x1 - x0, y1 - y0
    # Sort-based deduplication of the keys (np.unique's return_index sorts
    # the indices too, several times slower); the position along and across
    # the line depends only on the pixel, so distinct pixels are enough.
    keys = _distinct_keys(pixels)
    xs, ys = (keys >> 32) - ((1 << 30) + x0), (keys & 0xFFFFFFFF) - ((1 << 30) + y0)
    if abs(dx) >= abs(dy):
        along, v_d, n, m = xs, ys, dx, dy
    else:
        along, v_d, n, m = ys, xs, dy, dx
    u_d, big_n = along if n >= 0 else -along, abs(n)
    if big_n == 0:
        ok = (u_d == 0) & (v_d == 0)
    else:
        low, remainder = np.divmod(m * u_d, big_n)
        nearest = low + (2 * remainder >= big_n)
        tie = 2 * remainder == big_n
        ok = (u_d >= 0) & (u_d <= big_n) & ((v_d == nearest) | (tie & (v_d == low)))
    hit = int(np.count_nonzero(np.bincount(u_d[ok], minlength=1)))  # 0 <= u_d <= N where ok
    return len(keys), hit, big_n + 1


def _distinct_keys(pixels) -> np.ndarray:
    """The sorted distinct keys of some pixels (np.unique's hash table is
    many times slower on these keys than one sort). The stable sort is a
    merge of runs: a curve's pixels come in long ascending or descending
    runs of keys, which it sorts in about linear time."""
    keys = np.sort(pixel_keys(pixels), kind="stable")
    return keys[np.concatenate([[True], keys[1:] != keys[:-1]])] if len(keys) else keys


def distinct_pixels(pixels: np.ndarray) -> np.ndarray:
    """The distinct rows of an (n, 2) int64 pixel array, in key order."""
    keys = _distinct_keys(pixels)
    return np.stack([(keys >> 32) - (1 << 30), (keys & 0xFFFFFFFF) - (1 << 30)], axis=1)


def asymmetry(forward, backward) -> int:
    """Pixels drawn by one direction of a segment and not by the other."""
    # Sort-based: each side's distinct keys, then both sorted together; a
    # key of both sides shows up twice, next to itself.
    both = np.concatenate([_distinct_keys(forward), _distinct_keys(backward)])
    both.sort(kind="stable")  # two sorted runs: merged in linear time
    return int(len(both) - 2 * np.count_nonzero(both[1:] == both[:-1]))


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
            for p, q in fits:
                pixels = _line_pixels(spec, options, p, q)
                errors = line_errors(p, q, pixels)
                for key in ("differing", "gaps", "duplicates", "pixels", "columns", "missed",
                            "extra"):
                    totals[key] += errors[key]
                worst = max(worst, errors["max_deviation"])
                totals["asymmetric"] += asymmetry(pixels, _line_pixels(spec, options, q, p))
            kernel_seconds = median_seconds(
                lambda: [_line_pixels(spec, options, p, q) for p, q in fits], settings.repeats)
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
        traced = fits[:settings.traced_segments]
        record = lambda: [spec.record((p, q), options) for p, q in traced]  # noqa: E731
        traces, once = timed(record)
        for trace in traces:
            for op, count in op_counts(trace).items():
                counts[op] += count
            written += written_count(trace)
        del traces
        seconds = median_seconds(record, settings.generator_repeats, once=once)
        add_costs(rows, "lines", "length sweep", name, variant, "length", length, counts,
                   written, seconds)


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
                count = differing_pixels(p, q, spec.kernel((p, q), options))
                wrong += count > 0
                differing += count
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
            "differing": int(len(np.setxor1d(pixel_keys(distinct), pixel_keys(oracle))))}


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
            trace, once = timed(lambda: spec.record(((0, 0),), options))
            written = written_count(trace)
            seconds = median_seconds(lambda: spec.record(((0, 0),), options),
                                     settings.generator_repeats, once=once)
            add_costs(rows, "circles", "radius sweep", name, variant, "radius", r,
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
