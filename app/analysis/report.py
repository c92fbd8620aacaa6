"""`rasterlab report`: speed against error, written to a folder.

    rasterlab report [--quick] [--out DIR]

measures every algorithm family (app/analysis/measure.py) and writes into DIR
(default ./rasterlab-report):

* report.md: the headline findings, then tables per family;
* measurements.csv and measurements.json: every measurement, one row each
  (columns: measure.COLUMNS), the JSON with the settings and timings too;
* <family>.png: cost against error, one figure per family.

Every file is written to a temporary name beside it and renamed, so a
reader never sees half a file. ``--quick`` measures fewer and smaller
cases (under a minute on a 2-core machine); the full report takes a few
minutes.
"""
from __future__ import annotations

import csv
import io
import json
import math
import os
import platform
import tempfile
import time
from collections import defaultdict
from pathlib import Path

import numpy as np

from app.analysis import measure

from app.progress import TerminalBar

DEFAULT_OUT = "rasterlab-report"


class ReportError(Exception):
    """The report cannot be written; the message is one line for the person."""


# ============================================================ writing
def check_folder(out) -> Path:
    """Make the output folder (and its parents) and prove it takes files."""
    path = Path(out)
    if path.exists() and not path.is_dir():
        raise ReportError(f"--out {out}: not a folder")
    try:
        path.mkdir(parents=True, exist_ok=True)
    except OSError as error:
        raise ReportError(f"--out {out}: cannot create the folder "
                          f"({error.strerror or error})") from None
    try:
        handle, probe = tempfile.mkstemp(prefix=".rasterlab-", suffix=".tmp", dir=path)
        os.close(handle)
        os.unlink(probe)
    except OSError as error:
        raise ReportError(f"--out {out}: cannot write in the folder "
                          f"({error.strerror or error})") from None
    return path


def write_atomically(path: Path, data: bytes) -> None:
    """Write to a temporary file in the same folder, then rename over the target."""
    try:
        handle, temporary = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".tmp",
                                             dir=path.parent)
    except OSError as error:
        raise ReportError(f"{path}: cannot write ({error.strerror or error})") from None
    try:
        with os.fdopen(handle, "wb") as stream:
            stream.write(data)
            stream.flush()
            os.fsync(stream.fileno())
        os.chmod(temporary, 0o666 & ~_umask())  # mkstemp makes it private
        os.replace(temporary, path)
    except BaseException as error:
        Path(temporary).unlink(missing_ok=True)
        if isinstance(error, OSError):
            raise ReportError(f"{path}: cannot write ({error.strerror or error})") from None
        raise


