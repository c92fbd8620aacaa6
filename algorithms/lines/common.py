"""What every line algorithm shares: the inputs, endpoint colours, rounding,
and the mapping of a segment into the first octant."""
from __future__ import annotations

import math
from dataclasses import dataclass

from algorithms.core.registry import InputError, Inputs, Option
from algorithms.core.steps import NO_PIXEL

NAN = math.nan

COLORS = Option("colors", "colors", (), "endpoint colours #rrggbb,#rrggbb; the colour "
                "of each pixel is interpolated linearly in t along the segment")
SEGMENT = Inputs(2, integer=True, names=("P", "Q"))


class ColorRamp:
    """Linear interpolation between two colours, packed as 0xRRGGBB."""

    def __init__(self, first: str, last: str):
        self.first = _unpack_hex(first)
        self.last = _unpack_hex(last)

    def at(self, t: float) -> int:
        channels = [round(a + (b - a) * t) for a, b in zip(self.first, self.last)]
        return (channels[0] << 16) | (channels[1] << 8) | channels[2]


def _unpack_hex(text: str) -> tuple[int, int, int]:
    value = int(text[1:], 16)
    return (value >> 16) & 255, (value >> 8) & 255, value & 255


def color_ramp(options: dict) -> ColorRamp | None:
    colors = options.get("colors") or ()
    if not colors:
        return None
    if len(colors) != 2:
        raise InputError("option colors: give two colours, one for each endpoint")
    return ColorRamp(*colors)


def round_half_up(value: float) -> int:
    """Nearest integer, halves rounded up (floor(v + 1/2))."""
    return math.floor(value + 0.5)


@dataclass(frozen=True)
class OctantMap:
    """Which octant a direction (dx, dy) lies in, and the mirrors that take it
    to the first (0 <= dy <= dx), applied in this order: x -> -x when
    ``flip_x``, y -> -y when ``flip_y``, then x <-> y when ``swap``.

    Octants are numbered 1..8 counter-clockwise from +x. A direction on a
    boundary belongs to the octant whose mirrors the line algorithms apply
    to it: x is major at 45 degrees (no swap), and a step of 0 is not
    mirrored, so +x is octant 1, 45 degrees 1, +y 2, 135 degrees 4, -x 4,
    225 degrees 5, -y 7, 315 degrees 8. A point (0, 0) is octant 0.
    """

    number: int
    flip_x: bool
    flip_y: bool
    swap: bool

    def steps(self) -> tuple[str, ...]:
        """The mirrors in words, in the order they apply."""
        names = (("flip_x", "mirror x (x -> -x)"), ("flip_y", "mirror y (y -> -y)"),
                 ("swap", "swap x and y"))
        return tuple(text for name, text in names if getattr(self, name))

    def apply(self, x, y):
        """The vector (x, y) after the mirrors."""
        x, y = (-x if self.flip_x else x), (-y if self.flip_y else y)
        return (y, x) if self.swap else (x, y)

    def text(self) -> str:
        """One line: the octant and how it maps to the first."""
        if self.number == 0:
            return "P = Q: no direction, no octant"
        if self.number == 1:
            return "octant 1: already the first octant, nothing to swap"
        return f"octant {self.number} -> 1: " + ", then ".join(self.steps())


# Octant number by (flip_x, flip_y, swap).
_NUMBERS = {(False, False, False): 1, (False, False, True): 2, (True, False, True): 3,
            (True, False, False): 4, (True, True, False): 5, (True, True, True): 6,
            (False, True, True): 7, (False, True, False): 8}


def octant_map(dx, dy) -> OctantMap:
    """The octant of the direction (dx, dy) and its mirrors into the first."""
    flip_x, flip_y, swap = dx < 0, dy < 0, abs(dy) > abs(dx)
    number = 0 if dx == 0 and dy == 0 else _NUMBERS[(flip_x, flip_y, swap)]
    return OctantMap(number, flip_x, flip_y, swap)


class Octant:
    """How a segment maps into the first octant (0 <= slope <= 1, left to right).

    The major axis is the one with the larger extent. ``major`` and
    ``minor`` are unit steps in the original grid; the mapped segment runs
    from (0, 0) to (dx, dy) with 0 <= dy <= dx. ``number`` is the octant as
    octant_map numbers it.
    """

    def __init__(self, p, q):
        ddx, ddy = q[0] - p[0], q[1] - p[1]
        self.steep = abs(ddy) > abs(ddx)
        sx = 1 if ddx >= 0 else -1
        sy = 1 if ddy >= 0 else -1
        if self.steep:
            self.dx, self.dy = abs(ddy), abs(ddx)
            self.major, self.minor = (0, sy), (sx, 0)
        else:
            self.dx, self.dy = abs(ddx), abs(ddy)
            self.major, self.minor = (sx, 0), (0, sy)
        # +1 when the minor coordinate grows from P towards Q.
        self.minor_sign = self.minor[0] + self.minor[1]
        self.number = octant_map(ddx, ddy).number

    def to_grid(self, p, u, v):
        """Mapped (u, v) back to the original grid, from P."""
        return (p[0] + u * self.major[0] + v * self.minor[0],
                p[1] + u * self.major[1] + v * self.minor[1])


def with_color(ramp, names):
    return names + ("rgb",) if ramp else names


def colored(frames, ramp, steps: int):
    """The frames with each plot's colour appended: step k of ``steps`` takes
    the ramp at t = k / steps; a frame with no pixel takes no colour."""
    for k, frame in enumerate(frames):
        color = NAN if frame[1] == NO_PIXEL else ramp.at(fraction_of(k, steps))
        yield (*frame, color)


def fraction_of(k: int, n: int) -> float:
    """Where step k of n lies along the segment; 0 for a point."""
    return k / n if n else 0.0


def major_axis(points):
    """(steep, a0, b0, a1, b1): major coordinates a, minor b; x is major at 45 degrees."""
    (x0, y0), (x1, y1) = points
    if abs(y1 - y0) > abs(x1 - x0):
        return True, y0, x0, y1, x1
    return False, x0, y0, x1, y1


def pixel_at(steep: bool, a: int, b: int) -> tuple[int, int]:
    return (b, a) if steep else (a, b)


def sign(value: int) -> int:
    return 1 if value >= 0 else -1
