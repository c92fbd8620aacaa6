"""The line family: step generators (and fast kernels) for segments P -> Q.

Points are integer pixel coordinates; pixel (i, j) is the ideal line's
sample point at (i + 1/2, j + 1/2), so the ideal segment runs between the
centres of the two end pixels. Every algorithm plots both end pixels but
the listings shown as printed (line-dda-printed, line-explicit-printed, the
as-printed variant of line-bresenham-textbook, line-parametric-printed),
which can miss Q (add-first misses P too); their notes say when.
"""
from __future__ import annotations

# Imported in this order, so the algorithms are listed in this order.
from . import bresenham as _bresenham, explicit_printed, forms as _forms, textbook, traversal
from .common import COLORS, SEGMENT, Octant
from .bresenham import bresenham, bresenham_code, bresenham_pixels
from .forms import explicit, implicit, incremental, parametric

# The family's algorithms, in the order they are listed.
# (line-two-triangles, a line algorithm that fills triangles, is declared by
# the triangle package: algorithms/triangles/line_triangles.py.)
SPECS = _bresenham.SPECS + _forms.SPECS + explicit_printed.SPECS + textbook.SPECS + traversal.SPECS

__all__ = ["COLORS", "SEGMENT", "Octant", "bresenham", "bresenham_code", "bresenham_pixels",
           "explicit", "implicit", "incremental", "parametric"]
