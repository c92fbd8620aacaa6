"""The visibility family: which surface is seen at each pixel.

``zbuffer_painter``  the z-buffer and the painter's algorithm
``painter_split``    the painter's algorithm made right by splitting (a BSP tree)
``stencil``          the stencil buffer: a triangle drawn through a polygon mask
"""
from __future__ import annotations

from . import zbuffer_painter, painter_split, stencil

# The family's algorithms, in the order they are listed.
SPECS = zbuffer_painter.SPECS + painter_split.SPECS + stencil.SPECS
