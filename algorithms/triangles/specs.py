"""The triangle family's entries in the registry: options, notes and kernels of each traversal."""
from __future__ import annotations

import numpy as np

from algorithms.triangles.interpolate import COLORS as VERTEX_COLORS, PERSPECTIVE, S as S_OPTION, \
    W as W_OPTION, Z as Z_OPTION
from algorithms.core.registry import AlgorithmSpec, Option, Oracle
from algorithms.core.steps import NO_PIXEL, PLOT

from .attributes import PERSPECTIVE_CORRECT, PLANE, PerspectiveColumns, clip_near, perspective
from .edges import BASE_OPTIONS, OPTIONS, TRIANGLES, explain
from .kernels import _float_box_pixels, kernel_pixels
from .traversals import (BACKTRACK, BARYCENTRIC, BBOX, HALFPLANE, INCREMENTAL, LINEWISE, PINEDA,
                         SCAN)

def make_kernel(name: str, generator, code, top_down=False, box=None):
    """The spec's kernel: exact spans for fixed precision; floats as the generator does them."""
    def kernel(points, options, grid=None):
        options = {**{o.name: o.default for o in OPTIONS}, **options}
        if options.get("near", 0) > 0:  # the pieces left by the near plane are drawn
            points, _ = clip_near(points, PerspectiveColumns(options, len(points)),
                                  options["near"])
        if options["precision"] == "fixed":
            return kernel_pixels(points, options, grid, top_down)
        if box is not None:
            return _float_box_pixels(points, options, grid, whole=box == "whole")
        lines = code(points, options)
        plotted = []
        for frame in generator(points, options, grid):
            if type(frame) is tuple and lines[frame[0]].kind == PLOT and frame[1] != NO_PIXEL:
                plotted.append((frame[1], frame[2]))
        return np.array(plotted, dtype=np.int64).reshape(-1, 2)
    kernel.__name__ = f"{name.replace('-', '_')}_kernel"
    return kernel



NOTES = (
    "A pixel is covered when its centre (x + 1/2, y + 1/2) is inside; ties on an edge "
    "follow the fill rule.",
    "Top-left rule, y up: a centre on an edge counts when the triangle lies to the right "
    "of that edge (a > 0: a left edge) or, for a horizontal edge, above it (b > 0: a "
    "bottom edge). With counter-clockwise vertices a > 0 means the edge runs downwards.",
    "Vertices snap to the sub-pixel grid first; with precision fixed every decision is "
    "exact integer arithmetic. e values are shown in px^2; the panel's exact value is "
    "recomputed from the snapped vertices.",
    "tie = 1 marks a pixel whose verdict rested on the fill rule: no edge value below "
    "zero and at least one exactly zero.",
    "overlaps: pixels filled more than once. cracks: pixels whose centre lies in the "
    "interior of the union of the drawn triangles but that no triangle filled.",
)

# `run --json`'s fragments: the weights (input vertex order) and whatever the run
# interpolated; keys whose columns a run lacks are left out (see app/model/fragments.py).
FRAGMENTS = (("triangle", "@triangle"), ("weights", "@weights"),
             ("weights_p", "@weights_p"), ("1/w", "1/w"), ("z", "z"), ("s", "s"),
             ("s_affine", "s_affine"), ("s_persp", "s_persp"), ("color", "rgb"))


def _spec(name, title, summary, code, generator, oracle, notes=(), options=OPTIONS,
          top_down=False, box=None, kernel=True):
    return AlgorithmSpec(
        name=name, title=title, family="triangles", summary=summary, inputs=TRIANGLES,
        options=options, code=code, generator=generator,
        kernel=make_kernel(name, generator, code, top_down, box) if kernel else None,
        notes=NOTES + tuple(notes), explain=explain, uses_grid=True, fragments=FRAGMENTS,
        oracle=oracle)


# What the tests hold every traversal to. tests/algorithms/triangles/test_triangles_oracle.py
# runs each traversal that test_triangles_cases.py lists.
COVERAGE = ("The pixel centres each triangle covers, counted per pixel, for every fill rule and "
            "winding, from exact rational arithmetic (algorithms/exact/triangles.py); the top-left "
            "rule leaves no overlap and no crack.")
