"""Checking a student's flood fill, z-buffer (or painter) and antialiased line.

checking.py covers lines, circles, triangles and polygons; this module adds
the three families whose student output is not one pixel per step of a
fixed order:

- fill: ``draw(contours, seed)`` yields each pixel the fill colours, in any
  order (stack, queue and span fills visit the same region differently);
- visibility: ``draw(triangles)`` yields each fragment written to the colour
  buffer, ``x, y`` or ``x, y, {"z": z}``: per triangle in the given order,
  within a triangle in any order;
- antialias: ``draw(x0, y0, x1, y1)`` yields ``x, y, intensity``; the
  intensities are summed per pixel and compared within TOLERANCE.

Each family has hard cases, seeded random cases and an exact oracle written
here with integers and fractions (it does not run the reference's code).
"""
from __future__ import annotations

import random
from collections import Counter
from fractions import Fraction

from algorithms.core import cases as catalogue
from algorithms.fill import flood as fill_family
from algorithms.antialias import lines as aa_lines
from algorithms.exact import triangles as exact_triangles

KINDS = {"flood-fill": "fill", "zbuffer": "visibility", "painter": "visibility",
         "line-wu": "antialias", "line-area": "antialias"}
SIGNATURES = {"fill": "draw(contours, seed)", "visibility": "draw(triangles)",
              "antialias": "draw(x0, y0, x1, y1)"}
# How far a student's intensity (summed per pixel) may be from the expected
# one: a quarter of one step of an 8-bit grey level.
TOLERANCE = 1 / 1024
# How far a yielded z may be from the expected depth of the nearest fragment.
Z_TOLERANCE = 1e-9
WINDOW = (0, 0, 64, 64)

# Outlines (closed, integer vertices) and a seed inside: a square, a
# triangle whose outline steps diagonally, a concave U, a ring (the seed
# between two contours) and a corridor one pixel wide.
FILL_CASES = [
    (((2, 2), (12, 2), (12, 10), (2, 10)),), (5, 5),
    (((1, 1), (20, 4), (6, 16)),), (8, 6),
    (((2, 2), (16, 2), (16, 14), (12, 14), (12, 6), (6, 6), (6, 14), (2, 14)),), (3, 12),
    (((1, 1), (21, 1), (21, 21), (1, 21)), ((7, 7), (15, 7), (15, 15), (7, 15))), (3, 3),
    (((2, 2), (20, 2), (20, 4), (2, 4)),), (10, 3),
]
FILL_CASES = list(zip(FILL_CASES[0::2], FILL_CASES[1::2]))
# Triangles with a depth per vertex: near over far and far over near, two
# triangles that pierce each other, a mesh's shared edge, one with no area.
DEPTH_CASES = [
    ([(2, 2, 0.25), (20, 3, 0.25), (8, 18, 0.25), (6, 1, 0.75), (24, 8, 0.75), (10, 14, 0.75)],
     "near first"),
    ([(6, 1, 0.75), (24, 8, 0.75), (10, 14, 0.75), (2, 2, 0.25), (20, 3, 0.25), (8, 18, 0.25)],
     "far first"),
    ([(2, 3, 0.125), (29, 11, 0.875), (3, 21, 0.125), (30, 3, 0.125), (29, 21, 0.125),
      (2, 12, 0.875)], "piercing"),
    ([(2.5, 2.5, 0.5), (14.5, 2.5, 0.5), (2.5, 14.5, 0.5), (14.5, 2.5, 0.5), (14.5, 14.5, 0.5),
      (2.5, 14.5, 0.5)], "shared edge"),
    ([(1, 1, 0.5), (5, 5, 0.5), (9, 9, 0.5), (3, 2, 0.5), (9, 4, 0.5), (4, 8, 0.5)], "no area"),
]


def kind_of(spec) -> str | None:
    return KINDS.get(spec.name)


# -------------------------------------------------------------------- cases
def fill_case(make, name, contours, seed):
    contours = tuple(tuple(tuple(p) for p in c) for c in contours)
    return make(name, contours, {"seed": tuple(seed)},
                ([[list(p) for p in c] for c in contours], list(seed)))


