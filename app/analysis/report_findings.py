"""The report's reading of the measurements: number formats, tables, and the
headline findings."""
from __future__ import annotations

import math
from collections import defaultdict

import numpy as np

from app.analysis import measure


# ============================================================ formatting
def fmt(value, digits: int = 3) -> str:
    """A table cell: whole numbers as they are, others to a few significant digits."""
    if value is None:
        return "-"
    if isinstance(value, str):
        return value
    value = float(value)
    if not math.isfinite(value):
        return "-"
    if value == 0:
        return "0"
    if value.is_integer() and abs(value) < 1e9:
        return f"{int(value):,}".replace(",", " ")
    if abs(value) >= 1e5 or abs(value) < 1e-3:
        return f"{value:.{digits - 1}e}"
    return f"{value:.{digits}g}"


def table(headers, rows) -> str:
    """A Markdown table; columns of numbers align right, text columns left."""
    rows = [list(row) for row in rows]

    def numeric(n):
        cells = [row[n] for row in rows if n < len(row) and row[n] not in (None, "")]
        return bool(cells) and all(isinstance(c, (int, float, np.integer, np.floating))
                                   for c in cells)
    lines = ["| " + " | ".join(headers) + " |",
             "|" + "|".join("---:" if numeric(n) else "---" for n in range(len(headers))) + "|"]
    for row in rows:
        lines.append("| " + " | ".join(fmt(cell) for cell in row) + " |")
    return "\n".join(lines)


class View:
    """Look-ups into the rows: value(family, experiment, variant, parameter value, metric)."""

    def __init__(self, rows: list[dict]):
        self.rows = rows
        self.index = {}
        self.order = defaultdict(list)
        for row in rows:
            key = (row["family"], row["experiment"], row["variant"], row["parameter_value"],
                   row["metric"])
            self.index[key] = row["value"]
            variants = self.order[(row["family"], row["experiment"])]
            if row["variant"] not in variants:
                variants.append(row["variant"])

    def get(self, family, experiment, variant, parameter_value, metric, default=None):
        return self.index.get((family, experiment, variant, parameter_value, metric), default)

    def variants(self, family, experiment) -> list[str]:
        return self.order[(family, experiment)]

    def values(self, family, experiment, metric=None, variant=None) -> list:
        """Parameter values in first-seen order."""
        seen = []
        for row in self.rows:
            if (row["family"], row["experiment"]) == (family, experiment) and \
                    (metric is None or row["metric"] == metric) and \
                    (variant is None or row["variant"] == variant) and \
                    row["parameter_value"] not in seen:
                seen.append(row["parameter_value"])
        return seen

    def algorithm(self, family, experiment, variant) -> str:
        for row in self.rows:
            if (row["family"], row["experiment"], row["variant"]) == (family, experiment, variant):
                return row["algorithm"]
        return ""


# ============================================================ findings
def findings(view: View) -> list[tuple[str, str, str]]:
    """(topic, finding, measured) for the headline table, from whatever was measured."""
    parts = (_line_findings, _circle_findings, _mesh_findings, _traversal_findings,
             _interpolation_findings, _antialias_findings)
    return [(topic, text, value) for part in parts for topic, text, value in part(view)
            if value is not None]


def _line_findings(view: View):
    lengths = view.values("lines", "length sweep", "differing pixels")
    if lengths:
        longest = lengths[-1]
        exact = [v for v in view.variants("lines", "length sweep")
                 if all(view.get("lines", "length sweep", v, n, "differing pixels", 1) == 0
                        for n in lengths)]
        yield ("lines", "variants on the exact nearest-pixel line at every length",
               ", ".join(exact) or "none")
        first = view.get("lines", "DDA precision", "DDA float32", "all", "first wrong length")
        if first is not None:
            yield ("lines", "shortest segment on which float32 DDA misses a nearest pixel",
                   f"{fmt(first)} px" if first else "none found")
        first64 = view.get("lines", "DDA precision", "DDA float64", "all", "first wrong length")
        if first64 is not None:
            yield ("lines", "float64 DDA up to the longest length tried",
                   "never wrong" if not first64 else f"first wrong at {fmt(first64)} px")
        deviation = view.get("lines", "length sweep", "DDA float32", longest, "max deviation")
        yield ("lines", f"float32 DDA at {fmt(longest)} px: largest distance of a pixel from the line",
               None if deviation is None else f"{fmt(deviation)} px (exact: <= 0.5)")
        costs = view.values("lines", "length sweep", "ops")
        if costs:
            at = costs[-1]
            parts = [f"{name} {fmt(view.get('lines', 'length sweep', name, at, 'ops'))}"
                     for name in ("Bresenham", "DDA float64", "incremental (round)", "explicit",
                                  "parametric dt=auto")
                     if view.get("lines", "length sweep", name, at, "ops") is not None]
            yield ("lines", f"operations per pixel at {fmt(at)} px", ", ".join(parts))