FLOATS = (" The float precisions are held to it where they are provably exact: float32 below "
          "8 px, float64 below 2^16 px.")
FLOAT_TESTS = ("algorithms/triangles/test_triangles_float.py",
               "algorithms/triangles/test_triangles_offset_near.py")


def _coverage(*tests, more=FLOATS, check="triangle-coverage"):
    """The exact coverage oracle: the catalogue, the traversal list and ``tests`` hold it."""
    held = ("algorithms/test_stability.py", "algorithms/triangles/test_triangles_cases.py")
    return Oracle("exact", COVERAGE + more, held + tests, check)


TRAVERSAL = _coverage("algorithms/triangles/test_triangles_oracle.py", *FLOAT_TESTS)


TRIANGLE_SCAN = _spec("triangle-scan", "Every pixel (naive)", "test every pixel of the grid against the three "
      "edge functions", SCAN.code, SCAN.generator, box="whole",
      notes=("The simplest traversal: correct, but it tests every pixel of the grid for "
             "every triangle.",),
      oracle=TRAVERSAL)
TRIANGLE_BBOX = _spec("triangle-bbox", "Bounding box", "test the pixels of the triangle's bounding box",
      BBOX.code, BBOX.generator, box="box",
      notes=("Only rows and columns whose centres fall between the extreme vertices are "
             "tested; any order would do.",),
      oracle=TRAVERSAL)
TRIANGLE_INCREMENTAL = _spec("triangle-incremental", "Incremental edge functions", "bounding box, edge values "
      "updated by e += a per pixel and e += b per row", INCREMENTAL.code, INCREMENTAL.generator,
      notes=("One full evaluation per triangle; then one addition per edge and pixel. Exact "
             "in fixed precision; in floating point the additions accumulate rounding.",),
      oracle=TRAVERSAL)
BOUNDED = Option("bounded", "bool", False,
                 "keep the walk inside the triangle's bounding box: its edges count as outside, "
                 "as the lecture's remark that traversal never needs to leave it implies")
TRIANGLE_BACKTRACK = _spec("triangle-backtrack", "Backtracking", "from the top vertex down: back up left until "
      "outside, then right until outside", BACKTRACK.code, BACKTRACK.generator, top_down=True,
      options=OPTIONS + (BOUNDED,),
      notes=("Outside to the left: failing an edge with a > 0; outside to the right: one with "
             "a < 0. Pixels backtracked over are visited again going right.",
             "The walk never leaves the grid: its edges count as outside. It does leave the "
             "bounding box: backing up left until a pixel fails a left edge, or right until one "
             "fails a right edge, often takes it a column past xmin or xmax (on most random "
             "triangles); outside_box counts those visits, and a note names the first of each "
             "triangle.",
             "With bounded, the box's edges count as outside too, so the walk stays inside it, "
             "as the lecture remarks it can: every covered pixel lies in the box, so the pixels "
             "are the same, and fewer are visited."),
      oracle=Oracle("exact", COVERAGE + FLOATS + " bounded: the same pixels, and no visit "
                    "outside the box.", TRAVERSAL.tests + (
                        "algorithms/triangles/test_triangle_backtrack_box.py",), TRAVERSAL.check))
TRIANGLE_PINEDA = _spec("triangle-pineda", "Pineda pixel walk", "zig-zag from the top vertex, visiting a "
      "superset of the covered pixels, each once", PINEDA.code, PINEDA.generator, kernel=False,
      notes=("Each row first carries on in the last direction, then turns and walks back; "
             "edge values follow each step (e += a, e -= b).",
             "No fast kernel: the pixels equal triangle-bbox's, in the walk's order."),
      oracle=TRAVERSAL)
