"""The circle family: circles and ellipses around a centre, and curves.

``midpoint``  4- and 8-way symmetry, the midpoint circle and the midpoint ellipse
``variants``  Bresenham's circle and the other printed circle listings
``curves``    circles from real centres and radii, and curves beyond circles
``batch``     many midpoint circles at once, for large workloads
"""
from __future__ import annotations

# Imported in this order, so the algorithms are listed in this order.
from . import midpoint, variants, curves  # noqa: F401  (importing them registers the family)
