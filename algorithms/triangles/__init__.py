"""The triangle family: traversals that decide which pixel centres a triangle covers.

Conventions (see DESIGN.md): pixel (i, j) is the square [i, i+1) x [j, j+1),
sampled at its centre (i + 1/2, j + 1/2), y up. Vertices are real numbers,
snapped to the nearest multiple of 1/S px, S = 2^subpixel_bits (halves to
even), and every decision is made on those snapped vertices.

Edge functions. Edge k joins the two vertices other than P_k, from
P_i = P_(k+1) to P_j = P_(k+2) (indices mod 3):

    a_k = -(y_j - y_i),  b_k = x_j - x_i,  c_k = x_i*y_j - y_i*x_j,
    e_k(x, y) = a_k x + b_k y + c_k,

so e_k(x + 1, y) = e_k + a_k and e_k(x, y + 1) = e_k + b_k, and e_k is twice
the signed area of the triangle (P_i, P_j, point). For a counter-clockwise
triangle (2A = e_0(P_0) > 0) the inside is where all three are positive.
Clockwise input has P1 and P2 swapped (or is culled with ``cull``).

Exact arithmetic ("fixed" precision). In units of 1/S px, with the pixel
centre at (2i+1) S / 2, every E_k(i, j) = 2 S^2 e_k(i + 1/2, j + 1/2) is an
integer, E_k(i, j) = A_k i + B_k j + C_k with A_k = 2 S^2 a_k and
B_k = 2 S^2 b_k. The generators use Python integers (no limit); the numpy
kernel uses int64 where the bound 12 M^2 + 32 S M < 2^63 holds for the
triangle's extent M (in 1/S units, measured from its first vertex), which
covers every triangle with coordinates within +-2^20 px at S = 256, and
falls back to Python integers beyond. Frames show e_k in px^2
(E_k / 2S^2): exact whenever |E_k| < 2^53, which holds while the triangle
and the pixel fit in a box about 180,000 px wide; the decision itself is
always exact, and the panel's explanation recomputes the exact value.

Fill rule "top-left" (y up: left edges and bottom horizontal edges). A
centre with e_k = 0 lies on edge k. The tie rule keeps it when a_k > 0, or
a_k = 0 and b_k > 0. With counter-clockwise order the inside lies to the
left of each directed edge; a_k = y_i - y_j > 0 means the edge runs
downwards, and the left of a downward edge is the +x side, so the triangle
lies to the right of the edge: it is a *left* edge. a_k = 0 and b_k > 0 is
an edge running in +x, with the inside above it: a *bottom* edge. Two
counter-clockwise triangles sharing an edge see it with opposite a and b,
so exactly one of them keeps a centre on it. "inclusive" keeps every edge
(e >= 0: shared centres twice), "strict" none (e > 0: shared centres
never).

Precision "float64" and "float32" snap the same way and then evaluate the
implicit form a*x + b*y + c with a, b, c and the centre in that
floating-point type (the product terms cancel badly far from the origin,
which is what the option is there to show). For coordinates below 2^m px
on the 1/256 grid every intermediate is a multiple of 2^-16 below
2^(2m+2), so the result is exact while 2m + 18 bits fit the significand:
float32 is exact below 8 px, float64 below 2^17 px. The sweep in
tests/algorithms/triangles/test_triangles_float.py measures where they really start
to differ: float32 at coordinates of 16-32 px (a centre exactly on an
edge rounds to the wrong side), float64 at 2^19-2^20 px.

Frames. Every run starts with a Start record naming the values and the
constants S, fill_rule, precision and the number of triangles. Per
triangle: a Vars record (its number, snapped P0 P1 P2 in the order used,
2A, winding), a Note when it is degenerate, culled or swapped, and a Table
"edges" (a, b, c and the side of each edge). Every tested pixel is one
lean frame (line, x, y, e0, e1, e2, tie, ...): a PLOT frame on the
setPixel line when covered, a VISIT frame on the test line when not; tie
is 1 when no edge value is negative and one is exactly zero, so the fill
rule decided. Traversal bookkeeping (row starts, the backtracking walk,
linewise spans) uses CALC or VISIT frames on their own lines. With vertex
attributes (colors, z, w, s) covered pixels also carry alpha, beta, gamma,
the perspective-correct weights and 1/w (with w), z, s_affine and s_persp,
and a packed colour rgb (Start.pixel_value). The last frame is a Vars
record: tested, filled, overlaps (pixels filled more than once), cracks
(centres in the interior of the drawn triangles' union that no triangle
filled, decided exactly), drawn, degenerate, culled.

The generators take the grid (``uses_grid``) and never leave it; a
4-tuple (x0, y0, x1, y1) instead of (W, H) is a window anywhere in the
plane, which the tests use for coordinates up to 1e6 px.

Offset. The option offset = (X, Y), whole pixels, adds (X S, Y S) to the
snapped vertices and moves the window by (X, Y), so every edge function
is evaluated a long way from the origin while the frames name pixels of
the grid (moved back; Vars show the vertices where the run put them, and
Start's constants the offset). Exact arithmetic does not care: the pixels
equal those at offset 0. The float precisions do, which is what the option
shows. |X|, |Y| <= 2^21 px keeps every fixed-point term within int64.

Near-plane clipping (triangle-perspective, option near > 0). A vertex with
w <= 0 lies behind the eye, and the screen triangle of the projected
corners is not what it shows. Each triangle is first cut by w >= near in
homogeneous space (see clip_near); the 3 or 4 corners left are drawn as a
fan of triangles, with a Note and a Table "near clip" after Start.
"""
from __future__ import annotations
from __future__ import annotations

# The package's modules, by idea: edges (snapping, edge functions, fill
# rule), run (what every traversal shares), traversals, attributes (plane
# and perspective interpolation), kernels (spans without frames), canvas
# (the compiled fill straight into a picture) and specs
# (the registry's entries). The names below are the family's public face.
from .attributes import (PERSPECTIVE_COLUMNS, PLANE, PERSPECTIVE_CORRECT, PerspectiveColumns,
                         PlaneAttributes, clip_near, perspective)
from .edges import (BASE_OPTIONS, CULL, FILL_RULE, MAX_COORDINATE, MAX_KERNEL_PIXELS, MAX_OFFSET,
                    MAX_REGION, OFFSET, OPTIONS, PRECISION, PRECISIONS, RULES, SUBPIXEL_BITS,
                    TRIANGLES, Edges, ExactView, Setup, Triangle, ceil_div, dyadic_text,
                    edge_table, explain, floor_div, offset_of, prepare, snap_fixed, tie_keeps,
                    window_of)
from .kernels import (_fits_int64, _fits_int64_array, _float_box_pixels, _spans_python,
                      counts_from_spans, fill, kernel_pixels, oriented, pixels_from_spans,
                      snap_array, span_arrays, span_mask)
from .canvas import fill_canvas
from .run import BASE, Run, Traversal, drive, mesh_flaws, ops_sum
from .traversals import (BACKTRACK, BARYCENTRIC, BBOX, HALFPLANE, INCREMENTAL, LINEWISE, PINEDA,
                         SCAN, linewise_rows, top_start)
from .specs import NOTES, make_kernel
from . import specs, variants, span_interpolation, printed, line_triangles  # noqa: E402

# The family's algorithms, in the order they are listed: the traversals, then
# the other views of a triangle (barycentric, Cramer's plane, linewise interpolation),
# then two listings as printed; and a line drawn as two triangles, which is
# listed with the lines (its family).
SPECS = (specs.SPECS + variants.SPECS + span_interpolation.SPECS + printed.SPECS
         + line_triangles.SPECS)
