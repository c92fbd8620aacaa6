"""Sample student file: a 4-connected flood fill inside the outline, correct."""


def outline(contours):
    """The outline's pixels: each edge one pixel per step along its longer
    axis, the other coordinate rounded (halves up)."""
    wall = set()
    for contour in contours:
        for k, (x0, y0) in enumerate(contour):
            x1, y1 = contour[(k + 1) % len(contour)]
            n = max(abs(x1 - x0), abs(y1 - y0))
            for i in range(n + 1):
                if n == 0:
                    wall.add((x0, y0))
                else:
                    wall.add((x0 + (2 * i * (x1 - x0) + n) // (2 * n),
                              y0 + (2 * i * (y1 - y0) + n) // (2 * n)))
    return wall


def draw(contours, seed):
    wall = outline(contours)
    filled = set()
    stack = [tuple(seed)]
    while stack:
        x, y = stack.pop()
        if (x, y) in wall or (x, y) in filled:
            continue
        filled.add((x, y))
        yield x, y
        stack += [(x + 1, y), (x - 1, y), (x, y + 1), (x, y - 1)]
