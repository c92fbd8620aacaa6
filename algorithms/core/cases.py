"""The hard-case catalogue: the inputs where rasterization algorithms go wrong.

The stability tests run every line algorithm on these segments, and
`rasterlab check` runs a student's algorithm on them: one segment per octant,
then the special directions (a point, the axes, the diagonals) and the
segments whose ideal line passes exactly half-way between two pixels.
"""
from __future__ import annotations

# One segment per octant (counter-clockwise from +x).
OCTANT_CASES = [
    ((0, 0), (7, 3)), ((0, 0), (3, 7)), ((0, 0), (-3, 7)), ((0, 0), (-7, 3)),
    ((0, 0), (-7, -3)), ((0, 0), (-3, -7)), ((0, 0), (3, -7)), ((0, 0), (7, -3)),
]
SPECIAL_CASES = [
    ((4, 4), (4, 4)),                                      # zero length
    ((1, 2), (9, 2)), ((9, 2), (1, 2)),                    # horizontal
    ((3, 1), (3, 8)), ((3, 8), (3, 1)),                    # vertical
    ((0, 0), (5, 5)), ((5, 5), (0, 0)),                    # 45 degrees, rising
    ((0, 5), (5, 0)), ((5, 0), (0, 5)),                    # 45 degrees, falling
    ((0, 0), (4, 2)), ((0, 0), (2, 1)), ((2, 1), (0, 0)),  # ties
    ((0, 0), (1, 2)), ((0, 0), (-2, 1)), ((0, 0), (6, -3)),
]
LINE_CASES = OCTANT_CASES + SPECIAL_CASES

# Circles: the degenerate radii, the smallest ones whose octant has a tie or a
# knee, and a few ordinary ones.
CIRCLE_RADII = (0, 1, 2, 3, 4, 5, 7, 8, 12)
# Ellipses (rx, ry): flat, tall, round and the segments an axis of 0 makes.
ELLIPSE_AXES = ((10, 6), (6, 10), (5, 5), (1, 4), (7, 1), (0, 3), (4, 0), (12, 3))

# Triangles (real vertices, y up): the fill rule's ties, a sliver, no area,
# smaller than a pixel, and both windings.
TRIANGLE_CASES = [
    ((2.0, 2.0), (12.0, 3.0), (5.0, 10.0)),        # general, counter-clockwise
    ((5.0, 10.0), (12.0, 3.0), (2.0, 2.0)),        # the same, clockwise
    ((1.5, 1.5), (9.5, 1.5), (5.5, 7.5)),          # a bottom edge through pixel centres
    ((5.5, 1.5), (9.5, 7.5), (1.5, 7.5)),          # a top edge through centres (not filled)
    ((2.5, 2.5), (9.5, 6.5), (2.5, 10.5)),         # a left edge through centres
    ((1.0, 1.0), (20.0, 2.0), (20.25, 2.125)),     # a sliver
    ((1.0, 1.0), (5.0, 5.0), (9.0, 9.0)),          # no area
    ((3.25, 3.25), (3.75, 3.25), (3.5, 3.75)),     # smaller than a pixel, around a centre
    ((0.0, 0.0), (31.0, 0.0), (0.0, 23.0)),        # large
]
# Polygons, as lists of contours: centres on the edges, concave, self-crossing,
# a hole, thin.
POLYGON_CASES = [
    (((1.5, 1.5), (8.5, 1.5), (8.5, 8.5), (1.5, 8.5)),),
    (((2.0, 2.0), (14.0, 2.0), (14.0, 12.0), (10.0, 12.0), (10.0, 6.0), (6.0, 6.0),
      (6.0, 12.0), (2.0, 12.0)),),
    (((8.0, 1.0), (11.0, 14.0), (2.0, 6.0), (14.0, 6.0), (5.0, 14.0)),),
    (((1.0, 1.0), (15.0, 1.0), (15.0, 15.0), (1.0, 15.0)),
     ((5.0, 5.0), (11.0, 5.0), (11.0, 11.0), (5.0, 11.0))),
    (((1.0, 1.0), (20.0, 1.0), (20.0, 2.0)),),
    (((2.5, 2.5), (9.5, 2.5), (9.5, 5.5), (2.5, 5.5)),),
]
