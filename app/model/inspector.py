"""Everything known about one pixel at one frame of a run: the pixel inspector.

``inspect(trace, index, pixel, spec, points, options, grid)`` gives the rows
the "Pixel inspector" dock shows, as ``Row(section, label, value)``:

* Trace: the steps up to ``index`` that visited the pixel (frames on VISIT
  or PLOT lines, spans included) and that plotted it (PLOT lines), first,
  last and how many, the pseudo-code line of the last one, and what the
  replayed raster holds there now.
* Triangle (runs that record triangles, as the triangle and visibility
  families do): the exact edge values at the pixel centre, the barycentric
  weights and, with w, the perspective-correct weights, worked out in
  integers and fractions from the snapped vertices the run recorded.
* Sign conventions (the same runs): that centre under note 000's edge
  functions, note 004's normal form and note 003's barycentric
  coordinates, areal and homogeneous (``app/model/conventions.py``).
* Depth (runs with z): the fragment depth at the centre, and for a run
  with a depth buffer the depth stored there at this frame and the depth
  tests made so far.
* Samples and coverage (antialiasing runs): the samples tested and hit,
  the coverage the run has written so far, the exact coverage of the pixel
  square and the error.

Only the one pixel and the one frame are looked at. ``PixelInspector``
keeps, per trace, the step indices at which each inspected pixel appears,
so stepping with a pinned pixel costs a binary search, not a scan.
"""
from __future__ import annotations

import bisect
import math
from collections import OrderedDict
from fractions import Fraction
from typing import NamedTuple

import numpy as np

from algorithms import triangles
from algorithms.triangles.interpolate import affine_value, barycentric_weights, per_vertex, \
    perspective_weights
from algorithms.core.registry import InputError, format_value
from algorithms.core.steps import PLOT, VISIT, Vars

from app.model.conventions import convention_rows
from app.model.geometry import exact_reference

MAX_SAMPLE_ROWS = 16  # sample positions listed one per row, at most
MAX_DEPTH_ROWS = 6  # depth tests listed, the latest ones
PIXEL_CACHE = 64  # pixels whose step indices a PixelInspector keeps


class Row(NamedTuple):
    """One line of the inspector: its section, what it is, and its value."""

    section: str
    label: str
    value: str


def inspect(trace, index, pixel, spec, points, options, grid) -> list[Row]:
    """The rows for ``pixel`` at step ``index`` of ``trace`` (see the module text)."""
    return PixelInspector(trace, spec, points, options, grid).rows(index, pixel)


def rows_by_label(rows) -> dict[str, str]:
    """{label: value} of the rows (a later row with the same label wins)."""
    return {row.label: row.value for row in rows}