def _umask() -> int:
    mask = os.umask(0)
    os.umask(mask)
    return mask


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
    found = []

    def add(topic, text, value):
        if value is not None:
            found.append((topic, text, value))

    lengths = view.values("lines", "length sweep", "differing pixels")
    if lengths:
        longest = lengths[-1]
        exact = [v for v in view.variants("lines", "length sweep")
                 if all(view.get("lines", "length sweep", v, n, "differing pixels", 1) == 0
                        for n in lengths)]
        add("lines", "variants on the exact nearest-pixel line at every length",
            ", ".join(exact) or "none")
        first = view.get("lines", "DDA precision", "DDA float32", "all", "first wrong length")
        if first is not None:
            add("lines", "shortest segment on which float32 DDA misses a nearest pixel",
                f"{fmt(first)} px" if first else "none found")
        first64 = view.get("lines", "DDA precision", "DDA float64", "all", "first wrong length")
        if first64 is not None:
            add("lines", "float64 DDA up to the longest length tried",
                "never wrong" if not first64 else f"first wrong at {fmt(first64)} px")
        deviation = view.get("lines", "length sweep", "DDA float32", longest, "max deviation")
        add("lines", f"float32 DDA at {fmt(longest)} px: largest distance of a pixel from the line",
            None if deviation is None else f"{fmt(deviation)} px (exact: <= 0.5)")
        costs = view.values("lines", "length sweep", "ops")
        if costs:
            at = costs[-1]
            parts = [f"{name} {fmt(view.get('lines', 'length sweep', name, at, 'ops'))}"
                     for name in ("Bresenham", "DDA float64", "incremental (round)", "explicit",
                                  "parametric dt=auto")
                     if view.get("lines", "length sweep", name, at, "ops") is not None]
            add("lines", f"operations per pixel at {fmt(at)} px", ", ".join(parts))
    radii = view.values("circles", "radius sweep", "gaps")
    if radii:
        r = max(v for v in radii if isinstance(v, (int, float)))
        gaps = view.get("circles", "radius sweep", "sqrt4 (4-way)", r, "gaps")
        skipped = view.get("circles", "radius sweep", "sqrt4 (4-way)", r, "skipped")
        add("circles", f"sqrt4 circle of radius {fmt(r)}: gaps (pixels skipped)",
            None if gaps is None else f"{fmt(gaps)} ({fmt(skipped)})")
        dev = view.get("circles", "radius sweep", "midpoint", r, "max deviation")
        dev8 = view.get("circles", "radius sweep", "sqrt8 (8-way)", r, "max deviation")
        add("circles", f"largest distance from the true radius at r = {fmt(r)}: midpoint / sqrt8",
            None if dev is None else f"{fmt(dev)} / {fmt(dev8)} px")
        rings = view.values("circles", "concentric rings", "holes")
        if rings:
            holes = view.get("circles", "concentric rings", "midpoint", rings[0], "holes")
            add("circles", f"holes between concentric midpoint rings, radii {rings[0]}",
                None if holes is None else f"{fmt(holes)} px")
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
            add(family, f"{variant} edge tests: first coordinate magnitude with a wrong pixel",
                f"{fmt(first)} px" if first is not None else
                f"none up to {fmt(max(accepted, default=0))} px")
        overlaps = sum(view.get(family, "precision", "fixed 8 bits", m, "overlaps", 0)
                       + view.get(family, "precision", "fixed 8 bits", m, "cracks", 0)
                       for m in magnitudes)
        add(family, "fixed 8-bit meshes: overlaps + cracks over all magnitudes", fmt(overlaps))
        shares = [view.get(family, "precision", "fixed 0 bits", m, "misclassified fraction")
                  for m in magnitudes]
        shares = [s for s in shares if s is not None]
        if shares:
            add(family, "whole-pixel snapping (0 bits): pixels unlike the unsnapped shape",
                f"{fmt(100 * float(np.mean(shares)))} % of covered")
        rejected = [m for m in magnitudes if view.get(family, "precision", "fixed 8 bits", m,
                                                     "rejected") == 1]
        if rejected:
            add(family, "coordinates refused (InputError)", f">= {fmt(min(rejected))} px")
    shapes = view.values("triangles", "traversal", "tested per filled")
    if shapes:
        parts = []
        for variant in ("scan", "bbox", "backtrack", "pineda", "linewise"):
            ratios = [view.get("triangles", "traversal", variant, s, "tested per filled")
                      for s in shapes]
            ratios = [r for r in ratios if r is not None]
            if ratios:
                parts.append(f"{variant} {fmt(min(ratios))}-{fmt(max(ratios))}")
        add("triangles", "pixels tested per pixel filled, over the shapes", ", ".join(parts))
    ratios = view.values("interpolation", "w ratio", "max error")
    if ratios:
        for ratio in (10, ratios[-1]):
            err = view.get("interpolation", "w ratio", "affine", ratio, "max error")
            persp = view.get("interpolation", "w ratio", "perspective-correct", ratio, "max error")
            add("interpolation", f"w ratio {fmt(ratio)}: largest error, affine / perspective-correct",
                None if err is None else f"{fmt(err)} / {fmt(persp)} (of the attribute's range)")
    ratios = view.values("interpolation", "depth precision", "first fighting depth")
    if ratios:
        far = ratios[-1]
        parts = [f"{kind}: " + fmt(view.get("interpolation", "depth precision", kind, far,
                                            "first fighting depth"))
                 for kind in measure.DEPTH_BUFFERS]
        add("depth", f"far/near {fmt(far)}: first depth (x near) where a 0.1 % gap z-fights "
                     "(0: never)", ", ".join(parts))
    samples = view.values("antialiasing", "supersampling", "rms error", "grid box")
    if samples:
        parts = [f"{fmt(n)}: " + fmt(view.get("antialiasing", "supersampling", "grid box", n,
                                              "rms error"))
                 for n in samples]
        add("antialiasing", "grid box supersampling, RMS coverage error by samples per pixel",
            ", ".join(parts))
        front = aa_front(view, "samples")
        add("antialiasing", "Pareto front (samples per pixel against RMS error)",
            ", ".join(f"{label} ({fmt(cost)})" for cost, _, label in front))
    return found


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


# ============================================================ sections
def _ops_cells(view, family, experiment, variant, value):
    return [view.get(family, experiment, variant, value, "ops"),
            view.get(family, experiment, variant, value, "ops int_add"),
            view.get(family, experiment, variant, value, "ops float_add"),
            view.get(family, experiment, variant, value, "ops mul"),
            view.get(family, experiment, variant, value, "ops div"),
            view.get(family, experiment, variant, value, "ops sqrt"),
            view.get(family, experiment, variant, value, "ops round"),
            view.get(family, experiment, variant, value, "ops compare"),
            view.get(family, experiment, variant, value, "ops pixels_tested")]


