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
  pyramid halves exactly. The file must be a regular file (a FIFO or a
  device is refused before it is opened, and it is opened without blocking)
  of at most 16 MiB, and the sides are read from its header and checked
  before a pixel is decoded: a texture never costs more than 1024 x 1024
  texels (34 MB with its pyramid), whatever the file claims.

The pyramid (level 0 the texture, each next level the 2 x 2 box average of
the one before, down to 1 x 1) is built once per texture and kept with it;
textures are cached by name (and a file's modification time), so a run
does not rebuild them per frame or per run.
"""
from __future__ import annotations

import functools
import io
import math
import os
import stat
import warnings

import numpy as np

from algorithms.core.errors import InputError

CHECKER_SIZE = 64
ZONE_SIZE = 256
MAX_SIDE = 1024
# A 1024 x 1024 PNG of 16-bit RGBA stored without compression is 8.4 MB;
# twice that leaves room for metadata.
MAX_FILE_BYTES = 16 * 2 ** 20
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


def is_file_name(name: str) -> bool:
    """Whether the option names a file (rather than a built-in texture)."""
    name = name.strip()
    return name.lower().endswith(".png") or os.sep in name or "/" in name


def load(name: str) -> Texture:
    """The texture the option names (see the module's text); InputError when it cannot be."""
    name = name.strip()
    if name.startswith("checker:"):
        return _builtin(name)
    if name in ("zoneplate", "rings"):
        return _builtin("zoneplate")
    if is_file_name(name):
        try:
            status = os.stat(name)
        except OSError as error:
            raise InputError(f"option texture: cannot read {name!r} ({error.strerror})") from None
        _regular(name, status)
        return _png(name, status.st_mtime_ns)
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
    rgb = _decode(path, _read(path))
    return Texture(os.path.basename(path), rgb[::-1].copy())  # first row on top


def _regular(path: str, status: os.stat_result) -> None:
    if not stat.S_ISREG(status.st_mode):
        what = "a folder" if stat.S_ISDIR(status.st_mode) else "not a regular file"
        raise InputError(f"option texture: {path!r} is {what}, not a PNG file")


def _read(path: str) -> bytes:
    """The file's bytes. Opened without blocking, so a FIFO put in place
    after the stat cannot hang the run, and checked again on the handle."""
    flags = os.O_RDONLY | getattr(os, "O_NONBLOCK", 0) | getattr(os, "O_BINARY", 0)
    try:
        with os.fdopen(os.open(path, flags), "rb") as stream:
            status = os.fstat(stream.fileno())
            _regular(path, status)
            if status.st_size > MAX_FILE_BYTES:
                raise InputError(f"option texture: {path!r} is larger than "
                                 f"{MAX_FILE_BYTES:,} bytes, the most a texture file may be")
            return stream.read(MAX_FILE_BYTES + 1)
    except OSError as error:
        raise InputError(f"option texture: cannot read {path!r} ({error.strerror})") from None


def _decode(path: str, data: bytes) -> np.ndarray:
    """The texels of PNG ``data``: its sides are read from the header (Pillow
    opens lazily) and checked before anything is decoded."""
    # Pillow decodes: PNG is what it does well, and it is a dependency already.
    from PIL import Image, UnidentifiedImageError
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("error", Image.DecompressionBombWarning)
            with Image.open(io.BytesIO(data), formats=("PNG",)) as image:
                _check_sides(path, *image.size)
                return np.asarray(image.convert("RGB"), dtype=np.float64)
    except InputError:
        raise
    except (Image.DecompressionBombError, Image.DecompressionBombWarning):
        raise InputError(f"option texture: {path!r} is far larger than {MAX_SIDE} x {MAX_SIDE}, "
                         "the largest texture") from None
    except UnidentifiedImageError:
        raise InputError(f"option texture: cannot read {path!r} "
                         "(not an image in PNG format)") from None
    except (OSError, ValueError, EOFError, SyntaxError):  # what Pillow raises for a broken file
        raise InputError(f"option texture: cannot read {path!r} (unreadable)") from None


def _check_sides(path: str, width: int, height: int) -> None:
    for side in (width, height):
        if side > MAX_SIDE or side & (side - 1):
            raise InputError(f"option texture: {path!r} is {width} x {height}; each side must "
                             f"be a power of two up to {MAX_SIDE}")
