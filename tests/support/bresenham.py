"""The textbook Bresenham line, written out here as the oracle of every test
that checks the program's Bresenham pixels or decision variable."""
from __future__ import annotations


def bresenham_run(p, q) -> tuple[list[tuple[int, int]], list[int]]:
    """The first-octant loop (0 <= dy <= dx): the pixels it plots, and for
    each pixel after the first the d that chose it. d starts at 2dy - dx;
    d <= 0 chooses E (d += 2dy), else NE (d += 2(dy - dx), y += 1)."""
    (x0, y0), (x1, y1) = p, q
    dx, dy = x1 - x0, y1 - y0
    assert 0 <= dy <= dx, "first octant only"
    d, y = 2 * dy - dx, y0
    pixels, decisions = [(x0, y0)], []
    for x in range(x0 + 1, x1 + 1):
        decisions.append(d)
        if d <= 0:
            d += 2 * dy
        else:
            d += 2 * (dy - dx)
            y += 1
        pixels.append((x, y))
    return pixels, decisions


def bresenham_pixels(p, q) -> list[tuple[int, int]]:
    """The pixels of the textbook first-octant loop, in the order it plots them."""
    return bresenham_run(p, q)[0]
