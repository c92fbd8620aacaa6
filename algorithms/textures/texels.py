"""Textures as texel arrays and their mip pyramids.

A texture is a W x H array of RGB texels (floats 0..255). Texel (i, j)
covers [i, i+1) x [j, j+1) in texel space; texture coordinates (u, v) in
[0, 1] map to texel space (u W, v H), with v = 0 the bottom row (y up, as
OpenGL reads an image and as the grid is drawn), so a PNG's first row is
the texture's top row.

Three sources, named by the ``texture`` option:

* ``checker:N``: N x N squares per unit of uv, 64 x 64 texels (N a power
  of two up to 32, so every square is a whole number of texels);
* ``zoneplate`` (or ``rings``): 256 x 256 texels of concentric rings
  0.5 + 0.5 cos(pi r^2 / 256), r the distance from the centre in texels:
  the local frequency r / 256 cycles per texel grows to the Nyquist limit
  of 1/2 at the edge, so any minification aliases;
* a PNG file: sides powers of two up to 1024, so that every level of the
  pyramid halves exactly.

The pyramid (level 0 the texture, each next level the 2 x 2 box average of
the one before, down to 1 x 1) is built once per texture and kept with it;
textures are cached by name (and a file's modification time), so a run
does not rebuild them per frame or per run.
"""
from __future__ import annotations

import functools
import math
import os

import numpy as np

from algorithms.core.errors import InputError

CHECKER_SIZE = 64
ZONE_SIZE = 256
MAX_SIDE = 1024
LIGHT, DARK = 235.0, 35.0
BUILTIN = ("checker:8", "checker:4", "checker:16", "zoneplate")


class Texture:
    """A texture's name and its pyramid: ``levels[0]`` the texels, each (H, W, 3)."""

    def __init__(self, name: str, texels: np.ndarray):
        self.name = name
        self.levels = pyramid(texels)

    @property
    def width(self) -> int:
        return self.levels[0].shape[1]

    @property
    def height(self) -> int:
        return self.levels[0].shape[0]

    @property
    def top(self) -> int:
        """The coarsest level's number."""
        return len(self.levels) - 1


def pyramid(texels: np.ndarray) -> list[np.ndarray]:
    """Level 0 and every 2 x 2 box average of the level before, down to 1 x 1.

    A side already at 1 stays 1 (a 1 x 2 pair is averaged as a pair).
    """
    levels = [np.asarray(texels, dtype=np.float64)]
    while levels[-1].shape[0] > 1 or levels[-1].shape[1] > 1:
        level = levels[-1]
        if level.shape[0] > 1:
            level = (level[0::2] + level[1::2]) / 2
        if level.shape[1] > 1:
            level = (level[:, 0::2] + level[:, 1::2]) / 2
        levels.append(level)
    return levels


def checker(n: int, size: int = CHECKER_SIZE) -> np.ndarray:
    """n x n squares over the unit of uv, the square at (0, 0) light."""
    index = np.arange(size) * n // size
    dark = (index[:, None] + index[None, :]) % 2 == 1
    value = np.where(dark, DARK, LIGHT)
    return np.repeat(value[:, :, None], 3, axis=2)


def zone_plate(size: int = ZONE_SIZE) -> np.ndarray:
    """Rings 0.5 + 0.5 cos(pi r^2 / size) scaled to 0..255, r from the centre in texels."""
    centre = np.arange(size) + 0.5 - size / 2
    r2 = centre[:, None] ** 2 + centre[None, :] ** 2
    value = 255.0 * (0.5 + 0.5 * np.cos(math.pi * r2 / size))
    return np.repeat(value[:, :, None], 3, axis=2)


def load(name: str) -> Texture:
    """The texture the option names (see the module's text); InputError when it cannot be."""
    name = name.strip()
    if name.startswith("checker:"):
        return _builtin(name)
    if name in ("zoneplate", "rings"):
        return _builtin("zoneplate")
    if name.lower().endswith(".png") or os.sep in name or "/" in name:
        try:
            stamp = os.stat(name).st_mtime_ns
        except OSError as error:
            raise InputError(f"option texture: cannot read {name!r} ({error.strerror})") from None
        return _png(name, stamp)
    raise InputError(f"option texture: {name!r} is not checker:N, zoneplate or a .png file")


@functools.lru_cache(maxsize=8)
def _builtin(name: str) -> Texture:
    if name == "zoneplate":
        return Texture(name, zone_plate())
    text = name.partition(":")[2]
    if not text.isdigit() or not 1 <= int(text) <= CHECKER_SIZE // 2 \
            or int(text) & (int(text) - 1):
        raise InputError(f"option texture: {name!r}: N must be a power of two from 1 to "
                         f"{CHECKER_SIZE // 2}")
    return Texture(name, checker(int(text)))


@functools.lru_cache(maxsize=8)
def _png(path: str, stamp: int) -> Texture:
    # Pillow reads the file: the option names a file, and decoding PNG is
    # what Pillow (a dependency already) does well.
    from PIL import Image, UnidentifiedImageError
    try:
        with Image.open(path) as image:
            rgb = np.asarray(image.convert("RGB"), dtype=np.float64)
    except (OSError, UnidentifiedImageError, ValueError) as error:
        reason = "not an image" if isinstance(error, UnidentifiedImageError) else \
            (getattr(error, "strerror", None) or "unreadable")
        raise InputError(f"option texture: cannot read {path!r} ({reason})") from None
    height, width = rgb.shape[:2]
    for side in (width, height):
        if side > MAX_SIDE or side & (side - 1):
            raise InputError(f"option texture: {path!r} is {width} x {height}; each side must "
                             f"be a power of two up to {MAX_SIDE}")
    return Texture(os.path.basename(path), rgb[::-1].copy())  # first row on top
