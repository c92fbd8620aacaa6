"""Sample student file: the line y = m*x + b, truncated instead of rounded."""


def draw(x0, y0, x1, y1):
    dx, dy = x1 - x0, y1 - y0
    if abs(dx) >= abs(dy):
        step = 1 if dx >= 0 else -1
        for x in range(x0, x1 + step, step):
            t = (x - x0) / dx if dx else 0.0
            yield x, int(y0 + t * dy)        # int() cuts towards zero: should round
    else:
        step = 1 if dy >= 0 else -1
        for y in range(y0, y1 + step, step):
            t = (y - y0) / dy
            yield int(x0 + t * dx), y
