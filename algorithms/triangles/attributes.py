"""Vertex attributes across the triangle: the parameter plane and perspective-correct values.

``triangle-plane`` walks the plane q = c_x x + c_y y + c_k of each
attribute with q += c_x; ``triangle-perspective`` interpolates s/w and
1/w in screen space and divides per pixel, after cutting the triangles by
the near plane when asked to.
"""
from __future__ import annotations

from algorithms.core.code import Code
from algorithms.triangles.interpolate import (affine_value, check_w, mix, pack, per_vertex,
                                    perspective_weights, plane_coefficients, unpack)
from algorithms.core.registry import InputError
from algorithms.core.steps import PLOT, VISIT, Note, Table, Vars

from .edges import MAX_COORDINATE, NAN
from .run import (BASE, LOOP_OPS, TEST_OPS, Traversal, evaluate_ops, footer, header, ops_sum,
                  step_ops)

def _plane_code(options):
    code = Code()
    header(code, options)
    # Operation counts per attribute q (colour channels, z, s). The row
    # step (step_y) yields no frame and is not counted; the column step
    # (step_x) follows every pixel's frame and is counted with it.
    n = 3 * bool(options.get("colors")) + bool(options.get("z")) + bool(options.get("s"))
    code.add("setup", "    det = (x1-x0)(y2-y0) - (x2-x0)(y1-y0);  for each attribute q:  "
                      "c_x = ((q1-q0)(y2-y0) - (q2-q0)(y1-y0)) / det;  "
                      "c_y = ((q2-q0)(x1-x0) - (q1-q0)(x2-x0)) / det   (Cramer's rule)",
             ops={"mul": 2 + 4 * n, "float_add": 5 + 6 * n, "div": 2 * n})
    code.add("first", "    q_row = q0 + c_x (xmin + 1/2 - x0) + c_y (ymin + 1/2 - y0);  "
                      "e_row_k = e_k(xmin + 1/2, ymin + 1/2)",
             ops=ops_sum(evaluate_ops(options), {"mul": 2 * n, "float_add": 4 * n}))
    code.add("rows", "    for y = ymin .. ymax:")
    code.add("copy", "        q = q_row;  e_k = e_row_k")
    code.add("cols", "        for x = xmin .. xmax:")
    pixel = ops_sum(TEST_OPS, LOOP_OPS, step_ops(options), {"float_add": n})
    code.add("test", "            if not (inside(e0) and inside(e1) and inside(e2)): skip", VISIT,
             ops=pixel)
    code.add("plot", "            else: output(x, y, q)", PLOT,
             ops=ops_sum(pixel, {"round": 3} if options.get("colors") else {}))
    code.add("step_x", "            q += c_x;  e_k += a_k")
    code.add("step_y", "        q_row += c_y;  e_row_k += b_k")
    footer(code)
    return code


class NoAttributes:
    """Columns of a traversal that carries its attributes itself: none of VertexAttributes'."""

    names = ()
    nothing = ()
    pixel_value = None
    active = False

    def for_triangle(self, order):
        return None


class PlaneAttributes(NoAttributes):
    """Which attributes the plane walk carries: colour channels, z and s."""

    def __init__(self, options, count):
        colors = per_vertex(options, "colors", count)
        self.colors = [unpack(c) for c in colors] if colors else None
        self.z = per_vertex(options, "z", count)
        self.s = per_vertex(options, "s", count)
        if self.colors is None and self.z is None and self.s is None:
            raise InputError("triangle-plane interpolates an attribute: set colors, z or s")
        names = []
        if self.colors is not None:
            names += ["r", "g", "b"]
        if self.z is not None:
            names.append("z")
        if self.s is not None:
            names.append("s")
        if self.colors is not None:
            names.append("rgb")
        self.names = tuple(names)
        self.nothing = (NAN,) * len(names)
        self.pixel_value = "rgb" if self.colors is not None else None

    def vertex_values(self, order):
        """Per attribute: the three vertex values of a triangle."""
        values = []
        if self.colors is not None:
            values += [[self.colors[k][n] for k in order] for n in range(3)]
        for attr in (self.z, self.s):
            if attr is not None:
                values.append([attr[k] for k in order])
        return values


