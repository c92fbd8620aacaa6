"""Sample student file: a flood fill whose outline truncates instead of
rounding, so slanted edges sit a pixel off and the filled region differs."""


def outline(contours):
    wall = set()
    for contour in contours:
        for k, (x0, y0) in enumerate(contour):
            x1, y1 = contour[(k + 1) % len(contour)]
            n = max(abs(x1 - x0), abs(y1 - y0)) or 1
            for i in range(n + 1):
                wall.add((x0 + i * (x1 - x0) // n, y0 + i * (y1 - y0) // n))  # the mistake
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