OPS_HEADERS = ["ops/px", "int add", "float add", "mul", "div", "sqrt", "round", "compare",
               "tested"]


def section_lines(view: View) -> str:
    out = ["## Lines", ""]
    lengths = view.values("lines", "length sweep", "differing pixels")
    if not lengths:
        return ""
    variants = view.variants("lines", "length sweep")
    out.append("Random segments in random directions; each length is the segment's Euclidean "
               "length. *Differing*: pixels in the symmetric difference with the exact "
               "nearest-pixel line (one pixel per major-axis column; either pixel where the "
               "line passes exactly midway), mean per segment, from the fast kernels. A pixel "
               "one row off counts twice (the pixel drawn and the one missed); a second pixel "
               "in a column once. *Missed*: the share of columns without their nearest pixel. "
               "The implicit form is measured only where its bounding box has at most "
               f"{measure.IMPLICIT_MAX_BOX:,} pixels.")
    out.append("")
    out.append(table(["variant"] + [f"{fmt(n)} px" for n in lengths],
                     [[v] + [view.get("lines", "length sweep", v, n, "differing pixels")
                             for n in lengths] for v in variants]))
    longest = lengths[-1]
    out += ["", f"Other errors at {fmt(longest)} px (means per segment; deviation: the largest "
                "perpendicular distance of a pixel from the ideal line) and kernel time:", ""]
    out.append(table(["variant", "missed columns", "extra px", "max deviation (px)", "gaps",
                      "duplicates", "asymmetric px", "kernel ns/px"],
                     [[v] + [view.get("lines", "length sweep", v, longest, m)
                             for m in ("missed columns", "extra pixels", "max deviation", "gaps",
                                       "duplicates", "asymmetric pixels", "kernel time")]
                      for v in variants]))
    costs = view.values("lines", "length sweep", "ops")
    if costs:
        at = costs[-1]
        out += ["", f"Cost per plotted pixel at {fmt(at)} px, counted from the pseudo-code "
                    "lines each run executed (implicit: only the segments whose bounding box "
                    "the generator can walk), and generator recording time:", ""]
        out.append(table(["variant"] + OPS_HEADERS + ["generator us/px"],
                         [[v] + _ops_cells(view, "lines", "length sweep", v,
                                           at if view.get("lines", "length sweep", v, at, "ops")
                                           is not None else costs[0])
                          + [view.get("lines", "length sweep", v, at, "generator time")]
                          for v in variants]))
    dda = view.values("lines", "DDA precision", "segments wrong")
    if dda:
        out += ["", "DDA precision: the share of random segments of each length with at "
                    "least one pixel off the nearest-pixel line.", ""]
        out.append(table(["length (px)", "float32", "float64"],
                         [[n, view.get("lines", "DDA precision", "DDA float32", n, "segments wrong"),
                           view.get("lines", "DDA precision", "DDA float64", n, "segments wrong")]
                          for n in dda]))
    return "\n".join(out)


def section_circles(view: View) -> str:
    radii = [r for r in view.values("circles", "radius sweep", "gaps")]
    if not radii:
        return ""
    variants = view.variants("circles", "radius sweep")
    shown = [r for r in radii if r in (1, 2, 5, 10, 16, 32, 64, 128, 256, 1024, 4096)]
    out = ["## Circles", "",
           "Gaps: neighbours in angular order around the centre that are not 8-neighbours "
           "(pixels skipped in brackets). Deviation: the largest |distance to the centre - r| "
           "of a plotted pixel. Differing: pixels unlike the exact midpoint oracle (the pixel "
           "in each octant column whose cell the circle crosses).", ""]
    rows = []
    for r in shown:
        for v in variants:
            rows.append([r, v, f"{fmt(view.get('circles', 'radius sweep', v, r, 'gaps'))} "
                               f"({fmt(view.get('circles', 'radius sweep', v, r, 'skipped'))})",
                         view.get("circles", "radius sweep", v, r, "duplicates"),
                         view.get("circles", "radius sweep", v, r, "max deviation"),
                         view.get("circles", "radius sweep", v, r, "differing pixels")])
    out.append(table(["r", "variant", "gaps (skipped)", "duplicates", "max deviation (px)",
                      "differing"], rows))
    rings = view.values("circles", "concentric rings", "holes")
    if rings:
        out += ["", f"Concentric rings r = {rings[0]}: pixels whose centre lies strictly between "
                    "the circles r and r + 1 that neither ring drew.", ""]
        out.append(table(["variant", "holes (px)", "ring pairs with holes"],
                         [[v, view.get("circles", "concentric rings", v, rings[0], "holes"),
                           view.get("circles", "concentric rings", v, rings[0],
                                    "ring pairs with holes")] for v in variants]))
    costs = view.values("circles", "radius sweep", "ops")
    if costs:
        out += ["", "Cost per plotted pixel (from the executed pseudo-code lines) and time:", ""]
        rows = [[r, v] + _ops_cells(view, "circles", "radius sweep", v, r)
                + [view.get("circles", "radius sweep", v, r, "generator time"),
                   view.get("circles", "radius sweep", v, r, "kernel time")]
                for r in costs for v in variants]
        out.append(table(["r", "variant"] + OPS_HEADERS + ["generator us/px", "kernel ns/px"],
                         rows))
    return "\n".join(out)