def _circle_findings(view: View):
    radii = view.values("circles", "radius sweep", "gaps")
    if radii:
        r = max(v for v in radii if isinstance(v, (int, float)))
        gaps = view.get("circles", "radius sweep", "sqrt4 (4-way)", r, "gaps")
        skipped = view.get("circles", "radius sweep", "sqrt4 (4-way)", r, "skipped")
        yield ("circles", f"sqrt4 circle of radius {fmt(r)}: gaps (pixels skipped)",
               None if gaps is None else f"{fmt(gaps)} ({fmt(skipped)})")
        dev = view.get("circles", "radius sweep", "midpoint", r, "max deviation")
        dev8 = view.get("circles", "radius sweep", "sqrt8 (8-way)", r, "max deviation")
        yield ("circles", f"largest distance from the true radius at r = {fmt(r)}: midpoint / sqrt8",
               None if dev is None else f"{fmt(dev)} / {fmt(dev8)} px")
        rings = view.values("circles", "concentric rings", "holes")
        if rings:
            holes = view.get("circles", "concentric rings", "midpoint", rings[0], "holes")
            yield ("circles", f"holes between concentric midpoint rings, radii {rings[0]}",
                   None if holes is None else f"{fmt(holes)} px")


def _mesh_findings(view: View):
    for family in ("triangles", "polygons"):
        magnitudes = view.values(family, "precision", "misclassified vs true")
        if not magnitudes:
            continue
        for variant in ("float32", "float64"):
            first = next((m for m in magnitudes
                          if (view.get(family, "precision", variant, m, "misclassified vs snapped")
                              or 0) > 0), None)
            accepted = [m for m in magnitudes
                        if view.get(family, "precision", variant, m, "rejected") == 0]
            yield (family, f"{variant} edge tests: first coordinate magnitude with a wrong pixel",
                   f"{fmt(first)} px" if first is not None else
                   f"none up to {fmt(max(accepted, default=0))} px")
        overlaps = sum(view.get(family, "precision", "fixed 8 bits", m, "overlaps", 0)
                       + view.get(family, "precision", "fixed 8 bits", m, "cracks", 0)
                       for m in magnitudes)
        yield (family, "fixed 8-bit meshes: overlaps + cracks over all magnitudes", fmt(overlaps))
        shares = [view.get(family, "precision", "fixed 0 bits", m, "misclassified fraction")
                  for m in magnitudes]
        shares = [s for s in shares if s is not None]
        if shares:
            yield (family, "whole-pixel snapping (0 bits): pixels unlike the unsnapped shape",
                   f"{fmt(100 * float(np.mean(shares)))} % of covered")
        rejected = [m for m in magnitudes if view.get(family, "precision", "fixed 8 bits", m,
                                                     "rejected") == 1]
        if rejected:
            yield (family, "coordinates refused (InputError)", f">= {fmt(min(rejected))} px")


def _traversal_findings(view: View):
    shapes = view.values("triangles", "traversal", "tested per filled")
    if shapes:
        parts = []
        for variant in ("scan", "bbox", "backtrack", "pineda", "linewise"):
            ratios = [view.get("triangles", "traversal", variant, s, "tested per filled")
                      for s in shapes]
            ratios = [r for r in ratios if r is not None]
            if ratios:
                parts.append(f"{variant} {fmt(min(ratios))}-{fmt(max(ratios))}")
        yield ("triangles", "pixels tested per pixel filled, over the shapes", ", ".join(parts))


def _interpolation_findings(view: View):
    ratios = view.values("interpolation", "w ratio", "max error")
    if ratios:
        for ratio in (10, ratios[-1]):
            err = view.get("interpolation", "w ratio", "affine", ratio, "max error")
            persp = view.get("interpolation", "w ratio", "perspective-correct", ratio, "max error")
            yield ("interpolation", f"w ratio {fmt(ratio)}: largest error, affine / perspective-correct",
                   None if err is None else f"{fmt(err)} / {fmt(persp)} (of the attribute's range)")
    ratios = view.values("interpolation", "depth precision", "first fighting depth")
    if ratios:
        far = ratios[-1]
        parts = [f"{kind}: " + fmt(view.get("interpolation", "depth precision", kind, far,
                                            "first fighting depth"))
                 for kind in measure.DEPTH_BUFFERS]
        yield ("depth", f"far/near {fmt(far)}: first depth (x near) where a 0.1 % gap z-fights "
                        "(0: never)", ", ".join(parts))


def _antialias_findings(view: View):
    samples = view.values("antialiasing", "supersampling", "rms error", "grid box")
    if samples:
        parts = [f"{fmt(n)}: " + fmt(view.get("antialiasing", "supersampling", "grid box", n,
                                              "rms error"))
                 for n in samples]
        yield ("antialiasing", "grid box supersampling, RMS coverage error by samples per pixel",
               ", ".join(parts))
        front = aa_front(view, "samples")
        yield ("antialiasing", "Pareto front (samples per pixel against RMS error)",
               ", ".join(f"{label} ({fmt(cost)})" for cost, _, label in front))


def aa_front(view: View, cost: str):
    points = []
    for variant in view.variants("antialiasing", "supersampling"):
        for n in view.values("antialiasing", "supersampling", "rms error", variant):
            c = view.get("antialiasing", "supersampling", variant, n,
                         "samples" if cost == "samples" else "kernel time")
            e = view.get("antialiasing", "supersampling", variant, n, "rms error")
            if c is not None and e is not None:
                points.append((c, e, f"{variant} n={round(math.sqrt(n))}"))
    for depth in view.values("antialiasing", "adaptive", "rms error") if cost == "samples" else ():
        c = view.get("antialiasing", "adaptive", "adaptive", depth,
                     "samples" if cost == "samples" else "generator time")
        e = view.get("antialiasing", "adaptive", "adaptive", depth, "rms error")
        if c is not None and e is not None:
            points.append((c * (1 if cost == "samples" else 1000), e, f"adaptive depth {depth}"))
    return measure.pareto_front(points)
