"""The fill family: seed (flood) fill inside an outline drawn on the grid.

``flood``   the generators: an outline drawn, then the region of a seed filled
``seed``    where a fill starts and what stops it, shared with the kernel
``kernel``  the final raster at once, by a compiled span fill
"""
from __future__ import annotations

from .flood import SPECS  # noqa: F401  (the family's algorithms)