def _plane_traversal(run, tri, edges, attrs, at):
    plane = run.attributes
    values = plane.vertex_values(tri.order)
    corners = [tri.px(k) for k in range(3)]
    slopes = [plane_coefficients(corners, q) for q in values]
    yield Vars(line=at["setup"],
               values={f"c_x[{n}]": cx for n, (cx, _) in zip(plane.names, slopes)}
               | {f"c_y[{n}]": cy for n, (_, cy) in zip(plane.names, slopes)})
    i_lo, i_hi, j_lo, j_hi = run.clip(tri.box())
    if i_lo > i_hi or j_lo > j_hi:
        return
    x0, y0 = corners[0]
    q_row = [q[0] + cx * (i_lo + 0.5 - x0) + cy * (j_lo + 0.5 - y0)
             for q, (cx, cy) in zip(values, slopes)]
    e_row = edges.at(i_lo, j_lo)
    yield run.calc(at["first"], (i_lo, j_lo), e_row, edges)
    a, b = edges.a, edges.b
    plot, skip = at["plot"], at["test"]
    for j in range(j_lo, j_hi + 1):
        q, es = list(q_row), list(e_row)
        for i in range(i_lo, i_hi + 1):
            covered, tie = edges.test(es)
            run.count(i, j, covered)
            shown = edges.shown(es)
            if covered:
                extra = list(q)
                if plane.colors is not None:
                    extra.append(float(pack(q[:3])))
                yield (plot, i, j, *shown, 1.0 if tie else 0.0, *map(float, extra))
            else:
                yield (skip, i, j, *shown, 1.0 if tie else 0.0, *plane.nothing)
            q = [v + cx for v, (cx, _) in zip(q, slopes)]
            es = [e + d for e, d in zip(es, a)]
        q_row = [v + cy for v, (_, cy) in zip(q_row, slopes)]
        e_row = [e + d for e, d in zip(e_row, b)]


PLANE = Traversal(_plane_code, _plane_traversal, attributes=PlaneAttributes)


PERSPECTIVE_COLUMNS = BASE + ("alpha", "beta", "gamma", "1/w", "s/w", "s_affine", "s_persp",
                              "alpha_p", "beta_p", "gamma_p")


def _perspective_code(options):
    code = Code()
    if options.get("near", 0) > 0:
        # Runs once, before the triangles: the pieces are what is drawn.
        code.add("clip", "cut each triangle by the near plane w >= near in (x w, y w, w) space: "
                         "an edge crossing it gets the corner H_a + t (H_b - H_a), "
                         "t = (w_a - near) / (w_a - w_b); draw the 3 or 4 corners left as a fan "
                         "of triangles")
    header(code, options)
    code.add("setup", "    setup: a_k, b_k, c_k of the edges;  1 / 2A;  1 / w_k for each vertex",
             ops={"div": 4})
    code.add("rows", "    for y = ymin .. ymax:")
    code.add("cols", "        for x = xmin .. xmax:")
    pixel = ops_sum(evaluate_ops(options), TEST_OPS, LOOP_OPS)
    # A covered pixel: weights (3 products by 1/2A), s_affine, f_k = e_k / w_k
    # (3 products by 1/w_k), their sum and one division, the corrected
    # weights (3 products) and s (a blend); z and a colour where given.
    covered = ops_sum(pixel, {"mul": 15, "float_add": 6, "div": 1},
                   {"mul": 3, "float_add": 2} if options.get("z") else {},
                   {"mul": 9, "float_add": 6, "round": 3} if options.get("colors") else {})
    code.add("test", "            e_k at the centre;  if not (inside(e0), inside(e1), inside(e2)): "
                     "skip", VISIT, ops=pixel)
    code.add("plot", "            alpha, beta, gamma = e_k / 2A;  s_affine = alpha s0 + beta s1 + "
                     "gamma s2;  f_k = e_k / w_k;  alpha_p = f0 / (f0 + f1 + f2), ...;  "
                     "s = alpha_p s0 + beta_p s1 + gamma_p s2 = (s/w) / (1/w);  setPixel(x, y"
             + (", colour by the perspective-correct weights)" if options.get("colors")
                and options.get("perspective", True) else
                ", colour by alpha, beta, gamma)" if options.get("colors") else ")"), PLOT,
             ops=covered)
    footer(code)
    return code


