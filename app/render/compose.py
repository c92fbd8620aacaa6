"""Compose what the pixel grid shows into an RGBA image, with numpy only.

The grid view and any exporter share this module, so a picture written to a
file has the same colours, the same overdraw shade and the same outlines as
the window. Nothing here imports Qt.

Images come out with row 0 at y = 0, the same order as ``Raster.counts``.
In the default frame (origin bottom-left, y up) that row is the *bottom* of
the picture; ``top_down`` turns an image the right way up for a file.

At ``scale`` 1 every grid cell is one image pixel, and there is no room for
outlines: highlighted cells are tinted instead. At ``scale`` 3 and above each
cell becomes ``scale`` x ``scale`` image pixels, and highlights are drawn as
outlines inset into the cell, as the window draws them, together with the
grid lines and the ideal primitive.

``coverage=True`` colours each cell by how many times it was written
(0, 1, 2, 3 or more) instead of by its ink or colour, so that pixels two
triangles of a mesh both fill stand out; at ``scale`` 4 and above the
overlaps also carry a pattern (app/model/colours.py COVERAGE_PATTERNS), so
that their count is not told by colour alone.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Sequence

import numpy as np

from app.model import colours
from app.model.colours import DARK, LIGHT
from app.render import patterns

# Little-endian so that the bytes of each cell read R, G, B, A on any machine.
_RGBA = np.dtype("<u4")

__all__ = ["Palette", "PALETTE", "Overlay", "OUTLINE_STYLE", "compose", "top_down",
           "packed_rgba", "coverage_counts", "COVERAGE_LEVELS", "depth_image",
           "depth_range", "error_image", "error_stats", "diff_image", "coverage_image"]

# What the coverage colours stand for, in Palette.coverage order.
COVERAGE_LEVELS = ("not covered", "covered once", "covered twice", "covered 3+ times")


@dataclass(frozen=True)
class Palette:
    """Colours (#rrggbb) of everything the grid draws."""

    background: str = "#fbfcfd"   # a cell nothing was written to
    ink: str = "#2563a8"          # a cell written once, when the run writes no values
    overdraw: str = "#0b2a4f"     # a cell written more than once
    grid: str = "#c5ccd6"         # cell borders
    outside: str = "#e4e8ee"      # the view around the grid
    # The colours with a meaning come from app/model/colours.py.
    current: str = LIGHT.current      # the pixel the current step plots or visits
    candidate: str = LIGHT.candidate  # the pixels the current decision chooses between
    difference: str = LIGHT.difference  # cells where the compared run ended differently
    primitive: str = LIGHT.primitive  # the ideal primitive
    handle: str = "#ffffff"       # vertex handles (fill)
    handle_edge: str = "#1d2733"  # vertex handles (border and label)
    seed: str = "#7048e8"         # the seed marker of a fill
    guide: str = "#9c36b5"        # the reasoning drawn on the grid (scan line, M, samples)
    # Coverage counts 0, 1, 2, 3+: the ground, then app/model/colours.py's.
    coverage: tuple[str, str, str, str] = (LIGHT.ground, *LIGHT.coverage)
    # The compare diff's classes: only in A, only in B, both, different value.
    diff: tuple[str, str, str, str] = LIGHT.diff


PALETTE = Palette()
# The dark theme's grid (the window's and dark exports'): light ink on a
# dark ground, highlights kept in the same hues as the light theme so that
# the legend reads the same.
DARK_PALETTE = Palette(
    background="#1b2027", ink="#5fa8f5", overdraw="#b9dcff", grid="#38414d",
    outside="#11151a", current=DARK.current, candidate=DARK.candidate,
    difference=DARK.difference, primitive=DARK.primitive, handle="#1b2027", handle_edge="#e6edf3",
    seed="#9775fa", guide="#e599f7", coverage=(DARK.ground, *DARK.coverage),
    diff=DARK.diff)


@dataclass(frozen=True)
class OutlineStyle:
    """Where an outline sits in its cell and how it is drawn.

    ``inset`` is a fraction of the cell; ``width`` is in screen pixels in
    the window and scales with the cell size in composed images.
    """

    inset: float
    width: float
    dashed: bool = False


# Nested so that a cell that is at once current, a candidate and different
# shows all three rings.
OUTLINE_STYLE = {
    "difference": OutlineStyle(0.0, 2.5),
    "current": OutlineStyle(0.06, 3.0),
    "candidate": OutlineStyle(0.24, 2.0),
    # Around the whole run of cells a span step fills or scans.
    "span": OutlineStyle(0.0, 3.0),
}

# Tints used at scale 1, where there is no room for outlines.
TINT = {"difference": 0.55, "candidate": 0.45, "current": 0.7}


@dataclass(frozen=True)
class Overlay:
    """What is drawn over the pixels of one frame.

    ``current`` is the step's pixel, ``candidates`` the pixels its decision
    chose between, ``differences`` an (n, 2) array of cells (x, y) to mark
    as different from a compared run. ``primitive`` is the ideal primitive
    as a polyline in grid units (pixel (i, j) is the square [i, i+1) x
    [j, j+1)); ``closed`` joins its last point to the first. ``spans`` are
    runs (x_start, x_end, y) of cells x_start .. x_end - 1 on row y that a
    step fills or scans at once, outlined as one box each.
    """

    current: tuple[int, int] | None = None
    candidates: Sequence[tuple[int, int]] = ()
    differences: np.ndarray | None = None
    primitive: Sequence[tuple[float, float]] = ()
    closed: bool = False
    spans: Sequence[tuple[int, int, int]] = ()


def packed_rgba(color: str, alpha: int = 255) -> np.uint32:
    """'#rrggbb' as one uint32 whose bytes in memory are R, G, B, A."""
    r, g, b = _channels(color)
    return np.array(r | (g << 8) | (b << 16) | (alpha << 24), dtype=_RGBA)[()]


def _channels(color: str) -> tuple[int, int, int]:
    value = int(color.lstrip("#"), 16)
    return (value >> 16) & 255, (value >> 8) & 255, value & 255


def compose(raster, overlay: Overlay | None = None, palette: Palette = PALETTE,
            scale: int = 1, grid_lines: bool | None = None, coverage: bool = False) -> np.ndarray:
    """The grid as a uint8 array of shape (H * scale, W * scale, 4).

    ``raster`` is an ``algorithms.core.raster.Raster``. Cells written once take the ink colour, or their value from
    ``raster.colors`` where the run writes colours; cells written more than
    once take the overdraw colour (coloured cells are darkened instead).
    With ``coverage`` every cell takes the colour of its write count
    instead (``palette.coverage``: 0, 1, 2, 3 or more).
    """
    if scale < 1 or int(scale) != scale:
        raise ValueError(f"scale must be a whole number >= 1, got {scale}")
    scale = int(scale)
    cells = _coverage_cells(raster, palette) if coverage else _cells(raster, palette)
    if overlay is not None and scale < 3:
        _tint(cells, overlay, palette)
    if scale > 1:
        height, width = cells.shape
        if coverage:
            cells = _coverage_patterns(cells, raster.counts, palette, scale)
        else:
            cells = np.broadcast_to(cells[:, None, :, None], (height, scale, width, scale))
            cells = cells.reshape(height * scale, width * scale).copy()
        if grid_lines is None:
            grid_lines = scale >= 4
        if grid_lines:
            grid = packed_rgba(palette.grid)
            cells[scale::scale, :] = grid
            cells[:, scale::scale] = grid
        if overlay is not None and scale >= 3:
            draw_primitive(cells, overlay, palette, scale)
            draw_outlines(cells, overlay, palette, scale)
    return cells.view(np.uint8).reshape(cells.shape[0], cells.shape[1], 4)


def top_down(image: np.ndarray, y_down: bool = False) -> np.ndarray:
    """The image with its top row first, as files store pictures.

    In the default frame (y up) row 0 of a composed image is the bottom
    row of the picture, so it is flipped; in the y-down frame it is not.
    """
    return image if y_down else image[::-1]


def coverage_counts(raster) -> tuple[int, int, int, int]:
    """How many cells are covered 0, 1, 2 and 3 or more times."""
    levels = np.minimum(raster.counts, 3).ravel()
    return tuple(int(n) for n in np.bincount(levels, minlength=4)[:4])


# ------------------------------------------------------------------ parts
def _cells(raster, palette: Palette) -> np.ndarray:
    """One packed RGBA uint32 per cell."""
    return cell_colors(raster.counts, raster.colors, getattr(raster, "replaces", False), palette)


def cell_colors(counts: np.ndarray, colors: np.ndarray | None, replaces: bool,
                palette: Palette) -> np.ndarray:
    """Packed RGBA of cells given by their counts and colours (any shape:
    the whole grid, or some of its cells when only they changed)."""
    lut = np.array([packed_rgba(palette.background), packed_rgba(palette.ink),
                    packed_rgba(palette.overdraw)], dtype=_RGBA)
    # take(mode="clip") maps every count of 2 or more to the overdraw entry
    # in one pass over the buffer.
    counts = np.minimum(counts, 1) if replaces else counts
    cells = lut.take(counts, mode="clip")
    if colors is not None:
        valued = colors >= 0
        if valued.any():
            values = colors[valued].astype(np.uint32)  # int32 in compact rasters
            packed = (((values >> 16) & 255) | (values & 0xFF00) | ((values & 255) << 16)
                      | 0xFF000000).astype(_RGBA)
            again = counts[valued] > 1
            if again.any():
                packed[again] = _darken(packed[again], 0.6)
            cells[valued] = packed
    return cells


def _coverage_cells(raster, palette: Palette) -> np.ndarray:
    return coverage_colors(raster.counts, palette)


def coverage_colors(counts: np.ndarray, palette: Palette) -> np.ndarray:
    """Packed RGBA of cells by their write count (0, 1, 2, 3 or more)."""
    lut = np.array([packed_rgba(color) for color in palette.coverage], dtype=_RGBA)
    return lut.take(counts, mode="clip")


def coverage_image(counts: np.ndarray, palette: Palette = PALETTE, scale: int = 1) -> np.ndarray:
    """Coverage counts as a uint8 RGBA image (H * scale, W * scale, 4), row 0
    at y = 0. At ``scale`` 4 and above the cells written twice, and three
    times or more, carry their pattern (app/model/colours.py
    COVERAGE_PATTERNS) cut in the background colour."""
    cells = coverage_colors(counts, palette)
    return _coverage_patterns(cells, counts, palette, scale).view(np.uint8).reshape(
        cells.shape[0] * scale, cells.shape[1] * scale, 4)


def _coverage_patterns(cells: np.ndarray, counts: np.ndarray, palette: Palette,
                       scale: int) -> np.ndarray:
    """Packed cells enlarged ``scale`` times, with the coverage patterns cut in."""
    height, width = cells.shape
    image = cells.view(np.uint8).reshape(height, width, 4)
    big = patterns.stamp(image, np.minimum(counts, 3), colours.COVERAGE_PATTERNS,
                         _channels(palette.background), scale)
    return np.ascontiguousarray(big).view(_RGBA).reshape(height * scale, width * scale)


def _darken(packed: np.ndarray, factor: float) -> np.ndarray:
    rgba = packed.view(np.uint8).reshape(-1, 4).astype(np.float32)
    rgba[:, :3] *= factor
    return rgba.astype(np.uint8).view(_RGBA).reshape(-1)


def mix(packed: np.uint32, color: str, amount: float) -> np.uint32:
    rgba = np.array([packed], dtype=_RGBA).view(np.uint8).astype(np.float32)
    target = np.array(_channels(color), dtype=np.float32)
    rgba[:3] = rgba[:3] * (1 - amount) + target * amount
    return rgba.round().astype(np.uint8).view(_RGBA)[0]


def overlay_layers(overlay: Overlay):
    """(name, cells) from the bottom layer to the top one."""
    diff = overlay.differences
    yield "difference", [] if diff is None else [tuple(int(v) for v in cell) for cell in diff]
    yield "candidate", [tuple(cell) for cell in overlay.candidates]
    yield "current", [] if overlay.current is None else [tuple(overlay.current)]


def _span_cells(overlay: Overlay):
    for x_start, x_end, y in overlay.spans:
        for x in range(x_start, x_end):
            yield x, y


def _tint(cells: np.ndarray, overlay: Overlay, palette: Palette) -> None:
    height, width = cells.shape
    layers = list(overlay_layers(overlay)) + [("current", list(_span_cells(overlay)))]
    for name, layer in layers:
        color = getattr(palette, name)
        for x, y in layer:
            if 0 <= x < width and 0 <= y < height:
                cells[y, x] = mix(cells[y, x], color, TINT[name])


def draw_outlines(image: np.ndarray, overlay: Overlay, palette: Palette, scale: int) -> None:
    height, width = image.shape[0] // scale, image.shape[1] // scale
    for name, layer in overlay_layers(overlay):
        style = OUTLINE_STYLE[name]
        color = packed_rgba(getattr(palette, name))
        thick = max(1, round(scale * style.width / 36))
        inset = int(round(style.inset * scale))
        for x, y in layer:
            if not (0 <= x < width and 0 <= y < height):
                continue
            r0, c0 = y * scale + inset, x * scale + inset
            r1, c1 = (y + 1) * scale - inset, (x + 1) * scale - inset
            if r1 - r0 <= 2 * thick or c1 - c0 <= 2 * thick:
                image[r0:r1, c0:c1] = color
                continue
            ring = np.zeros((r1 - r0, c1 - c0), dtype=bool)
            ring[:thick, :] = ring[-thick:, :] = True
            ring[:, :thick] = ring[:, -thick:] = True
            if style.dashed:
                period = max(2, 2 * thick)
                rows, cols = np.indices(ring.shape)
                ring &= ((rows + cols) // period) % 2 == 0
            image[r0:r1, c0:c1][ring] = color
    _draw_span_boxes(image, overlay, palette, scale)


def _draw_span_boxes(image: np.ndarray, overlay: Overlay, palette: Palette, scale: int) -> None:
    """One box around each span's run of cells, in the current step's colour."""
    height, width = image.shape[0] // scale, image.shape[1] // scale
    color = packed_rgba(palette.current)
    thick = max(1, round(scale * OUTLINE_STYLE["span"].width / 36))
    for x_start, x_end, y in overlay.spans:
        x0, x1 = max(0, x_start), min(width, x_end)
        if not (0 <= y < height) or x1 <= x0:
            continue
        r0, r1, c0, c1 = y * scale, (y + 1) * scale, x0 * scale, x1 * scale
        image[r0:r0 + thick, c0:c1] = color
        image[r1 - thick:r1, c0:c1] = color
        image[r0:r1, c0:c0 + thick] = color
        image[r0:r1, c1 - thick:c1] = color


def draw_primitive(image: np.ndarray, overlay: Overlay, palette: Palette, scale: int) -> None:
    points = [(float(x) * scale, float(y) * scale) for x, y in overlay.primitive]
    if len(points) < 2:
        return
    if overlay.closed and len(points) > 2:
        points.append(points[0])
    color = packed_rgba(palette.primitive)
    radius = max(0.5, scale / 16)
    rows, cols = image.shape
    for (x0, y0), (x1, y1) in zip(points, points[1:]):
        length = math.hypot(x1 - x0, y1 - y0)
        t = np.linspace(0.0, 1.0, max(2, int(length * 2) + 1))
        xs, ys = x0 + (x1 - x0) * t, y0 + (y1 - y0) * t
        r = int(math.ceil(radius))
        for dy in range(-r, r + 1):
            for dx in range(-r, r + 1):
                if dx * dx + dy * dy > radius * radius + 0.25:
                    continue
                c = np.floor(xs + dx).astype(np.int64)
                rr = np.floor(ys + dy).astype(np.int64)
                keep = (c >= 0) & (c < cols) & (rr >= 0) & (rr < rows)
                image[rr[keep], c[keep]] = color


# ------------------------------------------------------------ depth and error
# Greys of the depth view: the nearest depth and the farthest (the clear value).
DEPTH_NEAR = 40
DEPTH_FAR = 250


def depth_range(depths, clear: float) -> tuple[float, float]:
    """(near, far) for ``depth_image``: the smallest and largest of the
    finite ``depths`` and the clear value, so that one run keeps one scale
    while it is stepped through."""
    depths = np.asarray(depths, dtype=np.float64).ravel()
    finite = depths[np.isfinite(depths)]
    lo = min(float(clear), float(finite.min())) if finite.size else float(clear)
    hi = max(float(clear), float(finite.max())) if finite.size else float(clear)
    return lo, hi


def depth_image(depth, clear: float, near: float, far: float) -> np.ndarray:
    """A depth buffer as a grey uint8 RGBA image (H, W, 4), row 0 at y = 0:
    ``near`` dark, ``far`` light; NaN (never written) takes ``clear``."""
    depth = np.asarray(depth, dtype=np.float64)
    depth = np.where(np.isnan(depth), float(clear), depth)
    span = far - near
    t = np.zeros(depth.shape) if not span > 0 else np.clip((depth - near) / span, 0.0, 1.0)
    grey = np.rint(DEPTH_NEAR + t * (DEPTH_FAR - DEPTH_NEAR)).astype(np.uint8)
    image = np.empty(depth.shape + (4,), np.uint8)
    image[..., 0] = image[..., 1] = image[..., 2] = grey
    image[..., 3] = 255
    return image


def error_stats(estimate, exact) -> tuple[float, float, np.ndarray]:
    """(RMS, max, per-pixel error) of |estimate - exact|. The RMS is taken
    over the pixels either one covers (the others are right trivially and
    would only dilute it with the size of the grid)."""
    error = np.abs(np.asarray(estimate, np.float64) - np.asarray(exact, np.float64))
    touched = (np.asarray(estimate) != 0) | (np.asarray(exact) != 0)
    if not touched.any():
        return 0.0, 0.0, error
    return (float(np.sqrt(np.mean(error[touched] ** 2))), float(error.max()), error)


def error_image(error, top: float | None = None, signed: bool = False,
                scale: int = 1) -> np.ndarray:
    """Per-pixel error as a uint8 RGBA image (H * scale, W * scale, 4):
    white for none, to the "too much" colour of app/model/colours.py for
    ``top`` (the largest error when not given) and above. ``signed``: a
    negative error (too little) goes to the "too little" colour instead,
    and at ``scale`` 4 and above its cells also carry a hatch, so the sign
    does not rest on colour alone."""
    error = np.asarray(error, dtype=np.float64)
    size = np.abs(error)
    if top is None:
        top = float(size.max()) if error.size else 0.0
    t = np.zeros(error.shape) if not top > 0 else np.clip(size / top, 0.0, 1.0)
    low = (error < 0) if signed else np.zeros(error.shape, bool)
    ends = np.array([colours.rgb(LIGHT.too_much), colours.rgb(LIGHT.too_little)], np.float64)
    image = np.empty(error.shape + (4,), np.uint8)
    image[..., :3] = np.rint(255 + (ends[low.astype(int)] - 255) * t[..., None]).astype(np.uint8)
    image[..., 3] = 255
    kinds = np.where(low & (t > 0), 0, -1)
    return patterns.stamp(image, kinds, ("stripes \\",), (255, 255, 255), scale)


def diff_image(d, palette=PALETTE, scale: int = 1) -> np.ndarray:
    """The diff as a uint8 RGBA image (H * scale, W * scale, 4), row 0 at
    y = 0. At ``scale`` 4 and above each class also carries its pattern
    (app/model/colours.py DIFF_PATTERNS) cut in the background colour."""
    lut = np.array([packed_rgba(palette.background)]
                   + [packed_rgba(c) for c in palette.diff], dtype="<u4")
    classes = d.classes()
    cells = lut[classes]
    image = cells.view(np.uint8).reshape(cells.shape[0], cells.shape[1], 4)
    return patterns.stamp(image, classes.astype(int) - 1, colours.DIFF_PATTERNS,
                          _channels(palette.background), scale)
