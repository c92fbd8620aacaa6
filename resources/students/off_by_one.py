"""Sample student file: Bresenham with an off-by-one loop end (the last pixel is missing)."""


def draw(x0, y0, x1, y1):
    dx, dy = abs(x1 - x0), abs(y1 - y0)
    sx = 1 if x1 >= x0 else -1
    sy = 1 if y1 >= y0 else -1
    steep = dy > dx
    if steep:
        dx, dy = dy, dx
    d = 2 * dy - dx
    x, y = x0, y0
    yield x, y, {"d": d}
    for _ in range(dx - 1):      # off by one: Q is never plotted
        decided = d
        if d <= 0:              # E: a step along the major axis only
            d += 2 * dy
        else:                   # NE: the minor axis moves too
            d += 2 * (dy - dx)
            if steep:
                x += sx
            else:
                y += sy
        if steep:
            y += sy
        else:
            x += sx
        yield x, y, {"d": decided}