def section_precision(view: View, family: str, title: str) -> str:
    magnitudes = view.values(family, "precision", "rejected")
    if not magnitudes:
        return ""
    variants = view.variants(family, "precision")
    what = ("triangles (triangle-bbox; float precisions snap to 1/256 px, then evaluate "
            "a x + b y + c in floating point)" if family == "triangles" else
            "quads (polygon-scanline; float arithmetic steps x by 1/m in that type; 0 and 4 "
            "bits snap the coordinates before the fill)")
    out = [f"## {title}", "",
           f"A jittered mesh of {what}, moved to coordinates of the given magnitude. "
           "*vs true*: pixels unlike the exact coverage of the unsnapped shapes; *vs snapped*: "
           "unlike the exact coverage of the shapes snapped as the variant snaps them (the "
           "arithmetic's own error); summed over the mesh. Overlaps: pixels filled twice; "
           "cracks: pixels inside the snapped mesh that no shape filled.", ""]
    rows = []
    for m in magnitudes:
        for v in variants:
            if view.get(family, "precision", v, m, "rejected") == 1:
                rows.append([m, v, "refused", "", "", ""])
                continue
            rows.append([m, v] + [view.get(family, "precision", v, m, metric) for metric in
                                  ("misclassified vs true", "misclassified vs snapped",
                                   "overlaps", "cracks")])
    out.append(table(["magnitude (px)", "variant", "vs true", "vs snapped", "overlaps", "cracks"],
                     rows))
    first = magnitudes[0]
    refused = " The polygon fill refuses coordinates beyond +-2^20 px (InputError)." \
        if family == "polygons" else ""
    out[2] += refused
    out += ["", f"Cost per covered pixel, the mesh at {fmt(first)} px (the kernel runs the "
                "mesh one shape at a time, so its time is mostly the cost of a call):", ""]
    out.append(table(["variant"] + OPS_HEADERS + ["generator us/px", "kernel ns/px"],
                     [[v] + _ops_cells(view, family, "precision", v, first)
                      + [view.get(family, "precision", v, first, "generator time"),
                         view.get(family, "precision", v, first, "kernel time")]
                      for v in variants]))
    shapes = view.values(family, "traversal", "ops")
    if shapes:
        out += ["", "Traversals: cost per written pixel by shape.", ""]
        traversal = view.variants(family, "traversal")
        has_ratio = bool(view.values(family, "traversal", "tested per filled"))
        headers = ["shape", "traversal"] + (["tested/filled"] if has_ratio else []) + \
            OPS_HEADERS + ["generator us/px", "kernel ns/px"]
        rows = []
        for s in shapes:
            for v in traversal:
                if view.get(family, "traversal", v, s, "ops") is None:
                    continue
                rows.append([s, v] + ([view.get(family, "traversal", v, s, "tested per filled")]
                                      if has_ratio else [])
                            + _ops_cells(view, family, "traversal", v, s)
                            + [view.get(family, "traversal", v, s, "generator time"),
                               view.get(family, "traversal", v, s, "kernel time")])
        out.append(table(headers, rows))
    return "\n".join(out)


def section_fill(view: View) -> str:
    variants = view.variants("fill", "disc")
    if not variants:
        return ""
    r = view.values("fill", "disc")[0]
    out = ["## Seed fill", "",
           f"The outline of a disc of radius {r} (48 vertices), filled from inside. All orders "
           "fill the same pixels for a connectivity (*differs* counts pixels unlike the stack "
           "order's); they differ in work and in memory (the largest number of pending "
           "entries). Costs are per filled pixel.", ""]
    out.append(table(["variant", "filled", "differs", "pops", "skipped pops", "largest pending"]
                     + OPS_HEADERS + ["generator us/px"],
                     [[v] + [view.get("fill", "disc", v, r, m) for m in
                             ("filled", "differs from stack order", "pops", "skipped pops",
                              "largest pending")]
                      + _ops_cells(view, "fill", "disc", v, r)
                      + [view.get("fill", "disc", v, r, "generator time")] for v in variants]))
    return "\n".join(out)


