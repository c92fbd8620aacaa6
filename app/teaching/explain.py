"""Why a student's first divergence is wrong, in the algorithm's own terms.

``check`` finds where the student's pixels first differ (checking.py);
this module says why, from the reference's trace and the case's inputs,
never from what the student yields beyond the pixel itself:

- lines: the decision variable at that step and the rule it follows
  (``d = 0 is a tie: this algorithm goes E on a tie; you went NE``), or
  for DDA the coordinate before rounding, exactly, and the rounding rule;
- circles and ellipses: the centre, the radius and the pixels missing or
  extra, octant by octant;
- polygons: the vertices, the scan line through the pixel's centre, where
  it crosses the edges and the fill rule;
- triangles: the edge values at the pixel's centre, computed exactly with
  fractions, and the fill rule.

Steps of a line are numbered as the window and ``run --steps`` number
them (the reference's trace steps); the pixels of an unordered family by
the student's yields, counted from 1.
"""
from __future__ import annotations

from collections import Counter
from dataclasses import replace
from decimal import Decimal
from fractions import Fraction

from algorithms.lines.common import Octant, octant_map

LISTED = 4  # pixels named per octant; the rest are counted


class ReferenceSteps(list):
    """The reference's (x, y, {variables}) per written pixel, with the
    trace step that wrote each one and the trace's last step."""

    def __init__(self, steps, trace_steps, last_step: int):
        super().__init__(steps)
        self.trace_steps = list(trace_steps)
        self.last_step = last_step


def explained(kind: str, spec, case, expected: list, got: list, divergence, options: dict,
              numbering: list | None = None):
    """``divergence`` with where it is (as the window numbers steps) and why.
    ``numbering`` is the reference's steps, whose trace steps name a line's
    step (``expected`` may be the exact result's pixels)."""
    if divergence is None:
        return None
    where = located(kind, divergence.step, expected if numbering is None else numbering)
    why = ""
    if kind == "lines":
        why = line_reason(spec, case, expected, got, divergence.step)
    elif divergence.pixel is not None:
        pixel, extra = divergence.pixel, divergence.extra
        if kind in ("circles", "ellipse"):
            why = circle_reason(case, expected, got)
        elif kind == "polygons":
            why = polygon_reason(case, pixel, options.get("fill_rule", "evenodd"))
        elif kind == "triangles":
            why = triangle_reason(case, pixel, extra, options)
    return replace(divergence, where=where, why=why)


def located(kind: str, index: int, reference: list) -> str:
    """"step S" for a line (the trace step of the reference's pixel), else
    "yield N" (the student's yields counted from 1)."""
    trace_steps = getattr(reference, "trace_steps", None)
    if kind != "lines" or trace_steps is None:
        return f"yield {index + 1}"
    return f"step {trace_steps[index] if index < len(trace_steps) else reference.last_step}"


# -------------------------------------------------------------------- lines
def line_reason(spec, case, expected: list, got: list, n: int) -> str:
    if n >= len(expected) or n >= len(got):
        return ""
    values = expected[n][2]
    if n == 0:
        return f"the line starts at its first end point {pair(case.points[0])}"
    if "d" in values and "choice" in values:
        return decision_reason(case, values, got[n - 1], got[n])
    if "x" in values and "y" in values and "steps" in values:
        return rounding_reason(case, values, n, got[n])
    return variables_text(values)


def decision_reason(case, values: dict, before, after) -> str:
    """The decision variable, its sign and the move it makes."""
    octant = Octant(*case.points)
    move = (after[0] - before[0], after[1] - before[1])
    went = {octant.major: "E", (octant.major[0] + octant.minor[0],
                                octant.major[1] + octant.minor[1]): "NE"}.get(move)
    went = f"went {went}" if went else f"moved by {pair(move)}"
    d, choice = values["d"], values["choice"]
    axes = ("y", "x") if octant.steep else ("x", "y")
    terms = (f" (octant {octant.number}: E steps along {axes[0]}, NE along {axes[0]} "
             f"and {axes[1]})")
    if d == 0:
        return f"d = 0 is a tie: this algorithm goes {choice} on a tie; you {went}{terms}"
    sign = "<" if d < 0 else ">"
    return f"d = {number(d)} {sign} 0: this algorithm goes {choice}; you {went}{terms}"


