"""Sample student file: the loop counter is never advanced, so the loop never ends."""


def draw(x0, y0, x1, y1):
    dx, dy = x1 - x0, y1 - y0
    n = max(abs(dx), abs(dy))
    i = 0
    while i <= n:
        t = i / n if n else 0.0
        yield round(x0 + t * dx), round(y0 + t * dy)
        # forgot: i += 1
