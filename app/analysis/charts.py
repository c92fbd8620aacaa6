"""Small static charts drawn with Pillow, for the report's PNG files.

A ``Chart`` is one panel: axes (linear or logarithmic), series of points
(joined by lines or not, with optional labels at the points) and a
legend. ``figure`` lays panels out side by side under a title and returns
a Pillow image. On a logarithmic axis, values at or below zero cannot be
placed: they are drawn on the axis's lower edge and the tick there reads
"<= lowest", so no point silently disappears.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field

from PIL import Image, ImageDraw, ImageFont

from app.model.colours import OKABE_ITO
from app.model.shipped import FONTS

# The Okabe-Ito set (app/model/colours.py), its light members darkened to
# reach 3:1 on white, and each colour with its own marker shape, so that a
# series is told by shape as well as by colour.
# Black is left for the reference series (the Pareto front, "adaptive").
PALETTE = (OKABE_ITO["blue"], OKABE_ITO["vermillion"], OKABE_ITO["bluish green"], "#995a7d",
           "#b87f00", "#3a8fc0")
MARKERS = ("o", "s", "^", "d")
BACKGROUND = "#ffffff"
INK = "#222222"
GRID = "#e4e4e4"


def font(size: int) -> ImageFont.FreeTypeFont:
    """DejaVu Sans as RasterLab ships it: the same charts on every system."""
    return ImageFont.truetype(str(FONTS / "DejaVuSans.ttf"), size)


@dataclass
class Series:
    label: str
    points: list  # (x, y) pairs
    color: str
    line: bool = True
    labels: list | None = None  # text per point, drawn beside it
    marker: str = "o"  # "o" disc, "s" square, "^" triangle, "d" diamond, "" none
    width: int = 2
    in_legend: bool = True


@dataclass
class Chart:
    title: str
    xlabel: str
    ylabel: str
    xlog: bool = False
    ylog: bool = False
    series: list = field(default_factory=list)
    note: str = ""
    legend: bool = True  # off where every point carries its own label
    palette: dict = field(default_factory=dict)  # label -> colour, the same in every panel

    def add(self, label, points, color=None, line=True, labels=None, marker=None, width=2,
            in_legend=True):
        """A series; ``marker`` None takes the shape that goes with its colour."""
        color = color or self.palette.get(label) or PALETTE[len(self.series) % len(PALETTE)]
        if marker is None:
            marker = MARKERS[PALETTE.index(color) % len(MARKERS)] if color in PALETTE else "o"
        points = [(float(x), float(y)) for x, y in points
                  if math.isfinite(float(x)) and math.isfinite(float(y))]
        self.series.append(Series(label, points, color, line, labels, marker, width, in_legend))
        return self

    # ------------------------------------------------------------ scales
    def _range(self, values, log):
        if log:
            positive = [v for v in values if v > 0]
            if not positive:
                return 1.0, 10.0
            lo, hi = min(positive), max(positive)
            lo, hi = 10 ** math.floor(math.log10(lo)), 10 ** math.ceil(math.log10(hi))
            return (lo, hi) if hi > lo else (lo, lo * 10)
        if not values:
            return 0.0, 1.0
        lo, hi = min(values), max(values)
        lo = min(lo, 0.0) if lo >= 0 and lo < 0.35 * hi else lo
        if hi == lo:
            hi = lo + (abs(lo) or 1.0)
        pad = 0.06 * (hi - lo)
        # Points at zero sit a little above the frame rather than on it.
        return lo - (pad if lo < 0 else 0.04 * (hi - lo)), hi + pad

    def render(self, width: int, height: int) -> Image.Image:
        image = Image.new("RGB", (width, height), BACKGROUND)
        draw = ImageDraw.Draw(image)
        small, normal, bold = font(12), font(14), font(15)
        xs = [x for s in self.series for x, _ in s.points]
        ys = [y for s in self.series for _, y in s.points]
        listed = [s for s in self.series if s.in_legend] if self.legend else []
        legend_rows = math.ceil(len(listed) / 2)
        bottom = height - 56 - 17 * legend_rows - (16 if self.note else 0)
        frame = Frame(78, 34, width - 16, bottom, self._range(xs, self.xlog), self.xlog,
                      self._range(ys, self.ylog), self.ylog)
        draw.text((frame.left, 8), self.title, fill=INK, font=bold)
        self._axes(image, draw, frame, (xs, ys), (small, normal))
        labels = []  # (x, y, text, colour) of point labels, merged where points coincide
        for series in self.series:
            placed = [(frame.sx(x), frame.sy(y)) for x, y in series.points]
            if series.line and len(placed) > 1:
                draw.line(placed, fill=series.color, width=series.width)
            for (x, y) in placed:
                _marker(draw, x, y, series.marker, series.color)
            if series.labels:
                for (x, y), text in zip(placed, series.labels):
                    if text:
                        labels.append((x, y, str(text), series.color))
        _draw_labels(draw, labels, small, (frame.left, frame.top, frame.right, frame.bottom))
        _legend(draw, frame, listed, small)
        if self.note:
            draw.text((frame.left, height - 18), self.note, fill="#555555", font=small)
        return image

    def _axes(self, image, draw, frame: Frame, values, fonts) -> None:
        """Grid lines, ticks, the frame and both axis labels."""
        (xs, ys), (small, normal) = values, fonts
        left, top, right, bottom = frame.left, frame.top, frame.right, frame.bottom
        for value in _ticks(*frame.x_range, self.xlog):
            x = frame.sx(value)
            draw.line([(x, top), (x, bottom)], fill=GRID)
            text = _tick_text(value, self.xlog)
            if self.xlog and value == frame.x_range[0] and any(v <= 0 for v in xs):
                text = "<=" + text
            w = draw.textlength(text, font=small)
            draw.text((x - w / 2, bottom + 4), text, fill=INK, font=small)
        for value in _ticks(*frame.y_range, self.ylog):
            y = frame.sy(value)
            draw.line([(left, y), (right, y)], fill=GRID)
            text = _tick_text(value, self.ylog)
            if self.ylog and value == frame.y_range[0] and any(v <= 0 for v in ys):
                text = "<=" + text
            w = draw.textlength(text, font=small)
            draw.text((left - 6 - w, y - 7), text, fill=INK, font=small)
        draw.rectangle([left, top, right, bottom], outline=INK)
        w = draw.textlength(self.xlabel, font=normal)
        draw.text(((left + right) / 2 - w / 2, bottom + 20), self.xlabel, fill=INK, font=normal)
        label = Image.new("RGBA", (int(draw.textlength(self.ylabel, font=normal)) + 4, 18),
                          (255, 255, 255, 0))
        ImageDraw.Draw(label).text((2, 0), self.ylabel, fill=INK, font=normal)
        rotated = label.rotate(90, expand=True)
        image.paste(rotated, (4, int((top + bottom) / 2 - rotated.height / 2)), rotated)


@dataclass(frozen=True)
class Frame:
    """A panel's plotting area and its scales, from data (x, y) to image pixels."""

    left: float
    top: float
    right: float
    bottom: float
    x_range: tuple
    xlog: bool
    y_range: tuple
    ylog: bool

    def sx(self, x: float) -> float:
        return self.left + _share(x, self.x_range, self.xlog) * (self.right - self.left)

    def sy(self, y: float) -> float:
        return self.bottom - _share(y, self.y_range, self.ylog) * (self.bottom - self.top)