def section_interpolation(view: View) -> str:
    ratios = view.values("interpolation", "w ratio", "max error")
    if not ratios:
        return ""
    out = ["## Interpolation and depth", "",
           "One triangle with s = 0, 1, 0.5 and w = 1, r, (1 + r)/2 at its vertices; errors "
           "against the exact perspective-correct value (fractions) at every covered centre, "
           "as a share of the attribute's range.", ""]
    out.append(table(["w ratio r", "affine max", "affine RMS", "perspective max",
                      "perspective RMS"],
                     [[r] + [view.get("interpolation", "w ratio", v, r, m)
                             for v in ("affine", "perspective-correct")
                             for m in ("max error", "rms error")] for r in ratios]))
    out += ["", "Cost per covered pixel (the pixel's test and the interpolation):", ""]
    out.append(table(["method"] + OPS_HEADERS + ["generator us/px"],
                     [[v] + _ops_cells(view, "interpolation", "cost", v, "one")
                      + [view.get("interpolation", "cost", v, "one", "generator time")]
                      for v in view.variants("interpolation", "cost")]))
    depth = view.values("interpolation", "depth precision", "z-fighting fraction")
    if depth:
        out += ["", "Depth precision: a second surface 0.1 % of its depth behind the first, at "
                    "eye depths spread log-uniformly from near to far. Share of depths that "
                    "z-fight (stored depths not strictly ordered), and the nearest such depth in "
                    "multiples of the near distance (0: none).", ""]
        kinds = view.variants("interpolation", "depth precision")
        out.append(table(["far/near"] + [f"{k}" for k in kinds] + [f"{k} first" for k in kinds],
                         [[f] + [view.get("interpolation", "depth precision", k, f,
                                          "z-fighting fraction") for k in kinds]
                          + [view.get("interpolation", "depth precision", k, f,
                                      "first fighting depth") for k in kinds]
                          for f in depth]))
    return "\n".join(out)


def section_antialias(view: View, missing: str) -> str:
    if missing:
        return ("## Antialiasing\n\nNot measured: " + missing + ". The measurement is "
                "app.analysis.measure.measure_antialias; it runs once algorithms.antialias "
                "provides supersample_image and reference_coverage.")
    samples = view.values("antialiasing", "supersampling", "rms error")
    if not samples:
        return ""
    out = ["## Antialiasing", "",
           "Random triangles; coverage against the exact area coverage of each pixel square. "
           "RMS over the whole grid / maximum; kernel time per pixel of the grid. The weighted, "
           "tent and gaussian filters estimate a filtered coverage, not the square's area, so "
           "they need not approach it as samples grow.", ""]
    rows = []
    for v in view.variants("antialiasing", "supersampling"):
        rows.append([v] + [f"{fmt(view.get('antialiasing', 'supersampling', v, n, 'rms error'))} / "
                           f"{fmt(view.get('antialiasing', 'supersampling', v, n, 'max error'))}"
                           for n in samples])
    out.append(table(["pattern filter"] + [f"{fmt(n)} samples" for n in samples], rows))
    adaptive = view.values("antialiasing", "adaptive", "rms error")
    if adaptive:
        out += ["", "Adaptive sampling (a few samples, more where they disagree):", ""]
        out.append(table(["max depth", "samples/px", "RMS", "max", "generator us/px"],
                         [[d] + [view.get("antialiasing", "adaptive", "adaptive", d, m)
                                 for m in ("samples", "rms error", "max error", "generator time")]
                          for d in adaptive]))
    front = aa_front(view, "samples")
    out += ["", "Pareto front, samples per pixel against RMS error (no other variant has both "
                "fewer samples and less error):", ""]
    out.append(table(["variant", "samples/px", "RMS error"], [[l, c, e] for c, e, l in front]))
    return "\n".join(out)


