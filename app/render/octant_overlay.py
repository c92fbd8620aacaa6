"""The octant diagram of the line on show, as overlay strokes.

Around P: the eight octants' boundary rays with their numbers (drawn as
seven-segment digits, so window and export need no font), the line's
octant outlined, the mirror lines that take it to the first octant
(dashed: x -> -x is the vertical line through P, y -> -y the horizontal
one, the swap the diagonal y = x), and the line's image in the first
octant. Which octant and which mirrors come from octant_map
(algorithms/lines/common.py), the mapping the line algorithms use.
"""
from __future__ import annotations

import math

from algorithms.lines.common import OctantMap, octant_map
from app.model import colours

RAY_COLOUR = (120, 120, 120)  # the rays and the other octants' numbers: neutral
# The line's octant, the mirrors applied and the line mapped into octant 1,
# from app/model/colours.py (overlays are drawn in the light set's colours,
# as the edges are: app/render/overlays.py). The mirrors are also dashed.
OCTANT_COLOUR, MIRROR_COLOUR, IMAGE_COLOUR = (colours.rgb(c) for c in colours.LIGHT.octants)
COLOURS = (RAY_COLOUR, OCTANT_COLOUR, MIRROR_COLOUR, IMAGE_COLOUR)
RADIUS = 5.0      # grid units from P to the end of each ray
DIGIT_SIZE = 0.9  # a digit's height in grid units
DASH = 0.5        # length of a dash and of the gap after it

# Seven-segment digits: segments as pairs of corners of a 1 x 2 box (x, y), y up.
_SEGMENTS = {"a": ((0, 2), (1, 2)), "b": ((1, 2), (1, 1)), "c": ((1, 1), (1, 0)),
             "d": ((0, 0), (1, 0)), "e": ((0, 0), (0, 1)), "f": ((0, 1), (0, 2)),
             "g": ((0, 1), (1, 1))}
_DIGITS = {1: "bc", 2: "abged", 3: "abgcd", 4: "fgbc", 5: "afgcd", 6: "afgedc", 7: "abc",
           8: "abcdefg"}


def line_on_grid(spec, points):
    """The segment P -> Q in grid units when the run draws a line, else None:
    whole-number points name pixels, whose centres the ideal line joins."""
    if spec is None or spec.inputs.names != ("P", "Q") or len(points) != 2:
        return None
    offset = 0.5 if spec.inputs.integer else 0.0
    (x0, y0), (x1, y1) = points
    return (x0 + offset, y0 + offset), (x1 + offset, y1 + offset)


def octant_strokes(segment, stroke) -> list:
    """The diagram for ``segment`` ((x0, y0), (x1, y1)); ``stroke(points,
    colour)`` makes one stroke."""
    (cx, cy), (qx, qy) = segment
    mapping = octant_map(qx - cx, qy - cy)
    strokes = []
    for k in range(8):
        angle = math.radians(45 * k)
        strokes.append(stroke(((cx, cy), _polar(cx, cy, RADIUS, angle)), RAY_COLOUR))
    for number in range(1, 9):
        colour = OCTANT_COLOUR if number == mapping.number else RAY_COLOUR
        centre = _polar(cx, cy, 0.7 * RADIUS, math.radians(45 * number - 22.5))
        strokes += [stroke(points, colour) for points in digit(number, centre)]
    if mapping.number:
        strokes += _wedge(cx, cy, mapping.number, stroke)
        strokes += _mirrors(cx, cy, mapping, stroke)
        image = mapping.apply(qx - cx, qy - cy)
        strokes.append(stroke(((cx, cy), (cx + image[0], cy + image[1])), IMAGE_COLOUR))
    return strokes


def digit(number: int, centre) -> list:
    """Polylines of a seven-segment digit centred at ``centre``."""
    half = DIGIT_SIZE / 2
    x0, y0 = centre[0] - half / 2, centre[1] - half
    return [tuple((x0 + x * half, y0 + y * half) for x, y in _SEGMENTS[name])
            for name in _DIGITS[number]]


def _polar(cx, cy, radius, angle):
    return (cx + radius * math.cos(angle), cy + radius * math.sin(angle))


def _wedge(cx, cy, number, stroke) -> list:
    """The line's octant: its two bounding rays and an arc between them."""
    start = math.radians(45 * (number - 1))
    arc = tuple(_polar(cx, cy, RADIUS, start + math.radians(45) * t / 8) for t in range(9))
    return [stroke(((cx, cy), arc[0]), OCTANT_COLOUR), stroke(((cx, cy), arc[-1]), OCTANT_COLOUR),
            stroke(arc, OCTANT_COLOUR)]


def _mirrors(cx, cy, mapping: OctantMap, stroke) -> list:
    """Dashed mirror lines through P: vertical (x -> -x), horizontal (y -> -y), y = x (swap)."""
    lines = []
    if mapping.flip_x:
        lines.append((0.0, 1.0))
    if mapping.flip_y:
        lines.append((1.0, 0.0))
    if mapping.swap:
        lines.append((math.sqrt(0.5), math.sqrt(0.5)))
    strokes = []
    for dx, dy in lines:
        t = -RADIUS
        while t < RADIUS:
            end = min(t + DASH, RADIUS)
            strokes.append(stroke(((cx + t * dx, cy + t * dy), (cx + end * dx, cy + end * dy)),
                                  MIRROR_COLOUR))
            t += 2 * DASH
    return strokes