def rounding_reason(case, values: dict, n: int, have) -> str:
    """DDA: each coordinate before rounding, exactly, and how it is rounded."""
    (x0, y0), (x1, y1) = case.points
    steps = values["steps"]
    parts = []
    for axis, start, end, value, mine in (("x", x0, x1, values["x"], have[0]),
                                          ("y", y0, y1, values["y"], have[1])):
        exact = start + Fraction(n * (end - start), steps or 1)
        rounded = (Fraction(value) + Fraction(1, 2)).__floor__()
        if mine == rounded:
            continue
        text = f"{axis} = {value!r} before rounding ({axis}0 + {n}*{axis}_inc"
        text += f", exactly {fraction(exact)})" if Fraction(value) != exact else ")"
        text += f"; round means floor({axis} + 1/2) = {rounded}, you gave {mine}"
        if mine == round(value) and exact.denominator == 2:
            text += (f" (Python's round() rounds halves to even: round({value!r}) = "
                     f"{round(value)}; write math.floor({axis} + 0.5))")
        parts.append(text)
    return "; ".join(parts)


def variables_text(values: dict) -> str:
    shown = [f"{name} = {number(v)}" for name, v in values.items()
             if isinstance(v, (int, float)) and not isinstance(v, bool)]
    return ("the reference's variables at this step: " + ", ".join(shown)) if shown else ""


# ------------------------------------------------------------------ circles
def circle_reason(case, expected: list, got: list) -> str:
    """The centre, the radius, and the pixels missing and extra by octant."""
    (cx, cy), = case.points
    want = Counter(tuple(p[:2]) for p in expected)
    have = Counter(tuple(p[:2]) for p in got)
    size = (f"radius {case.options['radius']}" if "radius" in case.options else
            f"rx {case.options['rx']}, ry {case.options['ry']}")
    parts = [f"centre {pair((cx, cy))}, {size}"]
    for what, pixels in (("missing", want - have), ("extra", have - want)):
        if pixels:
            parts.append(f"{what}: " + by_octant(pixels, cx, cy))
    return "; ".join(parts)


def by_octant(pixels: Counter, cx: int, cy: int) -> str:
    """Pixels grouped by the octant (numbered as the octant diagram numbers
    them) of their offset from the centre."""
    groups: dict = {}
    for pixel in sorted(pixels):
        number_of = octant_map(pixel[0] - cx, pixel[1] - cy).number
        groups.setdefault(number_of, []).extend([pixel] * pixels[pixel])
    texts = []
    for octant in sorted(groups):
        found = groups[octant]
        listed = ", ".join(pair(p) for p in found[:LISTED])
        more = f" and {len(found) - LISTED} more" if len(found) > LISTED else ""
        label = "the centre" if octant == 0 else f"octant {octant}"
        texts.append(f"{len(found)} in {label} ({listed}{more})")
    return ", ".join(texts)


# ----------------------------------------------------------------- polygons
def polygon_reason(case, pixel, rule: str) -> str:
    """Where the scan line through the pixel's centre crosses the edges, and
    what the fill rule makes of the crossings at or left of the centre."""
    i, j = pixel
    px, py = Fraction(2 * i + 1, 2), Fraction(2 * j + 1, 2)
    contours = [[(snap(x), snap(y)) for x, y in contour] for contour in case.points]
    crossings = scan_crossings(contours, py)
    left = [(x, up) for x, up in crossings if x <= px]
    ending = ", ".join(fraction(x) for x in upper_ends(contours, py))
    ending = f"; an edge whose upper end lies on it, at x = {ending}, does not" if ending else ""
    vertices = " | ".join(" ".join(pair(p) for p in contour) for contour in case.points)
    listed = ", ".join(f"{fraction(x)} {'up' if up else 'down'}" for x, up in crossings) or "none"
    if rule == "nonzero":
        winding = sum(1 if up else -1 for _, up in left)
        verdict = (f"winding number {winding}: "
                   f"{'inside' if winding else 'outside'} by the nonzero rule")
    else:
        verdict = (f"{len(left)} at or left of the centre: "
                   f"{'inside' if len(left) % 2 else 'outside'} by the even-odd rule")
    return (f"{pair(pixel)}: vertices {vertices}; the scan line y = {fraction(py)} crosses "
            f"the edges at x = {listed} (an edge counts when its lower end is at or below "
            f"the scan line and its upper end above it{ending}); centre x = {fraction(px)}, "
            f"{verdict}")


def snap(value) -> Fraction:
    """The reference's vertex: the nearest 1/256, halves to even."""
    return Fraction(round(Fraction(value) * 256), 256)