class PerspectiveColumns(NoAttributes):
    def __init__(self, options, count):
        self.s = per_vertex(options, "s", count)
        self.w = per_vertex(options, "w", count)
        self.z = per_vertex(options, "z", count)
        colors = per_vertex(options, "colors", count)
        self.colors = [unpack(c) for c in colors] if colors else None
        if self.s is None or self.w is None:
            raise InputError("triangle-perspective needs s and w, one per vertex (or three)")
        if not options.get("near", 0) > 0:
            try:
                check_w(self.w)
            except InputError as error:
                raise InputError(f"{error}; or set near (e.g. near=0.05) to clip triangles "
                                 "that cross w = 0") from None
        self.perspective = options.get("perspective", True)
        names = ["z"] if self.z is not None else []
        if self.colors is not None:
            names.append("rgb")
        self.names = tuple(names)
        self.nothing = (NAN,) * len(names)
        self.pixel_value = "rgb" if self.colors is not None else None


def _perspective_traversal(run, tri, edges, attrs, at):
    cols = run.attributes
    order = tri.order
    s = [cols.s[k] for k in order]
    w = [cols.w[k] for k in order]
    yield Vars(line=at["setup"], values={"1/2A": 1 / (tri.area2 / (tri.S * tri.S)),
                                         "1/w0": 1 / w[0], "1/w1": 1 / w[1], "1/w2": 1 / w[2]})
    i_lo, i_hi, j_lo, j_hi = run.clip(tri.box())
    empty = (NAN,) * (len(PERSPECTIVE_COLUMNS) - len(BASE)) + cols.nothing
    plot, skip = at["plot"], at["test"]
    for j in range(j_lo, j_hi + 1):
        for i in range(i_lo, i_hi + 1):
            es = edges.at(i, j)
            covered, tie = edges.test(es)
            run.count(i, j, covered)
            shown = edges.shown(es)
            if not covered:
                yield (skip, i, j, *shown, 1.0 if tie else 0.0, *empty)
                continue
            weights = edges.weights(es)
            corrected = perspective_weights(weights, w)  # InputError rather than inf or NaN
            inverse = affine_value(weights, [1 / v for v in w])
            over_w = affine_value(weights, [sv / wv for sv, wv in zip(s, w)])
            extra = [*weights, inverse, over_w, affine_value(weights, s),
                     affine_value(corrected, s), *corrected]
            if cols.z is not None:
                extra.append(affine_value(weights, [cols.z[k] for k in order]))
            if cols.colors is not None:
                shade = corrected if cols.perspective else weights
                extra.append(mix(shade, [cols.colors[k] for k in order]))
            yield (plot, i, j, *shown, 1.0 if tie else 0.0, *map(float, extra))


PERSPECTIVE_CORRECT = Traversal(_perspective_code, _perspective_traversal, PERSPECTIVE_COLUMNS,
                                attributes=PerspectiveColumns)


def perspective(points, options, grid=None):
    """PERSPECTIVE_CORRECT's frames, the triangles first cut by the near plane when near > 0."""
    cols = PerspectiveColumns(options, len(points))
    near = options.get("near", 0)
    report = None
    if near > 0:
        points, report = clip_near(points, cols, near)
    code = _perspective_code(options)
    frames = PERSPECTIVE_CORRECT.frames(points, options, grid, code, cols)
    return frames if report is None else _with_clip_frames(frames, report, code.at, near)


