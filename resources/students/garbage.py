"""Sample student file: yields float coordinates (round(v, 0) keeps a float)."""


def draw(x0, y0, x1, y1):
    dx, dy = x1 - x0, y1 - y0
    n = max(abs(dx), abs(dy))
    for i in range(n + 1):
        t = i / n if n else 0.0
        yield round(x0 + t * dx, 0), round(y0 + t * dy, 0)
