"""The polygon family: scan-line fill with edge tables, convex fill, tessellation.

Points are real pixel coordinates, snapped to a sub-pixel grid of 1/256 px
(8 fractional bits) and evaluated exactly from there on: a snapped
coordinate is the integer ``X = round(x * 256)``, and pixel (i, j) has its
sample point, its centre, at ``(256 i + 128, 256 j + 128)`` in those units.

Fill rule: a pixel is covered when its centre is strictly inside, or lies
exactly on a left edge or on a bottom horizontal edge. Scan line j (the row
of centres at y = j + 1/2) meets the edges with ``ymin <= j + 1/2 < ymax``,
and a run between crossings x_left and x_right covers the centres with
``x_left <= i + 1/2 < x_right``. Equivalently: a centre is covered when the
point a hair to its right and a far smaller hair above it is inside; that
point lies on no edge, so polygons that share an edge share no pixel and
leave no gap between them.
"""
from __future__ import annotations

# Imported in this order, so the algorithms are listed in this order.
from .common import ONE, POLYGON, snap, snap_contours
from .scanline import SCANLINE, scanline_mask, scanline_pixels
from .many import scanline_fill_many
from .convex import CONVEX, convexity_problem
from .tessellate import TESSELLATE, simplicity_problem
from . import textbook, trapezoids

# The family's algorithms, in the order they are listed.
SPECS = (SCANLINE, CONVEX, TESSELLATE) + textbook.SPECS + trapezoids.SPECS

__all__ = ["ONE", "POLYGON", "snap", "snap_contours", "SCANLINE", "scanline_mask",
           "scanline_pixels", "scanline_fill_many", "CONVEX", "convexity_problem", "TESSELLATE", "simplicity_problem"]
