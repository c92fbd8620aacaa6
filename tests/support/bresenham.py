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


def printed_draw_line(x1, y1, x2, y2):
    """Note 002's draw_line as printed, transcribed line by line (first octant;
    its `y = y0` read as `y = y1`): the as-printed Bresenham's oracle."""
    pixels, y = [], y1
    dx, dy = 2 * (x2 - x1), 2 * (y2 - y1)
    dydx, d = dy - dx, (dy - dx) // 2
    for x in range(x1, x2 + 1):
        pixels.append((x, y))
        if d > 0:
            d -= dy
        else:
            y += 1
            d -= dydx
    return pixels