def scan_crossings(contours, y: Fraction) -> list:
    """(x, going up) where the horizontal line at ``y`` crosses each edge, sorted by x."""
    found = []
    for contour in contours:
        for k, (ax, ay) in enumerate(contour):
            bx, by = contour[(k + 1) % len(contour)]
            if min(ay, by) <= y < max(ay, by):
                found.append((ax + (y - ay) * (bx - ax) / (by - ay), by > ay))
    return sorted(found)


def upper_ends(contours, y: Fraction) -> list:
    """The x of each slanted or upright edge whose upper end lies at ``y``."""
    return sorted(bx if by > ay else ax for contour in contours
                  for (ax, ay), (bx, by) in zip(contour, contour[1:] + contour[:1])
                  if ay != by and max(ay, by) == y)


# ---------------------------------------------------------------- triangles
def triangle_reason(case, pixel, extra: bool, options: dict) -> str:
    """The edge values at the pixel's centre, exactly, and what the fill rule does."""
    rule = options.get("fill_rule", "top-left")
    bits = options.get("subpixel_bits", 8)
    corners = [(snap_bits(x, bits), snap_bits(y, bits)) for x, y in case.points]
    if cross(*corners) == 0:
        return "the triangle has no area: it covers no pixel"
    if cross(*corners) < 0:
        corners = [corners[0], corners[2], corners[1]]
    centre = (Fraction(2 * pixel[0] + 1, 2), Fraction(2 * pixel[1] + 1, 2))
    edges = [edge_value(corners, k, centre) for k in range(3)]
    values = ", ".join(f"e{k} = {fraction(e)}" for k, e in enumerate(edges))
    head = f"{pair(pixel)}: at its centre {pair(centre)} {values}"
    outside = [k for k, e in enumerate(edges) if e < 0]
    if outside:
        k = outside[0]
        return f"{head}; e{k} < 0: the centre lies outside {edge_name(corners, k)}"
    on = [k for k, e in enumerate(edges) if e == 0]
    if not on:
        return f"{head}; all > 0: the centre lies inside"
    keeps = (rule == "inclusive" or
             (rule == "top-left" and all(edge_side(corners, m) in ("left", "bottom")
                                         for m in on)))
    verdict = "keeps it" if keeps else "leaves it out"
    where = " and ".join(f"a {edge_side(corners, k)} edge ({edge_name(corners, k)})" for k in on)
    where = f"on {where}" if len(on) == 1 else f"on the corner where {where} meet"
    return f"{head}; its centre lies {where}; the {rule} rule {verdict}"


def snap_bits(value, bits: int) -> Fraction:
    scale = 1 << bits
    return Fraction(round(Fraction(value) * scale), scale)


def cross(o, p, q) -> Fraction:
    """(p - o) x (q - o): positive when q lies left of o -> p (y up)."""
    return (p[0] - o[0]) * (q[1] - o[1]) - (p[1] - o[1]) * (q[0] - o[0])


def edge_value(corners, k: int, point) -> Fraction:
    """e_k: how far left of the edge opposite corner k (counter-clockwise) the point lies."""
    return cross(corners[(k + 1) % 3], corners[(k + 2) % 3], point)


def edge_name(corners, k: int) -> str:
    return f"e{k}, from {pair(corners[(k + 1) % 3])} to {pair(corners[(k + 2) % 3])}"


def edge_side(corners, k: int) -> str:
    """Left, right, top or bottom, for a counter-clockwise triangle with y up:
    going down is a left edge, going left along a horizontal a top edge."""
    (ax, ay), (bx, by) = corners[(k + 1) % 3], corners[(k + 2) % 3]
    if by != ay:
        return "left" if by < ay else "right"
    return "bottom" if bx > ax else "top"


# ------------------------------------------------------------------ numbers
def fraction(value) -> str:
    """A fraction as a decimal where that is exact (halves, 1/256s), else p/q."""
    value = Fraction(value)
    if value.denominator == 1:
        return str(value.numerator)
    if value.denominator & (value.denominator - 1) == 0:
        return str(Decimal(value.numerator) / Decimal(value.denominator))
    return f"{value.numerator}/{value.denominator}"


def number(value) -> str:
    return fraction(value) if float(value).is_integer() else repr(float(value))


def pair(point) -> str:
    return f"({fraction(point[0])}, {fraction(point[1])})"