# ============================================================ charts
def charts(view: View) -> dict:
    """Family name -> Pillow image."""
    from app.analysis.charts import Chart, figure, palette

    images = {}
    lengths = view.values("lines", "length sweep", "missed columns")
    if lengths:
        costs = view.values("lines", "length sweep", "ops")
        at = costs[-1] if costs else None
        axis = "columns without their nearest pixel, %"
        colors = palette(view.variants("lines", "length sweep"))
        left = Chart("Cost against error", "operations per pixel (executed pseudo-code)", axis,
                     xlog=True, legend=False,
                     note="error: mean over all lengths; cost at the longest traced length", palette=colors)
        middle = Chart("Time against error", "kernel time, ns per pixel (longest lines)", axis,
                       xlog=True, legend=False, palette=colors)
        right = Chart("Error against length", "segment length (px)", axis, xlog=True,
                      note="variants without a missed column at any length are left out", palette=colors)
        for n, v in enumerate(view.variants("lines", "length sweep")):
            error = [view.get("lines", "length sweep", v, L, "missed columns") for L in lengths]
            error = [e for e in error if e is not None]
            mean = 100 * float(np.mean(error))
            ops = view.get("lines", "length sweep", v, at, "ops") or \
                view.get("lines", "length sweep", v, costs[0], "ops") if costs else None
            if ops is not None:
                left.add(v, [(ops, mean)], line=False, labels=[v])
            longest = [L for L in lengths if view.get("lines", "length sweep", v, L, "kernel time")]
            if longest:
                middle.add(v, [(view.get("lines", "length sweep", v, longest[-1], "kernel time"),
                                mean)], line=False, labels=[v])
            curve = [(L, 100 * view.get("lines", "length sweep", v, L, "missed columns"))
                     for L in lengths if view.get("lines", "length sweep", v, L,
                                                  "missed columns") is not None]
            if any(y > 0 for _, y in curve):
                right.add(v, curve)
        images["lines"] = figure("Lines: cost against error", [left, middle, right])
    radii = [r for r in view.values("circles", "radius sweep", "gaps")]
    if radii:
        costs = view.values("circles", "radius sweep", "ops")
        colors = palette(view.variants("circles", "radius sweep"))
        left = Chart("Cost against error", "operations per pixel (executed pseudo-code)",
                     "largest |distance - r| (px), all radii", legend=False,
                     note="labels: gaps summed over all radii", palette=colors)
        middle = Chart("Gaps around the ring", "radius (px)", "gaps", xlog=True, palette=colors)
        right = Chart("Time against error", "kernel or generator time, ns per pixel",
                      "largest |distance - r| (px)", xlog=True, legend=False, palette=colors)
        for v in view.variants("circles", "radius sweep"):
            worst = max(view.get("circles", "radius sweep", v, r, "max deviation", 0) for r in radii)
            gaps = sum(view.get("circles", "radius sweep", v, r, "gaps", 0) for r in radii)
            if costs:
                ops = view.get("circles", "radius sweep", v, costs[-1], "ops")
                left.add(v, [(ops, worst)], line=False,
                         labels=[f"{v}: {fmt(gaps)} gaps" if gaps else v])
                t = (view.get("circles", "radius sweep", v, costs[-1], "kernel time")
                     or 1000 * view.get("circles", "radius sweep", v, costs[-1], "generator time"))
                right.add(v, [(t, worst)], line=False, labels=[v])
            middle.add(v, [(r, view.get("circles", "radius sweep", v, r, "gaps"))
                           for r in radii if r > 0])
        images["circles"] = figure("Circles: cost against error", [left, middle, right])
    for family in ("polygons", "triangles"):
        magnitudes = [m for m in view.values(family, "precision", "misclassified fraction")]
        if not magnitudes:
            continue
        colors = palette(view.variants(family, "precision"))
        left = Chart("Cost against error", "kernel time, ns per covered pixel",
                     "pixels unlike the true shapes, % (mean)", xlog=True, legend=False, palette=colors)
        right = Chart("Error against coordinate size", "coordinate magnitude (px)",
                      "pixels unlike the true shapes, %", xlog=True, palette=colors)
        panels = [left, right]
        for v in view.variants(family, "precision"):
            curve = [(m, 100 * view.get(family, "precision", v, m, "misclassified fraction"))
                     for m in magnitudes
                     if view.get(family, "precision", v, m, "misclassified fraction") is not None]
            times = [view.get(family, "precision", v, m, "kernel time") for m, _ in curve]
            if curve:
                left.add(v, [(float(np.median(times)), float(np.mean([y for _, y in curve])))],
                         line=False, labels=[v])
                right.add(v, curve)
        shapes = view.values(family, "traversal", "tested per filled")
        if shapes:
            traversal = Chart("Traversal: work against waste", "operations per filled pixel",
                              "pixels tested per pixel filled", xlog=True, ylog=True,
                              legend=False, palette=palette(view.variants(family, "traversal")))
            for v in view.variants(family, "traversal"):
                # Over all shapes: tested and operations per filled pixel, each shape's
                # triangles weighted by the pixels they fill.
                filled = [view.get(family, "traversal", v, s, "filled") or 0 for s in shapes]
                tested = [view.get(family, "traversal", v, s, "tested") or 0 for s in shapes]
                ops = [view.get(family, "traversal", v, s, "ops") or 0 for s in shapes]
                if sum(filled):
                    traversal.add(v, [(sum(o * f for o, f in zip(ops, filled)) / sum(filled),
                                       sum(tested) / sum(filled))], line=False, labels=[v])
            traversal.note = "all shapes together: " + ", ".join(str(s) for s in shapes)
            panels.append(traversal)
        images[family] = figure(f"{family.capitalize()}: cost against error", panels)
    if view.variants("fill", "disc"):
        r = view.values("fill", "disc")[0]
        colors = palette(view.variants("fill", "disc"))
        chart = Chart("Work against memory", "operations per filled pixel",
                      "largest number of pending entries", ylog=True, legend=False, palette=colors)
        timing = Chart("Time against memory", "generator time, us per filled pixel",
                       "largest number of pending entries", ylog=True, legend=False, palette=colors)
        for v in view.variants("fill", "disc"):
            chart.add(v, [(view.get("fill", "disc", v, r, "ops"),
                           view.get("fill", "disc", v, r, "largest pending"))], line=False,
                      labels=[v])
            timing.add(v, [(view.get("fill", "disc", v, r, "generator time"),
                            view.get("fill", "disc", v, r, "largest pending"))], line=False,
                       labels=[v])
        images["fill"] = figure("Seed fill: cost against memory (every order is exact)",
                                [chart, timing])
    ratios = view.values("interpolation", "w ratio", "max error")
    if ratios:
        left = Chart("Cost against error", "w ratio (largest / smallest w)",
                     "largest error (share of range)", xlog=True, ylog=True,
                     note="legend: operations per covered pixel")
        for v in ("affine", "perspective-correct"):
            ops = view.get("interpolation", "cost", v, "one", "ops")
            left.add(f"{v} ({fmt(ops)} ops/px)",
                     [(max(r, 1.0001) if r == 1 else r,
                       max(view.get("interpolation", "w ratio", v, r, "max error"), 1e-18))
                      for r in ratios])
        right = Chart("Depth buffers: z-fighting", "far / near", "share of depths that fight",
                      xlog=True)
        for k in view.variants("interpolation", "depth precision"):
            depths = view.values("interpolation", "depth precision", "z-fighting fraction")
            fixed = k.startswith("fixed")
            right.add(k, [(f, view.get("interpolation", "depth precision", k, f,
                                       "z-fighting fraction")) for f in depths],
                      marker="s" if fixed else "o", width=6 if fixed else 2)
        images["interpolation"] = figure("Interpolation and depth: cost against error",
                                         [left, right])
    if view.values("antialiasing", "supersampling", "rms error"):
        from app.analysis.charts import PALETTE
        variants = view.variants("antialiasing", "supersampling")
        patterns = list(dict.fromkeys(v.split()[0] for v in variants))
        filters = list(dict.fromkeys(v.split()[1] for v in variants if " " in v))
        markers = dict(zip(filters, ("o", "s", "^", "d")))
        panels = []
        for cost, label in (("samples", "samples per pixel"), ("time", "kernel time, ns per pixel")):
            chart = Chart(f"RMS error against {label}", label, "RMS coverage error",
                          xlog=True, ylog=True,
                          note="colour: pattern; marker: filter; thick line: the Pareto front"
                          + ("; adaptive: generator" if cost == "time" else ""))
            for v in variants:
                pattern, _, name = v.partition(" ")
                pts = [(view.get("antialiasing", "supersampling", v, n,
                                 "samples" if cost == "samples" else "kernel time"),
                        view.get("antialiasing", "supersampling", v, n, "rms error"))
                       for n in view.values("antialiasing", "supersampling", "rms error", v)]
                chart.add(v, pts, color=PALETTE[patterns.index(pattern) % len(PALETTE)],
                          marker=markers.get(name, "o"), width=1, in_legend=False)
            for pattern in patterns:
                chart.add(pattern, [], color=PALETTE[patterns.index(pattern) % len(PALETTE)])
            for name in filters:
                chart.add(f"{name} filter", [], color="#555555", line=False, marker=markers[name])
            adaptive = [(view.get("antialiasing", "adaptive", "adaptive", d,
                                  "samples" if cost == "samples" else "generator time")
                         * (1 if cost == "samples" else 1000),
                         view.get("antialiasing", "adaptive", "adaptive", d, "rms error"))
                        for d in view.values("antialiasing", "adaptive", "rms error")]
            if adaptive:
                chart.add("adaptive", adaptive, color="#000000", marker="s", width=1)
            front = aa_front(view, cost)
            chart.add("Pareto front", [(c, e) for c, e, _ in front], color="#000000",
                      marker="", width=4)
            panels.append(chart)
        images["antialiasing"] = figure("Antialiasing: cost against error", panels,
                                        panel_size=(640, 560))
    return images


