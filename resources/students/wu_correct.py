"""Sample student file: Wu's antialiased line in every octant, correct."""


def draw(x0, y0, x1, y1):
    steep = abs(y1 - y0) > abs(x1 - x0)
    if steep:
        x0, y0, x1, y1 = y0, x0, y1, x1
    if x1 < x0:
        x0, y0, x1, y1 = x1, y1, x0, y0
    dx, dy = x1 - x0, y1 - y0
    step = 1 if dy >= 0 else -1
    dy = abs(dy)
    if dx == 0:
        yield x0, y0, 1.0
        return
    e, y = 0, y0
    for x in range(x0, x1 + 1):
        # The ideal line is e/dx of a pixel beyond y, toward the next row.
        for offset, intensity in ((0, (dx - e) / dx), (step, e / dx)):
            if intensity > 0:
                yield ((y + offset, x) if steep else (x, y + offset)) + (intensity,)
        e += dy
        if e >= dx:
            e -= dx
            y += step
