"""What the texture panel shows at a step: the texture level in use, the pixel's footprint on
it, the texels fetched, and the grid coloured by mip level.

Worked out for the visible step only, from the trace's values and the
options (the lookup is repeated for the pixel on show, which gives every
texel fetched, not only the four a frame keeps).
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from algorithms.core.steps import PLOT
from algorithms.textures import texels
from algorithms.textures.sampling import Mapping, Sampler

# One colour per mip level (0 the finest), repeated beyond the eighth.
LEVEL_COLOURS = np.array([(66, 133, 244), (52, 168, 83), (251, 188, 5), (234, 67, 53),
                          (171, 71, 188), (0, 172, 193), (255, 112, 67), (158, 157, 36)],
                         dtype=np.uint8)


@dataclass
class TexturePicture:
    """The texture panel's content at one step."""

    image: np.ndarray  # (H, W, 4) uint8 of the level shown, row 0 at v = 0
    level: int
    caption: str
    levels: int  # how many levels the texture's pyramid has
    footprint: list = field(default_factory=list)  # (s, t) corners in the level's texels
    texels: list = field(default_factory=list)  # (i, j, weight) fetched in the level shown


def texture_picture(trace, index: int, options: dict) -> TexturePicture | None:
    """The texture and, when the step looks a pixel up, its footprint and fetches."""
    if trace is None or "level" not in trace.value_names:
        return None
    try:
        texture = texels.load(options.get("texture", "checker:8"))
    except ValueError:
        return None
    step = trace.step(index)
    looked_up = step.pixel is not None and "u" in step.values \
        and trace.code[step.line].kind == PLOT
    if not looked_up:
        return TexturePicture(_rgba(texture.levels[0]), 0,
                              f"{texture.name}: {texture.width} x {texture.height}, "
                              f"{texture.top + 1} levels", texture.top + 1)
    sample = _lookup(trace, index, options, texture, step.pixel)
    level = sample.levels[0][0] if sample is not None else int(step.values.get("level", 0))
    values = step.values
    height, width = texture.levels[level].shape[:2]
    u, v = values["u"], values["v"]
    shift_u, shift_v = math.floor(u), math.floor(v)  # show the footprint on the base tile
    corners = []
    for sx, sy in ((-0.5, -0.5), (0.5, -0.5), (0.5, 0.5), (-0.5, 0.5)):
        cu = u - shift_u + sx * values.get("du/dx", 0.0) + sy * values.get("du/dy", 0.0)
        cv = v - shift_v + sx * values.get("dv/dx", 0.0) + sy * values.get("dv/dy", 0.0)
        corners.append((cu * width, cv * height))
    fetched = [] if sample is None else [(i, j, w) for lv, i, j, w in sample.fetches
                                        if lv == level]
    caption = (f"level {level} ({width} x {height}) \u00b7 u {u:.4f}, v {v:.4f} \u00b7 "
               f"rho {values.get('rho', float('nan')):.3g}, lambda "
               f"{values.get('lambda', float('nan')):.3g} \u00b7 "
               f"{int(values.get('fetches', 0))} texels fetched")
    return TexturePicture(_rgba(texture.levels[level]), level, caption, texture.top + 1, corners,
                          fetched)


def _lookup(trace, index, options, texture, pixel):
    """The step's lookup again, with every fetch (None when the vertices are unknown)."""
    var = trace.variables_at(index)
    try:
        corners = [tuple(var[f"P{k}"]) for k in range(3)]
        uv = [tuple(var[f"uv{k}"]) for k in range(3)]
        w = [float(var[f"w{k}"]) for k in range(3)]
        mapping = Mapping(corners, uv, w, bool(options.get("perspective", True)))
        sampler = Sampler(texture, options.get("filter", "bilinear"), options.get("wrap", "repeat"),
                          int(options.get("max_aniso", 8)), int(options.get("samples", 8)))
        ox, oy = var.get("offset", (0, 0))
        return sampler.sample(mapping, pixel[0] + ox, pixel[1] + oy)
    except (KeyError, TypeError, ValueError):
        return None


def _rgba(level: np.ndarray) -> np.ndarray:
    rgb = np.clip(np.rint(level), 0, 255).astype(np.uint8)
    alpha = np.full(rgb.shape[:2] + (1,), 255, np.uint8)
    return np.concatenate([rgb, alpha], axis=2)


def level_map(trace, index: int) -> np.ndarray | None:
    """(H, W, 4) uint8: each pixel written up to step ``index`` in the colour of the mip
    level it read (the finer one of two), transparent elsewhere; None without levels."""
    if trace is None or "level" not in trace.value_names:
        return None
    writes = trace.written(0, index + 1)
    levels = trace.series("level")[writes.steps]
    image = np.zeros((trace.height, trace.width, 4), np.uint8)
    inside = (writes.pixels[:, 0] >= 0) & (writes.pixels[:, 0] < trace.width) \
        & (writes.pixels[:, 1] >= 0) & (writes.pixels[:, 1] < trace.height) & ~np.isnan(levels)
    x, y = writes.pixels[inside, 0], writes.pixels[inside, 1]
    image[y, x, :3] = LEVEL_COLOURS[levels[inside].astype(int) % len(LEVEL_COLOURS)]
    image[y, x, 3] = 255
    return image