# ============================================================ the report
def markdown(view: View, config, seconds: dict, missing_aa: str, figures=()) -> str:
    total = sum(seconds.values())
    head = ["# RasterLab: speed against error", "",
            f"{'Quick' if config.quick else 'Full'} report, {time.strftime('%Y-%m-%d %H:%M')}, "
            f"Python {platform.python_version()}, numpy {np.__version__}, "
            f"{os.cpu_count()} CPUs; measured in {total:.1f} s. Every number is in "
            "measurements.csv (and .json); inputs are seeded, so counts and errors repeat "
            "exactly, times do not.", "",
            "Operation counts come from the algorithms' own pseudo-code: each code line carries "
            "the operations one execution of it performs, and a run counts its executed lines "
            "(Note frames do nothing; a Span frame counts per pixel it fills). *ops/px* adds "
            "integer and float additions, multiplications, divisions, square roots, roundings "
            "and comparisons per pixel written; *tested* is pixels looked at per pixel written.",
            "", "## Headline findings", ""]
    head.append(table(["topic", "finding", "measured"], findings(view)))
    sections = [section_lines(view), section_circles(view),
                section_precision(view, "polygons", "Polygons"),
                section_precision(view, "triangles", "Triangles"),
                section_fill(view), section_interpolation(view),
                section_antialias(view, missing_aa)]
    pictures = "## Figures\n\n" + "\n\n".join(f"![{f}]({f}.png)" for f in FIGURE_ORDER
                                                 if f in figures)
    timing = "## Time per part\n\n" + table(["part", "seconds"],
                                             [[k, round(v, 1)] for k, v in seconds.items()])
    return "\n\n".join(["\n".join(head)] + [s for s in sections if s] + [pictures, timing]) + "\n"