class PixelInspector:
    """The inspector for one run: rows for any pixel at any step."""

    def __init__(self, trace, spec, points, options, grid, raster_at=None):
        self.trace, self.spec = trace, spec
        self.points, self.options, self.grid = list(points or ()), dict(options or {}), grid
        # Where the replayed raster comes from: the player's cached state when
        # the window asks, else the trace itself.
        self._raster_at = raster_at or trace.raster_at
        self._pixels: OrderedDict = OrderedDict()
        self._kinds = np.array([line.kind for line in trace.code])
        self._triangles = [i for i, r in trace.records_of(Vars) if "triangle" in r.values
                           and all(f"P{k}" in r.values for k in range(3))]

    # ------------------------------------------------------------ rows
    def rows(self, index: int, pixel) -> list[Row]:
        trace = self.trace
        index = min(max(int(index), 0), len(trace) - 1)
        x, y = int(pixel[0]), int(pixel[1])
        if not (0 <= x < trace.width and 0 <= y < trace.height):
            return [Row("Trace", "pixel", f"({x}, {y}) is outside the grid")]
        visits, plots = self.steps_at((x, y), index)
        rows = [Row("Trace", "pixel", f"({x}, {y}) \u00b7 centre ({x + 0.5:g}, {y + 0.5:g})"),
                Row("Trace", "at step", f"{index:,} of {len(trace) - 1:,}")]
        rows += self._trace_rows(visits, plots)
        raster = self._raster_at(index)
        rows += self._raster_rows(raster, x, y)
        rows += self._triangle_rows(index, (x, y), visits, raster)
        rows += self._depth_test_rows(visits)
        rows += self._sample_rows((x, y), visits)
        rows += self._coverage_rows((x, y), plots)
        return rows

    # ------------------------------------------------------- the trace
    def steps_at(self, pixel, index: int) -> tuple[np.ndarray, np.ndarray]:
        """Step indices up to ``index`` that visited the pixel (VISIT or PLOT
        frames, spans included), and those that plotted it (PLOT)."""
        visits, plots = self._pixel_steps(pixel)
        return (visits[:bisect.bisect_right(visits, index)],
                plots[:bisect.bisect_right(plots, index)])

    def _pixel_steps(self, pixel):
        if pixel in self._pixels:
            self._pixels.move_to_end(pixel)
            return self._pixels[pixel]
        trace, (x, y) = self.trace, pixel
        lean = np.flatnonzero((trace.x == x) & (trace.y == y))
        # Rich records carry a pixel for show; only lean frames and spans
        # stand for work on the pixel.
        lean = lean[~np.isin(lean, trace.steps_of())]
        kinds = self._kinds[trace.line[lean]] if len(lean) else np.zeros(0, str)
        spans = trace.spans()
        spans = spans[(spans["y"] == y) & (spans["x_start"] <= x) & (x < spans["x_end"])]
        span_kinds = self._kinds[spans["line"]]
        steps = np.concatenate([lean, spans["step"]])
        kinds = np.concatenate([kinds, span_kinds]) if len(steps) else np.zeros(0, str)
        order = np.argsort(steps, kind="stable")
        steps, kinds = steps[order], kinds[order]
        visits = steps[(kinds == VISIT) | (kinds == PLOT)]
        plots = steps[kinds == PLOT]
        self._pixels[pixel] = (visits, plots)
        if len(self._pixels) > PIXEL_CACHE:
            self._pixels.popitem(last=False)
        return visits, plots

    def _trace_rows(self, visits, plots) -> list[Row]:
        rows = [Row("Trace", "visited", _steps_text(visits)),
                Row("Trace", "plotted", _steps_text(plots))]
        if len(visits):
            last = int(visits[-1])
            line = int(self.trace.line[last])
            text = self.trace.code[line].text.strip()
            rows.append(Row("Trace", "last visit", f"step {last:,}, line {line + 1}: {text}"))
        return rows

    def _raster_rows(self, raster, x, y) -> list[Row]:
        count = int(raster.counts[y, x])
        text = "not written" if not count else f"written {count}\u00d7"
        if count and raster.colors is not None and raster.colors[y, x] >= 0:
            text += f" \u00b7 #{int(raster.colors[y, x]):06x}"
        return [Row("Trace", "raster now", text)]

    # ----------------------------------------------------- triangles
    def triangle_at(self, index: int, visits) -> int | None:
        """Step of the Vars record of the triangle the pixel belongs to at
        ``index``: the one being drawn at the pixel's last visit, else the
        one being drawn now, else the first."""
        if not self._triangles:
            return None
        at = int(visits[-1]) if len(visits) else index
        k = bisect.bisect_right(self._triangles, at) - 1
        return self._triangles[max(k, 0)]

    def _triangle_rows(self, index, pixel, visits, raster) -> list[Row]:
        record_at = self.triangle_at(index, visits)
        if record_at is None:
            return []
        values = self.trace.record_at(record_at).values
        tri = recorded_triangle(self.trace, values)
        if tri is None:
            return [Row("Triangle", "triangle", f"{values['triangle']}: no area once snapped")]
        es = exact_edges(self.trace, tri, pixel)
        section = f"Triangle {values['triangle']}"
        rows = [Row(section, "vertices", "  ".join(f"P{k} ({format_value(values[f'P{k}'][0])}, "
                                                    f"{format_value(values[f'P{k}'][1])})"
                                                    for k in range(3)))]
        for k, e in enumerate(es):
            text = _fraction_text(e)
            if e == 0:
                text += f"  on the {tri.side(k)} edge: " + (
                    "kept" if tri.include[k] else "left out") + " by the fill rule"
            rows.append(Row(section, f"e{k}", text))
        rows += self._run_edge_rows(section, visits)
        inside = all(tri.sign * e > 0 or (e == 0 and keep) for e, keep in zip(es, tri.include))
        rows.append(Row(section, "centre inside", "yes" if inside else "no"))
        weights = barycentric_weights(*es, Fraction(tri.area2, tri.S * tri.S))
        rows += [Row(section, name, _number(w)) for name, w in zip(("alpha", "beta", "gamma"),
                                                                   weights)]
        rows += self._convention_rows(tri, pixel, "swapped" in str(values.get("winding", "")))
        order = self._vertex_order(values)
        w = self._per_vertex("w", order)
        if w is not None:
            try:
                p = perspective_weights(weights, [Fraction(v) for v in w])
                rows += [Row(section, name, _number(v))
                         for name, v in zip(("alpha_p", "beta_p", "gamma_p"), p)]
            except InputError as error:
                rows.append(Row(section, "perspective", str(error)))
        z = [values[f"z{k}"] for k in range(3)] if "z0" in values else self._per_vertex("z", order)
        if z is not None:
            depth = float(affine_value(weights, [Fraction(v) for v in z]))
            rows.append(Row("Depth", "fragment depth",
                            f"{depth!r} (triangle {values['triangle']})"))
        rows += self._stored_depth_rows(raster, pixel)
        return rows

    def _convention_rows(self, tri, pixel, swapped: bool) -> list[Row]:
        """The centre under note 000's, 004's and 003's conventions side by
        side, for the vertices a, b, c in the order they were given (a run
        that turned a clockwise triangle round recorded them swapped)."""
        ox, oy = self.trace.start.constants.get("offset", (0, 0))
        order = (0, 2, 1) if swapped else (0, 1, 2)
        vertices = [(Fraction(tri.v[k][0], tri.S), Fraction(tri.v[k][1], tri.S)) for k in order]
        centre = (Fraction(2 * (pixel[0] + ox) + 1, 2), Fraction(2 * (pixel[1] + oy) + 1, 2))
        return [Row("Sign conventions", label, value)
                for label, value in convention_rows(vertices, centre)]

    def _run_edge_rows(self, section, visits) -> list[Row]:
        """The edge values a floating-point run itself computed at its last
        visit, beside the exact ones."""
        precision = self.trace.start.constants.get("precision", "fixed")
        names = self.trace.value_names
        if precision == "fixed" or not len(visits) or "e0" not in names:
            return []
        last = int(visits[-1])
        values = [float(self.trace.series(f"e{k}")[last]) for k in range(3)]
        if any(math.isnan(v) for v in values):
            return []
        return [Row(section, f"e0 e1 e2 ({precision})",
                    "  ".join(repr(v) for v in values) + f"  at step {last:,}")]

    def _vertex_order(self, values) -> list[int]:
        """Input point indices of the triangle's P0 P1 P2 as the run used them."""
        first = 3 * (int(values["triangle"]) - 1)
        swapped = "swapped" in str(values.get("winding", ""))
        return [first, first + 2, first + 1] if swapped else [first, first + 1, first + 2]

    def _per_vertex(self, name, order):
        try:
            values = per_vertex(self.options, name, len(self.points))
        except InputError:
            return None
        if values is None or max(order) >= len(values):
            return None
        return [values[k] for k in order]

    # ---------------------------------------------------------- depth
    def _stored_depth_rows(self, raster, pixel) -> list[Row]:
        if raster.depth is None:
            return []
        x, y = pixel
        stored = float(raster.depth[y, x])
        clear = self.trace.start.constants.get("clear_depth", self.options.get("clear_depth"))
        if math.isnan(stored):
            text = "clear" + (f" ({format_value(clear)})" if clear is not None else "")
        else:
            text = repr(stored)
        return [Row("Depth", "stored depth", text)]

    def _depth_test_rows(self, visits) -> list[Row]:
        names = self.trace.value_names
        if "z" not in names or "zb" not in names or not len(visits):
            return []
        z, zb = self.trace.series("z"), self.trace.series("zb")
        tests = [int(i) for i in visits if not math.isnan(z[i])][-MAX_DEPTH_ROWS:]
        rows = []
        for i in tests:
            passed = self._kinds[self.trace.line[i]] == PLOT
            rows.append(Row("Depth", f"test at step {i:,}",
                            f"z {float(z[i])!r} vs stored {float(zb[i])!r}: "
                            + ("passed, written" if passed else "failed, kept")))
        return rows

    # ------------------------------------------------- antialiasing
    def _sample_rows(self, pixel, visits) -> list[Row]:
        names = self.trace.value_names
        if "sx" not in names or "sy" not in names:
            return []
        sx, sy = self.trace.series("sx"), self.trace.series("sy")
        rows_at = [int(i) for i in visits if np.isfinite(sx[i]) and np.isfinite(sy[i])]
        if not rows_at:
            return [Row("Samples", "tested", "none yet")]
        hit = self.trace.series("hit") if "hit" in names else None
        hits = [hit is None or hit[i] > 0 for i in rows_at]
        rows = [Row("Samples", "hit / tested", f"{sum(hits)} / {len(hits)} = "
                                               f"{sum(hits) / len(hits):.6g}")]
        x, y = pixel
        for n, (i, h) in enumerate(zip(rows_at[:MAX_SAMPLE_ROWS], hits)):
            rows.append(Row("Samples", f"sample {n + 1}",
                            f"+({sx[i] - x:.4g}, {sy[i] - y:.4g}) {'hit' if h else 'miss'}"
                            f" \u00b7 step {i:,}"))
        if len(rows_at) > MAX_SAMPLE_ROWS:
            rows.append(Row("Samples", "more", f"{len(rows_at) - MAX_SAMPLE_ROWS} more samples"))
        return rows

    def _coverage_rows(self, pixel, plots) -> list[Row]:
        if self.spec is None or self.spec.family != "antialias" \
                or self.trace.start.pixel_value is None:
            return []
        coverage = self.coverage(plots)
        exact = self.exact_coverage(pixel)
        rows = [Row("Coverage", "coverage", repr(coverage))]
        if exact is None:
            rows.append(Row("Coverage", "exact coverage", "not defined for this run"))
            return rows
        rows += [Row("Coverage", "exact coverage", repr(exact)),
                 Row("Coverage", "error", f"{coverage - exact!r}  (coverage - exact)")]
        return rows

    def coverage(self, plots) -> float:
        """The value the run wrote into the pixel last, at or before the step
        (0 before it writes any)."""
        if not len(plots):
            return 0.0
        last = int(plots[-1])
        span = self.trace.spans(last, last + 1)
        if len(span):
            value = float(span["value"][0])
            return 0.0 if math.isnan(value) else value
        return float(self.trace.series(self.trace.start.pixel_value)[last])

    def exact_coverage(self, pixel) -> float | None:
        """Exact area of the pixel square the shape covers, or None."""
        x, y = pixel
        exact = exact_reference(self.spec, self.points, self.options,
                                           (x, y, x + 1, y + 1))
        return None if exact is None or exact.shape != (1, 1) else float(exact[0, 0])


