"""Sample student file: "caches" rows of a table that never stops growing."""


def draw(x0, y0, x1, y1):
    cache = []
    while len(cache) >= 0:
        cache.append([0] * 1_000_000)
    yield x0, y0