def depth_case(make, name, vertices):
    points = tuple((x, y) for x, y, _ in vertices)
    z = tuple(z for _, _, z in vertices)
    triangles = [[list(v) for v in vertices[k:k + 3]] for k in range(0, len(vertices), 3)]
    return make(name, points, {"z": z}, (triangles,))


def line_case(make, name, p, q):
    return make(name, (tuple(p), tuple(q)), {}, (p[0], p[1], q[0], q[1]))


def student_args(kind: str, points, options: dict) -> tuple:
    """draw()'s arguments for a run on these points and options."""
    if kind == "fill":
        return ([[list(p) for p in c] for c in points], list(options["seed"]))
    if kind == "visibility":
        z = list(options.get("z") or ()) or [0.5] * len(points)
        if len(z) == 3 and len(points) > 3:  # three depths shared by every triangle
            z = z * (len(points) // 3)
        vertices = [[x, y, d] for (x, y), d in zip(points, z)]
        return ([vertices[k:k + 3] for k in range(0, len(vertices), 3)],)
    (x0, y0), (x1, y1) = points
    return (x0, y0, x1, y1)


def hard_cases(make, kind: str) -> list:
    if kind == "fill":
        return [fill_case(make, f"hard {n + 1}: {sum(map(len, c))} points, seed {s}", c, s)
                for n, (c, s) in enumerate(FILL_CASES)]
    if kind == "visibility":
        return [depth_case(make, f"hard {n + 1}: {what}", v) for n, (v, what) in
                enumerate(DEPTH_CASES)]
    return [line_case(make, f"hard {n + 1}: ({p[0]},{p[1]})->({q[0]},{q[1]})", p, q)
            for n, (p, q) in enumerate(catalogue.LINE_CASES)]


def random_cases(make, kind: str, count: int, seed: int) -> list:
    """``count`` inputs from a seeded generator: the same seed, the same cases."""
    rng = random.Random(seed)
    made = []
    for n in range(count):
        if kind == "fill":
            contour, inside = random_outline(rng)
            made.append(fill_case(make, f"random {n + 1}: seed {inside}", (contour,), inside))
        elif kind == "visibility":
            vertices = [(rng.randint(0, 255) / 8, rng.randint(0, 191) / 8, rng.randint(1, 15) / 16)
                        for _ in range(3 * rng.randint(2, 3))]
            made.append(depth_case(make, f"random {n + 1}: {len(vertices) // 3} triangles",
                                   vertices))
        else:
            p = (rng.randint(0, 31), rng.randint(0, 31))
            q = (rng.randint(0, 31), rng.randint(0, 31))
            made.append(line_case(make, f"random {n + 1}: ({p[0]},{p[1]})->({q[0]},{q[1]})", p, q))
    return made


def random_outline(rng):
    """A triangle with whole-number vertices and a free pixel inside it for the seed."""
    while True:
        contour = tuple((rng.randint(0, 40), rng.randint(0, 40)) for _ in range(3))
        outline = set(fill_family.outline_pixels((contour,)))
        x = sum(p[0] for p in contour) // 3
        y = sum(p[1] for p in contour) // 3
        if (x, y) not in outline and inside_triangle(contour, (x + 0.5, y + 0.5)):
            return contour, (x, y)


def inside_triangle(contour, point) -> bool:
    (ax, ay), (bx, by), (cx, cy) = contour
    px, py = point
    sides = [(bx - ax) * (py - ay) - (by - ay) * (px - ax),
             (cx - bx) * (py - by) - (cy - by) * (px - bx),
             (ax - cx) * (py - cy) - (ay - cy) * (px - cx)]
    return all(s > 0 for s in sides) or all(s < 0 for s in sides)


def scene_case(make, kind: str, scene, name: str, options: dict):
    if kind == "fill":
        if options["seed"] == "auto":
            return None  # the caller says that check needs a seed
        return fill_case(make, name, scene.points, options["seed"])
    if kind == "visibility":
        args = student_args(kind, scene.points, options)
        return make(name, tuple(scene.points), {"z": tuple(v[2] for t in args[0] for v in t)},
                    args)
    p, q = scene.points
    return line_case(make, name, p, q)


# ---------------------------------------------------------------- reference
def reference(spec, trace, kind: str) -> list:
    """(x, y, {values}) per pixel the reference writes that the student yields too:
    the fill's pixels without the outline, the fragments with their z, the
    line's pixels with their intensity."""
    writes = trace.written()
    pixels = writes.pixels.tolist()
    if kind == "fill":
        fill_colour = int(trace.start.constants["fill colour"][1:], 16)
        return [(x, y, {}) for (x, y), v in zip(pixels, writes.values.tolist())
                if int(v) == fill_colour]
    if kind == "visibility":
        z = trace.series("z")[writes.steps].tolist()
        return [(x, y, {"z": d}) for (x, y), d in zip(pixels, z)]
    return [(x, y, {"intensity": v}) for (x, y), v in zip(pixels, writes.values.tolist())]


def exact(spec, case, options: dict) -> list | None:
    """The exact result for the reference's convention, in the reference's shape."""
    kind = KINDS[spec.name]
    if kind == "fill":
        if options["connectivity"] != "4" or options["mode"] != "boundary":
            return None
        return [(x, y, {}) for x, y in exact_fill(case.points, tuple(options["seed"]),
                                                   options["outline"] == "4")]
    if kind == "visibility":
        if options.get("fill_rule", "top-left") != "top-left":
            return None
        return exact_fragments(case.args[0], spec.name == "zbuffer", options)
    if spec.name == "line-wu":
        gap = options["endpoints"] == "gap"
        return [(x, y, {"intensity": v}) for (x, y), v in exact_wu(*case.points, gap).items()]
    _, coverage = aa_lines.area_image(case.points, options, exact=True)
    window = aa_lines.segment_window(*case.points, options["width"], options["caps"])
    return [(window[0] + i, window[1] + j, {"intensity": float(coverage[j, i])})
            for j, i in zip(*coverage.nonzero())]


def exact_fill(contours, seed, four_outline: bool) -> set:
    """The 4-connected region the seed reaches without crossing the outline,
    within the oracle's window (a plain breadth-first search over sets)."""
    wall = set()
    for contour in contours:
        for k, (x0, y0) in enumerate(contour):
            x1, y1 = contour[(k + 1) % len(contour)]
            n = max(abs(x1 - x0), abs(y1 - y0))
            steps = [(x0 + round_half_up(Fraction(i * (x1 - x0), n or 1)),
                      y0 + round_half_up(Fraction(i * (y1 - y0), n or 1))) for i in range(n + 1)]
            wall.update(steps)
            if four_outline:  # the corner pixel of each diagonal step: across, then along
                wall.update((b[0], a[1]) for a, b in zip(steps, steps[1:]))
    region, frontier = {seed}, [seed]
    while frontier:
        x, y = frontier.pop()
        for pixel in ((x + 1, y), (x - 1, y), (x, y + 1), (x, y - 1)):
            if pixel not in wall and pixel not in region and inside_window(pixel):
                region.add(pixel)
                frontier.append(pixel)
    return region


def round_half_up(value: Fraction) -> int:
    return (value + Fraction(1, 2)).__floor__()


def inside_window(pixel) -> bool:
    return WINDOW[0] <= pixel[0] < WINDOW[2] and WINDOW[1] <= pixel[1] < WINDOW[3]


def exact_fragments(triangles, depth_test: bool, options: dict) -> list:
    """The fragments written, triangle by triangle: every covered pixel for
    the painter; for the z-buffer those whose exact depth at the pixel centre
    passes the depth test against what the earlier triangles left."""
    stored = {}
    clear = Fraction(options.get("clear_depth", 1.0))
    less_equal = options.get("depth_test", "less") == "less-equal"
    written = []
    for triangle in triangles:
        corners = tuple((Fraction(x), Fraction(y)) for x, y, _ in triangle)
        depths = [Fraction(z) for _, _, z in triangle]
        covered = exact_triangles.coverage(corners, 8, "top-left", WINDOW)
        for pixel in sorted(covered):
            z = depth_at(corners, depths, exact_triangles.centre(*pixel))
            before = stored.get(pixel, clear)
            if not depth_test or z < before or (less_equal and z == before):
                stored[pixel] = z
                written.append((pixel[0], pixel[1], {"z": float(z)}))
    return written


def depth_at(corners, depths, point) -> Fraction:
    """The depth at the point by its barycentric weights (exact)."""
    (ax, ay), (bx, by), (cx, cy) = corners
    px, py = point
    area = (bx - ax) * (cy - ay) - (by - ay) * (cx - ax)
    wa = ((bx - px) * (cy - py) - (by - py) * (cx - px)) / area
    wb = ((cx - px) * (ay - py) - (cy - py) * (ax - px)) / area
    return wa * depths[0] + wb * depths[1] + (1 - wa - wb) * depths[2]


def exact_wu(p, q, gap: bool) -> dict:
    """Wu's intensities from the ideal line itself: in each column (row, for a
    steep line) the two pixels around the line share the column's ink by
    their distance to it, 1 - f below and f above."""
    (x0, y0), (x1, y1) = p, q
    steep = abs(y1 - y0) > abs(x1 - x0)
    if steep:
        x0, y0, x1, y1 = y0, x0, y1, x1
    if x1 < x0:
        x0, y0, x1, y1 = x1, y1, x0, y0
    image = {}
    dx = x1 - x0
    for x in range(x0, x1 + 1):
        y = Fraction(y0) + (Fraction(y1 - y0, dx) * (x - x0) if dx else 0)
        base = y.__floor__()
        f = y - base
        scale = Fraction(1, 2) if gap and dx and x in (x0, x1) else 1
        for offset, share in ((0, 1 - f), (1, f)):
            if share > 0:
                pixel = (base + offset, x) if steep else (x, base + offset)
                image[pixel] = image.get(pixel, 0) + float(share * scale)
    return image


# ---------------------------------------------------------------- comparing
def divergence(kind: str, expected: list, got: list, make_divergence):
    """The first difference between the expected and the student's output, or None."""
    if kind == "antialias":
        return intensity_divergence(expected, got, make_divergence)
    found = pixel_divergence(expected, got, make_divergence)
    if found is None and kind == "visibility":
        return depth_divergence(expected, got, make_divergence)
    return found


def pixel_divergence(expected, got, make_divergence):
    left = Counter(tuple(p[:2]) for p in expected)
    for n, have in enumerate(got):
        pixel = tuple(have[:2])
        if left[pixel] <= 0:
            times = Counter(tuple(p[:2]) for p in expected)[pixel]
            want = f"{text(pixel)} only {times} time{'s' if times > 1 else ''}" if times else \
                f"none of {text(pixel)}"
            return make_divergence(n, want, f"pixel {text(pixel)}")
        left[pixel] -= 1
    missing = [tuple(p[:2]) for p in expected if left[tuple(p[:2])] > 0]
    if missing:
        return make_divergence(len(got), f"pixel {text(missing[0])} (and "
                                         f"{len(missing) - 1} more)", "the end")
    return None


def depth_divergence(expected, got, make_divergence):
    """Where the student yields z: the k-th write at a pixel has the depth of
    the reference's k-th write there (triangles come in their given order)."""
    depths = {}
    for x, y, values in expected:
        depths.setdefault((x, y), []).append(values["z"])
    seen = Counter()
    for n, (x, y, values) in enumerate(got):
        k = seen[(x, y)]
        seen[(x, y)] += 1
        want = depths[(x, y)][k]
        if "z" in values and abs(values["z"] - want) > Z_TOLERANCE:
            return make_divergence(n, f"z = {want:.6g} at {text((x, y))}",
                                   f"z = {values['z']:.6g}")
    return None


def intensity_divergence(expected, got, make_divergence):
    want, have, first = {}, {}, {}
    for x, y, values in expected:
        want[(x, y)] = want.get((x, y), 0.0) + values["intensity"]
    for n, (x, y, values) in enumerate(got):
        have[(x, y)] = have.get((x, y), 0.0) + values.get("intensity", 1.0)
        first.setdefault((x, y), n)
    for pixel in sorted(set(want) | set(have), key=lambda p: first.get(p, len(got))):
        a, b = want.get(pixel, 0.0), have.get(pixel, 0.0)
        if abs(a - b) > TOLERANCE:
            return make_divergence(first.get(pixel, len(got)),
                                   f"intensity {a:.4f} at {text(pixel)}",
                                   f"intensity {b:.4f}" if pixel in have else "no such pixel")
    return None


def text(pixel) -> str:
    return f"({pixel[0]}, {pixel[1]})"
