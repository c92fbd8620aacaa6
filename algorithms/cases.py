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
