"""The report's figures: cost against error, one per family."""
from __future__ import annotations

import numpy as np

from .charts import PALETTE, Chart, figure, palette
from .report_findings import View, aa_front, fmt
from .report_textures import texture_figure


def charts(view: View) -> dict:
    """Family name -> Pillow image, for every family that was measured."""
    drawn = {"lines": _lines(view), "circles": _circles(view),
             "polygons": _meshes(view, "polygons"), "triangles": _meshes(view, "triangles"),
             "fill": _fill(view), "interpolation": _interpolation(view),
             "antialiasing": _antialiasing(view), "textures": texture_figure(view)}
    return {family: image for family, image in drawn.items() if image is not None}


def _lines(view: View):
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
        return figure("Lines: cost against error", [left, middle, right])
    return None


def _circles(view: View):
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
        return figure("Circles: cost against error", [left, middle, right])
    return None


def _meshes(view: View, family: str):
    magnitudes = [m for m in view.values(family, "precision", "misclassified fraction")]
    if magnitudes:
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
            panels.append(_traversal(view, family, shapes))
        return figure(f"{family.capitalize()}: cost against error", panels)
    return None


def _traversal(view: View, family: str, shapes) -> Chart:
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
    return traversal


def _fill(view: View):
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
        return figure("Seed fill: cost against memory (every order is exact)", [chart, timing])
    return None


def _interpolation(view: View):
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
        return figure("Interpolation and depth: cost against error", [left, right])
    return None


def _antialiasing(view: View):
    if view.values("antialiasing", "supersampling", "rms error"):
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
                chart.add(pattern, [], color=PALETTE[patterns.index(pattern) % len(PALETTE)],
                          marker="o")  # here the marker tells the filter, not the pattern
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
        return figure("Antialiasing: cost against error", panels, panel_size=(640, 560))
    return None