def _share(value: float, limits: tuple, log: bool) -> float:
    """Where value lies between the limits, 0 to 1 (log: on a log scale, clamped below)."""
    lo, hi = limits
    if log:
        value = max(value, lo)
        return (math.log10(value) - math.log10(lo)) / (math.log10(hi) - math.log10(lo))
    return (value - lo) / (hi - lo)


def _legend(draw, frame: Frame, listed, small) -> None:
    """Two columns under the axis label."""
    y0 = frame.bottom + 40
    column = (frame.right - frame.left) / 2
    for n, series in enumerate(listed):
        x = frame.left + (n % 2) * column
        y = y0 + 17 * (n // 2)
        if series.line:
            draw.line([(x, y + 7), (x + 18, y + 7)], fill=series.color, width=2)
        _marker(draw, x + 9, y + 7, series.marker or "o", series.color)
        draw.text((x + 24, y), series.label, fill=INK, font=small)


def _draw_labels(draw, labels, small, box, near: float = 3.0) -> None:
    """Point labels; points closer than ``near`` px share one stacked label."""
    groups = []
    for x, y, text, color in sorted(labels, key=lambda item: (item[1], item[0])):
        for group in groups:
            if abs(group[0] - x) < near and abs(group[1] - y) < near:
                group[2].append((text, color))
                break
        else:
            groups.append([x, y, [(text, color)]])
    left, top, right, bottom = box
    taken = []  # rectangles of labels placed so far

    def free(rect):
        return all(rect[2] < r[0] or rect[0] > r[2] or rect[3] < r[1] or rect[1] > r[3]
                   for r in taken)

    for x, y, texts in groups:
        height = 14 * len(texts)
        widest = max(draw.textlength(t, font=small) for t, _ in texts)
        choice = None
        for shift in [0] + [s * sign for s in range(14, 200, 14) for sign in (-1, 1)]:
            for tx in (x + 7, x - 7 - widest):
                ty = y - height / 2 + shift
                rect = (tx, ty, tx + widest, ty + height)
                if tx < left + 2 or rect[2] > right - 2 or ty < top + 2 or rect[3] > bottom - 2:
                    continue
                if free(rect):
                    choice = rect
                    break
            if choice:
                break
        if choice is None:  # nowhere free: beside the point, overlapping
            tx = x + 7 if x + 7 + widest <= right else x - 7 - widest
            ty = min(max(y - height / 2, top + 2), bottom - height - 2)
            choice = (tx, ty, tx + widest, ty + height)
        taken.append(choice)
        tx, ty = choice[0], choice[1]
        if abs(ty + height / 2 - y) > 10:  # moved away: a leader line to the point
            anchor_x = choice[0] if choice[0] > x else choice[2]
            draw.line([(x, y), (anchor_x, ty + height / 2)], fill="#999999", width=1)
        for n, (text, color) in enumerate(texts):
            draw.text((tx, ty + 14 * n - 1), text, fill=color, font=small)


def _marker(draw, x, y, kind, color, size=4):
    if kind == "o":
        draw.ellipse([x - size, y - size, x + size, y + size], fill=color)
    elif kind == "s":
        draw.rectangle([x - size, y - size, x + size, y + size], fill=color)
    elif kind == "^":
        draw.polygon([(x, y - size - 1), (x - size - 1, y + size), (x + size + 1, y + size)],
                     fill=color)
    elif kind == "d":
        draw.polygon([(x, y - size - 1), (x + size + 1, y), (x, y + size + 1), (x - size - 1, y)],
                     fill=color)


def _ticks(lo: float, hi: float, log: bool) -> list[float]:
    if log:
        first, last = math.floor(math.log10(lo)), math.ceil(math.log10(hi))
        step = max(1, math.ceil((last - first) / 8))
        return [10.0 ** k for k in range(first, last + 1, step) if lo <= 10.0 ** k <= hi * 1.0001]
    span = hi - lo
    raw = span / 6
    magnitude = 10 ** math.floor(math.log10(raw))
    step = min((m * magnitude for m in (1, 2, 2.5, 5, 10) if m * magnitude >= raw),
               default=10 * magnitude)
    start = math.ceil(lo / step) * step
    ticks = []
    value = start
    while value <= hi + 1e-9 * span:
        ticks.append(0.0 if abs(value) < 1e-12 * span else value)
        value += step
    return ticks


def _tick_text(value: float, log: bool) -> str:
    if log:
        exponent = round(math.log10(value))
        return f"1e{exponent}" if abs(exponent) > 3 else f"{value:g}"
    if value == 0:
        return "0"
    if abs(value) >= 1e5 or abs(value) < 1e-3:
        return f"{value:.0e}"
    return f"{value:g}"


def palette(labels) -> dict:
    """A colour per label, in order, for charts that should agree on colours."""
    return {label: PALETTE[n % len(PALETTE)] for n, label in enumerate(labels)}


def figure(title: str, panels: list[Chart], panel_size=(560, 460)) -> Image.Image:
    """The panels side by side under a title."""
    width, height = panel_size
    image = Image.new("RGB", (width * len(panels), height + 34), BACKGROUND)
    ImageDraw.Draw(image).text((12, 8), title, fill=INK, font=font(18))
    for n, panel in enumerate(panels):
        image.paste(panel.render(width, height), (n * width, 34))
    return image
