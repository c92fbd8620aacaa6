"""The report's tables, one section per family."""
from __future__ import annotations

from app.analysis import measure

from .report_findings import View, aa_front, fmt, table


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
                    "lines each run executed, and generator recording time. A variant not "
                    f"measured at {fmt(at)} px (the implicit form walks only bounding boxes of "
                    f"at most {measure.IMPLICIT_MAX_BOX:,} pixels) shows its longest measured "
                    "length, named in the *length* column:", ""]
        rows = []
        for v in variants:
            length = max((n for n in costs
                          if view.get("lines", "length sweep", v, n, "ops") is not None),
                         default=at)
            rows.append([v, f"{fmt(length)} px"] + _ops_cells(view, "lines", "length sweep", v,
                                                             length)
                        + [view.get("lines", "length sweep", v, length, "generator time")])
        out.append(table(["variant", "length"] + OPS_HEADERS + ["generator us/px"], rows))
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