# ------------------------------------------------------------ helpers
def recorded_triangle(trace, values):
    """The triangle of a Vars record as the run snapped it, or None without area."""
    scale = int(trace.start.constants.get("S", 256))
    rule = trace.start.constants.get("fill_rule", "top-left")
    vertices = [(round(px * scale), round(py * scale))
                for px, py in (values[f"P{k}"] for k in range(3))]
    tri = triangles.Triangle(0, vertices, (0, 1, 2), scale, rule)
    return tri if tri.area2 != 0 else None


def exact_edges(trace, tri, pixel) -> list[Fraction]:
    """e_k at the pixel centre in px^2, exactly (the run's offset undone)."""
    ox, oy = trace.start.constants.get("offset", (0, 0))
    unit = 2 * tri.S * tri.S
    return [Fraction(e, unit) for e in tri.at(pixel[0] + ox, pixel[1] + oy)]


def _steps_text(steps) -> str:
    if not len(steps):
        return "never"
    first, last, count = int(steps[0]), int(steps[-1]), len(steps)
    if count == 1:
        return f"once, step {first:,}"
    return f"{count:,} times, steps {first:,} \u2026 {last:,}"


def _fraction_text(value: Fraction) -> str:
    if value.denominator & (value.denominator - 1) == 0:
        return triangles.dyadic_text(value.numerator, value.denominator)
    return f"{float(value)!r}"


def _number(value) -> str:
    """A weight: its exact decimal when short, else 10 significant digits."""
    value = Fraction(value)
    text = f"{float(value):.10g}"
    return text if Fraction(text) == value else text + "\u2026"
