"""The visibility family: which surface is seen at each pixel.

``zbuffer_painter``  the z-buffer and the painter's algorithm
``painter_split``    the painter's algorithm made right by splitting (a BSP tree)
"""
from __future__ import annotations

# Imported in this order, so the algorithms are listed in this order.
from . import zbuffer_painter, painter_split  # noqa: F401  (importing them registers the family)
