"""Sample student file: a z-buffer over edge functions, exact with fractions, correct."""
from fractions import Fraction


def edge(a, b, p):
    return (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0])


def covered(tri, p):
    """Inside, or on a left edge or a bottom horizontal edge (tri counter-clockwise)."""
    for k in range(3):
        a, b = tri[k], tri[(k + 1) % 3]
        e = edge(a, b, p)
        if e < 0:
            return False
        if e == 0:
            dx, dy = b[0] - a[0], b[1] - a[1]
            if not (dy < 0 or (dy == 0 and dx > 0)):
                return False
    return True


def draw(triangles):
    depth = {}
    for triangle in triangles:
        tri = [(Fraction(x), Fraction(y), Fraction(z)) for x, y, z in triangle]
        area = edge(tri[0], tri[1], tri[2])
        if area == 0:
            continue
        if area < 0:
            tri = [tri[0], tri[2], tri[1]]
            area = -area
        xs = [v[0] for v in tri]
        ys = [v[1] for v in tri]
        for y in range(int(min(ys)) - 1, int(max(ys)) + 1):
            for x in range(int(min(xs)) - 1, int(max(xs)) + 1):
                p = (Fraction(2 * x + 1, 2), Fraction(2 * y + 1, 2))
                if not covered(tri, p):
                    continue
                w0 = edge(tri[1], tri[2], p) / area
                w1 = edge(tri[2], tri[0], p) / area
                z = w0 * tri[0][2] + w1 * tri[1][2] + (1 - w0 - w1) * tri[2][2]
                if z < depth.get((x, y), 1):
                    depth[(x, y)] = z
                    yield x, y, {"z": float(z)}