# ------------------------------------------------------ near-plane clipping
# A vertex (x, y) with clip-space w is the homogeneous point (x w, y w, w):
# its screen position is that point divided by w. A triangle with some w
# below 0 is not the screen triangle of its projected corners: the part
# behind the eye projects through infinity to the far side. Cutting the
# triangle by the plane w = near in homogeneous space first (Sutherland-
# Hodgman against one plane) leaves a polygon whose corners all have
# w >= near, so its projection is the visible part. Attributes that are
# perspective-correct (s, colours) are linear in homogeneous space and are
# cut with the same t; z is a screen-space depth z = Z / w, so Z = z w is.
def clip_near(points, cols, near):
    """The triangles cut by w >= near, fanned into triangles.

    Replaces cols' per-vertex lists (w, s, z, colours) by the pieces' and
    returns (the pieces' points, one (triangle, w's, kept corners, pieces)
    entry per input triangle).
    """
    out_points, report = [], []
    lists = {"w": [], "s": [], "z": [] if cols.z is not None else None,
             "colors": [] if cols.colors is not None else None}
    for n in range(len(points) // 3):
        corners = [_homogeneous(points[k], cols, k) for k in range(3 * n, 3 * n + 3)]
        polygon = _cut(corners, near)
        first = len(out_points) // 3
        for k in range(1, len(polygon) - 1):
            for corner in (polygon[0], polygon[k], polygon[k + 1]):
                _append(corner, out_points, lists)
        report.append((n + 1, [c["w"] for c in corners], polygon,
                       list(range(first + 1, len(out_points) // 3 + 1))))
    cols.w, cols.s, cols.z, cols.colors = lists["w"], lists["s"], lists["z"], lists["colors"]
    return out_points, report


def _homogeneous(point, cols, k):
    w = cols.w[k]
    corner = {"X": point[0] * w, "Y": point[1] * w, "w": w, "s": cols.s[k]}
    if cols.z is not None:
        corner["Z"] = cols.z[k] * w
    if cols.colors is not None:
        corner["rgb"] = tuple(float(c) for c in cols.colors[k])
    return corner


def _cut(corners, near):
    """Sutherland-Hodgman against w >= near: 0, 3 or 4 corners, in order."""
    kept = []
    for a, b in zip(corners, corners[1:] + corners[:1]):
        if a["w"] >= near:
            kept.append(a)
        if (a["w"] >= near) != (b["w"] >= near):
            corner = _between(a, b, (a["w"] - near) / (a["w"] - b["w"]))
            corner["w"] = near  # on the plane by construction, whatever the rounding
            kept.append(corner)
    return kept


def _between(a, b, t):
    corner = {}
    for key, value in a.items():
        if key == "rgb":
            corner[key] = tuple(p + t * (q - p) for p, q in zip(value, b[key]))
        else:
            corner[key] = value + t * (b[key] - value)
    return corner


def _append(corner, out_points, lists):
    w = corner["w"]
    x, y = corner["X"] / w, corner["Y"] / w
    if not max(abs(x), abs(y)) <= MAX_COORDINATE:
        raise InputError(f"option near: a cut corner lands beyond +-{MAX_COORDINATE:g} px; "
                         "use a larger near")
    out_points.append((x, y))
    lists["w"].append(w)
    lists["s"].append(corner["s"])
    if lists["z"] is not None:
        lists["z"].append(corner["Z"] / w)
    if lists["colors"] is not None:
        lists["colors"].append(corner["rgb"])


def _with_clip_frames(frames, report, at, near):
    """The run's frames with what the clipping did, right after Start."""
    yield next(frames)
    line = at["clip"]
    rows = []
    for number, ws, polygon, pieces in report:
        shown = ", ".join(f"{w:g}" for w in ws)
        names = " and ".join(str(p) for p in pieces)
        if not pieces:
            text = f"Triangle {number} (w = {shown}) lies wholly behind w = {near:g}: nothing drawn."
        elif min(ws) >= near:
            text = f"Triangle {number} (w = {shown}) lies in front of w = {near:g}: drawn as {names}."
        else:
            text = (f"Triangle {number} (w = {shown}) crosses w = {near:g}: cut to "
                    f"{len(polygon)} corners, drawn as triangle{'s' if len(pieces) > 1 else ''} "
                    f"{names}.")
        yield Note(line=line, text=text)
        for corner in polygon:
            w = corner["w"]
            rows.append((number, round(corner["X"] / w, 6), round(corner["Y"] / w, 6),
                         round(w, 6), round(corner["s"], 6)))
    yield Table(line=line, name="near clip", columns=("triangle", "x", "y", "w", "s"),
                rows=tuple(rows))
    yield from frames