FIGURE_ORDER = ("lines", "circles", "polygons", "fill", "triangles", "interpolation",
                "antialiasing")


def csv_text(rows: list[dict]) -> str:
    buffer = io.StringIO()
    writer = csv.DictWriter(buffer, fieldnames=measure.COLUMNS, lineterminator="\n")
    writer.writeheader()
    for row in rows:
        writer.writerow({**row, "value": repr(row["value"])})
    return buffer.getvalue()


def write_report(out=DEFAULT_OUT, quick: bool = False, progress=None) -> dict:
    """Measure and write the report into ``out``; returns what was written."""
    folder = check_folder(out)
    config = measure.settings(quick)
    started = time.perf_counter()
    rows, seconds = measure.run(config, progress)
    return write_files(folder, config, rows.rows, seconds, started)


def write_files(out, config, rows: list, seconds: dict, started: float | None = None) -> dict:
    """Write the files of a report from measurements already made."""
    folder = check_folder(out)
    started = time.perf_counter() if started is None else started
    missing_aa = measure.antialias_available()
    view = View(rows)
    images = charts(view)
    documents = {
        "report.md": markdown(view, config, seconds, missing_aa, images).encode("utf-8"),
        "measurements.csv": csv_text(rows).encode("utf-8"),
        "measurements.json": (json.dumps({
            "quick": config.quick, "seed": measure.SEED, "columns": list(measure.COLUMNS),
            "settings": {k: v for k, v in vars(config).items()},
            "seconds": seconds, "antialiasing": missing_aa or "measured",
            "findings": [{"topic": t, "finding": f, "measured": m} for t, f, m in findings(view)],
            "rows": rows}, indent=1, allow_nan=False) + "\n").encode("utf-8"),
    }
    for family, image in images.items():
        buffer = io.BytesIO()
        image.save(buffer, format="PNG", optimize=True)
        documents[f"{family}.png"] = buffer.getvalue()
    for name, data in documents.items():
        write_atomically(folder / name, data)
    return {"folder": str(folder), "files": sorted(documents), "rows": len(rows),
            "seconds": time.perf_counter() - started}


class ProgressBar(TerminalBar):
    """The report's progress: measurements done so far."""

    def __call__(self, done: int, total: int, label: str) -> None:
        self.draw("measuring", done, total, f"{label[:30]:<30}")
