"""Meshes, traversals and seed fill: coverage against the exact oracle, cost per pixel."""
from __future__ import annotations

import math
from fractions import Fraction
from math import lcm

import numpy as np

from algorithms.core import registry
from algorithms.core.errors import InputError
from algorithms.core.steps import OP_NAMES

from .counting import (Rows, add_costs, median_seconds, op_counts, pixel_keys, timed,
                       written_count)


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
                run = lambda: [_run_shape(spec, family, shape, options, bits,  # noqa: E731
                                          window) for shape in shapes]
                try:
                    covers, once = timed(run)
                except InputError:
                    add("rejected", 1)
                    continue
                masks = [_mask_of(cover, window) for cover in covers]
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
                seconds = median_seconds(run, settings.repeats, once=once)
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
    size = (window[2] + 1, window[3] + 1)
    resolved = spec.resolve(options)
    if family == "triangles":
        inputs = [list(shape) for shape in shapes]
    else:
        inputs = [([(float(snapped(x, bits)), float(snapped(y, bits))) for x, y in shape],)
                  for shape in shapes]
    record = lambda: [spec.record(points, resolved, size) for points in inputs]  # noqa: E731
    traces, once = timed(record)
    for trace in traces:
        for op, count in op_counts(trace).items():
            counts[op] += count
        written += written_count(trace)
    seconds = median_seconds(record, settings.generator_repeats, once=once)
    add_costs(rows, family, "precision", spec.name, variant, "magnitude", magnitude, counts,
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
            inputs = [list(triangle) for triangle in cases]
            record = lambda: [spec.record(points, options, grid)  # noqa: E731
                              for points in inputs]
            traces, once = timed(record)
            for trace in traces:
                final = trace.final_variables()
                tested += int(final["tested"])
                filled += int(final["filled"])
                for op, count in op_counts(trace).items():
                    counts[op] += count
                written += written_count(trace)
            del traces
            seconds = median_seconds(record, settings.generator_repeats, once=once)
            if spec.kernel is not None:
                kernel_seconds = median_seconds(
                    lambda: [spec.kernel(points, options, grid) for points in inputs],
                    settings.repeats)
            add = lambda metric, v, unit="": rows.add(  # noqa: E731
                "triangles", "traversal", name, name.removeprefix("triangle-"), "shape", shape,
                metric, v, unit)
            add("tested", tested / len(cases), "px per triangle")
            add("filled", filled / len(cases), "px per triangle")
            add("tested per filled", tested / max(filled, 1))
            add_costs(rows, "triangles", "traversal", name, name.removeprefix("triangle-"),
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
    for name in ("polygon-scanline", "polygon-brute-scanline", "polygon-convex", "polygon-tessellate"):
        spec = registry.get(name)
        options = spec.resolve({})
        for shape, cases in shapes.items():
            counts = dict.fromkeys(OP_NAMES, 0)
            written = 0
            inputs = []
            for polygon in cases:
                try:
                    trace = spec.record((polygon,), options, (size, size))
                except InputError:
                    continue  # a star is not convex: polygon-convex refuses it
                inputs.append((polygon,))
                for op, count in op_counts(trace).items():
                    counts[op] += count
                written += written_count(trace)
            if not inputs:
                continue
            seconds = median_seconds(lambda: [spec.record(points, options, (size, size))
                                              for points in inputs], settings.generator_repeats)
            if spec.kernel is not None:
                kernel_seconds = median_seconds(
                    lambda: [spec.kernel(points, options) for points in inputs], settings.repeats)
            variant = name.removeprefix("polygon-")
            add_costs(rows, "polygons", "traversal", name, variant, "shape", shape, counts,
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
            trace, once = timed(lambda: spec.record((outline,), options, (size, size)))
            final = trace.final_variables()
            filled = int(final["filled"])
            seconds = median_seconds(lambda: spec.record((outline,), options, (size, size)),
                                     settings.generator_repeats, once=once)
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
            add_costs(rows, "fill", "disc", "flood-fill", variant, "radius", r,
                       op_counts(trace), filled, seconds, per="filled px")
    tick()


def fill_pixels(trace) -> np.ndarray:
    """Keys of the pixels a seed fill filled (its outline, line 0, left out)."""
    writes = trace.written()
    return np.unique(pixel_keys(writes.pixels[trace.line[writes.steps] != 0]))