TRIANGLE_LINEWISE = _spec("triangle-linewise", "Linewise (explicit form)", "per row, the span between the long "
      "edge and a short edge", LINEWISE.code, LINEWISE.generator,
      notes=("The span's ends are rational; in fixed precision they are compared with the "
             "centres exactly, so the fill rule holds at both ends.",
             "The e values shown are computed for display; the algorithm needs only the spans."),
      oracle=TRAVERSAL)
TRIANGLE_HALFPLANE = _spec("triangle-halfplane", "Half-plane (implicit form)", "a centre is inside when it lies "
      "on the inner side of all three edges, by the winding order", HALFPLANE.code,
      HALFPLANE.generator,
      notes=("Clockwise triangles keep their order: the inside is then to the right of every "
             "edge, and the fill rule is mirrored to match.",
             "Floating-point side tests use (V - U) x (P - U), relative to a vertex."),
      oracle=TRAVERSAL)
TRIANGLE_BARYCENTRIC = _spec("triangle-barycentric", "Barycentric (parametric form)", "inside when alpha, beta, gamma "
      "= e_k / 2A are all in range", BARYCENTRIC.code, BARYCENTRIC.generator,
      notes=("alpha, beta, gamma are shown rounded; the test uses their exact signs in fixed "
             "precision.",),
      oracle=_coverage(
          *FLOAT_TESTS, "algorithms/triangles/test_interpolate.py",
          more=FLOATS + " alpha, beta and gamma are Cramer's rule in Fractions, rounded once."))
TRIANGLE_PLANE = _spec("triangle-plane", "Parameter plane (Cramer's rule)", "fit q = c_x x + c_y y + c_k "
      "through the vertex values; walk it with q += c_x", PLANE.code, PLANE.generator,
      options=BASE_OPTIONS + (Option("colors", "colors", ("#ff0000", "#00ff00", "#0000ff"),
                                     VERTEX_COLORS.help), Z_OPTION, S_OPTION),
      notes=("The plane's value at each pixel equals the barycentric interpolation "
             "alpha q0 + beta q1 + gamma q2 (tests check it exactly).",),
      oracle=_coverage(
          "algorithms/triangles/test_interpolate.py",
          more=" float32 is held to it below 8 px. The plane equals the barycentric interpolation "
          "exactly, in Fractions."))
TRIANGLE_PERSPECTIVE = _spec("triangle-perspective", "Perspective-correct interpolation", "interpolate s/w and 1/w "
      "in screen space and divide per pixel", PERSPECTIVE_CORRECT.code, perspective,
      options=BASE_OPTIONS + (VERTEX_COLORS, Z_OPTION,
                              Option("w", "numbers", (1.0, 3.0, 3.0), W_OPTION.help),
                              Option("s", "numbers", (4.0, 6.0, 6.0), S_OPTION.help),
                              Option("perspective", "bool", True, PERSPECTIVE.help),
                              Option("near", "float", 0.0, "clip each triangle against the "
                                     "plane w = near before the divide, so triangles crossing "
                                     "w = 0 draw only their visible part (0: no clipping; "
                                     "every w must then be > 0)", minimum=0.0, maximum=1e6)),
      notes=("Defaults follow the classic example: s = 4 at w = 1 and s = 6 at w = 3; half way "
             "along P0 -> P1 the affine value is 5, the perspective-correct one 4.5.",),
      oracle=_coverage(
          "algorithms/triangles/test_interpolate.py",
          "algorithms/triangles/test_triangles_offset_near.py",
          more=" float32 is held to it below 8 px. Each perspective-correct value lies between "
          "its vertex values; with near, the pixels and values the eye sees, from a homogeneous "
          "oracle in Fractions (but for centres near a tie).", check="perspective-coverage"))

# The module's algorithms, in the order they are listed.
SPECS = (TRIANGLE_SCAN, TRIANGLE_BBOX, TRIANGLE_INCREMENTAL, TRIANGLE_BACKTRACK, TRIANGLE_PINEDA,
         TRIANGLE_LINEWISE, TRIANGLE_HALFPLANE, TRIANGLE_BARYCENTRIC, TRIANGLE_PLANE,
         TRIANGLE_PERSPECTIVE)
