"""The distances of the Bresenham derivation, drawn where they are measured.

At each step the textbook compares two distances in the column being
decided: s, from the lower candidate's centre up to the ideal line, and n,
from the line up to the upper candidate's centre (a slide calls them b and
a). ``distance_segments`` gives them as segments in grid units for the step
on show, so the window can draw them beside the values. Qt-free.
"""
from __future__ import annotations

import math

from algorithms.lines.common import Octant


def distance_segments(points, trace, i: int) -> list[tuple[str, float, tuple, tuple]]:
    """[("s", s, start, end), ("n", n, start, end)] for step i, or [] when
    the step decides nothing (the first pixel, the end, a run without s and n).
    A negative s (the line below both candidates) runs downwards."""
    if i <= 0 or i >= len(trace) or len(points) != 2:
        return []
    step = trace.step(i)
    s, n = step.values.get("s"), step.values.get("n")
    if step.pixel is None or s is None or n is None or math.isnan(s) or math.isnan(n):
        return []
    before = trace.step(i - 1).pixel
    if before is None:
        return []
    octant = Octant(*points)
    (ax, ay), (bx, by) = octant.major, octant.minor
    # The lower candidate (E) one step along the major axis; the line and
    # the upper candidate (NE) further along the minor axis.
    lower = (before[0] + ax + 0.5, before[1] + ay + 0.5)
    line = (lower[0] + s * bx, lower[1] + s * by)
    upper = (lower[0] + bx, lower[1] + by)
    return [("s", s, lower, line), ("n", n, line, upper)]
